#!/usr/bin/python3
"""The independent CAN peer of the robustness cases that need vcan (issue 13).

Plain AF_CAN raw sockets of the Python standard library (no rig code, no python-can: one fast
process in the slow VM). The EPS_Status frame of config/can/steering-bench.dbc is built by hand:
EPS_MotorTorque 0|16@1- (0.01 Nm), EPS_Counter 48|4, CRC-8 SAE J1850 of bytes 0..6 in byte 7.

  can_peer.py IFACE [--wait-start EVENTS.jsonl] [--torque NM] [--period-ms MS] STEP...

Waits for the rig's "start" event in EVENTS.jsonl, then runs the steps in order:
  classic:SPEC   EPS_Status classic frames, one per period, with the counter values of SPEC:
                 comma-separated values, "N*V" = V N times, "A+N" = N values counting up from A
                 (mod 16); e.g. classic:0+8,20*7 = a proper sequence 0..7, then frozen at 7
  fd:SPEC        the same as CAN FD frames (8 bytes)
  rtr:N          N remote (RTR) frames on the EPS_Status id
  error:CLASS[/CTRL]  one error frame: can_id CAN_ERR_FLAG | CLASS, data[1] = CTRL (hex)
  sleep:S        wait S seconds
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


def wait_start(events, timeout_s=20.0):
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
    raise SystemExit(f"can_peer: no start event in {events}")


def run_step(step, args, sockets):
    kind, _, arg = step.partition(":")
    period_s = args.period_ms / 1000.0
    if kind in ("classic", "fd"):
        s = sockets[kind == "fd"]
        make = fd_frame if kind == "fd" else classic
        for counter in parse_counters(arg):
            send(s, make(EPS_STATUS, eps_status(args.torque, counter)))
            time.sleep(period_s)
    elif kind == "rtr":
        for _ in range(int(arg)):
            frame = bytearray(classic(EPS_STATUS | CAN_RTR_FLAG, b""))
            frame[4] = 8  # a remote request asks for 8 bytes
            send(sockets[False], bytes(frame))
            time.sleep(period_s)
    elif kind == "error":
        error_class, _, controller = arg.partition("/")
        data = bytearray(8)
        data[1] = int(controller or "0", 16)
        send(sockets[False], classic(CAN_ERR_FLAG | int(error_class, 16), bytes(data)))
    elif kind == "sleep":
        time.sleep(float(arg))
    else:
        raise SystemExit(f"can_peer: unknown step {step!r}")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("iface")
    p.add_argument("steps", nargs="+")
    p.add_argument("--wait-start")
    p.add_argument("--torque", type=float, default=1.0)
    p.add_argument("--period-ms", type=float, default=10.0)
    args = p.parse_args()
    sockets = {False: open_socket(args.iface), True: open_socket(args.iface, fd=True)}
    if args.wait_start:
        wait_start(args.wait_start)
    for step in args.steps:
        run_step(step, args, sockets)
    return 0


if __name__ == "__main__":
    sys.exit(main())
