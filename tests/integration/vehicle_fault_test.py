#!/usr/bin/python3
"""Vehicle faults end to end (issue 12.5): `rig run` offline on configurations written here.

usage: vehicle_fault_test.py RIG RIG_LOG2CSV SOURCE_DIR CASE

stop       the sedan at 30 m/s braking with 300 bar: exit 1, the message names the fault, time,
           unit and file, the event log has "vehicle_fault", the summary its vehicle_fault object
           (kind pitch or body_ground), the last logged state within the limits. On this
           main the sedan no longer flips (it dives to 0.055 rad and stops, wheels locked), so
           the pitch limit is 0.045 rad here: the dive is the fault.
truck      the 3-axle truck at a period of 1 s: a fault, and no logged value beyond a limit.
hold       the same braking with on_vehicle_fault = "hold": the run completes its duration
           (every cycle counted and logged), model_valid 0 from the fault on, the state frozen,
           the summary's outputs empty (all invalid), exit 1 at the end.
combination  the car and trailer with a roll limit of 0.01 rad: the fault names its unit (from 0)
           and that unit's vehicle file.
badconfig  bad values of the new keys are `file:line:` errors of `rig run` and `rig check`.
"""
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rig_checks import check, fail  # noqa: E402

RIG, LOG2CSV, SRC, CASE = sys.argv[1:5]
SRC = os.path.abspath(SRC)
VEHICLES = os.path.join(SRC, "config", "vehicles")
TMP = tempfile.mkdtemp(prefix="rig_fault_")
LIMITS = {"roll": 1.0, "pitch": 0.6, "speed": 100.0, "rate": 10.0}
DIVE_PITCH_LIMIT = 0.045  # [rad] below the sedan's dive at 300 bar (0.055 rad)



def config(name, rig_keys, vehicle="sedan.toml", speed=30.0, brake_bar=300.0):
    path = os.path.join(TMP, name)
    with open(path, "w") as f:
        f.write(f"[rig]\n{rig_keys}\n[model]\nkind = \"vehicle\"\n"
                f"vehicle = \"{os.path.join(VEHICLES, vehicle)}\"\ninitial_speed_mps = {speed}\n"
                "[routing]\nbrake_pressure_front_pa = \"driver\"\nbrake_pressure_rear_pa = \"driver\"\n"
                "[driver]\nkind = \"table\"\n"
                "columns = [\"time_s\", \"brake_pressure_front_pa\", \"brake_pressure_rear_pa\"]\n"
                f"rows = [[0.0, 0.0, 0.0], [0.2, {brake_bar * 1e5}, {brake_bar * 1e5}], "
                f"[100.0, {brake_bar * 1e5}, {brake_bar * 1e5}]]\n")
    return path


def run(cfg, duration, tag):
    sj, log, lcm = (os.path.join(TMP, f"{tag}.{ext}") for ext in ("json", "jsonl", "lcm"))
    r = subprocess.run([RIG, "run", "--config", cfg, "--offline", "--duration", str(duration),
                        "--summary-json", sj, "--overrun-log", log, "--lcm-url", "none",
                        "--lcm-log", lcm], capture_output=True, text=True, timeout=120)
    out = os.path.join(TMP, tag)
    c = subprocess.run([LOG2CSV, lcm, out], capture_output=True, text=True)
    check(c.returncode == 0, f"rig-log2csv: {c.stderr}")
    rows = list(csv.DictReader(open(os.path.join(out, "RIG_STATE.csv"))))
    events = [json.loads(line) for line in open(log).read().splitlines()]
    return r, json.load(open(sj)), events, rows


def check_rows_within_limits(rows, pitch_limit=LIMITS["pitch"]):
    for row in rows:
        for col, value in row.items():
            v = float(value)
            check(math.isfinite(v), f"{col} = {value} at t = {row['sim_time_s']}")
        check(abs(float(row["unit0_roll_rad"])) <= LIMITS["roll"], f"roll {row['unit0_roll_rad']}")
        check(abs(float(row["unit0_pitch_rad"])) <= pitch_limit, f"pitch {row['unit0_pitch_rad']}")
        v = math.sqrt(sum(float(row[f"unit0_v{a}_mps"]) ** 2 for a in "xyz"))
        check(v <= LIMITS["speed"], f"speed {v} at t = {row['sim_time_s']}")
        w = math.sqrt(sum(float(row[f"unit0_w{a}_radps"]) ** 2 for a in "xyz"))
        check(w <= LIMITS["rate"], f"rate {w} at t = {row['sim_time_s']}")


def check_fault(r, s, events, kinds, sedan_file):
    check(r.returncode == 1, f"exit {r.returncode}: {r.stderr}")
    f = s.get("vehicle_fault")
    check(f is not None, f"no vehicle_fault in the summary: {s}")
    check(f["kind"] in kinds, f"fault kind {f['kind']}")
    check(f["unit"] == 0 and f["file"] == sedan_file, f"fault unit {f['unit']} file {f['file']}")
    check(f["time_s"] > 0.2, f"fault time {f['time_s']}")
    msg = re.search(r"rig: error: vehicle fault (\w+): .* at t = ([0-9.]+) s, unit 0 \((.*?)\)",
                    r.stderr)
    check(msg and msg.group(1) == f["kind"] and msg.group(3) == sedan_file,
          f"message: {r.stderr!r}")
    check(abs(float(msg.group(2)) - f["time_s"]) < 1e-6, f"message time {msg.group(2)}")
    fault_events = [e for e in events if e.get("event") == "vehicle_fault"]
    check(len(fault_events) == 1, f"vehicle_fault events: {fault_events}")
    print("fault:", json.dumps(f), "|", fault_events[0].get("detail"))
    return f


def case_stop():
    sedan = os.path.join(VEHICLES, "sedan.toml")
    r, s, events, rows = run(config("stop.toml", f"fault_pitch_limit_rad = {DIVE_PITCH_LIMIT}"),
                             5.0, "stop")
    f = check_fault(r, s, events, ("pitch", "body_ground"), sedan)
    check(s["stop_reason"] == "vehicle-fault", f"stop_reason {s['stop_reason']}")
    check(s["cycles"] < 5000, f"cycles {s['cycles']}: did not stop")
    check_rows_within_limits(rows, DIVE_PITCH_LIMIT)
    check(rows[-1]["model_valid"] == "0" and rows[0]["model_valid"] == "1", "model_valid")
    check(float(rows[-1]["unit0_z_m"]) > 0, f"CG below the road: {rows[-1]['unit0_z_m']}")


def case_truck():
    cfg = os.path.join(TMP, "truck.toml")
    with open(cfg, "w") as out:
        out.write(f"[rig]\nperiod_s = 1.0\n[model]\nkind = \"vehicle\"\n"
                  f"vehicle = \"{os.path.join(VEHICLES, 'truck-3axle.toml')}\"\n")
    r, s, events, rows = run(cfg, 200.0, "truck")
    check(r.returncode == 1, f"exit {r.returncode}: {r.stderr}")
    f = s.get("vehicle_fault")
    check(f is not None and f["kind"] != "none", f"no vehicle_fault: {s}")
    print("fault:", json.dumps(f))
    check_rows_within_limits(rows)
    for key, value in s["outputs"].items():
        check(abs(value) < 1e6, f"summary output {key} = {value}")


def case_hold():
    sedan = os.path.join(VEHICLES, "sedan.toml")
    keys = f'on_vehicle_fault = "hold"\nfault_pitch_limit_rad = {DIVE_PITCH_LIMIT}'
    r, s, events, rows = run(config("hold.toml", keys), 5.0, "hold")
    f = check_fault(r, s, events, ("pitch", "body_ground"), sedan)
    check(s["stop_reason"] == "duration", f"stop_reason {s['stop_reason']}")
    check(s["cycles"] == 5000 and len(rows) == 5000, f"cycles {s['cycles']}, rows {len(rows)}")
    check(s["outputs"] == {}, f"valid outputs after the fault: {s['outputs']}")
    check("held until the end" in r.stderr, f"stderr {r.stderr!r}")
    check_rows_within_limits(rows, DIVE_PITCH_LIMIT)
    held = [row for row in rows if row["model_valid"] == "0"]
    check(held and len(held) == 5000 - round(f["time_s"] * 1000) + 1, f"{len(held)} invalid rows")
    frozen = {row["unit0_x_m"] + row["unit0_pitch_rad"] + row["sim_time_s"] for row in held}
    check(len(frozen) == 1, f"state not frozen: {len(frozen)} distinct")
    check(all(row["model_fault_kind"] != "0" for row in held), "model_fault_kind")


def case_combination():
    text = open(os.path.join(SRC, "config", "combinations", "car-trailer.toml")).read()
    text = text.replace('vehicle = "../vehicles/', f'vehicle = "{VEHICLES}/')
    text = text.replace("[rig]\n", "[rig]\nfault_roll_limit_rad = 0.01\n", 1)
    cfg = os.path.join(TMP, "combination.toml")
    open(cfg, "w").write(text)
    r, s, events, rows = run(cfg, 20.0, "combination")
    check(r.returncode == 1, f"exit {r.returncode}: {r.stderr}")
    f = s.get("vehicle_fault")
    check(f is not None and f["kind"] == "roll", f"vehicle_fault: {f}")
    files = {0: os.path.join(VEHICLES, "sedan.toml"), 1: os.path.join(VEHICLES, "trailer-1axle.toml")}
    check(f["unit"] in files and f["file"] == files[f["unit"]], f"unit {f['unit']} file {f['file']}")
    check(f"unit {f['unit']} ({f['file']})" in r.stderr, f"message: {r.stderr!r}")
    check(abs(f["value"]) > 0.01 and f["limit"] == 0.01, f"value {f['value']}")
    u = f"unit{f['unit']}_roll_rad"
    check(all(abs(float(row[u])) <= 0.01 for row in rows), f"{u} beyond the limit in the log")
    print("fault:", json.dumps(f))


def case_badconfig():
    cases = {
        "roll.toml": ("fault_roll_limit_rad = -1.0", r":2: \[rig\] fault_roll_limit_rad: must be"),
        "pitch.toml": ("fault_pitch_limit_rad = 0", r":2: \[rig\] fault_pitch_limit_rad: must be"),
        "speed.toml": ("fault_speed_limit_mps = -5", r":2: \[rig\] fault_speed_limit_mps: must be"),
        "rate.toml": ("fault_rate_limit_radps = \"x\"", r":2: \[rig\] fault_rate_limit_radps"),
        "action.toml": ('on_vehicle_fault = "ignore"', r":2: \[rig\] on_vehicle_fault: .*'ignore'"),
    }
    for name, (line, pattern) in cases.items():
        path = config(name, line)
        for args in (["run", "--config", path, "--offline", "--duration", "1"], ["check", path]):
            r = subprocess.run([RIG] + args, capture_output=True, text=True, timeout=60)
            check(r.returncode == 2, f"{name} {args[0]}: exit {r.returncode}: {r.stderr}")
            check(re.search(re.escape(path) + pattern, r.stderr), f"{name}: stderr {r.stderr!r}")
    body = os.path.join(TMP, "body.toml")
    text = open(os.path.join(VEHICLES, "sedan.toml")).read()
    open(body, "w").write(text.replace("[chassis]\n", "[chassis]\nbody_points_m = [[1, 2]]\n", 1))
    r = subprocess.run([RIG, "check", body], capture_output=True, text=True, timeout=60)
    check(r.returncode == 2 and re.search(re.escape(body) + r":\d+: .*body_points_m", r.stderr),
          f"body points: {r.returncode} {r.stderr!r}")


{"stop": case_stop, "truck": case_truck, "hold": case_hold, "combination": case_combination,
 "badconfig": case_badconfig}[CASE]()
print("PASS", CASE)
