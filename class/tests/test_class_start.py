"""The class server's start (docs/class.md, "The teacher's steps", "https on the phones", "What
is kept"), as a teacher meets it: the first command after the set-up, the address phones are
sent to (the laptop's own hotspot: a network namespace with one interface and no default
route), the short address, the class's CA constrained to the class's addresses and short-lived,
the store and keys readable by the teacher's account alone, the teacher's key never in the
terminal, and options that cannot serve. Real servers, real HTTPS clients, real OpenSSL
(Python's ssl). What a start that cannot serve leaves: test_class_stays.py."""
import contextlib
import ctypes
import datetime
import http.client
import io
import ipaddress
import os
import pathlib
import socket
import ssl
import stat
import subprocess
import sys
import tempfile
import threading

import pytest

from class_server import require_packages  # noqa: E402

require_packages('aiohttp', 'psutil', 'segno', 'cryptography')
import segno  # noqa: E402
from cryptography import x509  # noqa: E402
from cryptography.hazmat.primitives import serialization  # noqa: E402

from class_server import Server, in_ci
from class_start_shared import (listing, namespace_problem, one_error_line, page,  # noqa: F401
                                servers)
from conftest import EXE, SOURCE_DIR


def mode(path):
    return stat.S_IMODE(os.stat(path).st_mode)


# The first command.

def test_the_first_command_names_what_is_missing_and_the_command_that_builds_it(tmp_path, page):
    """Without the module (after `make figures`, which does not build it): one line naming
    `make class`, the command that builds it, not the command just run; the Makefile's `class`
    builds the module and the page and names the command that starts the class."""
    data = tmp_path / "data"
    empty = tmp_path / "empty-build"
    empty.mkdir()
    env = dict(os.environ, PYTHONPATH=str(SOURCE_DIR / "class"))
    env.pop("BOOKSPIN_CLASS_BUILD", None)
    command = [sys.executable, "-m", "bookspin_class", "--data", str(data), "--page", str(page)]
    probe = subprocess.run([sys.executable, "-c", "import bookspin"], env=env,
                           capture_output=True)
    if probe.returncode == 0:
        pytest.skip("a bookspin module is installed for this python: it cannot be missing")
    # As BUILD/bookspin-class runs it, with a build that has no module.
    done = subprocess.run(command, env=dict(env, BOOKSPIN_CLASS_BUILD=str(empty)),
                          capture_output=True, text=True, timeout=60)
    line = one_error_line(done.returncode, done.stdout, done.stderr, "`make ")
    assert f" class BUILD={empty}` builds it" in line and f"not built in {empty}/python" in line
    assert "BUILD/bookspin-class" not in line
    # Run another way, without the launcher's PYTHONPATH: the launcher is the fix.
    done = subprocess.run(command, env=env, capture_output=True, text=True, timeout=60)
    line = one_error_line(done.returncode, done.stdout, done.stderr, "build/bookspin-class")
    assert not data.exists()
    # The build's own launcher says where its module should be.
    launcher = pathlib.Path(EXE).parent / "bookspin-class"
    if launcher.is_file() and f":{SOURCE_DIR / 'class'}" in launcher.read_text():
        text = launcher.read_text().replace(str(pathlib.Path(EXE).parent), str(empty))
        (empty / "bookspin-class").write_text(text)
        done = subprocess.run(["sh", str(empty / "bookspin-class"), "--data", str(data),
                               "--page", str(page)], capture_output=True, text=True,
                              timeout=60, env=dict(os.environ, PYTHONPATH=""))
        line = one_error_line(done.returncode, done.stdout, done.stderr, "`make ")
        assert f" class BUILD={empty}` builds it" in line, line
    # `make class` builds the module and the page, then says the command.
    done = subprocess.run(["make", "-n", "class", f"BUILD={empty}"], cwd=SOURCE_DIR,
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "--target bookspin_python" in done.stdout
    assert f"web/build.sh {empty}" in done.stdout and "bookspin explore" in done.stdout
    assert f"{empty}/bookspin-class starts the class" in done.stdout
    readme = (SOURCE_DIR / "README.md").read_text().split("```")[1]
    assert "make class" in readme, readme


# The address phones are sent to.

def test_address_takes_a_host_or_an_ip_alone(tmp_path, page, servers):
    data = tmp_path / "data"
    for value in ("a b", "http://192.168.1.20/", "", "192.168.1.300", "☃.net",
                  "laptop.local:8443"):
        status, stdout, stderr = Server(data, page, address=value).run()
        one_error_line(status, stdout, stderr, "--address")
        assert not data.exists(), value
    # A name in another script: its IDNA form, in the phones' address and the certificate.
    server = servers(Server(data, page, address="Bücher.example")).start()
    assert server.line("phones join:") == \
        f"https://xn--bcher-kva.example:{server.port}/explorer.html?class={server.code}#lab"
    cert = x509.load_pem_x509_certificate((data / "tls" / "server.pem").read_bytes())
    names = cert.extensions.get_extension_for_class(x509.SubjectAlternativeName).value
    assert "xn--bcher-kva.example" in names.get_values_for_type(x509.DNSName)
    assert server.state()["join_url"].startswith("https://xn--bcher-kva.example:")


def test_behind_the_schools_proxy_phones_and_teacher_are_sent_to_its_port(tmp_path, page,
                                                                          servers):
    data = tmp_path / "data"
    for value in ("0", "65536", "x", ""):
        status, stdout, stderr = Server(data, page, extra=["--public-port", value]).run()
        one_error_line(status, stdout, stderr, "--public-port")
        assert not data.exists(), value
    # The proxy on https's own port: no port in the addresses; on another, that port.
    for public, shown in ((443, ""), (8080, ":8080")):
        server = servers(Server(data, page, address="class.school.example",
                                extra=["--public-port", str(public)])).start()
        base = f"https://class.school.example{shown}"
        assert server.line("phones join:") == \
            f"{base}/explorer.html?class={server.code}#lab"
        assert server.state()["join_url"] == f"{base}/explorer.html?class={server.code}#lab"
        assert (data / "teacher-address.txt").read_text().startswith(f"{base}/teacher?key=")
        server.stop()


def test_the_short_address_opens_the_classs_join_form(tmp_path, page, servers):
    server = servers(Server(tmp_path / "data", page)).start()
    status, body = server.request("GET", "/")
    assert status == 302, (status, body)
    connection = http.client.HTTPSConnection("127.0.0.1", server.port, context=server.context,
                                             timeout=30)
    connection.request("GET", "/")
    location = connection.getresponse().getheader("Location")
    connection.close()
    assert location == f"/explorer.html?class={server.code}#lab"
    assert server.state()["join_url"].endswith(location)
    # Once the class is ended, the short address is the page alone.
    assert server.request("DELETE", f"/api/class/{server.code}", token=server.key)[0] == 200
    assert server.request("GET", "/") == (200, page.read_bytes())


@contextlib.contextmanager
def network_namespace(interfaces):
    """A network namespace with loopback up, each of `interfaces` ({name: (kind, "ADDR/PREFIX")})
    an interface up with that address, and no route out; yields its name. A kind "dummy" is a
    veth pair (its peer up, without an address) where the kernel has no dummy interfaces."""
    why, should = namespace_problem()
    if why:
        if in_ci() and should:
            pytest.fail(f"network namespaces should work here (root, CAP_SYS_ADMIN): {why}")
        pytest.skip(f"no network namespace: {why}")
    name = f"bkclass{os.getpid()}{len(interfaces)}"
    subprocess.run(["ip", "netns", "add", name], check=True)
    try:
        subprocess.run(["ip", "-n", name, "link", "set", "lo", "up"], check=True)
        for interface, (kind, address) in interfaces.items():
            made = subprocess.run(["ip", "-n", name, "link", "add", interface, "type", kind],
                                  capture_output=True, text=True)
            if made.returncode and kind == "dummy":
                subprocess.run(["ip", "-n", name, "link", "add", interface, "type", "veth",
                                "peer", "name", f"{interface}p"], check=True)
                subprocess.run(["ip", "-n", name, "link", "set", f"{interface}p", "up"],
                               check=True)
            elif made.returncode:
                raise AssertionError(f"ip link add {interface} type {kind}: {made.stderr}")
            for command in (["addr", "add", address, "dev", interface],
                            ["link", "set", interface, "up"]):
                subprocess.run(["ip", "-n", name, *command], check=True)
        routes = subprocess.run(["ip", "-n", name, "route", "show", "default"], check=True,
                                capture_output=True, text=True).stdout
        assert routes.strip() == "", routes
        yield name
    finally:
        subprocess.run(["ip", "netns", "del", name], capture_output=True)


def in_namespace(name, function):
    """function()'s value, called on a thread that entered the network namespace `name`
    (setns(2): a thread's network namespace is its own)."""
    result = {}

    def run():
        try:
            libc = ctypes.CDLL(None, use_errno=True)
            with open(f"/run/netns/{name}") as handle:
                if libc.setns(handle.fileno(), 0x40000000) != 0:  # CLONE_NEWNET
                    raise OSError(ctypes.get_errno(), "setns")
            result["value"] = function()
        except BaseException as error:  # raised again on the caller's thread
            result["error"] = error

    thread = threading.Thread(target=run)
    thread.start()
    thread.join()
    if "error" in result:
        raise result["error"]
    return result["value"]


def test_on_the_laptops_hotspot_phones_are_sent_to_its_address(tmp_path, page, servers):
    """A hotspot: one interface (10.42.0.1/24), no default route, a container's bridge
    (docker0, no container on it) beside it. The address printed, in the class's state and in
    its QR code is 10.42.0.1, the bridge's is listed, and a phone's HTTPS client verifying the
    class's CA reaches the server there."""
    with network_namespace({"wlan0": ("dummy", "10.42.0.1/24"),
                            "docker0": ("bridge", "172.17.0.1/16")}) as name:
        server = servers(Server(tmp_path / "data", page, address=None, host="0.0.0.0",
                                prefix=["ip", "netns", "exec", name])).start()
        join = f"https://10.42.0.1:{server.port}/explorer.html?class={server.code}#lab"
        assert server.line("phones join:") == join, server.lines
        assert server.line("certificate:").startswith(f"https://10.42.0.1:{server.port}/")
        others = server.line("other addresses:")
        assert "172.17.0.1 (docker0)" in others and "--address" in others, others
        assert not any("NO ADDRESS" in line for line in server.lines), server.lines

        def as_a_phone():
            state = server.state()
            svg = server.request("GET", f"/api/class/{server.code}/qr.svg", token=server.key)
            connection = http.client.HTTPSConnection("10.42.0.1", server.port,
                                                     context=server.context, timeout=30)
            connection.request("GET", "/")
            response = connection.getresponse()
            connection.close()
            return state, svg, response.status, response.getheader("Location")

        state, (status, svg), front, location = in_namespace(name, as_a_phone)
        assert state["join_url"] == join
        out = io.BytesIO()
        segno.make(join, error="m", micro=False).save(
            out, kind="svg", scale=10, border=4, dark="#000", light="#fff", xmldecl=False)
        assert status == 200 and svg == out.getvalue()  # the QR code holds 10.42.0.1's address
        assert (front, location) == (302, f"/explorer.html?class={server.code}#lab")
        server.stop()

    # Loopback alone: one loud line that says so.
    with network_namespace({}) as name:
        server = servers(Server(tmp_path / "data2", page, address=None, host="0.0.0.0",
                                prefix=["ip", "netns", "exec", name])).start()
        assert server.line("phones join:").startswith(f"https://127.0.0.1:{server.port}/")
        loud = [line for line in server.lines if "NO ADDRESS PHONES CAN REACH" in line]
        assert len(loud) == 1 and "--address" in loud[0] and "hotspot" in loud[0], server.lines
        server.stop()


# Trust a school can accept.

def handshake(ca_pem, cert_pem, key_pem, name):
    """None where a client trusting `ca_pem` alone accepts a server presenting `cert_pem` for
    `name` (OpenSSL, through Python's ssl); otherwise OpenSSL's reason."""
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        (folder / "ca.pem").write_bytes(ca_pem)
        (folder / "cert.pem").write_bytes(cert_pem)
        (folder / "key.pem").write_bytes(key_pem)
        served = ssl.create_default_context(ssl.Purpose.CLIENT_AUTH)
        served.load_cert_chain(folder / "cert.pem", folder / "key.pem")
        client = ssl.create_default_context(cafile=str(folder / "ca.pem"))
        left, right = socket.socketpair()
        with left, right:
            def serve():
                try:
                    with served.wrap_socket(right, server_side=True) as tls:
                        tls.recv(1)
                except (ssl.SSLError, OSError):
                    pass
            thread = threading.Thread(target=serve)
            thread.start()
            try:
                with client.wrap_socket(left, server_hostname=name) as tls:
                    tls.sendall(b"x")
                return None
            except ssl.SSLCertVerificationError as error:
                return error.verify_message
            finally:
                left.close()
                thread.join()


def test_the_class_ca_vouches_for_the_classs_addresses_alone_for_a_month(tmp_path, page,
                                                                        servers):
    sys.path.insert(0, str(SOURCE_DIR / "class"))
    try:
        from bookspin_class import tls
    finally:
        sys.path.remove(str(SOURCE_DIR / "class"))
    data = tmp_path / "data"
    server = servers(Server(data, page, address="192.0.2.10")).start()
    status, ca_pem = server.request("GET", "/ca.pem")
    assert status == 200 and ca_pem == (data / "tls" / "bookspin-class-ca.pem").read_bytes()
    ca = x509.load_pem_x509_certificate(ca_pem)
    constraints = ca.extensions.get_extension_for_class(x509.NameConstraints)
    assert constraints.critical and constraints.value.excluded_subtrees is None
    assert set(constraints.value.permitted_subtrees) == {
        x509.IPAddress(ipaddress.ip_network("192.0.2.10/32")),
        x509.IPAddress(ipaddress.ip_network("127.0.0.1/32")), x509.DNSName("localhost")}
    assert ca.not_valid_after - ca.not_valid_before <= datetime.timedelta(days=31)
    assert ca.not_valid_after - datetime.datetime.utcnow() > datetime.timedelta(days=28)
    # No private key in DATA but the server's own: the CA's signed once and was dropped.
    keys = [p.name for p in (data / "tls").iterdir() if b"PRIVATE KEY" in p.read_bytes()]
    assert keys == ["server-key.pem"], keys
    server_key = serialization.load_pem_private_key((data / "tls" / "server-key.pem")
                                                    .read_bytes(), None)
    assert server_key.public_key().public_bytes(
        serialization.Encoding.DER, serialization.PublicFormat.SubjectPublicKeyInfo) != \
        ca.public_key().public_bytes(serialization.Encoding.DER,
                                     serialization.PublicFormat.SubjectPublicKeyInfo)
    # Such a CA vouches for the class's addresses and for nothing else (OpenSSL's own check).
    now = datetime.datetime.now(datetime.timezone.utc)
    ca_key, ca_cert = tls.make_authority(["192.0.2.10", "127.0.0.1", "localhost"], now)
    pem = serialization.Encoding.PEM
    for name, accepted in (("192.0.2.10", True), ("localhost", True),
                           ("www.example.com", False), ("10.9.9.9", False)):
        key, cert = tls.make_server_certificate(ca_key, ca_cert, [name])
        why = handshake(ca_cert.public_bytes(pem), cert.public_bytes(pem), key.private_bytes(
            pem, serialization.PrivateFormat.PKCS8, serialization.NoEncryption()), name)
        assert (why is None) == accepted, (name, why)
        assert accepted or "subtree" in why, why
    # The phones' address changes: a new CA for the new address set.
    server.stop()
    moved = servers(Server(data, page, address="192.0.2.11")).start()
    moved_ca = x509.load_pem_x509_certificate(moved.request("GET", "/ca.pem")[1])
    assert x509.IPAddress(ipaddress.ip_network("192.0.2.11/32")) in \
        moved_ca.extensions.get_extension_for_class(x509.NameConstraints).value \
        .permitted_subtrees
    assert moved_ca.serial_number != ca.serial_number


def test_the_store_and_keys_are_the_teachers_alone_and_the_key_never_shown(tmp_path, page,
                                                                          servers):
    data = tmp_path / "data"
    opened = tmp_path / "opened.txt"
    browser = tmp_path / "browser.sh"
    browser.write_text(f"#!/bin/sh\nprintf '%s' \"$1\" > '{opened}'\n")
    browser.chmod(0o755)
    server = servers(Server(data, page, extra=["--open"],
                            env={"BROWSER": f"{browser} %s", "DISPLAY": ""})).start()
    server.join("Anna")
    server.request("GET", f"/teacher?key={server.key}")
    assert mode(data) == 0o700 and mode(data / "tls") == 0o700
    files = [p for p in data.rglob("*") if p.is_file()]
    assert {p.name for p in files} >= {"class.sqlite3", "teacher-address.txt", "server-key.pem"}
    assert {p.name: oct(mode(p)) for p in files} == {p.name: "0o600" for p in files}
    # The teacher's address: in a file of the teacher's, and opened in the laptop's browser.
    address = (data / "teacher-address.txt").read_text().strip()
    assert address == f"https://127.0.0.1:{server.port}/teacher?key={server.key}"
    assert opened.read_text() == address
    assert str(data / "teacher-address.txt") in server.line("projector:")
    assert "opened in this laptop's browser" in server.line("projector:")
    status, _ = server.request("GET", address[address.index("/teacher"):])
    assert status == 302
    server.stop()
    shown = "\n".join(server.output) + server.process.stderr.read()
    assert server.key not in shown and "key=" not in shown, shown
    # A folder an earlier version made readable by all is made the teacher's alone.
    data.chmod(0o755)
    for path in files:
        if path.exists():
            path.chmod(0o644)
    server.extra = []
    server.start()
    assert mode(data) == 0o700
    assert all(mode(p) == 0o600 for p in data.rglob("*") if p.is_file())


# Options that cannot serve.

def test_an_empty_data_folder_and_a_page_that_is_not_html_are_refused(tmp_path, page):
    here = tmp_path / "here"
    here.mkdir()
    server = Server(here, page)
    command = server.command()
    command[command.index("--data") + 1] = ""
    done = subprocess.run(command, cwd=here, capture_output=True, text=True,
                          env=server.environment(), timeout=30)
    one_error_line(done.returncode, done.stdout, done.stderr, "--data")
    assert listing(here) == []
    data = tmp_path / "data"
    empty, binary, text = tmp_path / "empty.html", tmp_path / "binary.html", tmp_path / "t.html"
    empty.write_bytes(b"")
    binary.write_bytes(b"\x89PNG\r\n\x1a\n" + bytes(range(256)))
    text.write_text("hello, not a page\n")
    for bad in (empty, binary, text):
        line = one_error_line(*Server(data, bad).run(timeout=30), "--page")
        assert str(bad) in line and "make class" in line, line
        assert not data.exists()
