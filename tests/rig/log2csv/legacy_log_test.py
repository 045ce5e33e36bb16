#!/usr/bin/python3
"""rig-log2csv reads LCM logs written before rig.vehicle_state_t gained the per-wheel road fields
(v1, issue 16: wheel_road_z_m, wheel_road_normal_x/y/z, wheel_road_mu) and before it gained the
differentials (v2, issue 17: num_diffs, diff_*), and before it gained the frame torsion and the
leaf springs (v3, issue 17: unit_frame_*, wheel_leaf_*), and before the leaf balance (v4, issue 17:
wheel_leaf_rocker_rad).

usage: legacy_log_test.py RIG_LOG2CSV

v1/*.lcm were written by main's `rig run` at 8f435e5 (the sedan's ISO 7401 step steer and the
car + trailer, 20 cycles each, --offline), v1/*.RIG_STATE.csv by main's rig-log2csv from them;
v2/* likewise by main at cc32032 (--duration 0.02), v3/* by main at 5a0a584 (the sedan's ISO 7401
step steer and the truck on rigid axles, --duration 0.02), v4/* by main at 31ef863 (the van's
leaf-spring braking and the frame tractor's circle, --duration 0.02, before the leaf balance's
wheel_leaf_rocker_rad).
Today's rig-log2csv must give the same RIG_STATE.csv byte for byte (the columns the log has, the
same values: a field the legacy decoder forgot to carry over would read 0) and name the layout.
"""
import pathlib
import subprocess
import sys
import tempfile

LOG2CSV = sys.argv[1]
ROOT = pathlib.Path(__file__).resolve().parent
failures = 0
for version, log in [(v, log) for v in ("v1", "v2", "v3", "v4") for log in sorted((ROOT / v).glob("*.lcm"))]:
    HERE = ROOT / version
    with tempfile.TemporaryDirectory() as out:
        r = subprocess.run([LOG2CSV, str(log), out], capture_output=True, text=True)
        if r.returncode != 0:
            print(f"FAIL {log.name}: exit {r.returncode}: {r.stderr}")
            failures += 1
            continue
        state = [line for line in r.stdout.splitlines() if "RIG_STATE.csv" in line]
        if not state or version not in state[0] or "20 rows" not in state[0]:
            print(f"FAIL {log.name}: rig-log2csv says {state}")
            failures += 1
        got = (pathlib.Path(out) / "RIG_STATE.csv").read_bytes()
        want = (HERE / f"{log.stem}.RIG_STATE.csv").read_bytes()
        if got != want:
            g, w = got.decode().splitlines(), want.decode().splitlines()
            print(f"FAIL {log.name}: RIG_STATE.csv differs from main's rig-log2csv "
                  f"({len(g)} vs {len(w)} lines; headers equal: {g[0] == w[0]})")
            if g[0] == w[0]:
                head = w[0].split(",")
                for gl, wl in zip(g[1:], w[1:]):
                    bad = [h for h, a, b in zip(head, gl.split(","), wl.split(",")) if a != b]
                    if bad:
                        print(f"  first differing row, columns: {bad[:10]}")
                        break
            failures += 1
        else:
            print(f"ok {log.name}: {len(want.splitlines())} lines identical to main's CSV; {state[0]}")
        if version == "v1" and b"wheel0_road_" in got:
            print(f"FAIL {log.name}: the CSV of a v1 log has road columns the log does not carry")
            failures += 1
        header = got.splitlines()[0]
        if version == "v4" and (b"leaf_rocker" in header or b"frame_twist" not in header
                                or (b"leaf" in log.name.encode() and b"_leaf_windup" not in header)):
            print(f"FAIL {log.name}: the CSV of a v4 log has the rocker column or lacks the "
                  "frame / leaf columns the log carries")
            failures += 1
        if version != "v4" and (b"frame_twist" in got or b"_leaf_" in header):
            print(f"FAIL {log.name}: the CSV of a {version} log has frame or leaf columns")
            failures += 1
        if version in ("v1", "v2") and b"diff" in got.splitlines()[0]:
            print(f"FAIL {log.name}: the CSV of a {version} log has differential columns")
            failures += 1
sys.exit(1 if failures else 0)
