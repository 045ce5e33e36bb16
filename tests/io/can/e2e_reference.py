#!/usr/bin/python3
"""An independent AUTOSAR E2E reference (issue 14), written in Python from the E2E Protocol
Specification, with every CRC through python3-crcmod (Debian), not through rig code.

Profiles (offsets in bits, bit n = bit n % 8 of byte n // 8):
  P01  CRC-8 (poly 0x1D, start 0x00, final XOR 0x00) over the Data ID bytes the mode names
       (BOTH: low, high; ALT: low for an even counter, high for an odd one; LOW: low; NIBBLE:
       low, then 0x00, the high byte's low nibble sent at bit 12), then every byte but the CRC
       byte; 4-bit counter 0..14 at counter_offset_bits (low nibble if a multiple of 8).
  P02  CRC-8H2F over bytes 1..n-1, then data_id_list[counter]; CRC byte 0; counter 0..15 in the
       low nibble of byte 1.
  P04  header at `offset`: Length 16 bit, Counter 16 bit, Data ID 32 bit, CRC-32P4 32 bit, all
       big-endian; the CRC covers every byte but its own 4.
  P05  CRC-16/CCITT-FALSE little-endian at `offset`, 8-bit counter at offset + 16; the CRC covers
       every byte but its own 2, then the Data ID low byte, high byte.

Usage:
  e2e_reference.py vectors N SEED     C++ table of random frames protected here (for the host
                                      GoogleTest tests/io/can/e2e/e2e_vectors.inc)
  e2e_reference.py crc-vectors N SEED random CRC parameters and messages with crcmod's CRC
                                      (tests/io/can/e2e/crc_vectors.inc)
  e2e_reference.py peer IFACE --mapping TOML --wait-start EVENTS --out RESULT.json
                                      the independent ECU of the vcan case e2e_vcan_profiles:
                                      checks every frame the rig sends, sends protected frames
                                      with random values, then a wrong Data ID, a repeated and a
                                      skipped counter per message (see peer())
  e2e_reference.py selftest           check values of every CRC and profile round trips
"""
import json
import random
import socket
import struct
import sys
import time
import tomllib

import crcmod

# name: (width, poly, init, refin, refout, xorout, check of "123456789")
CRCS = {
    "crc8_sae_j1850": (8, 0x1D, 0xFF, False, False, 0xFF, 0x4B),
    "crc8_h2f": (8, 0x2F, 0xFF, False, False, 0xFF, 0xDF),
    "crc16_ccitt_false": (16, 0x1021, 0xFFFF, False, False, 0x0000, 0x29B1),
    "crc32": (32, 0x04C11DB7, 0xFFFFFFFF, True, True, 0xFFFFFFFF, 0xCBF43926),
    "crc32_p4": (32, 0xF4ACFB13, 0xFFFFFFFF, True, True, 0xFFFFFFFF, 0x1697D06A),
    "p01": (8, 0x1D, 0x00, False, False, 0x00, 0x37),
}


def reflect(value, width):
    return int(f"{value:0{width}b}"[::-1], 2)


def crc_function(width, poly, init, refin, refout, xorout):
    """A CRC through crcmod (which takes refin == refout, the register reflected when rev, and
    initCrc as the result of the empty message, i.e. init XOR xorout)."""
    assert refin == refout, "crcmod has one reflection flag"
    start = reflect(init, width) if refin else init
    fun = crcmod.mkCrcFun((1 << width) | poly, initCrc=start ^ xorout, rev=refin, xorOut=xorout)
    return fun


def crc(name, data):
    width, poly, init, refin, refout, xorout, _ = CRCS[name]
    return crc_function(width, poly, init, refin, refout, xorout)(bytes(data))


def counter_modulus(profile):
    return {"P01": 15, "P02": 16, "P04": 65536, "P05": 256}[profile]


def nibble_get(data, offset):
    b = data[offset // 8]
    return b & 0x0F if offset % 8 == 0 else b >> 4


def nibble_set(data, offset, value):
    i = offset // 8
    if offset % 8 == 0:
        data[i] = (data[i] & 0xF0) | (value & 0x0F)
    else:
        data[i] = (data[i] & 0x0F) | ((value & 0x0F) << 4)


def p01_crc(cfg, data, counter):
    low, high = cfg["data_id"] & 0xFF, (cfg["data_id"] >> 8) & 0xFF
    mode = cfg.get("data_id_mode", "BOTH")
    ids = {"BOTH": [low, high], "ALT": [low if counter % 2 == 0 else high], "LOW": [low],
           "NIBBLE": [low, 0]}[mode]
    c = cfg.get("crc_offset_bits", 0) // 8
    return crc("p01", bytes(ids) + bytes(data[:c]) + bytes(data[c + 1:]))


def protect(cfg, data, counter):
    """Fills counter, explicit fields and CRC into bytearray `data` as the profile says."""
    p = cfg["profile"]
    o = cfg.get("offset", 0) // 8
    if p == "P01":
        nibble_set(data, cfg.get("counter_offset_bits", 8), counter)
        if cfg.get("data_id_mode") == "NIBBLE":
            nibble_set(data, 12, cfg["data_id"] >> 8)
        data[cfg.get("crc_offset_bits", 0) // 8] = p01_crc(cfg, data, counter)
    elif p == "P02":
        nibble_set(data, 8, counter)
        data[0] = crc("crc8_h2f", bytes(data[1:]) + bytes([cfg["data_id_list"][counter]]))
    elif p == "P04":
        data[o:o + 2] = len(data).to_bytes(2, "big")
        data[o + 2:o + 4] = counter.to_bytes(2, "big")
        data[o + 4:o + 8] = cfg["data_id"].to_bytes(4, "big")
        data[o + 8:o + 12] = crc("crc32_p4", bytes(data[:o + 8]) + bytes(data[o + 12:])).to_bytes(
            4, "big")
    elif p == "P05":
        data[o + 2] = counter
        value = crc("crc16_ccitt_false",
                    bytes(data[:o]) + bytes(data[o + 2:]) + cfg["data_id"].to_bytes(2, "little"))
        data[o:o + 2] = value.to_bytes(2, "little")
    return data


def check(cfg, data):
    """(crc_ok, counter) of a received frame: protect a copy with its counter and compare."""
    p = cfg["profile"]
    o = cfg.get("offset", 0) // 8
    if p == "P01":
        counter = nibble_get(data, cfg.get("counter_offset_bits", 8))
    elif p == "P02":
        counter = nibble_get(data, 8)
    elif p == "P04":
        counter = int.from_bytes(data[o + 2:o + 4], "big")
    else:
        counter = data[o + 2]
    if p == "P01" and counter == 15:
        return False, counter
    return protect(cfg, bytearray(data), counter) == bytearray(data), counter


# The configurations of the host vectors (one per profile and Data ID mode).
VECTOR_CONFIGS = [
    {"profile": "P01", "data_id": 0x1234, "data_id_mode": "BOTH", "length": 8},
    {"profile": "P01", "data_id": 0x1234, "data_id_mode": "ALT", "length": 8},
    {"profile": "P01", "data_id": 0x0042, "data_id_mode": "LOW", "length": 8},
    {"profile": "P01", "data_id": 0x0ABC, "data_id_mode": "NIBBLE", "length": 8},
    {"profile": "P01", "data_id": 0xBEEF, "data_id_mode": "BOTH", "length": 8,
     "crc_offset_bits": 56, "counter_offset_bits": 52},
    {"profile": "P02", "data_id_list": [(17 * i + 3) & 0xFF for i in range(16)], "length": 8},
    {"profile": "P04", "data_id": 0x0A0B0C0D, "length": 16, "offset": 0},
    {"profile": "P04", "data_id": 0x12345678, "length": 24, "offset": 64},
    {"profile": "P05", "data_id": 0x1234, "length": 8, "offset": 0},
    {"profile": "P05", "data_id": 0xCAFE, "length": 12, "offset": 40},
]


def vectors(n, seed):
    rng = random.Random(seed)
    print("// Generated by tests/io/can/e2e_reference.py vectors %d %d: do not edit." % (n, seed))
    print("// {config index, counter, length, protected frame}")
    for k, cfg in enumerate(VECTOR_CONFIGS):
        for _ in range(n):
            counter = rng.randrange(counter_modulus(cfg["profile"]))
            data = protect(cfg, bytearray(rng.randbytes(cfg["length"])), counter)
            print("{%d, %d, %d, {%s}}," % (k, counter, len(data),
                                           ", ".join("0x%02X" % b for b in data)))


def crc_vectors(n, seed):
    """Random CRC parameters (width 8/16/32, refin == refout, as crcmod takes them) and
    random messages, with crcmod's CRC."""
    rng = random.Random(seed)
    print("// Generated by tests/io/can/e2e_reference.py crc-vectors %d %d: do not edit." % (n, seed))
    print("// {width, poly, init, refin, refout, xorout, crc (python3-crcmod), length, data}")
    for _ in range(n):
        width = rng.choice([8, 16, 32])
        poly = rng.randrange(1 << width) | 1
        init, xorout = rng.randrange(1 << width), rng.randrange(1 << width)
        ref = rng.random() < 0.5
        data = rng.randbytes(rng.randrange(0, 65))
        value = crc_function(width, poly, init, ref, ref, xorout)(data)
        print("{%d, 0x%X, 0x%X, %s, %s, 0x%X, 0x%X, %d, {%s}}," % (
            width, poly, init, str(ref).lower(), str(ref).lower(), xorout, value, len(data),
            ", ".join("0x%02X" % b for b in data)))


def selftest():
    for name, (*_, expected) in CRCS.items():
        assert crc(name, b"123456789") == expected, name
    rng = random.Random(1)
    for cfg in VECTOR_CONFIGS:
        data = protect(cfg, bytearray(rng.randbytes(cfg["length"])), 3)
        assert check(cfg, data) == (True, 3), cfg
        data[-1] ^= 0x01
        assert not check(cfg, data)[0], cfg
    print("e2e_reference: selftest ok")


# The test bench tests/io/can/e2e/e2e-bench.dbc, read by hand: id, length, and for the messages
# the rig receives the one value signal (start byte, little-endian 16 bit, signed, factor), the
# model input it feeds and the factor of its conversion to SI.
BENCH_RX = {
    "ECU_P01": (0x300, 8, (2, True, 0.01), "assist_torque_nm", 1.0),
    "ECU_P02": (0x301, 8, (2, False, 0.001), "throttle_pedal", 1.0),
    "ECU_P04": (0x302, 16, (12, False, 0.01), "brake_pressure_front_pa", 1e5),
    "ECU_P05": (0x303, 8, (3, False, 0.01), "brake_pressure_rear_pa", 1e5),
    "ECU_Crc": (0x304, 8, (0, True, 0.01), "steering_wheel_torque_cmd_nm", 1.0),
}
BENCH_TX = {"RIG_P01": (0x310, 8), "RIG_P02": (0x311, 8), "RIG_P04": (0x312, 16),
            "RIG_P05": (0x313, 8), "RIG_Crc": (0x314, 8)}
CANFD_MTU = 72


def e2e_config(table, length):
    cfg = dict(table)
    cfg["length"] = length
    p = cfg["profile"]
    if p in ("P04", "P05"):  # the rig's offset keys place the one header (docs/e2e.md)
        crc_at = 64 if p == "P04" else 0
        if "crc_offset_bits" in cfg:
            cfg["offset"] = cfg["crc_offset_bits"] - crc_at
        elif "counter_offset_bits" in cfg:
            cfg["offset"] = cfg["counter_offset_bits"] - 16
    return cfg


def generic_crc(table, data):
    fun = crc_function(table["width"], table["poly"], table.get("init", 0),
                       table.get("refin", False), table.get("refout", False),
                       table.get("xorout", 0))
    return fun(bytes(data[b] for b in table["bytes"]))


def frame_bytes(can_id, data):
    if len(data) > 8:
        return struct.pack("=IBB2x64s", can_id, len(data), 0x01, bytes(data).ljust(64, b"\0"))
    return struct.pack("=IB3x8s", can_id, len(data), bytes(data).ljust(8, b"\0"))


class Peer:
    """One raw CAN socket: sends protected frames, checks every frame the rig sends."""

    def __init__(self, iface, mapping):
        self.sock = socket.socket(socket.AF_CAN, socket.SOCK_RAW, socket.CAN_RAW)
        self.sock.setsockopt(socket.SOL_CAN_RAW, socket.CAN_RAW_FD_FRAMES, 1)
        self.sock.bind((iface,))
        self.sock.setblocking(False)
        self.tx = {m["message"]: m for m in mapping["tx"]}
        self.rx = {m["message"]: m for m in mapping["rx"]}
        self.checked = {name: 0 for name in BENCH_TX}
        self.bad = []
        self.last_counter = {}
        self.counter_gaps = 0
        self.sent = 0

    def send(self, can_id, data):
        for _ in range(500):  # ENOBUFS on a busy vcan queue: retry shortly
            try:
                self.sock.send(frame_bytes(can_id, data))
                self.sent += 1
                return
            except OSError:
                time.sleep(0.001)
        raise SystemExit("e2e_reference peer: send failed")

    def drain(self):
        while True:
            try:
                raw = self.sock.recv(CANFD_MTU)
            except BlockingIOError:
                return
            can_id, length = struct.unpack_from("=IB", raw)
            self.judge(can_id & 0x1FFFFFFF, bytearray(raw[8:8 + length]))

    def judge(self, can_id, data):
        for name, (tx_id, length) in BENCH_TX.items():
            if tx_id != can_id:
                continue
            m = self.tx[name]
            if "e2e" in m:
                ok, counter = check(e2e_config(m["e2e"], length), data)
                last = self.last_counter.get(name)
                modulus = counter_modulus(m["e2e"]["profile"])
                if last is not None and counter != (last + 1) % modulus:
                    self.counter_gaps += 1
                self.last_counter[name] = counter
            else:
                c = m["checksum"]
                at, size = c["position"], c["width"] // 8
                ok = int.from_bytes(data[at:at + size], "big") == generic_crc(c, data)
            self.checked[name] += 1
            if not ok:
                self.bad.append((name, data.hex()))

    def frame(self, name, raw_value, counter, wrong_id=False, bad_crc=False):
        can_id, length, (at, signed, _), _, _ = BENCH_RX[name]
        data = bytearray(length)
        data[at:at + 2] = raw_value.to_bytes(2, "little", signed=signed)
        m = self.rx[name]
        if "e2e" in m:
            cfg = e2e_config(m["e2e"], length)
            if wrong_id:
                if "data_id_list" in cfg:
                    cfg["data_id_list"] = [x ^ 0x01 for x in cfg["data_id_list"]]
                else:
                    cfg["data_id"] ^= 0x0101
            protect(cfg, data, counter)
        else:
            c = m["checksum"]
            value = generic_crc(c, data) ^ (1 if bad_crc else 0)
            data[c["position"]:c["position"] + c["width"] // 8] = value.to_bytes(
                c["width"] // 8, "big")
        return can_id, data


def random_raw(rng, name):
    signed = BENCH_RX[name][2][1]
    limit = {"ECU_P01": 9000, "ECU_P02": 1000, "ECU_P04": 25000, "ECU_P05": 25000,
             "ECU_Crc": 9000}[name]
    return rng.randrange(-limit if signed else 0, limit + 1)


def peer(argv):
    """Checks the rig's frames for 0.5 s; then per round sends one valid frame of each RX
    message (random value, counter + 1); then per E2E message a wrong Data ID, a repeated
    counter, a proper step, a skipped counter (step max_delta_counter + 1), three proper steps
    with the final value; for the generic CRC message one frame with a wrong CRC and three good
    ones. Expected at the rig: checksum_failures 5, counter_failures 8."""
    iface = argv[0]
    opts = dict(zip(argv[1::2], argv[2::2]))
    with open(opts["--mapping"], "rb") as f:
        mapping = tomllib.load(f)
    p = Peer(iface, mapping)
    wait_start(opts["--wait-start"])
    rng = random.Random(14)
    end = time.monotonic() + 0.5
    while time.monotonic() < end:
        p.drain()
        time.sleep(0.005)
    counters = {name: 0 for name in BENCH_RX}
    final = {}
    for _ in range(int(opts.get("--rounds", "30"))):
        for name in BENCH_RX:
            raw = random_raw(rng, name)
            counters[name] = (counters[name] + 1) % 65536
            p.send(*p.frame(name, raw, counters[name] % modulus_of(mapping, name)))
        p.drain()
        time.sleep(0.01)
    for name in BENCH_RX:
        raw = random_raw(rng, name)
        final[name] = raw
        m = p.rx[name]
        if "e2e" not in m:
            p.send(*p.frame(name, raw, 0, bad_crc=True))
            for _ in range(3):
                p.send(*p.frame(name, raw, 0))
            continue
        mod = modulus_of(mapping, name)
        c = counters[name] % mod
        step = m["e2e"].get("max_delta_counter", 1) + 1
        sequence = [(c + 1, True), (c, False), (c + 1, False), (c + 1 + step, False)]
        sequence += [(c + 2 + step + k, False) for k in range(3)]
        for value, wrong_id in sequence:
            p.send(*p.frame(name, raw, value % mod, wrong_id=wrong_id))
        p.drain()
        time.sleep(0.01)
    end = time.monotonic() + 0.3
    while time.monotonic() < end:
        p.drain()
        time.sleep(0.005)
    scale = {name: BENCH_RX[name][2][2] * BENCH_RX[name][4] for name in BENCH_RX}
    result = {"sent": p.sent, "checked": p.checked, "bad": p.bad, "counter_gaps": p.counter_gaps,
              "final": {BENCH_RX[n][3]: final[n] * scale[n] for n in final}}
    with open(opts["--out"], "w") as f:
        json.dump(result, f)


def modulus_of(mapping, name):
    m = {x["message"]: x for x in mapping["rx"]}[name]
    return counter_modulus(m["e2e"]["profile"]) if "e2e" in m else 1


def wait_start(events, timeout_s=30.0):
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        try:
            with open(events) as f:
                for line in f:
                    try:
                        if json.loads(line).get("event") == "start":
                            return
                    except json.JSONDecodeError:
                        pass
        except FileNotFoundError:
            pass
        time.sleep(0.01)
    raise SystemExit(f"e2e_reference peer: no start event in {events}")


if __name__ == "__main__":
    if sys.argv[1:2] == ["peer"]:
        peer(sys.argv[2:])
        sys.exit(0)
    if sys.argv[1:2] == ["vectors"]:
        vectors(int(sys.argv[2]), int(sys.argv[3]))
    elif sys.argv[1:2] == ["crc-vectors"]:
        crc_vectors(int(sys.argv[2]), int(sys.argv[3]))
    else:
        selftest()
