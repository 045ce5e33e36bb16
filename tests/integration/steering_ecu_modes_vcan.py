#!/usr/bin/python3
"""The steering ECU's modes against the rig on vcan (issue 15, item 7): `scripts/virtual-ecu
--mode lka` and `--mode park-assist` as the EPS of config/bench.toml's CAN mapping, the sedan
released (hand torque 0: a copy of sedan.toml with `input = "torque"`), judged by the physics
at the end of the run rather than by timing (the VM cannot hold 1 kHz; the rig skips what it
misses):

- lka: the overlay torque A alone on the released wheel at 15 m/s (the boost acts on the
  torsion-bar torque, ~0 with the hands off): the rack force the tie rods put on the rack
  balances A / i_SB up to the rack's dry friction, |F - A / i_SB| <= rack_friction_n (+ 5 %),
  and the car turns the way A pushes (yaw rate > 0 for A > 0, < 0 for A < 0).
- park-assist: the ECU's angle PID turns the released wheel to its target at 10 km/h: within
  0.1 rad of 0.5 rad at the end (from 0), and the motor torque the rig received within its limit.
  Function, not timing: in the TCG VM the PID integrates on the ECU's wall clock while the rig
  misses cycles (a third to half of them), so how far the loop has settled at the end is
  timing-bound - 0.544 and 0.556 rad measured in two runs; a loop that does not close stays
  at 0 rad.

    steering_ecu_modes_vcan.py BIN_DIR SOURCE_DIR     (needs vcan0: run inside scripts/with-vcan)
"""
import json
import pathlib
import re
import signal
import subprocess
import sys
import tempfile
import tomllib

DURATION_S = 6.0


def released_sedan(src, tmp):
    """sedan.toml with the hand on nothing: the wheel takes the hand torque (0)."""
    text = (src / "config" / "vehicles" / "sedan.toml").read_text()
    text, n = re.subn(r'(?m)^input = "angle"', 'input = "torque"', text)
    if n != 1:
        raise SystemExit("sedan.toml: no `input = \"angle\"` line to release the wheel")
    path = tmp / "sedan-released.toml"
    path.write_text(text)
    return path


def config(src, tmp, vehicle, speed_mps, name):
    path = tmp / f"{name}.toml"
    path.write_text(f'''[rig]
period_s = 0.001
duration_s = {DURATION_S}

[model]
kind = "vehicle"
vehicle = "{vehicle}"
road_friction = 1.0
initial_speed_mps = {speed_mps}

[routing]
throttle_pedal = "driver"
assist_torque_nm = "can"

[driver]
kind = "table"
columns = ["time_s", "throttle_pedal"]
rows = [[0.0, 0.08], [3600.0, 0.08]]

[can]
interface = "vcan0"
mapping = "{src}/config/can/steering-bench.toml"
''')
    return path


def run_pair(bin_dir, src, cfg, ecu_args, summary):
    ecu = subprocess.Popen(
        ["/usr/bin/python3", str(src / "scripts" / "virtual-ecu"), "--interface", "vcan0",
         "--dbc", str(src / "config" / "can" / "steering-bench.dbc")] + ecu_args,
        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    line = ecu.stdout.readline()
    if '"ready": true' not in line:
        ecu.kill()
        raise SystemExit(f"virtual-ecu did not start: {line}")
    run = subprocess.run([str(bin_dir / "rig"), "run", "--config", str(cfg), "--lcm-url", "none",
                          "--summary-json", str(summary)],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, timeout=600)
    ecu.send_signal(signal.SIGTERM)
    out = ecu.communicate(timeout=60)[0].strip().splitlines()
    if run.returncode != 0:
        raise SystemExit(f"rig failed ({run.returncode}): {run.stderr[-2000:]}")
    return json.loads(summary.read_text()), (json.loads(out[-1]) if out else {})


def main(argv):
    bin_dir, src = pathlib.Path(argv[1]), pathlib.Path(argv[2])
    if not pathlib.Path("/sys/class/net/vcan0").exists():
        print("steering_ecu_modes_vcan: no vcan0 (run inside scripts/with-vcan)")
        return 1
    steering = tomllib.load(open(src / "config" / "vehicles" / "sedan.toml", "rb"))["steering"]
    i_sb, f_c = steering["rack_per_pinion_m_per_rad"], steering["rack_friction_n"]
    checks = []
    with tempfile.TemporaryDirectory(prefix="rig_ecu_modes_") as tmp:
        tmp = pathlib.Path(tmp)
        vehicle = released_sedan(src, tmp)
        for a in (3.0, -3.0):
            s, ecu = run_pair(bin_dir, src, config(src, tmp, vehicle, 15.0, "lka"),
                              ["--mode", "lka", "--lka-torque-nm", str(a), "--lka-period-s", "0"],
                              tmp / "lka.json")
            o = s["outputs"]
            f, want = o["rack_force_n"], a / i_sb
            print(f"lka {a:+.1f} N m: rack force {f:.1f} N (A / i_SB {want:.1f} N, friction "
                  f"{f_c:.0f} N), torsion bar {o['torsion_bar_torque_nm']:.3f} N m, yaw rate "
                  f"{o['yaw_rate_radps']:.4f} rad/s, wheel {o['steering_wheel_angle_rad']:.3f} "
                  f"rad; {s['cycles']} cycles, {s['deadline_misses']} misses; ecu {ecu}")
            checks += [
                (f"lka {a:+}: |F - A / i_SB| <= friction",
                 abs(f - want) <= 1.05 * f_c + 0.05 * abs(want)),
                (f"lka {a:+}: turns the way A pushes", o["yaw_rate_radps"] * a > 0.005 * abs(a)),
                (f"lka {a:+}: CAN frames received", s["can"]["frames_received"] > 100)]
        s, ecu = run_pair(bin_dir, src, config(src, tmp, vehicle, 2.78, "park"),
                          ["--mode", "park-assist", "--target-angle-rad", "0.5"],
                          tmp / "park.json")
        o = s["outputs"]
        print(f"park-assist: wheel {o['steering_wheel_angle_rad']:.4f} rad (target 0.5), "
              f"speed {o['vehicle_speed_mps']:.2f} m/s; {s['cycles']} cycles; ecu {ecu}")
        checks += [("park-assist: within 0.1 rad of the target",
                    abs(o["steering_wheel_angle_rad"] - 0.5) < 0.1),
                   ("park-assist: the motor torque within its 10 N m",
                    abs(ecu.get("assist_torque_nm", 99)) <= 10.0 + 1e-9)]
    ok = True
    for what, good in checks:
        print(("ok   " if good else "FAIL ") + what)
        ok &= good
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
