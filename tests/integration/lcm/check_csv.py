#!/usr/bin/python3
"""Checks the CSVs of rig-log2csv against the synthetic snapshots of rig-lcm-feed.

The formulas mirror tests/io/lcm/synthetic_snapshot.h (keep them in step). Exits 1 with a reason
on the first mismatch.
"""
import argparse
import csv
import math
import pathlib
import sys

PERIOD_S = 0.001
WHEEL_IDS = [0, 1, 2, 3, 10, 11]  # 10 * unit + wheel index, units of 4 and 2 wheels


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def close(a, b):
    return math.isclose(float(a), b, rel_tol=1e-12, abs_tol=1e-12)


def expect(row, column, value, what):
    if not close(row[column], value):
        fail(f"{what}: {column} = {row[column]}, published {value!r}")


def check_count(name, rows, expected, tolerance):
    n = len(rows)
    if abs(n - expected) > tolerance * expected:
        fail(f"{name}: {n} messages, expected {expected} within {tolerance:.0%}")
    print(f"{name}: {n} messages (expected {expected}, tolerance {tolerance:.0%})")


def check_state(rows):
    seen = set()
    for row in rows:
        c = int(row["cycle"])
        if c in seen:
            fail(f"RIG_STATE: cycle {c} twice")
        seen.add(c)
        t = c * PERIOD_S
        what = f"RIG_STATE cycle {c}"
        expect(row, "sim_time_s", t, what)
        expect(row, "lateness_ns", (c % 97) * 1000, what)
        expect(row, "deadline_miss", 1 if c % 500 == 499 else 0, what)
        expect(row, "num_units", 2, what)
        expect(row, "num_wheels", 6, what)
        for u in range(2):
            expect(row, f"unit{u}_x_m", 20.0 * t - 6.0 * u, what)
            expect(row, f"unit{u}_y_m", 0.001 * c + u, what)
            expect(row, f"unit{u}_yaw_rad", 0.0005 * c, what)
            expect(row, f"unit{u}_ax_mps2", 0.001 * c, what)
        for w, k in enumerate(WHEEL_IDS):
            expect(row, f"wheel{w}_unit", k // 10, what)
            expect(row, f"wheel{w}_spin_radps", 30.0 + 0.01 * c + k, what)
            expect(row, f"wheel{w}_slip_x", 0.001 * k, what)
            expect(row, f"wheel{w}_slip_y", -0.002 * k + 1e-6 * c, what)
            expect(row, f"wheel{w}_load_n", 4000.0 + k, what)
            expect(row, f"wheel{w}_x_e_m", 1e-4 * k, what)
        expect(row, "steering_wheel_angle_rad", 0.0001 * c, what)
        expect(row, "torsion_bar_torque_nm", 3.0, what)
        expect(row, "rack_travel_m", 1e-6 * c, what)
        expect(row, "engine_speed_radps", 200.0 + 0.1 * c, what)
        expect(row, "gear", 1 + c // 1000, what)
        expect(row, "brake_pressure_fr_pa", 1.1e5, what)
        expect(row, "joint0_force_x_n", 1000.0 + c, what)


def check_signals(rows):
    for row in rows:
        c = int(row["cycle"])
        what = f"RIG_SIGNALS cycle {c}"
        if c % 10 != 0:
            fail(f"{what}: not a multiple of 10 at 100 Hz")
        expect(row, "vehicle_speed_mps", 7 + 0.001 * c, what)
        expect(row, "vehicle_speed_mps_valid", 1, what)
        expect(row, "steering_wheel_angle_cmd_rad_valid", 0, what)
        if row["steering_wheel_torque_cmd_nm_source"] != "can":
            fail(f"{what}: source of steering_wheel_torque_cmd_nm")


def check_status(rows):
    for row in rows:
        c = round(float(row["sim_time_s"]) / PERIOD_S)
        what = f"RIG_STATUS cycle {c}"
        expect(row, "cycles", c + 1, what)
        expect(row, "can_frames_received", 3 * c, what)
        expect(row, "deadline_misses", (c + 1) // 500, what)
        if row["bus_state"] != "up":
            fail(f"{what}: bus_state {row['bus_state']}")


def without_timestamps(path):
    with open(path, newline="") as f:
        return sorted(tuple(r[1:]) for r in csv.reader(f))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("csvdir", type=pathlib.Path)
    p.add_argument("--state", type=int, required=True)
    p.add_argument("--signals", type=int, required=True)
    p.add_argument("--status", type=int, required=True)
    p.add_argument("--tolerance", type=float, default=0.0)
    p.add_argument("--same-as", type=pathlib.Path)
    a = p.parse_args()
    tables = {}
    for channel, expected, check in (("RIG_STATE", a.state, check_state),
                                     ("RIG_SIGNALS", a.signals, check_signals),
                                     ("RIG_STATUS", a.status, check_status)):
        path = a.csvdir / f"{channel}.csv"
        if not path.exists():
            fail(f"no {path}")
        rows = read(path)
        check_count(channel, rows, expected, a.tolerance)
        check(rows)
        tables[channel] = path
    if a.same_as:
        for channel, path in tables.items():
            if without_timestamps(path) != without_timestamps(a.same_as / f"{channel}.csv"):
                fail(f"{channel}: replayed messages differ from the original log")
        print("replayed messages equal the original log")
    print("PASS")


if __name__ == "__main__":
    main()
