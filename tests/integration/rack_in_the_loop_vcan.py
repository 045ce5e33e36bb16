#!/usr/bin/python3
"""Rack-in-the-loop closed on vcan (issue 15): `rig run --lockstep` with the sedan's
rack_in_the_loop variant against `scripts/virtual-ecu --mode rack --lockstep` (the rig's column
model as the bench's rack, its robot stepping the wheel 0.5 rad at 0.5 s in 0.1 s), 3 s at
80 km/h. Its yaw rate and rack travel at the end within 5 % of the built-in model's step steer
(an offline run of the same sedan with system = "column", the same step from the driver).

    rack_in_the_loop_vcan.py BIN_DIR SOURCE_DIR     (needs vcan0: run inside scripts/with-vcan)
"""
import json
import os
import pathlib
import signal
import subprocess
import sys
import tempfile
import time

DURATION_S = 3.0


def reference_config(src, out):
    """The built-in step steer: config/rack-in-the-loop.toml's vehicle and speed, the column
    steering, the robot's step from the driver's table."""
    out.write_text(f'''[rig]
period_s = 0.001
duration_s = {DURATION_S}

[model]
kind = "vehicle"
vehicle = "{src}/config/vehicles/sedan.toml"
road_friction = 1.0
initial_speed_mps = 22.222222

[routing]
steering_wheel_angle_cmd_rad = "driver"
throttle_pedal = "driver"
brake_pressure_front_pa = "driver"
brake_pressure_rear_pa = "driver"
gear_request = "driver"

[driver]
kind = "table"
columns = ["time_s", "steering_wheel_angle_cmd_rad", "throttle_pedal", "gear_request"]
rows = [[0.0, 0.0, 0.2, 4], [0.5, 0.0, 0.2, 4], [0.6, 0.5, 0.2, 4], [3600.0, 0.5, 0.2, 4]]
''')


def outputs(summary):
    return json.loads(pathlib.Path(summary).read_text())


def main(argv):
    bin_dir, src = pathlib.Path(argv[1]), pathlib.Path(argv[2])
    if not pathlib.Path("/sys/class/net/vcan0").exists():
        print("rack_in_the_loop_vcan: no vcan0 (run inside scripts/with-vcan)")
        return 1
    rig = str(bin_dir / "rig")
    with tempfile.TemporaryDirectory(prefix="rig_ritl_") as tmp:
        tmp = pathlib.Path(tmp)
        ref_cfg = tmp / "reference.toml"
        reference_config(src, ref_cfg)
        subprocess.run([rig, "run", "--config", str(ref_cfg), "--offline", "--can", "none",
                        "--lcm-url", "none", "--summary-json", str(tmp / "ref.json")],
                       check=True, stdout=subprocess.DEVNULL)
        ref = outputs(tmp / "ref.json")

        ecu = subprocess.Popen(
            ["/usr/bin/python3", str(src / "scripts" / "virtual-ecu"), "--mode", "rack",
             "--lockstep", "--dbc", str(src / "config" / "can" / "rack-bench.dbc"),
             "--vehicle", str(src / "config" / "vehicles" / "sedan.toml"),
             "--interface", "vcan0", "--robot-angle-rad", "0.5", "--step-time-s", "0.5",
             "--ramp-s", "0.1"], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        line = ecu.stdout.readline()  # {"ready": true, ...}: python starts slowly in the VM
        if '"ready": true' not in line:
            print("virtual-ecu did not start:", line)
            ecu.kill()
            return 1
        t0 = time.monotonic()
        run = subprocess.run([rig, "run", "--config", str(src / "config" / "rack-in-the-loop.toml"),
                              "--lockstep", "--duration", str(DURATION_S), "--can", "vcan0",
                              "--lcm-url", "none", "--summary-json", str(tmp / "ritl.json")],
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                             timeout=600)
        wall = time.monotonic() - t0
        ecu.send_signal(signal.SIGTERM)
        ecu_out = ecu.communicate(timeout=60)[0].strip().splitlines()
        if run.returncode != 0:
            print("rig failed:", run.stderr[-2000:])
            return 1
        ritl = outputs(tmp / "ritl.json")
    ecu_summary = json.loads(ecu_out[-1]) if ecu_out else {}
    cf = ritl["cycle_frames"]
    r_yaw, b_yaw = ref["outputs"]["yaw_rate_radps"], ritl["outputs"]["yaw_rate_radps"]
    r_rack, b_rack = ref["outputs"]["rack_position_m"], ritl["outputs"]["rack_position_m"]
    print(f"built-in: yaw rate {r_yaw:.5f} rad/s, rack {r_rack:.6f} m; rack in the loop: "
          f"yaw rate {b_yaw:.5f} rad/s, rack {b_rack:.6f} m ({wall:.1f} s wall, "
          f"{ritl['cycles']} cycles, misses {ritl['deadline_misses']}); cycle frames {cf}; "
          f"virtual rack {ecu_summary}")
    ok = True
    for what, good in [
        ("yaw rate within 5 %", abs(b_yaw - r_yaw) <= 0.05 * abs(r_yaw)),
        ("rack travel within 5 %", abs(b_rack - r_rack) <= 0.05 * abs(r_rack)),
        ("the step steers (yaw rate > 0.1 rad/s)", r_yaw > 0.1),
        ("every cycle waited", cf["lockstep_waits"] == ritl["cycles"]),
        ("answers in the same or the next cycle", cf["answered_later"] == 0 and
         cf["answered_same_cycle"] + cf["answered_next_cycle"] > 0.9 * ritl["cycles"]),
        ("at most the start-up timeout", cf["lockstep_timeouts"] <= 1),
    ]:
        print(("ok   " if good else "FAIL ") + what)
        ok &= good
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
