#!/usr/bin/python3
"""Checks the rig's restbus traffic of one DBC node, independently of the rig's code
(python3-canmatrix for the DBC, python3-crcmod for the CRC, the mapping read with tomllib).

The log has one line per frame the rig sent, `CYCLE ID#DATA` (hex), CYCLE being the loop cycle
that produced it (the vcan test writes it from the bridge's per-cycle send count and candump).
For every message of --node with a GenMsgCycleTime (canmatrix):

- it is sent in the cycles 0, P, 2P, ... with P = cycle time / --cycle-ms: consecutive sends
  exactly P cycles apart, ceil(--cycles / P) sends;
- each signal decodes (canmatrix) to its GenSigStartValue (canmatrix's physical initial value),
  or to the mapping's `set` value (a number; --value SIGNAL=X for one bound to a model signal);
- the alive counter of its [[restbus.message]] advances by 1 modulo its modulus;
- its checksum (crc8_sae_j1850 over crcmod, or xor) verifies over every other byte;
- its `e2e` protection is valid for tests/io/can/e2e_reference.py (the AUTOSAR profiles in
  Python, CRCs through crcmod) and its E2E counter advances by 1 modulo the profile's;

and a message without a cycle time is never sent. One JSON line per message; exit 1 on any
failure.

Usage: restbus_check.py --mapping ecu-mapping.toml --node GW --log sent.log --cycles 3000
                        [--cycle-ms 1] [--value GW_RefSpeed=12.5]
"""

import argparse
import json
import math
import pathlib
import sys
import tomllib

import canmatrix.formats
import crcmod

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))
import e2e_reference  # noqa: E402  (tests/io/can/e2e_reference.py)

# CRC-8 SAE J1850: poly 0x1D, init 0xFF, xorout 0xFF (crcmod's initCrc is init ^ xorout).
CRC8_SAE_J1850 = crcmod.mkCrcFun(0x11D, initCrc=0x00, rev=False, xorOut=0xFF)
assert CRC8_SAE_J1850(b"123456789") == 0x4B  # the published check value


def xor8(data):
    out = 0
    for byte in data:
        out ^= byte
    return out


def parse_log(path):
    frames = []
    for line in pathlib.Path(path).read_text().splitlines():
        cycle, _, frame = line.partition(" ")
        ident, _, payload = frame.partition("#")
        frames.append((int(cycle), int(ident, 16), bytes.fromhex(payload)))
    return frames


def signal_byte(frame, name):
    signal = frame.signal_by_name(name)
    return signal.start_bit // 8  # 8-bit Intel checksum signals: one byte


def e2e_bits(cfg):
    """The bits an E2E profile writes (Intel numbering), as e2e_reference lays them out."""
    p, o = cfg["profile"], cfg.get("offset", 0)
    if p == "P01":
        crc, cnt = cfg.get("crc_offset_bits", 0), cfg.get("counter_offset_bits", 8)
        bits = set(range(crc, crc + 8)) | set(range(cnt, cnt + 4))
        return bits | (set(range(12, 16)) if cfg.get("data_id_mode") == "NIBBLE" else set())
    if p == "P02":
        return set(range(0, 12))
    return set(range(o, o + (96 if p == "P04" else 24)))


def check_e2e(frame, sends, cfg, fails):
    modulus = e2e_reference.counter_modulus(cfg["profile"])
    for k, (_, data) in enumerate(sends):
        ok, counter = e2e_reference.check(dict(cfg, length=len(data)), bytearray(data))
        if not ok or counter != k % modulus:
            fails.append(f"{frame.name}: E2E {cfg['profile']} send {k}: valid {ok}, counter "
                         f"{counter}, expected {k % modulus}")
            return


def check_message(frame, sends, spec, args, fails):
    period = int(frame.effective_cycle_time) // args.cycle_ms
    cycles = [c for c, _ in sends]
    expected = math.ceil(args.cycles / period)
    if len(cycles) != expected:
        fails.append(f"{frame.name}: {len(cycles)} sends, expected {expected}")
    gaps = sorted({b - a for a, b in zip(cycles, cycles[1:])})
    if gaps and gaps != [period]:
        fails.append(f"{frame.name}: sends {gaps} cycles apart, expected {period}")
    if cycles and cycles[0] != 0:
        fails.append(f"{frame.name}: first send in cycle {cycles[0]}, expected 0")
    counter = spec.get("counter")
    checksum = spec.get("checksum")
    skip = {x["signal"] for x in (counter, checksum) if x}
    if "e2e" in spec:
        bits = e2e_bits(spec["e2e"])
        skip |= {sig.name for sig in frame.signals
                 if bits & set(range(sig.start_bit, sig.start_bit + sig.size))}
        check_e2e(frame, sends, spec["e2e"], fails)
    for k, (_, data) in enumerate(sends):
        decoded = frame.decode(data)
        for signal in frame.signals:
            if signal.name in skip:
                continue
            want = float(args.set.get(signal.name, signal.initial_value))
            got = float(decoded[signal.name].phys_value)
            if abs(got - want) > float(signal.factor) / 2:
                fails.append(f"{frame.name}.{signal.name} = {got} in send {k}, expected {want}")
                return
        if counter:
            got = int(decoded[counter["signal"]].raw_value)
            want = k % counter.get("modulus", 16)
            if got != want:
                fails.append(f"{frame.name}: counter {got} in send {k}, expected {want}")
                return
        if checksum:
            at = signal_byte(frame, checksum["signal"])
            covered = bytes(b for i, b in enumerate(data) if i != at)
            want = xor8(covered) if checksum.get("type") == "xor" else CRC8_SAE_J1850(covered)
            if data[at] != want:
                fails.append(f"{frame.name}: checksum {data[at]:#04x} in send {k}, "
                             f"expected {want:#04x}")
                return


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--mapping", required=True)
    ap.add_argument("--node", required=True)
    ap.add_argument("--log", required=True)
    ap.add_argument("--cycles", type=int, required=True)
    ap.add_argument("--cycle-ms", type=int, default=1)
    ap.add_argument("--value", action="append", default=[],
                    help="SIGNAL=X: the physical value of a signal `set` to a model signal")
    args = ap.parse_args()
    mapping_path = pathlib.Path(args.mapping)
    mapping = tomllib.loads(mapping_path.read_text())
    db = canmatrix.formats.loadp_flat(str(mapping_path.parent / mapping["dbc"]))
    restbus = next(r for r in mapping["restbus"] if r["node"] == args.node)
    args.set = {k: v for k, v in restbus.get("set", {}).items() if not isinstance(v, str)}
    for item in args.value:
        name, _, value = item.partition("=")
        args.set[name] = float(value)
    specs = {m["name"]: m for m in restbus.get("message", [])}
    frames = parse_log(args.log)
    fails = []
    for frame in db.frames:
        if args.node not in frame.transmitters:
            continue
        sends = [(c, d) for c, i, d in frames if i == frame.arbitration_id.id]
        if not frame.effective_cycle_time:
            if sends:
                fails.append(f"{frame.name}: no cycle time, yet sent {len(sends)} times")
            print(json.dumps({"message": frame.name, "cycle_ms": 0, "sends": len(sends)}))
            continue
        check_message(frame, sends, specs.get(frame.name, {}), args, fails)
        print(json.dumps({"message": frame.name, "cycle_ms": int(frame.effective_cycle_time),
                          "sends": len(sends),
                          "gaps_cycles": sorted({b[0] - a[0] for a, b in zip(sends, sends[1:])})}))
    for f in fails:
        print("FAIL: " + f, file=sys.stderr)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
