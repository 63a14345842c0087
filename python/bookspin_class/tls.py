"""https for the classroom (docs/class.md, "https on the phones"): phones give the gyroscope to
a secure context only. The server makes, once per data folder, a local certificate authority
(DATA/tls/bookspin-class-ca.pem, its key beside it, 10 years) and with it the server's
certificate for the laptop's addresses (remade when they change, 1 year: under the 398 days
Apple's and Chrome's rules allow). The CA's certificate is served at /ca.pem so a teacher may
install it on the phones; without it each phone passes the browser's warning once. Made with
python3-cryptography; served through Python's ssl (the platform's OpenSSL)."""
import datetime
import ipaddress
import pathlib
import ssl

from cryptography import x509
from cryptography.hazmat.primitives import hashes, serialization
from cryptography.hazmat.primitives.asymmetric import ec
from cryptography.x509.oid import ExtendedKeyUsageOID, NameOID

CA_NAME = "bookspin-class-ca"


def _write_key(path, key):
    path.write_bytes(key.private_bytes(serialization.Encoding.PEM,
                                       serialization.PrivateFormat.PKCS8,
                                       serialization.NoEncryption()))
    path.chmod(0o600)


def _name(common):
    return x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, common),
                      x509.NameAttribute(NameOID.ORGANIZATION_NAME, "bookspin class")])


def _make_ca(folder):
    key = ec.generate_private_key(ec.SECP256R1())
    now = datetime.datetime.now(datetime.timezone.utc)
    cert = (x509.CertificateBuilder().subject_name(_name("bookspin class local CA"))
            .issuer_name(_name("bookspin class local CA")).public_key(key.public_key())
            .serial_number(x509.random_serial_number())
            .not_valid_before(now - datetime.timedelta(minutes=5))
            .not_valid_after(now + datetime.timedelta(days=3650))
            .add_extension(x509.BasicConstraints(ca=True, path_length=0), critical=True)
            .add_extension(x509.KeyUsage(False, False, False, False, False, True, True, False,
                                         False), critical=True)
            .add_extension(x509.SubjectKeyIdentifier.from_public_key(key.public_key()),
                           critical=False)
            .sign(key, hashes.SHA256()))
    _write_key(folder / f"{CA_NAME}-key.pem", key)
    (folder / f"{CA_NAME}.pem").write_bytes(cert.public_bytes(serialization.Encoding.PEM))


def _server_names(addresses):
    names = []
    for address in addresses:
        try:
            names.append(x509.IPAddress(ipaddress.ip_address(address)))
        except ValueError:
            names.append(x509.DNSName(address))
    return names


def _make_server_cert(folder, addresses):
    ca_key = serialization.load_pem_private_key((folder / f"{CA_NAME}-key.pem").read_bytes(),
                                                password=None)
    ca_cert = x509.load_pem_x509_certificate((folder / f"{CA_NAME}.pem").read_bytes())
    key = ec.generate_private_key(ec.SECP256R1())
    now = datetime.datetime.now(datetime.timezone.utc)
    cert = (x509.CertificateBuilder().subject_name(_name(addresses[0]))
            .issuer_name(ca_cert.subject).public_key(key.public_key())
            .serial_number(x509.random_serial_number())
            .not_valid_before(now - datetime.timedelta(minutes=5))
            .not_valid_after(now + datetime.timedelta(days=365))
            .add_extension(x509.SubjectAlternativeName(_server_names(addresses)), critical=False)
            .add_extension(x509.BasicConstraints(ca=False, path_length=None), critical=True)
            .add_extension(x509.ExtendedKeyUsage([ExtendedKeyUsageOID.SERVER_AUTH]),
                           critical=False)
            .add_extension(x509.AuthorityKeyIdentifier.from_issuer_public_key(
                ca_key.public_key()), critical=False)
            .sign(ca_key, hashes.SHA256()))
    _write_key(folder / "server-key.pem", key)
    (folder / "server.pem").write_bytes(cert.public_bytes(serialization.Encoding.PEM))
    (folder / "server-names.txt").write_text("\n".join(addresses) + "\n")


def server_context(data_dir, addresses):
    """The TLS context serving `addresses` (IPs or host names), making DATA/tls/ as needed;
    returns (ssl.SSLContext, path of the CA's certificate)."""
    folder = pathlib.Path(data_dir) / "tls"
    folder.mkdir(mode=0o700, parents=True, exist_ok=True)
    if not (folder / f"{CA_NAME}.pem").is_file():
        _make_ca(folder)
    names = folder / "server-names.txt"
    if not names.is_file() or names.read_text().split() != list(addresses) or \
            not (folder / "server.pem").is_file():
        _make_server_cert(folder, list(addresses))
    context = ssl.create_default_context(ssl.Purpose.CLIENT_AUTH)
    context.minimum_version = ssl.TLSVersion.TLSv1_2
    context.load_cert_chain(folder / "server.pem", folder / "server-key.pem")
    return context, folder / f"{CA_NAME}.pem"
