"""LCM's UDP multicast transport, receive side (the protocol as LCM documents it).

A small message is one datagram: magic "LC02" (0x4C433032), uint32 sequence number, the channel
(NUL-terminated), the payload. A larger one is fragmented: magic "LC03" (0x4C433033), uint32
sequence number, uint32 payload size, uint32 offset of this fragment in the payload, uint16
fragment number, uint16 fragment count; fragment 0 carries the channel (NUL-terminated) before
its data. All big endian.
"""
import os
import re
import select
import socket
import struct
import time
import urllib.parse

from .types import decode

DEFAULT_URL = "udpm://239.255.76.67:7667?ttl=0"
MAGIC_SHORT = 0x4C433032
MAGIC_LONG = 0x4C433033
_SHORT = struct.Struct(">II")
_LONG = struct.Struct(">IIIIHH")
MAX_PAYLOAD_BYTES = 256 * 1024 * 1024  # a larger announced size is garbage, not a message


def parse_url(url):
    """(group, port, recv_buf_size) of a udpm URL; ValueError for anything else."""
    url = url or os.environ.get("LCM_DEFAULT_URL") or DEFAULT_URL
    parts = urllib.parse.urlsplit(url)
    if parts.scheme != "udpm":
        raise ValueError(f"{url}: only udpm:// URLs can be received (provider '{parts.scheme}')")
    group = parts.hostname or "239.255.76.67"
    try:
        port = parts.port or 7667
        first = int(group.split(".")[0])
        socket.inet_aton(group)
    except ValueError as error:
        raise ValueError(f"{url}: {error}") from None
    if not 224 <= first <= 239 or group.count(".") != 3:
        raise ValueError(f"{url}: {group} is not an IPv4 multicast group (224.0.0.0/4)")
    options = dict(urllib.parse.parse_qsl(parts.query))
    unknown = set(options) - {"ttl", "recv_buf_size"}
    if unknown:
        raise ValueError(f"{url}: unknown option {sorted(unknown)[0]!r} (ttl, recv_buf_size)")
    return group, port, int(options.get("recv_buf_size", 2 * 1024 * 1024))


class _Fragments:
    """The message being reassembled from one sender."""

    def __init__(self, seq, size, count):
        self.seq, self.count = seq, count
        self.data = bytearray(size)
        self.channel = None
        self.seen = set()


class Datagrams:
    """A joined udpm socket; `receive(timeout_s)` returns the next whole message as (channel,
    payload) or None when nothing came in time. Fragments of one message are collected per sender
    (a new sequence number from a sender drops its unfinished message, as LCM does)."""

    def __init__(self, url=None):
        group, port, buf = parse_url(url)
        self.url = url or DEFAULT_URL
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM, socket.IPPROTO_UDP)
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.sock.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, buf)
        self.sock.bind((group, port))  # the group only: no unicast traffic to the port
        mreq = socket.inet_aton(group) + socket.inet_aton("0.0.0.0")
        self.sock.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, mreq)
        self._partial = {}
        self.bad_datagrams = 0

    def close(self):
        self.sock.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def receive(self, timeout_s=None):
        deadline = None if timeout_s is None else time.monotonic() + timeout_s
        while True:
            wait = None if deadline is None else max(0.0, deadline - time.monotonic())
            if not select.select([self.sock], [], [], wait)[0]:
                return None
            datagram, sender = self.sock.recvfrom(65536)
            message = self._take(datagram, sender)
            if message is not None:
                return message

    def _take(self, datagram, sender):
        if len(datagram) < _SHORT.size:
            self.bad_datagrams += 1
            return None
        magic = _SHORT.unpack_from(datagram)[0]
        if magic == MAGIC_SHORT:
            end = datagram.find(b"\0", _SHORT.size)
            if end < 0:
                self.bad_datagrams += 1
                return None
            return datagram[_SHORT.size:end].decode("utf-8", "replace"), datagram[end + 1:]
        if magic == MAGIC_LONG and len(datagram) >= _LONG.size:
            return self._fragment(datagram, sender)
        self.bad_datagrams += 1
        return None

    def _fragment(self, datagram, sender):
        _, seq, size, offset, number, count = _LONG.unpack_from(datagram)
        body = datagram[_LONG.size:]
        if size > MAX_PAYLOAD_BYTES or number >= count:
            self.bad_datagrams += 1
            return None
        frag = self._partial.get(sender)
        if frag is None or frag.seq != seq or len(frag.data) != size or frag.count != count:
            frag = self._partial[sender] = _Fragments(seq, size, count)
        if number == 0:
            end = body.find(b"\0")
            if end < 0:
                self.bad_datagrams += 1
                return None
            frag.channel = body[:end].decode("utf-8", "replace")
            body = body[end + 1:]
        if offset + len(body) > size:
            self.bad_datagrams += 1
            return None
        frag.data[offset:offset + len(body)] = body
        frag.seen.add(number)
        if len(frag.seen) == frag.count and frag.channel is not None:
            del self._partial[sender]
            return frag.channel, bytes(frag.data)
        return None


def subscribe(url, channel, timeout_s=None):
    """Yields the decoded messages (the generated rig types) of every channel that `channel`
    matches as a whole (a regular expression, as LCM's subscribe takes), live from the udpm
    `url` (None: $LCM_DEFAULT_URL or the rig's default). Messages of other types are skipped.
    With `timeout_s`, the iteration ends after that long without a matching message."""
    pattern = re.compile(channel)
    with Datagrams(url) as sock:
        last = time.monotonic()
        while True:
            wait = None if timeout_s is None else timeout_s - (time.monotonic() - last)
            got = sock.receive(wait) if wait is None or wait > 0 else None
            if got is None:
                return
            name, payload = got
            if pattern.fullmatch(name):
                msg = decode(payload)
                if msg is not None:
                    last = time.monotonic()
                    yield msg
