#!/usr/bin/python3
"""`rig signals CONFIG --json` is strict JSON: an array of objects with exactly the keys name,
unit, direction, min, max, aliases; inputs have finite ranges, outputs null ones; names and
aliases are unique; the enum's 31 names are aliases; a bad configuration exits 2 with file:line.

usage: signals_json_test.py RIG SOURCE_DIR
"""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

RIG, SRC = sys.argv[1], Path(sys.argv[2])
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def catalogue(config):
    out = subprocess.run([RIG, "signals", str(config), "--json"], capture_output=True, text=True)
    check(out.returncode == 0, f"{config}: exit {out.returncode}: {out.stderr}")
    return json.loads(out.stdout, parse_constant=lambda c: failures.append(f"constant {c}"))


LEGACY = ["steering_wheel_angle_cmd_rad", "steering_wheel_torque_cmd_nm", "assist_torque_nm",
          "throttle_pedal", "brake_pressure_front_pa", "brake_pressure_rear_pa", "gear_request",
          "steering_overlay_angle_cmd_rad", "ignition_state", "vehicle_speed_mps",
          "wheel_speed_fl_radps", "wheel_speed_fr_radps", "wheel_speed_rl_radps",
          "wheel_speed_rr_radps", "longitudinal_accel_mps2", "lateral_accel_mps2",
          "yaw_rate_radps", "steering_wheel_angle_rad", "steering_wheel_speed_radps",
          "torsion_bar_torque_nm", "rack_position_m", "rack_force_n", "engine_speed_radps", "gear",
          "brake_pressure_fl_pa", "brake_pressure_fr_pa", "brake_pressure_rl_pa",
          "brake_pressure_rr_pa", "position_x_m", "position_y_m", "heading_rad"]

for config, count in [(SRC / "config/rig.toml", 178),
                      (SRC / "tests/io/signals/configs/truck.toml", 244),
                      (SRC / "tests/io/signals/configs/three-units.toml", 492),
                      (SRC / "config/maneuvers/mu-split-acceleration-4x4.toml", 190)]:
    entries = catalogue(config)
    check(len(entries) == count, f"{config}: {len(entries)} entries, expected {count}")
    seen = set()
    for e in entries:
        check(set(e) == {"name", "unit", "direction", "min", "max", "aliases"}, f"keys {set(e)}")
        check(e["direction"] in ("in", "out"), f"{e['name']}: direction {e['direction']}")
        if e["direction"] == "in":
            check(isinstance(e["min"], (int, float)) and e["min"] <= e["max"], f"{e['name']} range")
        else:
            check(e["min"] is None and e["max"] is None, f"{e['name']}: output with a range")
        for n in [e["name"]] + e["aliases"]:
            check(n not in seen, f"{config}: {n} twice")
            seen.add(n)
    for n in LEGACY:
        check(n in seen, f"{config}: {n} missing")
    by_name = {e["name"]: e for e in entries}
    check("unit1.speed_x_mps" in by_name and "vehicle_speed_mps" in by_name["unit1.speed_x_mps"]["aliases"],
          "vehicle_speed_mps is unit1.speed_x_mps")

with tempfile.TemporaryDirectory() as d:
    bad = Path(d) / "bad.toml"
    bad.write_text("[model]\nkind = \"vehicle\"\nvehicle = \"none.toml\"\n")
    out = subprocess.run([RIG, "signals", str(bad)], capture_output=True, text=True)
    check(out.returncode == 2 and "bad.toml:3" in out.stderr, f"bad config: {out.returncode} {out.stderr}")

print("FAILED" if failures else "OK", len(failures))
sys.exit(1 if failures else 0)
