#!/usr/bin/python3
"""The ESC of the ESC bench case: ESC_WheelPressures (esc.dbc, id 0x250, 4 x 16 bit LE, 0.01 bar)
with FL RL at PRESSURE bar and FR RR at 0, every 10 ms, on a plain AF_CAN raw socket.

  esc_peer.py IFACE EVENTS.jsonl [--delay-s S] [--frames N] [--bar P] [--out peer.json]

Waits for the rig's "start" event, then S seconds (the sedan coasts), then sends N frames."""
import argparse
import json
import socket
import struct
import time

ESC_WHEEL_PRESSURES = 0x250


def wait_start(events, timeout_s=60.0):
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        try:
            with open(events) as f:
                if any('"start"' in line for line in f):
                    return
        except FileNotFoundError:
            pass
        time.sleep(0.01)
    raise SystemExit(f"esc_peer: no start event in {events}")


def frame(bar_fl, bar_fr, bar_rl, bar_rr):
    raws = [int(round(b / 0.01)) for b in (bar_fl, bar_fr, bar_rl, bar_rr)]
    return struct.pack("=IB3x8s", ESC_WHEEL_PRESSURES, 8, struct.pack("<4H", *raws))


def send(s, data):
    for _ in range(200):  # ENOBUFS on a busy vcan queue: retry shortly
        try:
            s.send(data)
            return
        except OSError:
            time.sleep(0.001)
    raise SystemExit("esc_peer: send failed")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("iface")
    p.add_argument("events")
    p.add_argument("--delay-s", type=float, default=0.5)
    p.add_argument("--frames", type=int, default=400)
    p.add_argument("--bar", type=float, default=30.0)
    p.add_argument("--out", default="peer.json")
    args = p.parse_args()
    s = socket.socket(socket.AF_CAN, socket.SOCK_RAW, socket.CAN_RAW)
    s.bind((args.iface,))
    wait_start(args.events)
    time.sleep(args.delay_s)
    data = frame(args.bar, 0.0, args.bar, 0.0)
    next_t = time.monotonic()
    for _ in range(args.frames):
        send(s, data)
        next_t += 0.010
        time.sleep(max(0.0, next_t - time.monotonic()))
    json.dump({"sent": args.frames, "bar": args.bar}, open(args.out, "w"))


if __name__ == "__main__":
    main()
