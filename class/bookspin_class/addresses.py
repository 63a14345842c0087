"""The laptop's addresses on the classroom's network (docs/class.md, "The teacher's steps"):
which address the phones are sent to, and the teacher's `--address` checked. The interfaces
and their addresses come from psutil (python3-psutil); a host name in any script is turned into
its IDNA form (xn--…) by the idna package (python3-idna), IDNA 2008 with UTS 46 mapping."""
import ipaddress
import socket
import typing

import idna
import psutil

# Interfaces that phones do not reach: containers' and virtual machines' bridges, VPN tunnels.
# Their addresses are listed, after the others.
VIRTUAL_PREFIXES = ("docker", "br-", "virbr", "veth", "vboxnet", "vmnet", "lxc", "lxd", "podman",
                    "cni", "flannel", "tun", "tap", "wg", "zt", "tailscale")


class Address(typing.NamedTuple):
    """One IPv4 address of the laptop: `address` (dotted) on `interface` (its name)."""
    address: str
    interface: str


def routed_address():
    """The source address of this laptop's route to a documentation address (a UDP socket
    connected, nothing sent): its address on the network it routes through, or None where
    there is no route (a laptop's own hotspot has no default route)."""
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as probe:
        try:
            probe.connect(("192.0.2.1", 9))
            return probe.getsockname()[0]
        except OSError:
            return None


def reachable_addresses():
    """Every IPv4 address of an interface that is up, but loopback, best first: the routed
    address, then private (RFC 1918) addresses before others and link-local ones (169.254/16)
    last, interfaces that are running before those that are not, real ones before containers'
    and VPNs'. A list of Address; empty where the laptop has loopback alone."""
    stats = psutil.net_if_stats()
    routed = routed_address()
    found = []
    for interface, entries in psutil.net_if_addrs().items():
        stat = stats.get(interface)
        if stat is None or not stat.isup:
            continue
        for entry in entries:
            if entry.family != socket.AF_INET:
                continue
            ip = ipaddress.IPv4Address(entry.address)
            if ip.is_loopback or ip.is_unspecified or ip.is_multicast:
                continue
            rank = (entry.address != routed, ip.is_link_local, not ip.is_private,
                    interface.startswith(VIRTUAL_PREFIXES),
                    "running" not in getattr(stat, "flags", "running"), interface, ip)
            found.append((rank, Address(entry.address, interface)))
    return [address for _, address in sorted(found)]


def host_option(text):
    """--address checked: an IP address (returned in its short form) or a host name (returned
    in ASCII: a name in any script as its IDNA A-labels, lower case, no trailing dot). Raises
    ValueError with the reason, one line, where it is empty or neither (a space, a scheme, a
    port or a path in it; a name all digits that is no IP address)."""
    if not text:
        raise ValueError("empty: give this laptop's address on the classroom's network, "
                         "e.g. --address 192.168.1.20")
    try:
        return str(ipaddress.ip_address(text))
    except ValueError:
        pass
    example = "e.g. --address 192.168.1.20 or --address laptop.local"
    try:
        host = idna.encode(text, uts46=True).decode("ascii").rstrip(".")
    except (idna.IDNAError, UnicodeError):
        raise ValueError(f"{text!r} is not a host name or an IP address (a host alone: no "
                         f"scheme, port, path or space), {example}") from None
    if not host or len(host) > 253:
        raise ValueError(f"{text!r} is not a host name (1 to 253 characters), {example}")
    if host.rsplit(".", 1)[-1].isdigit():
        raise ValueError(f"{text!r} is not an IP address (each of its 4 numbers 0 to 255), "
                         f"{example}")
    return host
