#!/usr/bin/python3
"""Records the rig's frames on IFACE (plain AF_CAN raw socket) to OUT (JSON lines: id, data hex)
until the rig's "stop" event is in EVENTS.jsonl (then 0.5 s to drain) or TIMEOUT_S.

  recorder.py IFACE EVENTS.jsonl OUT [--timeout-s S]"""
import argparse
import json
import socket
import struct
import time


def stopped(events):
    try:
        with open(events) as f:
            return any('"stop"' in line for line in f)
    except FileNotFoundError:
        return False


def main():
    p = argparse.ArgumentParser()
    p.add_argument("iface")
    p.add_argument("events")
    p.add_argument("out")
    p.add_argument("--timeout-s", type=float, default=240.0)
    args = p.parse_args()
    s = socket.socket(socket.AF_CAN, socket.SOCK_RAW, socket.CAN_RAW)
    s.bind((args.iface,))
    s.settimeout(0.1)
    open(args.out + ".ready", "w").close()
    deadline = time.monotonic() + args.timeout_s
    drain_until = None
    with open(args.out, "w") as out:
        while time.monotonic() < deadline:
            if drain_until is None and stopped(args.events):
                drain_until = time.monotonic() + 0.5
            if drain_until is not None and time.monotonic() > drain_until:
                break
            try:
                raw = s.recv(16)
            except socket.timeout:
                continue
            can_id, length, data = struct.unpack("=IB3x8s", raw)
            out.write(json.dumps({"id": can_id, "data": data[:length].hex()}) + "\n")


if __name__ == "__main__":
    main()
