#!/usr/bin/python3
"""Checks a `candump -L` recording of the rig's CAN traffic, independently of the rig's code
(python3-canmatrix for the DBC, its own CRC-8 SAE J1850 and XOR):

- each rig (TX) message of the mapping appears duration/period times, within --tolerance;
- its alive counter increments by 1 modulo its modulus from frame to frame;
- its checksum verifies (over every byte except the checksum byte);
- optional --expect SIGNAL=VALUE: every frame carrying SIGNAL decodes to VALUE (+- 1 raw step).

Usage: can_traffic_check.py --mapping config/can/steering-bench.toml --log rec.log
                            --duration-ms 3000 [--tolerance 0.02] [--expect VehicleSpeed=36]
Prints one JSON line per message; exit status 1 on any failure.
"""

import argparse
import json
import pathlib
import sys
import tomllib

import canmatrix.formats


def crc8_sae_j1850(data):
    crc = 0xFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1D) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
    return crc ^ 0xFF


def xor8(data):
    out = 0
    for byte in data:
        out ^= byte
    return out


def parse_log(path):
    """(timestamp, id, data) per frame of a candump -L log."""
    frames = []
    for line in pathlib.Path(path).read_text().splitlines():
        parts = line.split()
        if len(parts) != 3 or "#" not in parts[2]:
            continue
        ident, _, payload = parts[2].partition("#")
        if payload.startswith("#"):  # CAN FD: "##<flags><data>"
            payload = payload[2:]
        frames.append((float(parts[0].strip("()")), int(ident, 16), bytes.fromhex(payload)))
    return frames


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mapping", required=True)
    ap.add_argument("--log", required=True)
    ap.add_argument("--duration-ms", type=float, required=True)
    ap.add_argument("--tolerance", type=float, default=0.02)
    ap.add_argument("--expect", action="append", default=[])
    args = ap.parse_args()

    mapping_path = pathlib.Path(args.mapping)
    mapping = tomllib.loads(mapping_path.read_text())
    db = canmatrix.formats.loadp_flat(str(mapping_path.parent / mapping["dbc"]))
    frames = parse_log(args.log)
    expect = {k: float(v) for k, v in (e.split("=", 1) for e in args.expect)}
    ok = True
    for tx in mapping.get("tx", []):
        msg = db.frame_by_name(tx["message"])
        period_ms = float(msg.attributes["GenMsgCycleTime"])
        mine = [f for f in frames if f[1] == msg.arbitration_id.id]
        expected = args.duration_ms / period_ms
        rate_ok = abs(len(mine) - expected) <= args.tolerance * expected
        report = {"message": msg.name, "count": len(mine), "expected": expected, "rate_ok": rate_ok}
        if "counter" in tx:
            sig = msg.signal_by_name(tx["counter"]["signal"])
            modulus = int(tx["counter"].get("modulus", 16))
            values = [int(msg.decode(f[2])[sig.name].raw_value) for f in mine]
            bad = sum(1 for a, b in zip(values, values[1:]) if b != (a + 1) % modulus)
            report["counter_errors"] = bad
            ok &= bad == 0
        if "checksum" in tx:
            sig = msg.signal_by_name(tx["checksum"]["signal"])
            idx = sig.get_startbit(bit_numbering=1, start_little=True) // 8
            algo = crc8_sae_j1850 if tx["checksum"]["type"] == "crc8_sae_j1850" else xor8
            default_bytes = [i for i in range(len(mine[0][2]) if mine else 0) if i != idx]
            covered = tx["checksum"].get("bytes", default_bytes)
            bad = sum(1 for f in mine if algo(bytes(f[2][i] for i in covered)) != f[2][idx])
            report["checksum_errors"] = bad
            ok &= bad == 0
        for name, value in expect.items():
            sig = next((s for s in msg.signals if s.name == name), None)
            if sig is None:
                continue
            step = float(sig.factor)
            wrong = sum(1 for f in mine
                        if abs(float(msg.decode(f[2])[name].phys_value) - value) > step * 1.01)
            report[f"{name}_wrong"] = wrong
            ok &= wrong == 0
        ok &= rate_ok
        print(json.dumps(report))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
