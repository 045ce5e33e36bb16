#!/usr/bin/python3
"""The independent CAN peer of the robustness cases that need vcan (issue 13).

Plain AF_CAN raw sockets of the Python standard library (no rig code, no python-can: it starts
fast in the VM). The EPS_Status frame of config/can/steering-bench.dbc is built by hand here:
EPS_MotorTorque 0|16@1- (0.01 Nm), EPS_Counter 48|4, CRC-8 SAE J1850 of bytes 0..6 in byte 7.

  can_peer.py wait-start EVENTS.jsonl [TIMEOUT_S]    # until the rig's "start" event
  can_peer.py eps IFACE --counters SPEC [--torque NM] [--period-ms MS] [--fd] [--rtr]
      SPEC: comma-separated counter values, "N*V" repeats V N times, "A+N" counts N values up
      from A (mod 16), e.g. "0+8,20*7" = a proper sequence 0..7, then 20 frames frozen at 7.
  can_peer.py error IFACE CLASS [CONTROLLER]         # one error frame: can_id CAN_ERR_FLAG|CLASS
                                                     # (hex), data[1] = CONTROLLER (hex)
"""
import argparse
import json
import socket
import struct
import sys
import time

CAN_ERR_FLAG = 0x20000000
CAN_RTR_FLAG = 0x40000000
CANFD_BRS = 0x01
EPS_STATUS = 0x200


def crc8_sae_j1850(data):
    crc = 0xFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1D) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
    return crc ^ 0xFF


def eps_status(torque_nm, counter):
    raw = int(round(torque_nm / 0.01)) & 0xFFFF
    data = bytearray(8)
    data[0:2] = raw.to_bytes(2, "little")
    data[6] = counter & 0x0F
    data[7] = crc8_sae_j1850(data[:7])
    return bytes(data)


def open_socket(iface, fd=False):
    s = socket.socket(socket.AF_CAN, socket.SOCK_RAW, socket.CAN_RAW)
    if fd:
        s.setsockopt(socket.SOL_CAN_RAW, socket.CAN_RAW_FD_FRAMES, 1)
    s.bind((iface,))
    return s


def classic(can_id, data):
    return struct.pack("=IB3x8s", can_id, len(data), data.ljust(8, b"\0"))


def fd_frame(can_id, data):
    return struct.pack("=IBB2x64s", can_id, len(data), CANFD_BRS, data.ljust(64, b"\0"))


def parse_counters(spec):
    values = []
    for part in spec.split(","):
        if "*" in part:
            n, v = part.split("*")
            values += [int(v)] * int(n)
        elif "+" in part:
            a, n = (int(x) for x in part.split("+"))
            values += [(a + k) % 16 for k in range(n)]
        else:
            values.append(int(part))
    return values


def send(s, frame):
    for _ in range(200):  # ENOBUFS on a busy vcan queue: retry shortly
        try:
            s.send(frame)
            return
        except OSError:
            time.sleep(0.001)
    raise SystemExit("can_peer: send failed")


def cmd_wait_start(args):
    deadline = time.monotonic() + args.timeout_s
    while time.monotonic() < deadline:
        try:
            with open(args.events) as f:
                for line in f:
                    try:
                        if json.loads(line).get("event") == "start":
                            return 0
                    except json.JSONDecodeError:
                        pass
        except FileNotFoundError:
            pass
        time.sleep(0.01)
    print(f"can_peer: no start event in {args.events}", file=sys.stderr)
    return 1


def cmd_eps(args):
    s = open_socket(args.iface, fd=args.fd)
    for counter in parse_counters(args.counters):
        if args.rtr:
            frame = classic(EPS_STATUS | CAN_RTR_FLAG, b"")
            frame = frame[:4] + bytes([8]) + frame[5:]  # an RTR asks for 8 bytes
        elif args.fd:
            frame = fd_frame(EPS_STATUS, eps_status(args.torque, counter))
        else:
            frame = classic(EPS_STATUS, eps_status(args.torque, counter))
        send(s, frame)
        time.sleep(args.period_ms / 1000.0)
    return 0


def cmd_error(args):
    s = open_socket(args.iface)
    data = bytearray(8)
    data[1] = int(args.controller, 16)
    send(s, classic(CAN_ERR_FLAG | int(args.error_class, 16), bytes(data)))
    return 0


def main():
    p = argparse.ArgumentParser()
    sub = p.add_subparsers(dest="cmd", required=True)
    w = sub.add_parser("wait-start")
    w.add_argument("events")
    w.add_argument("timeout_s", nargs="?", type=float, default=20.0)
    e = sub.add_parser("eps")
    e.add_argument("iface")
    e.add_argument("--counters", required=True)
    e.add_argument("--torque", type=float, default=1.0)
    e.add_argument("--period-ms", type=float, default=10.0)
    e.add_argument("--fd", action="store_true")
    e.add_argument("--rtr", action="store_true")
    r = sub.add_parser("error")
    r.add_argument("iface")
    r.add_argument("error_class")
    r.add_argument("controller", nargs="?", default="0")
    args = p.parse_args()
    return {"wait-start": cmd_wait_start, "eps": cmd_eps, "error": cmd_error}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
