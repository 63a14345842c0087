"""https for the classroom (docs/class.md, "https on the phones"): phones give the gyroscope to
a secure context only. The server makes a local certificate authority for the class's own
addresses and with it the server's certificate for them (DATA/tls/). The CA can vouch for
nothing else: its X.509 name constraints permit only those addresses (the chosen address,
127.0.0.1 and localhost), and it lives CA_DAYS days. Its private key is never written to disk:
it signs the server's certificate once and is dropped, so a new address set (or an expired CA)
means a new CA, which phones install again. The CA's certificate is served at /ca.pem so a
teacher may install it on the phones; without it each phone passes the browser's warning once.
Made with python3-cryptography; served through Python's ssl (the platform's OpenSSL)."""
import datetime
import ipaddress
import pathlib
import ssl

from cryptography import x509
from cryptography.hazmat.primitives import hashes, serialization
from cryptography.hazmat.primitives.asymmetric import ec
from cryptography.x509.oid import ExtendedKeyUsageOID, NameOID

from bookspin_class.data_folder import write_private

CA_NAME = "bookspin-class-ca"
# A month of lessons: a CA a phone keeps after the class vouches for nothing after it, and a
# school's block of lessons needs at most one reinstall. Remade a day before it ends.
CA_DAYS = 30
RENEW_BEFORE = datetime.timedelta(days=1)


def _name(common):
    return x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, common),
                      x509.NameAttribute(NameOID.ORGANIZATION_NAME, "bookspin class")])


def _general_names(addresses, ip=ipaddress.ip_address):
    """x509 names of `addresses` (IPs or ASCII host names): each IP through `ip` (ip_address for
    a certificate's SAN, ip_network for a constraint: the address alone, /32 or /128), each host
    name a DNSName."""
    names = []
    for address in addresses:
        try:
            names.append(x509.IPAddress(ip(address)))
        except ValueError:
            names.append(x509.DNSName(address))
    return names


def _constraints(addresses):
    """The CA's NameConstraints: each of `addresses` alone, nothing else. localhost is always
    among them, so that DNS names are constrained too (a type with no permitted subtree would
    be unconstrained, RFC 5280 4.2.1.10)."""
    return x509.NameConstraints(permitted_subtrees=_general_names(addresses, ipaddress.ip_network),
                                excluded_subtrees=None)


def make_authority(addresses, now):
    """A new CA for `addresses` (IPs or ASCII host names): (private key, certificate), valid
    CA_DAYS days from `now` (an aware datetime), name-constrained to `addresses` alone, for
    server authentication alone."""
    key = ec.generate_private_key(ec.SECP256R1())
    cert = (x509.CertificateBuilder().subject_name(_name("bookspin class local CA"))
            .issuer_name(_name("bookspin class local CA")).public_key(key.public_key())
            .serial_number(x509.random_serial_number())
            .not_valid_before(now - datetime.timedelta(minutes=5))
            .not_valid_after(now + datetime.timedelta(days=CA_DAYS))
            .add_extension(x509.BasicConstraints(ca=True, path_length=0), critical=True)
            .add_extension(x509.KeyUsage(False, False, False, False, False, True, True, False,
                                         False), critical=True)
            .add_extension(_constraints(addresses), critical=True)
            .add_extension(x509.ExtendedKeyUsage([ExtendedKeyUsageOID.SERVER_AUTH]),
                           critical=False)
            .add_extension(x509.SubjectKeyIdentifier.from_public_key(key.public_key()),
                           critical=False)
            .sign(key, hashes.SHA256()))
    return key, cert


def make_server_certificate(ca_key, ca_cert, addresses):
    """The server's (private key, certificate) for `addresses` (its subjectAltName), signed by
    the CA, valid as long as the CA. Its subject's common name is no host name, so that a
    verifier that reads one there (OpenSSL does where no DNS name is in the SAN) checks the
    SAN's names alone against the CA's constraints."""
    key = ec.generate_private_key(ec.SECP256R1())
    cert = (x509.CertificateBuilder().subject_name(_name("bookspin class server"))
            .issuer_name(ca_cert.subject).public_key(key.public_key())
            .serial_number(x509.random_serial_number())
            .not_valid_before(ca_cert.not_valid_before).not_valid_after(ca_cert.not_valid_after)
            .add_extension(x509.SubjectAlternativeName(_general_names(addresses)),
                           critical=False)
            .add_extension(x509.BasicConstraints(ca=False, path_length=None), critical=True)
            .add_extension(x509.ExtendedKeyUsage([ExtendedKeyUsageOID.SERVER_AUTH]),
                           critical=False)
            .add_extension(x509.AuthorityKeyIdentifier.from_issuer_public_key(
                ca_key.public_key()), critical=False)
            .sign(ca_key, hashes.SHA256()))
    return key, cert


def _make(folder, addresses, now):
    """A new CA and the server's certificate for `addresses`; writes both certificates and the
    server's key (0600). The CA's key signs once and is not kept."""
    ca_key, ca_cert = make_authority(addresses, now)
    key, cert = make_server_certificate(ca_key, ca_cert, addresses)
    write_private(folder / "server-key.pem", key.private_bytes(
        serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
        serialization.NoEncryption()))
    write_private(folder / "server.pem", cert.public_bytes(serialization.Encoding.PEM))
    write_private(folder / f"{CA_NAME}.pem", ca_cert.public_bytes(serialization.Encoding.PEM))
    write_private(folder / "server-names.txt", ("\n".join(addresses) + "\n").encode("ascii"))
    # A CA key of an earlier version, whose CA could vouch for any name: gone.
    (folder / f"{CA_NAME}-key.pem").unlink(missing_ok=True)


def _still_good(folder, addresses, now):
    """Whether DATA/tls/ holds a CA with name constraints for exactly `addresses`, more than
    RENEW_BEFORE from its end, and the server's certificate and key."""
    try:
        if (folder / "server-names.txt").read_text().split() != list(addresses):
            return False
        ca = x509.load_pem_x509_certificate((folder / f"{CA_NAME}.pem").read_bytes())
        ca.extensions.get_extension_for_class(x509.NameConstraints)
        if not (folder / "server.pem").is_file() or not (folder / "server-key.pem").is_file():
            return False
    except (OSError, ValueError, x509.ExtensionNotFound):
        return False
    return ca.not_valid_after.replace(tzinfo=datetime.timezone.utc) - now > RENEW_BEFORE


def server_context(data_dir, addresses):
    """The TLS context serving `addresses` (IPs or ASCII host names, the phones' address first),
    making DATA/tls/ (0700) as needed; returns (ssl.SSLContext, path of the CA's certificate).
    Raises OSError where a file cannot be written (a full disk)."""
    folder = pathlib.Path(data_dir) / "tls"
    folder.mkdir(mode=0o700, exist_ok=True)
    folder.chmod(0o700)
    now = datetime.datetime.now(datetime.timezone.utc)
    if not _still_good(folder, addresses, now):
        _make(folder, list(addresses), now)
    context = ssl.create_default_context(ssl.Purpose.CLIENT_AUTH)
    context.minimum_version = ssl.TLSVersion.TLSv1_2
    context.load_cert_chain(folder / "server.pem", folder / "server-key.pem")
    return context, folder / f"{CA_NAME}.pem"
