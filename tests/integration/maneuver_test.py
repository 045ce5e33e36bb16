#!/usr/bin/python3
"""Runs one maneuver file offline through `rig run` and checks physical results from the LCM log.

Usage: maneuver_test.py RIG_BINARY LOG2CSV_BINARY SOURCE_DIR NAME
NAME is a file of config/maneuvers/ without .toml, "rig" for config/rig.toml (the demo),
"bench" for config/bench.toml (the CAN bench, run until stopped: here 5 s with `--can none`), or
"combination-FILE" for config/combinations/FILE.toml.

Each run: `rig check` passes, `rig run --offline --lcm-url none --lcm-log F` exits 0 with stop
reason "duration" (a NaN stops the run with exit 1), every logged state is finite; then
rig-log2csv turns the log into RIG_STATE.csv (one row per 1 ms step) and the maneuver's own
physical checks run on it. The numbers are the ones the model tests print
(model/vehicle/README.md), with margins that still catch a broken model.
"""

import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rig_checks import fail  # noqa: E402
import rig_checks  # noqa: E402

RIG, LOG2CSV, SRC, NAME = sys.argv[1:5]
COLUMNS = ("sim_time_s", "unit0_", "unit1_", "wheel0_", "wheel1_", "wheel2_", "wheel3_", "wheel4_",
           "wheel5_", "steering_", "gear", "num_", "joint0_", "rack_", "torsion_bar_", "tie_rod_",
           "brake_pressure_", "diff", "body")
TMP = tempfile.mkdtemp(prefix=f"rig_maneuver_{NAME}_")
# Configurations that run until stopped get a duration here.
DURATION_S = {"bench": "5"}
STDERR = []  # of the run


def check(cond, msg):
    rig_checks.check(cond, msg, verbose=True)


def config_path(name):
    if name in ("rig", "bench"):
        return os.path.join(SRC, "config", name + ".toml")
    if name.startswith("combination-"):
        return os.path.join(SRC, "config", "combinations", name[len("combination-"):] + ".toml")
    return os.path.join(SRC, "config", "maneuvers", name + ".toml")


def run_offline(config, extra=()):
    r = subprocess.run([RIG, "check", config], capture_output=True, text=True, timeout=30)
    if r.returncode != 0:
        fail(f"rig check: exit {r.returncode}: {r.stdout}{r.stderr}")
    log, summary = f"{TMP}/run.lcm", f"{TMP}/summary.json"
    duration = ["--duration", DURATION_S[NAME]] if NAME in DURATION_S else []
    r = subprocess.run([RIG, "run", "--config", config, "--offline", "--can", "none", "--lcm-url",
                        "none", "--lcm-log", log, "--summary-json", summary] + duration + list(extra),
                       capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        fail(f"rig run: exit {r.returncode}: {r.stderr[-2000:]}")
    STDERR.append(r.stderr)
    s = json.load(open(summary))
    # a scenario's stop event ends it early (config/maneuvers/braking-100-0.toml)
    check(s["stop_reason"] in ("duration", "event"), f"stop reason {s['stop_reason']} (no NaN stop)")
    r = subprocess.run([LOG2CSV, log, f"{TMP}/csv"], capture_output=True, text=True, timeout=120)
    if r.returncode != 0:
        fail(f"rig-log2csv: {r.stderr}")
    rows = []
    with open(f"{TMP}/csv/RIG_STATE.csv", newline="") as f:
        for row in csv.DictReader(f):
            rows.append({k: float(v) for k, v in row.items() if k.startswith(COLUMNS)})
    check(len(rows) == s["cycles"], f"{len(rows)} logged states = {s['cycles']} cycles")
    bad = [k for k, v in rows[-1].items() if not math.isfinite(v)]
    check(not bad and all(math.isfinite(r["unit0_x_m"]) for r in rows), f"all states finite {bad}")
    return s, rows


def at(rows, t):
    """The row at simulated time t (nearest step; rows are 1 step apart)."""
    dt = rows[1]["sim_time_s"] - rows[0]["sim_time_s"]
    i = round((t - rows[0]["sim_time_s"]) / dt)
    return rows[max(0, min(len(rows) - 1, i))]


def speed(r):
    return math.hypot(r["unit0_vx_mps"], r["unit0_vy_mps"])


def iso3888_centreline_y(x, start_x, offset=3.5):
    """rig/driver/path_driver.cpp iso3888_1_centreline: cosine lane changes over 15..45 m and
    70..95 m after start_x (the driver follows it by straight segments of 1 m; 1 mm apart)."""
    u = x - start_x
    if 15 <= u <= 45:
        return offset * 0.5 * (1 - math.cos(math.pi * (u - 15) / 30))
    if 45 < u < 70:
        return offset
    if 70 <= u <= 95:
        return offset * 0.5 * (1 + math.cos(math.pi * (u - 70) / 25))
    return 0.0


def dlc_offsets(rows, start_x):
    """Max |CG offset from the centreline| in lane 1 (0-15 m), lane 3 (45-70 m), lane 5
    (95-110 m) of the ISO 3888-1 track, as tests/model/vehicle DoubleLaneChangeClosedLoopAt60kmh."""
    lanes = {1: (0, 15), 3: (45, 70), 5: (95, 110)}
    out = {k: 0.0 for k in lanes}
    for r in rows:
        u = r["unit0_x_m"] - start_x
        off = abs(r["unit0_y_m"] - iso3888_centreline_y(r["unit0_x_m"], start_x))
        for k, (a, b) in lanes.items():
            if a <= u <= b:
                out[k] = max(out[k], off)
    return out


def check_dlc(rows, start_x, v_target):
    off = dlc_offsets(rows, start_x)
    print(f"DLC max |offset| lane 1/3/5: {off[1]:.3f}/{off[3]:.3f}/{off[5]:.3f} m")
    # ISO 3888-1 lane half-widths minus half the car width (1.80 m): 0.21, 0.30, 0.39 m
    check(off[1] < 0.21 and off[3] < 0.30 and off[5] < 0.39, "DLC stays in the lanes")
    on_track = [r for r in rows if 0 <= r["unit0_x_m"] - start_x <= 125]
    check(on_track and rows[-1]["unit0_x_m"] > start_x + 125, "DLC track completed")
    v = [speed(r) for r in on_track]
    check(min(v) > 0.95 * v_target and max(v) < 1.05 * v_target,
          f"speed on the track {min(v) * 3.6:.1f}-{max(v) * 3.6:.1f} km/h within 5 % of "
          f"{v_target * 3.6:.0f} km/h")
    ay = max(abs(r["unit0_ay_mps2"]) for r in on_track)
    check(2.0 < ay < 8.0, f"max |a_y| on the track {ay:.2f} m/s^2 (lane changes, below mu g)")


def creep_mm(rows, t0, t1):
    """Distance travelled between t0 and t1 [mm]."""
    a, b = at(rows, t0), at(rows, t1)
    return 1e3 * math.hypot(b["unit0_x_m"] - a["unit0_x_m"], b["unit0_y_m"] - a["unit0_y_m"])


def case_rig(s, rows):
    # DLC at 60 km/h on the flat, onto the 10 % hill (config/roads/demo-hill.xodr), brakes at
    # 12 s, stand-still on the hill, held to 20 s.
    flat = [r for r in rows if r["sim_time_s"] < 10.0]
    check(all(r[f"wheel{i}_road_z_m"] == 0.0 and r[f"wheel{i}_road_normal_z"] == 1.0
              for r in flat for i in (0, 1)), "the lane change (t < 10 s) is driven on the flat")
    check_dlc([r for r in rows if r["sim_time_s"] < 10.5], 40.0, 16.67)
    stop = next(r["sim_time_s"] for r in rows if r["sim_time_s"] > 12.0 and speed(r) < 0.01)
    check(stop < 15.5, f"stand-still at t = {stop:.2f} s (< 15.5 s)")
    end = rows[-1]
    grade = -end["wheel0_road_normal_x"] / end["wheel0_road_normal_z"]
    check(abs(grade - 0.10) < 1e-6 and end["unit0_x_m"] > 200.0,
          f"parked on the 10 % hill: x = {end['unit0_x_m']:.1f} m, grade under the wheels {grade:.4f}")
    check(abs(end["unit0_pitch_rad"] + math.atan(0.10)) < 0.02,
          f"pitched up the hill: {end['unit0_pitch_rad']:.4f} rad (atan 0.1 = 0.0997)")
    creep = creep_mm(rows, 16.0, 20.0)
    check(creep < 1.0, f"creep on the 10 % grade over 16-20 s: {creep:.3f} mm (< 1 mm)")
    check(all(r["wheel0_brake_torque_nm"] != 0 for r in rows if r["sim_time_s"] > 15),
          "brakes hold the car")


def case_bench(s, rows):
    # The CAN bench offline with --can none: one warning, the assist (routed to CAN) takes its
    # fallback 0 N m, flagged invalid; the path driver holds the R = 40 m circle at 10 m/s.
    warnings = [line for line in STDERR[0].splitlines() if "--can none" in line]
    check(len(warnings) == 1 and "assist_torque_nm" in warnings[0] and "fallback" in warnings[0],
          f"one --can none warning naming the CAN input: {warnings}")
    check(s["sim_time_s"] > 4.99, f"ran {s['sim_time_s']} s of the endless bench")
    end = rows[-1]
    check(abs(speed(end) - 10.0) < 0.5, f"speed {speed(end):.2f} m/s (target 10)")
    check(1.8 < abs(end["unit0_ay_mps2"]) < 3.2, f"a_y {end['unit0_ay_mps2']:.2f} m/s^2 (v^2/R 2.5)")


def case_double_lane_change_iso3888(s, rows):
    check_dlc(rows, 30.0, 16.67)
    k = kpis_of(s)
    kept, hit = iso3888_lanes_and_cones(rows, 30.0, 3.5, 1.8, 4.7, 2.1, 5.0, 0.15)
    print(f"ISO 3888-1 from the log: lanes kept {kept}, cones hit {hit}; kpis "
          f"{k['lanes_kept']['value']}, {k['cones_hit']['value']}")
    check(k["lanes_kept"]["value"] == kept and k["cones_hit"]["value"] == hit,
          "kpis lanes_kept and cones_hit = this test's ISO 3888-1 outline check of the log")
    check(k["lanes_kept"]["passed"] and k["cones_hit"]["passed"], "the sedan keeps the lanes")
    # lane 3 put 0.5 m to the right of the driver's (--set, lane_offset_m = 3.0): it is lost and
    # its left cones are hit; the same counts as this test's
    sets = ["kpi[0].lane_offset_m=3.0", "kpi[1].lane_offset_m=3.0"]
    s2, rows2 = run_offline(config_path(NAME), [a for x in sets for a in ("--set", x)])
    k2 = kpis_of(s2)
    kept2, hit2 = iso3888_lanes_and_cones(rows2, 30.0, 3.0, 1.8, 4.7, 2.1, 5.0, 0.15)
    print(f"lane 3 offset 3.0 m: lanes kept {kept2}, cones hit {hit2} (log); kpis "
          f"{k2['lanes_kept']['value']}, {k2['cones_hit']['value']}")
    check(kept2 == 2 and hit2 > 0, "lane 3 lost, cones hit")
    check(k2["lanes_kept"]["value"] == kept2 and k2["cones_hit"]["value"] == hit2,
          "kpis = this test's counts for the shifted lane")
    check(not k2["lanes_kept"]["passed"] and not k2["cones_hit"]["passed"], "and they fail")


def iso3888_lanes_and_cones(rows, start, offset, b, length, front, spacing, radius):
    """ISO 3888-1 (docs/kpis.md): lanes 1/3/5 of widths 1.1 b + 0.25, 1.2 b + 0.25, 1.3 b + 0.25
    over 0-15, 45-70, 95-110 m from `start`, lane 3 `offset` to the left. The outline's part in a
    lane's x range must stay within its limits; a cone (base `radius`, standing `radius` outside
    a limit, at each lane's ends and every `spacing`) is hit when the outline comes within
    `radius` of it. Written from the definitions, apart from rig/kpi/iso3888_kpis.cpp."""
    lanes = [(start, start + 15, 0.0, 1.1 * b + 0.25), (start + 45, start + 70, offset, 1.2 * b + 0.25),
             (start + 95, start + 110, 0.0, 1.3 * b + 0.25)]
    cones = []
    for x0, x1, yc, w in lanes:
        xs = [x0 + i * spacing for i in range(int((x1 - x0) / spacing + 1e-9) + 1)]
        if xs[-1] < x1 - 1e-9:
            xs.append(x1)
        cones += [(x, yc + side * (w / 2 + radius)) for x in xs for side in (1, -1)]
    out, hit, through = [False] * 3, set(), False
    for r in rows:
        x, y, psi = r["unit0_x_m"], r["unit0_y_m"], r["unit0_yaw_rad"]
        c, sn = math.cos(psi), math.sin(psi)
        corners = [(x + c * bx - sn * by, y + sn * bx + c * by)
                   for bx, by in ((front, b / 2), (front, -b / 2), (front - length, -b / 2),
                                  (front - length, b / 2))]
        for k, (x0, x1, yc, w) in enumerate(lanes):
            ys = [py for px, py in corners if x0 <= px <= x1]
            for (ax, ay), (bx_, by_) in zip(corners, corners[1:] + corners[:1]):
                for xl in (x0, x1):
                    if (ax - xl) * (bx_ - xl) < 0:
                        ys.append(ay + (xl - ax) / (bx_ - ax) * (by_ - ay))
            if ys and (max(ys) > yc + w / 2 or min(ys) < yc - w / 2):
                out[k] = True
        through = through or min(px for px, _ in corners) > lanes[2][1]
        for i, (qx, qy) in enumerate(cones):
            if i in hit or abs(qx - x) > length + b:
                continue
            u, v = c * (qx - x) + sn * (qy - y), -sn * (qx - x) + c * (qy - y)
            du = max(front - length - u, 0.0, u - front)
            dv = max(abs(v) - b / 2, 0.0)
            if math.hypot(du, dv) <= radius:
                hit.add(i)
    return (3 - sum(out) if through else 0), len(hit)


def case_grade_hold_20pct(s, rows):
    # braked from 5 m/s up 20 %: at rest within 2 s, held to 14 s, then drives away uphill
    check(speed(at(rows, 2.0)) < 0.01, f"at rest at 2 s ({speed(at(rows, 2.0)):.4f} m/s)")
    creep = creep_mm(rows, 3.5, 13.5)
    check(creep < 1.0, f"creep on the 20 % grade over 10 s: {creep:.3f} mm (< 1 mm)")
    up = at(rows, 30.0)["unit0_x_m"] - at(rows, 14.0)["unit0_x_m"]
    check(up > 20.0, f"drives {up:.1f} m uphill in 16 s after release")


def iso7401_step(rows, response, t_from, steady_s, fraction=0.9):
    """ISO 7401 step input from the log (docs/kpis.md): the time reference where the steering-
    wheel angle reaches 50 % of its change; response time to `fraction` of the response's
    change, the peak's time, overshoot and gain; changes from the window's first sample to the
    mean over its last `steady_s`. Written from the definitions, apart from rig/kpi."""
    w = [r for r in rows if r["sim_time_s"] >= t_from - 5e-4]
    t = [r["sim_time_s"] for r in w]
    x = [r["steering_wheel_angle_rad"] for r in w]
    y = [r[response] for r in w]
    late = [i for i in range(len(t)) if t[i] >= t[-1] - steady_s]
    dx = sum(x[i] for i in late) / len(late) - x[0]
    dy = sum(y[i] for i in late) / len(late) - y[0]

    def cross(v, v0, dv, level, start):
        for i in range(start, len(v)):
            if (v[i] - v0) / dv >= level:
                a, b = (v[i - 1] - v0) / dv, (v[i] - v0) / dv
                return i, t[i - 1] + (level - a) / (b - a) * (t[i] - t[i - 1])
        return None, float("nan")

    i_ref, t_ref = cross(x, x[0], dx, 0.5, 1)
    _, t_resp = cross(y, y[0], dy, fraction, i_ref)
    i_peak = max(range(i_ref, len(y)), key=lambda i: (y[i] - y[0]) / dy)
    return {"response_time": t_resp - t_ref, "peak_response_time": t[i_peak] - t_ref,
            "overshoot": (y[i_peak] - y[0]) / dy - 1, "steady_gain": dy / dx}


def case_step_steer_iso7401(s, rows):
    k = kpis_of(s)
    yaw = iso7401_step(rows, "unit0_wz_radps", 0.5, 1.0)
    ay = iso7401_step(rows, "unit0_ay_mps2", 0.5, 1.0)
    print(f"ISO 7401 from the log: yaw rate response {yaw['response_time']:.4f} s, peak "
          f"{yaw['peak_response_time']:.4f} s, overshoot {100 * yaw['overshoot']:.2f} %, gain "
          f"{yaw['steady_gain']:.4f} 1/s; a_y response {ay['response_time']:.4f} s")
    for name, ref in (("yaw_rate_response_time_s", yaw["response_time"]),
                      ("yaw_rate_peak_response_time_s", yaw["peak_response_time"]),
                      ("yaw_rate_overshoot", yaw["overshoot"]), ("yaw_rate_gain_1ps", yaw["steady_gain"]),
                      ("lateral_accel_response_time_s", ay["response_time"])):
        check(abs(k[name]["value"] - ref) <= 1e-6 * max(1.0, abs(ref)),
              f"kpi {name} {k[name]['value']:.6f} = this test's ISO 7401 {ref:.6f}")
    # the steady gain against the model's steady state (model/vehicle/README.md: 0.187 rad/s at
    # 0.5 rad): the hand value r / delta_H
    end = at(rows, 6.0)
    check(abs(yaw["steady_gain"] - end["unit0_wz_radps"] / end["steering_wheel_angle_rad"]) < 0.005,
          "gain = steady yaw rate / wheel angle at 6 s")
    end = at(rows, 6.0)
    r_end, ay_end = end["unit0_wz_radps"], end["unit0_ay_mps2"]
    # model/vehicle/README.md: 0.187 rad/s, 4.1 m/s^2 at 80 km/h
    check(0.16 < r_end < 0.22, f"steady yaw rate {r_end:.4f} rad/s")
    check(3.5 < ay_end < 4.7, f"steady a_y {ay_end:.3f} m/s^2")
    late = [r["unit0_wz_radps"] for r in rows if r["sim_time_s"] >= 4.0]
    check(max(late) - min(late) < 0.02 * r_end, "yaw rate settled over 4-6 s (no oscillation)")
    peak = max(r["unit0_wz_radps"] for r in rows)
    check(peak < 1.2 * r_end, f"overshoot {100 * (peak / r_end - 1):.1f} % (< 20 %)")


def iso4138_understeer(rows, plateau_s, steady_s, wheelbase, ratio, ay_max=4.0, band=0.1):
    """ISO 4138 constant radius (docs/kpis.md): per speed step the means over its last
    `steady_s` (steady if v varied < `band`); K = slope of delta_H / i_s - l r / v over a_y = v r
    up to `ay_max`. Written from the definitions, apart from rig/kpi/circle_kpis.cpp."""
    groups = {}
    for r in rows:
        j = math.floor(r["sim_time_s"] / plateau_s)
        if r["sim_time_s"] - j * plateau_s >= plateau_s - steady_s:
            groups.setdefault(j, []).append(r)
    xs, ys = [], []
    for j, g in sorted(groups.items()):
        if (j + 1) * plateau_s > rows[-1]["sim_time_s"] + 2e-3:
            continue  # the run ended before this step did
        v = [r["unit0_vx_mps"] for r in g]
        if max(v) - min(v) >= band:
            continue
        vm, rm = sum(v) / len(v), sum(r["unit0_wz_radps"] for r in g) / len(g)
        am = sum(r["steering_wheel_angle_rad"] for r in g) / len(g)
        if 0 <= vm * rm <= ay_max:
            xs.append(vm * rm)
            ys.append(am / ratio - wheelbase * rm / vm)
    return lsq_slope(xs, ys), len(xs)


def case_step_steer_truck_rigid(s, rows):
    # issue 17: the truck on rigid axles; tests/model/vehicle/rigid_axle_test.cpp: a_y ~1.5 m/s^2
    end = at(rows, 6.0)
    ay_end = end["unit0_ay_mps2"]
    check(1.0 < ay_end < 2.5, f"steady a_y {ay_end:.3f} m/s^2")
    late = [r["unit0_wz_radps"] for r in rows if r["sim_time_s"] >= 4.5]
    check(max(late) - min(late) < 0.02 * abs(end["unit0_wz_radps"]),
          "yaw rate settled over 4.5-6 s (no oscillation at h = 1 ms)")
    check(end["unit0_roll_rad"] > 0.003, f"body roll {end['unit0_roll_rad']:.4f} rad to the outside")
    # each rigid axle's heave and roll, alike on both its wheels; the hub travel follows from them
    roll = end["wheel2_axle_roll_rad"]
    check(roll < -0.002 and end["wheel3_axle_roll_rad"] == roll,
          f"drive axle 1 rolls against the body: {roll:.5f} rad on both wheels")
    hub = end["wheel2_axle_heave_m"] + 0.5 * 1.85 * roll
    check(abs(end["wheel2_hub_travel_m"] - hub) < 1e-12,
          f"hub travel = heave + track/2 roll ({end['wheel2_hub_travel_m']:.6f} m)")


def case_circle_iso4138(s, rows):
    k = kpis_of(s)["understeer_gradient_radpmps2"]
    st = vehicle_file(config_path(NAME))["steering"]
    ratio = st["steering_arm_m"] / st["rack_per_pinion_m_per_rad"]
    veh = vehicle_file(config_path(NAME))
    steered = [a["position_x_m"] for a in veh["axle"] if a.get("steered")]
    rear = [a["position_x_m"] for a in veh["axle"] if not a.get("steered")]
    wheelbase = steered[0] - sum(rear) / len(rear)
    ref, n = iso4138_understeer(rows, 8.0, 3.0, wheelbase, ratio)
    print(f"ISO 4138 from the log: K {ref:.6f} rad/(m/s^2) over {n} steady states (i_s {ratio:.2f}, "
          f"l {wheelbase:.2f} m); kpi {k['value']:.6f}")
    check(n >= 6, f"{n} steady states with a_y <= 4 m/s^2")
    check(abs(k["value"] - ref) <= 1e-6 * abs(ref), "kpi understeer_gradient = this test's ISO 4138")
    check(k["passed"], "within the bench's band")
    ay = [abs(r["unit0_ay_mps2"]) for r in rows]
    check(max(ay) > 7.0, f"a_y reaches {max(ay):.2f} m/s^2 (> 7, saturation near mu g)")
    check(max(ay) < 9.81, "a_y below mu g")
    check(speed(rows[-1]) > speed(rows[0]) + 10.0, "speed raised along the circle")


def braking_from_log(rows, brake_row, stop=0.01):
    """From the brake point's row: the distance until |v| falls to `stop` (trapezoids, the
    crossing interpolated) and the UN ECE R13-H mean fully developed deceleration
    (v_b^2 - v_e^2) / (2 (s_e - s_b)), v_b = 0.8 v0, v_e = 0.1 v0. Apart from rig/kpi."""
    def distance_to(level):
        d = 0.0
        for a, b in zip(rows[brake_row:], rows[brake_row + 1:]):
            va, vb, dt = abs(a["unit0_vx_mps"]), abs(b["unit0_vx_mps"]), b["sim_time_s"] - a["sim_time_s"]
            if vb > level:
                d += 0.5 * (va + vb) * dt
                continue
            f = (va - level) / (va - vb)
            return d + 0.5 * (va + level) * f * dt
        return float("nan")
    v0 = abs(rows[brake_row]["unit0_vx_mps"])
    sb, se = distance_to(0.8 * v0), distance_to(0.1 * v0)
    return distance_to(stop), ((0.8 * v0) ** 2 - (0.1 * v0) ** 2) / (2 * (se - sb)), v0


def case_braking_100_0(s, rows):
    k = kpis_of(s)
    ev = {e["name"]: e["time_s"] for e in s["scenario_events"]}
    check(s["stop_reason"] == "event", "the stop event ended the run")
    # the brake event fires at the first cycle whose last state is past x = 30 m
    i_fire = next(i for i, r in enumerate(rows) if r["unit0_x_m"] >= 30.0)
    check(abs(ev["brake"] - rows[i_fire]["sim_time_s"]) < 1e-9,
          f"brake event at {ev['brake']:.3f} s, when x passed 30 m")
    # the ramp from 0 to 80 bar in 0.2 s: 4e4 Pa per 1 ms cycle from the firing cycle (0) on;
    # a cycle's input shows in the state one step later, so 1 bar is crossed 3 + 1 steps later
    i_brake = next(i for i, r in enumerate(rows) if r["brake_pressure_fl_pa"] >= 1e5)
    check(i_brake == i_fire + 4, f"brake point {rows[i_brake]['sim_time_s']:.3f} s = firing + 4 ms")
    check(abs(rows[i_fire + 3]["brake_pressure_fl_pa"] - 8e4) < 1e-3, "the ramp: 80 kPa after 2 steps")
    # stop: speed below 0.1 m/s for 2 s
    i_slow = next(i for i, r in enumerate(rows) if r["sim_time_s"] > ev["brake"] and abs(r["unit0_vx_mps"]) < 0.1)
    check(abs(ev["stopped"] - rows[i_slow]["sim_time_s"] - 2.0) < 2e-3,
          f"stopped at {ev['stopped']:.3f} s, 2 s after the speed fell below 0.1 m/s")
    dist, mfdd, v0 = braking_from_log(rows, i_brake)
    print(f"braking from {v0 * 3.6:.1f} km/h: distance {dist:.3f} m, MFDD {mfdd:.3f} m/s^2 (log); "
          f"kpis {k['braking_distance_m']['value']:.3f} m, {k['mean_deceleration_mps2']['value']:.3f}")
    check(abs(k["braking_distance_m"]["value"] - dist) < 1e-6, "kpi braking distance = the log's")
    check(abs(k["mean_deceleration_mps2"]["value"] - mfdd) < 1e-6, "kpi MFDD = the log's")
    # hand bound: with the MFDD from 0.8 v0 down and the ramp's lag, v0^2 / (2 MFDD) plus v0 t_ramp/2
    hand = v0 ** 2 / (2 * mfdd) + v0 * 0.1
    check(abs(dist - hand) < 0.1 * hand, f"distance {dist:.2f} m within 10 % of v0^2/(2 d_m) + v0 t_r/2 = {hand:.2f}")
    check(k["braking_distance_m"]["passed"] and k["mean_deceleration_mps2"]["passed"], "within limits")


def case_acceleration_coastdown(s, rows):
    t100 = next((r["sim_time_s"] for r in rows if speed(r) >= 100 / 3.6), None)
    check(t100 is not None and 4.0 < t100 < 10.0, f"0-100 km/h in {t100} s")
    v15, v40 = speed(at(rows, 15.0)), speed(at(rows, 40.0))
    check(v40 < v15 - 3.0 and v40 > 0.5 * v15, f"coast-down {v15:.1f} -> {v40:.1f} m/s")


def case_paper_quarter_car(s, rows):
    # Quarter car after 2 s of 1000 N m up a 10 % grade: a = (F - m g sin) / (m + I/r^2) ~ 7.2 m/s^2.
    v = at(rows, 2.0)["unit0_vx_mps"]
    check(13.5 < v < 15.0, f"speed after 2 s {v:.2f} m/s")
    creep = creep_mm(rows, 14.0, 17.9)
    check(creep < 1.0, f"braked creep 14-17.9 s: {creep:.3f} mm")
    check(at(rows, 20.0)["unit0_vx_mps"] < -0.5, "released at 18 s: rolls back")


def kpis_of(s):
    """The summary's `kpis` list (docs/kpis.md) by name, its shape checked."""
    check(isinstance(s.get("kpis"), list) and s["kpis"], "summary has a non-empty kpis list")
    out = {}
    for k in s["kpis"]:
        check(set(k) == {"name", "value", "unit", "limits", "passed"} and
              set(k["limits"]) == {"min", "max"} and isinstance(k["passed"], bool),
              f"kpi {k.get('name')}: name, value, unit, limits {{min, max}}, passed")
        lo, hi, v = k["limits"]["min"], k["limits"]["max"], k["value"]
        within = v is not None and (lo is None or v >= lo) and (hi is None or v <= hi)
        check(k["passed"] == within, f"kpi {k['name']}: passed {k['passed']} = within limits")
        out[k["name"]] = k
    return out


def lsq_slope(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx


def vehicle_file(config):
    import tomllib
    path = os.path.join(os.path.dirname(config), tomllib.load(open(config, "rb"))["model"]["vehicle"])
    return tomllib.load(open(path, "rb"))


def case_weave_iso13674(s, rows):
    k = kpis_of(s)
    late = [r for r in rows if r["sim_time_s"] >= 7.0]
    ay_peak = max(abs(r["unit0_ay_mps2"]) for r in late)
    check(abs(ay_peak - 2.0) <= 0.2, f"a_y peak {ay_peak:.3f} m/s^2 (2 +- 0.2, ISO 13674-1 weave)")
    check(abs(k["ay_peak_mps2"]["value"] - ay_peak) < 1e-6, "kpi ay_peak_mps2 = the log's peak")
    v = [speed(r) for r in late]
    check(min(v) > 26.4 and max(v) < 29.2, f"speed {min(v) * 3.6:.1f}-{max(v) * 3.6:.1f} km/h "
          "(100 +- 5 %)")
    # Hand calculation: quasi-static pinion balance T_tb + T_a = F_rack r_p, the boost curve near
    # centre T_a = G T_tb, so T_tb = F_rack r_p / (1 + G) and dT/da_y = dF_rack/da_y r_p/(1 + G);
    # dF_rack/da_y from the logged rack force over the same band |a_y| <= 0.2 m/s^2.
    st = vehicle_file(config_path(NAME))["steering"]
    r_p, g = st["rack_per_pinion_m_per_rad"], st["assist_gain"]
    band = [r for r in late if abs(r["unit0_ay_mps2"]) <= 0.2]
    df_day = lsq_slope([r["unit0_ay_mps2"] for r in band], [r["rack_force_n"] for r in band])
    expected = abs(df_day) * r_p / (1.0 + g)
    grad0 = k["torque_gradient_at_0_mps2"]["value"]
    print(f"weave: dF_rack/da_y {df_day:.1f} N/(m/s^2), r_p {r_p} m/rad, G {g}: hand "
          f"{expected:.4f}, kpi {grad0:.4f} N m/(m/s^2); at 1 m/s^2 "
          f"{k['torque_gradient_at_1_mps2']['value']:.4f}; deadband "
          f"{k['torque_deadband_nm']['value']:.4f} N m; a_y hysteresis "
          f"{k['ay_hysteresis_mps2']['value']:.4f} m/s^2")
    check(abs(abs(grad0) - expected) <= 0.10 * expected,
          f"torque gradient at 0: |{grad0:.4f}| within 10 % of the hand {expected:.4f}")
    for name in ("torque_gradient_at_1_mps2", "torque_deadband_nm", "ay_hysteresis_mps2"):
        check(k[name]["value"] is not None and math.isfinite(k[name]["value"]), f"kpi {name} reported")


def bore_params(tire):
    """The tire's bore-torque table, None without one. ASSUMED key layout (the axis branch had
    not wired its keys yet): `bore = { stiffness_nmprad, damping_nmsprad, contact_width_m }` in
    [tires.X], or `bore_torque = true` with `contact_width_m` beside it; the lead aligns it."""
    b = tire.get("bore")
    if isinstance(b, dict):
        return b if b.get("enabled", True) else None
    if tire.get("bore_torque"):
        return {"contact_width_m": tire.get("contact_width_m", 0.2)}
    return None


def parking_hand_estimate(config, fz_front_n):
    """Peak rack force at stand-still, assist off, from the vehicle and maneuver files: both
    front tires' bore-torque maximum M_B,max = (2/3) R_P mu F_z (sliding at lock), R_P =
    (L/2 + B/2)/2, L = sqrt(8 r_0 F_z / c_z) (model/tire/tmeasy_bore.h), plus the jacking torque
    of the kingpin inclination ~ F_z (r_s + R tan KPI) sin(KPI) psi (steering_axis.h, small
    angles; the caster's terms cancel between equal loads), through the steering linkage at lock:
    the steer is asin(u / arm), so F_rack = M dgamma/du = M / (arm cos gamma). Returns (None,
    why) while the vehicle has no bore torque."""
    import tomllib
    veh = vehicle_file(config)
    mu = tomllib.load(open(config, "rb"))["model"].get("road_friction", 1.0)
    front = next(a for a in veh["axle"] if a.get("steered"))
    tire = veh["tires"][front["tire"]]
    bore = bore_params(tire)
    if bore is None:
        return None, f"[tires.{front['tire']}] has no bore torque (bore = {{...}} / bore_torque)"
    r0, cz = tire["radius_unloaded_m"], tire["vertical_stiffness_npm"]
    st = veh["steering"]
    arm = st["steering_arm_m"]
    u_lock = LOCK_RAD * st["rack_per_pinion_m_per_rad"]
    psi = math.asin(u_lock / arm)
    kpi, r_s = front.get("kingpin_inclination_rad", 0.0), front.get("scrub_radius_m", 0.0)
    total_nm = 0.0
    for fz in fz_front_n:
        length = math.sqrt(8.0 * r0 * fz / cz)
        r_p = 0.5 * (0.5 * length + 0.5 * bore["contact_width_m"])
        m_bore = 2.0 / 3.0 * r_p * mu * fz
        m_jack = fz * (r_s + r0 * math.tan(kpi)) * math.sin(kpi) * psi
        total_nm += m_bore + m_jack
        print(f"hand estimate, one wheel: F_z {fz:.0f} N, L {length * 1e3:.1f} mm, R_P "
              f"{r_p * 1e3:.1f} mm, M_B,max {m_bore:.1f} N m, jacking at {math.degrees(psi):.1f} deg "
              f"{m_jack:.1f} N m")
    return total_nm / (arm * math.cos(psi)), ""


LOCK_RAD = 9.42  # the maneuver's lock (1.5 turns)


def parking_peak(s, rows, name):
    k = kpis_of(s)
    peak = k["peak_rack_force_n"]["value"]
    logged = max(abs(r["rack_force_n"]) for r in rows if r["sim_time_s"] >= 1.0)
    check(abs(peak - logged) <= 1e-6 * max(1.0, logged), f"{name}: kpi peak {peak:.1f} N = the log's")
    hyst = k["rack_force_hysteresis_n"]["value"]
    check(hyst is not None and math.isfinite(hyst), f"{name}: hysteresis {hyst} N reported")
    lock = max(abs(r["steering_wheel_angle_rad"]) for r in rows)
    check(abs(lock - LOCK_RAD) < 0.3, f"{name}: the wheel reaches the lock ({lock:.2f} rad)")
    print(f"{name}: peak rack force {peak:.1f} N, hysteresis at the centre {hyst:.1f} N")
    return peak


def case_parking_effort(s, rows):
    check(max(speed(r) for r in rows) < 0.05, "stand-still throughout")
    peak = parking_peak(s, rows, "stand-still")
    fz = [at(rows, 1.0)["wheel0_tire_load_n"], at(rows, 1.0)["wheel1_tire_load_n"]]
    expected, missing = parking_hand_estimate(config_path(NAME), fz)
    if expected is None:
        print(f"NOT CHECKED (the model has no bore torque yet): {missing}")
        return
    check(abs(peak - expected) <= 0.15 * expected,
          f"peak {peak:.1f} N within 15 % of the hand estimate {expected:.1f} N")


def case_parking_effort_5kmh(s, rows):
    v = [speed(r) for r in rows if r["sim_time_s"] >= 1.0]
    check(min(v) > 3 / 3.6 and max(v) < 7 / 3.6, f"speed {min(v) * 3.6:.1f}-{max(v) * 3.6:.1f} km/h")
    peak = parking_peak(s, rows, "5 km/h")
    veh = vehicle_file(config_path(NAME))
    front = next(a for a in veh["axle"] if a.get("steered"))
    if bore_params(veh["tires"][front["tire"]]) is None:
        print("NOT CHECKED (the model has no bore torque yet): 5 km/h peak <= half the stand-still")
        return
    s0, rows0 = run_offline(config_path("parking-effort"))
    peak0 = kpis_of(s0)["peak_rack_force_n"]["value"]
    check(peak <= 0.5 * peak0, f"5 km/h peak {peak:.1f} N at most half the stand-still {peak0:.1f} N")


def case_returnability(s, rows):
    k = kpis_of(s)["returnability_residual"]
    a0, a3 = at(rows, 4.0)["steering_wheel_angle_rad"], at(rows, 7.0)["steering_wheel_angle_rad"]
    check(abs(a0 - math.pi / 2) < 0.05, f"the robot holds 90 deg until the release ({a0:.4f} rad)")
    v = [speed(r) for r in rows if r["sim_time_s"] >= 1.0]
    check(min(v) > 15 / 3.6 and max(v) < 25 / 3.6,
          f"speed {min(v) * 3.6:.1f}-{max(v) * 3.6:.1f} km/h (20 +- 5)")
    check(abs(k["value"] - abs(a3) / abs(a0)) < 1e-9, f"kpi {k['value']:.4f} = |{a3:.4f}| / |{a0:.4f}|")
    for t in (4.0, 4.5, 5.0, 6.0, 7.0, 8.0):
        r = at(rows, t)
        print(f"t {t:.1f} s: wheel {r['steering_wheel_angle_rad']:.4f} rad, torsion bar "
              f"{r['torsion_bar_torque_nm']:.3f} N m, rack force {r['rack_force_n']:.1f} N")
    check(k["value"] < 0.1, f"residual angle 3 s after the release {100 * k['value']:.1f} % (< 10 %)")
    passive = passive_returnability()
    print(f"without the EPS's active return (the tires' restoring moments against the rack "
          f"friction alone): residual {100 * passive:.1f} %")
    check(passive > k["value"], "the active return is what brings the wheel back")


def passive_returnability():
    """The same maneuver with the vehicle's active_return_* keys removed (a copy in TMP)."""
    import re
    import tomllib
    config = config_path(NAME)
    vehicle = os.path.normpath(os.path.join(os.path.dirname(config),
                                            tomllib.load(open(config, "rb"))["model"]["vehicle"]))
    text, removed = re.subn(r"(?m)^active_return_\w+ *=.*$", "", open(vehicle).read())
    check(removed >= 1, f"the passive copy drops the vehicle's {removed} active_return_* keys")
    copy = os.path.join(TMP, "vehicles", os.path.basename(vehicle))
    os.makedirs(os.path.dirname(copy), exist_ok=True)
    open(copy, "w").write(text)
    maneuver = os.path.join(TMP, "maneuvers", "returnability-passive.toml")
    os.makedirs(os.path.dirname(maneuver), exist_ok=True)
    open(maneuver, "w").write(open(config).read().replace(
        tomllib.load(open(config, "rb"))["model"]["vehicle"], "../vehicles/" + os.path.basename(vehicle)))
    s, _ = run_offline(maneuver)
    return kpis_of(s)["returnability_residual"]["value"]


def check_joint(rows, units=2):
    """Every logged step: the units are there and the joint holds (issue 7: |g| < 0.1 mm)."""
    check(all(r["num_units"] == units for r in rows), f"{units} units in every state")
    worst = max(r["joint0_violation_m"] for r in rows)
    check(worst < 1e-4, f"joint violation max {worst:.3g} m < 0.1 mm at every step")


def articulation_deg(r):
    d = r["unit0_yaw_rad"] - r["unit1_yaw_rad"]
    return math.degrees(math.remainder(d, 2 * math.pi))


def case_combination_car_trailer(s, rows):
    check_joint(rows)
    check_dlc(rows, 30.0, 16.67)
    peak = max(abs(articulation_deg(r)) for r in rows)
    check(2.0 < peak < 30.0, f"articulation through the lane change peaks at {peak:.1f} deg")
    check(speed(rows[-1]) < 0.05, "braked to stand-still")
    # Hitch force on the car (road x): the car pulls the trailer at 60 km/h (rolling resistance and
    # drag, a few hundred N backwards); while braking the trailer pushes (kN forwards).
    pull = at(rows, 10.0)["joint0_force_x_n"]
    check(-1000.0 < pull < -100.0, f"towing at 60 km/h: hitch force {pull:.0f} N (pulls back)")
    push = at(rows, 12.0)["joint0_force_x_n"]
    check(push > 1000.0, f"braking: hitch force {push:.0f} N (trailer pushes)")


def check_lane_change_and_stop(rows):
    """A semitrailer combination's lane change and braking: joint held, articulation, stopped."""
    check_joint(rows)
    peak = max(abs(articulation_deg(r)) for r in rows)
    check(2.0 < peak < 30.0, f"articulation through the lane change peaks at {peak:.1f} deg")
    check(speed(rows[-1]) < 0.05, "braked to stand-still")


def case_combination_tractor_semitrailer(s, rows):
    check_lane_change_and_stop(rows)
    kingpin = -at(rows, 1.0)["joint0_force_z_n"]
    check(80e3 < abs(kingpin) < 140e3, f"kingpin load {abs(kingpin) / 1e3:.1f} kN (static 110.5)")


def case_combination_tractor_semitrailer_40t(s, rows):
    # 40 t: the 6x4 tractor with cab, engine and seat, the loaded semitrailer's tridem equalised
    # (static loads: tests/model/combination/tractor_semitrailer_40t_test.cpp)
    check_lane_change_and_stop(rows)
    kingpin = -at(rows, 1.0)["joint0_force_z_n"]
    check(abs(kingpin / 105.85e3 - 1) < 0.05, f"kingpin load {kingpin / 1e3:.1f} kN (static 105.9)")
    # the cab rides the lane change off its stops; braking at ~6.7 m/s^2 pitches it onto them
    # (no fault: it does not go through them)
    lane = [r for r in rows if 1.0 < r["sim_time_s"] < 14.0]
    check(all(r["body0_on_stop"] == 0 for r in lane), "the cab stays off its stops, 1-14 s")
    on = [r["sim_time_s"] for r in rows if r["body0_on_stop"] != 0]
    print(f"cab on its stops {len(on)} ms of the run (braking from 14 s; the start)")


def case_combination_car_trailer_split_mu(s, rows):
    check_joint(rows)
    peak = max(abs(articulation_deg(r)) for r in rows)
    check(peak > 20.0, f"split-mu braking without ABS: jackknife tendency, {peak:.0f} deg")


def case_combination_car_towbar_car(s, rows):
    check_joint(rows)
    towing = [r["joint0_rod_force_n"] for r in rows if r["sim_time_s"] < 1.0]
    check(min(r["joint0_rod_force_n"] for r in rows) < -1000.0, "rod in compression while braking")
    check(max(towing) > 50.0, f"rod in tension while towing ({max(towing):.0f} N)")


# ---- issue 16: real roads (config/maneuvers/*: Belgian block, sine, ISO 8608, cleat, mu jumps)


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def correlation(a, b):
    ma, mb = sum(a) / len(a), sum(b) / len(b)
    cov = sum((x - ma) * (y - mb) for x, y in zip(a, b))
    return cov / math.sqrt(sum((x - ma) ** 2 for x in a) * sum((y - mb) ** 2 for y in b))


def wheels(rows):
    return int(rows[0]["num_wheels"])


def check_ride(rows, x_from, x_to, az_band, v_target):
    """On the rough stretch x_from..x_to of the CG: speed held, the body's vertical acceleration
    rms within az_band, the share of wheel-steps lifted off printed; the road seen under wheel 0."""
    on = [r for r in rows if x_from <= r["unit0_x_m"] <= x_to]
    check(len(on) > 500, f"{len(on)} steps on the rough stretch")
    v = [speed(r) for r in on]
    check(min(v) > 0.9 * v_target and max(v) < 1.1 * v_target,
          f"speed {min(v) * 3.6:.1f}-{max(v) * 3.6:.1f} km/h within 10 % of {v_target * 3.6:.0f}")
    az = rms([r["unit0_az_mps2"] for r in on])
    check(az_band[0] < az < az_band[1], f"body a_z rms {az:.3f} m/s^2 in {az_band}")
    n = wheels(rows)
    lifted = sum(1 for r in on for i in range(n) if r[f"wheel{i}_load_n"] <= 0) / (n * len(on))
    print(f"a wheel lifted off {100 * lifted:.2f} % of the wheel-steps on the stretch")
    z = [r["wheel0_road_z_m"] for r in on]
    check(max(z) - min(z) > 0.05, f"road under wheel 0 from {min(z):.4f} to {max(z):.4f} m")
    return az


def case_belgian_block_30kmh_sedan(s, rows):
    # the block from x = 5 to 15 m; CG from the front wheels' entry (1.2 m ahead) to the rear's
    # exit (1.6 m behind); tests/model/vehicle/road_ride_test.cpp: 2.46 m/s^2 at 30 km/h
    check_ride(rows, 3.8, 16.6, (1.5, 3.5), 8.333)


def case_belgian_block_30kmh_truck(s, rows):
    # axles 3.23 m ahead of and 1.95 m behind the CG; a 27 t truck shakes less than the sedan
    check_ride(rows, 1.8, 17.0, (0.5, 2.5), 8.333)


def case_sine_wave_road(s, rows):
    # 10 waves of 8 m from x = 10 m, 30 mm peak to peak: the road under the front-left wheel (its
    # static contact point ~1.2 m ahead of the CG) is the closed form within 0.5 mm
    worst = 0.0
    for r in rows:
        u = r["unit0_x_m"] + 1.2 - 10.0
        z = 0.015 * (1 - math.cos(2 * math.pi * u / 8.0)) if 0 <= u <= 80 else 0.0
        worst = max(worst, abs(r["wheel0_road_z_m"] - z))
    check(worst < 5e-4, f"road under wheel 0 = 0.015 (1 - cos(2 pi u / 8)) within {worst * 1e3:.3f} mm")
    on = [r for r in rows if 2.0 <= r["sim_time_s"] <= 5.0]
    heave = max(r["unit0_z_m"] for r in on) - min(r["unit0_z_m"] for r in on)
    pitch = max(r["unit0_pitch_rad"] for r in on) - min(r["unit0_pitch_rad"] for r in on)
    check(0.010 < heave < 0.045, f"body heave {heave * 1e3:.1f} mm peak to peak (road 30 mm)")
    check(0.005 < pitch < 0.06, f"body pitch {pitch:.4f} rad peak to peak")
    v = [speed(r) for r in rows]
    check(min(v) > 0.95 * 13.89, f"speed held ({min(v) * 3.6:.1f} km/h at least)")


def case_iso8608_class_c_80kmh(s, rows):
    on = [r for r in rows if r["sim_time_s"] >= 1.0]
    v = [speed(r) for r in on]
    check(min(v) > 0.95 * 22.22 and max(v) < 1.05 * 22.22,
          f"speed {min(v) * 3.6:.1f}-{max(v) * 3.6:.1f} km/h within 5 % of 80")
    left, right = [r["wheel0_road_z_m"] for r in on], [r["wheel1_road_z_m"] for r in on]
    mean = sum(left) / len(left)
    std = math.sqrt(sum((z - mean) ** 2 for z in left) / len(left))
    # class C over 0.011 cycles/m .. Nyquist: sqrt(integral G_d(n0) (n/n0)^-2 dn) ~ 15 mm on the
    # ~440 m driven (the longest waves are few)
    check(0.008 < std < 0.035, f"road under wheel 0: std {std * 1e3:.1f} mm (class C)")
    c = correlation(left, right)
    check(0.5 < c < 0.98, f"left and right tracks correlated but not equal ({c:.3f}): roll input")
    lag = round(2.8 / 22.22 / 0.001)  # the rear wheel follows the front one by wheelbase / v
    front, rear = [r["wheel0_road_z_m"] for r in rows], [r["wheel2_road_z_m"] for r in rows]
    c_fr = correlation(front[1000:-lag], rear[1000 + lag:])
    check(c_fr > 0.99, f"the rear wheel rolls over the front one's track ({c_fr:.5f})")
    az = rms([r["unit0_az_mps2"] for r in on])
    check(0.4 < az < 2.5, f"body a_z rms {az:.3f} m/s^2")
    roll = rms([r["unit0_wx_radps"] for r in on])
    check(roll > 0.01, f"roll rate rms {roll:.4f} rad/s (the tracks differ)")


def case_cleat_20mm(s, rows):
    static = rows[0]["wheel0_load_n"]
    peak = max(r["wheel0_load_n"] for r in rows)
    above = sum(1 for r in rows if r["wheel0_load_n"] > 1.2 * static)
    check(1.5 * static < peak < 4 * static,
          f"front-left F_z peak {peak:.0f} N over the static {static:.0f} N "
          "(road_ride_test: 8.8 kN at 40 km/h)")
    check(above >= 3, f"a force history, not a spike: {above} ms above 1.2 x static")
    road = max(r["wheel0_road_z_m"] for r in rows)
    check(0.009 < road <= 0.0201, f"the road under wheel 0 rises to {road * 1e3:.1f} mm (the "
          "probes' mean: 10 mm with both side probes on the 20 mm cleat)")
    check(min(speed(r) for r in rows) > 0.95 * 11.11, "speed held over the cleat")


def case_mu_jump_braking(s, rows):
    # dry until the front wheels reach x = 20 m (x_cg 18.8 m), wet (0.3) after
    dry = [r for r in rows if 0.9 <= r["sim_time_s"] and r["unit0_x_m"] < 18.0]
    wet = [r for r in rows if r["unit0_x_m"] > 22.0 and speed(r) > 1.0]
    check(all(r["wheel0_road_mu"] == 1.0 for r in dry) and all(
        r["wheel0_road_mu"] == 0.3 and r["wheel2_road_mu"] == 0.3 for r in wet),
        "wheel_road_mu 1 on the dry part, 0.3 on the wet")
    ax_dry = sum(r["unit0_ax_mps2"] for r in dry) / len(dry)
    ax_wet = sum(r["unit0_ax_mps2"] for r in wet) / len(wet)
    check(ax_dry < -5.0, f"braking on the dry road {ax_dry:.2f} m/s^2")
    # locked on the wet road: the sliding force; the sedan's F_S / F_z at mu 1 is ~1.1-1.2
    check(-0.3 * 9.81 * 1.4 < ax_wet < -0.3 * 9.81 * 0.8,
          f"sliding on the wet road {ax_wet:.2f} m/s^2 (0.3 g x the tires' sliding ratio)")
    check(all(r["wheel0_spin_radps"] == 0.0 for r in wet), "the front wheels lock on the low mu")
    check(speed(rows[-1]) < 0.01 and abs(rows[-1]["unit0_y_m"]) < 0.1, "stops on the x axis")


def case_mu_split_braking(s, rows):
    r1 = at(rows, 1.0)
    check(r1["wheel0_road_mu"] == 1.0 and r1["wheel1_road_mu"] == 0.3,
          "left wheels on mu 1, right wheels on 0.3")
    end = rows[-1]
    check(speed(end) < 0.01, "stand-still")
    check(end["unit0_yaw_rad"] > 0.03,
          f"yawed to the high-mu (left) side: {end['unit0_yaw_rad']:.4f} rad")
    held = max(abs(r["steering_wheel_angle_rad"]) for r in rows)
    check(held < 0.01, f"the wheel held straight by the robot (within {held:.4f} rad)")


def case_mu_split_acceleration_4x4(s, rows):
    r1 = at(rows, 1.0)
    check(r1["wheel0_road_mu"] == 1.0 and r1["wheel1_road_mu"] == 0.1, "right wheels on ice")
    check(r1["num_diffs"] == 3, f"centre, rear and front differentials: {r1['num_diffs']}")
    # the rear limited slip (diff1: 40 N m + |T_in| / 3 of the step's start) while it slips
    slipping = 0
    for prev, r in zip(rows, rows[1:]):
        if r["sim_time_s"] < 0.5 or r["diff1_locked"] != 0:
            continue
        t_in = prev["wheel2_drive_torque_nm"] + prev["wheel3_drive_torque_nm"]
        locking = 40.0 + abs(t_in) / 3.0
        diff = r["wheel2_drive_torque_nm"] - r["wheel3_drive_torque_nm"]
        check(abs(diff - locking) < 1e-6 * locking,
              f"t {r['sim_time_s']}: T_RL - T_RR {diff}, T_L {locking}")
        slipping += 1
    check(slipping > 1000, f"the rear clutch slips ({slipping} states)")
    r3, r5 = at(rows, 3.0), at(rows, 5.0)
    check(r3["diff0_locked"] == 0 and r5["diff0_locked"] == 1, "the driver's centre lock 4..6 s")
    check(r5["diff0_output_a_speed_radps"] == r5["diff0_output_b_speed_radps"],
          "the locked centre's outputs turn as one")
    check(speed(rows[-1]) > 10.0, f"accelerates on split mu: {speed(rows[-1]):.2f} m/s at 8 s")


def case_mu_split_acceleration_6x4(s, rows):
    r2 = at(rows, 2.0)
    check(r2["num_diffs"] == 3, "inter-axle and two axle differentials")
    t = [r2[f"wheel{i}_drive_torque_nm"] for i in range(2, 6)]
    check(max(t) - min(t) < 1e-9 * max(t), f"all open: the four drive wheels' torques equal {t}")
    check(r2["wheel5_spin_radps"] > 2 * r2["wheel4_spin_radps"], "a right-hand (ice) wheel spins")
    r4, r6 = at(rows, 4.0), at(rows, 6.0)
    check(r4["diff0_locked"] == 1 and r4["diff1_locked"] == 0, "the inter-axle lock from 3 s")
    check(all(r6[f"diff{j}_locked"] == 1 for j in range(3)), "every lock in from 5 s")
    check(speed(rows[-1]) > 2 * speed(r2), f"pulls away: {speed(r2):.2f} -> {speed(rows[-1]):.2f} m/s")


summary, states = run_offline(config_path(NAME))
# ---- issue 17 item 4: free bodies (model/vehicle/free_body/README.md)
def case_sine_steer_tractor_cab(s, rows):
    check(all(r["num_bodies"] == 3 for r in rows), "three free bodies: cab, engine, seat")
    late = [r for r in rows if 3.0 <= r["sim_time_s"] < 9.0]
    ay = max(abs(r["unit0_ay_mps2"]) for r in late)
    roll = max(abs(r["body0_roll_rad"]) for r in late)
    # the cab rolls against the frame: 0.02-0.03 rad at 0.9 m/s^2 (mounts 69 kN m/rad, the
    # frame's own roll and roll acceleration add to the lateral load at the cab's CG)
    check(0.6 < ay < 1.2, f"peak a_y {ay:.2f} m/s^2")
    check(0.01 < roll < 0.06, f"peak cab roll relative to the frame {roll:.4f} rad")
    check(all(r["body0_on_stop"] == 0 and r["body1_on_stop"] == 0 and r["body2_on_stop"] == 0
              for r in rows), "no body on its stops")
    seat = [r["body2_z_m"] for r in late]
    check(-0.105 < min(seat) and max(seat) < -0.09, "seat near its static sag 97 mm")


# ---- issue 17 item 5: frame torsion (model/vehicle/README.md "Frame torsion")
def case_circle_tractor_frame(s, rows):
    veh = vehicle_file(config_path(NAME))
    frame = veh["frame"]
    late = [r for r in rows if r["sim_time_s"] >= 15.0]
    ay = sum(r["unit0_ay_mps2"] for r in late) / len(late)
    check(2.2 < ay < 2.8, f"steady a_y {ay:.3f} m/s^2 (10 m/s on R = 40 m)")
    for r in late[::500]:
        moment = (frame["torsion_stiffness_nmprad"] * r["unit0_frame_twist_rad"] +
                  frame["torsion_damping_nmsprad"] * r["unit0_frame_twist_rate_radps"])
        check(abs(r["unit0_frame_torsion_moment_nm"] - moment) <= 1e-9 * abs(moment),
              f"torsion moment = k twist + c rate ({moment:.1f} N m)")
    twist = sum(r["unit0_frame_twist_rad"] for r in late) / len(late)
    # the front part (cab, engine on the soft front axle) rolls more than the rear: twist < 0
    check(-0.03 < twist < -0.005, f"steady twist {twist:.5f} rad")

    def roll_stiffness(a):  # the axle's suspension in series with its tires
        t2 = a["track_m"] ** 2
        susp = t2 * (0.5 * a["spring_stiffness_npm"] + a["anti_roll_stiffness_npm"])
        tire = 0.5 * veh["tires"][a["tire"]]["vertical_stiffness_npm"] * t2
        return susp * tire / (susp + tire)
    c = [roll_stiffness(a) for a in veh["axle"]]
    rigid_share = c[0] / sum(c)  # a rigid chassis shares its roll moment by roll stiffness
    moments = []
    for a, axle in enumerate(veh["axle"]):
        dl = sum(r[f"wheel{2 * a + 1}_load_n"] - r[f"wheel{2 * a}_load_n"] for r in late) / len(late)
        moments.append(0.5 * dl * axle["track_m"])
    share = moments[0] / sum(moments)
    print(f"front axle's share of the roll moment {share:.3f} (rigid chassis {rigid_share:.3f})")
    check(share > rigid_share + 0.15, "the soft frame keeps the front part's roll moment at the front")


def steady_braking(s, rows, after_s, min_states, mass_kg, wheels):
    """A leaf-braking maneuver's steady window (from after_s past the brake event's ramp until
    3 m/s) and its mean a_x, checked: the stop event ended the run, the window has more than
    min_states states, and a_x is within 5 % of the brake and drive torques at the rolling radii,
    sum T / (r_D m) (minus drag, the wheels' spin inertia). Returns (events, steady rows, a_x)."""
    check(s["stop_reason"] == "event", "the stop event ended the run")
    ev = {e["name"]: e["time_s"] for e in s["scenario_events"]}
    steady = [r for r in rows if r["sim_time_s"] > ev["brake"] + after_s and r["unit0_vx_mps"] > 3.0]
    check(len(steady) > min_states, f"{len(steady)} steady braking states")
    ax = sum(r["unit0_ax_mps2"] for r in steady) / len(steady)
    force = sum(sum((r[f"wheel{i}_brake_torque_nm"] + r[f"wheel{i}_drive_torque_nm"]) /
                    r[f"wheel{i}_rolling_radius_m"] for i in range(wheels)) for r in steady) / len(steady)
    check(abs(ax - force / mass_kg) < 0.05 * abs(ax),
          f"a_x {ax:.2f} m/s^2, sum T/r_D/m {force / mass_kg:.2f}")
    return ev, steady, ax


def case_braking_van_leaf(s, rows):
    # steady braking 0.5 s after the ramp until 3 m/s; m = 3500 kg
    ev, steady, ax = steady_braking(s, rows, 0.5, 2000, 3500.0, 4)
    # the rear axle winds up nose-down (+ about y) under the brake reaction: at most what the
    # moment alone gives the FE leaf (43.71 kN m/rad each), at least 60 % of it (the rear's
    # unloading takes some back; leaf_axle_test compares the superposition within 10 %)
    for r in steady[::250]:
        moment = -(r["wheel2_brake_torque_nm"] + r["wheel2_drive_torque_nm"])  # per leaf
        windup, alone = r["wheel2_leaf_windup_rad"], moment / 43711.8
        check(0.6 * alone < windup < alone, f"wind-up {windup * 1e3:.2f} mrad, M/k_w {alone * 1e3:.2f}")
        check(r["wheel2_leaf_windup_rad"] == r["wheel3_leaf_windup_rad"], "one axle: one wind-up")
        check(abs(r["wheel2_leaf_fore_aft_m"]) < 0.005, "the axle moves mm fore-aft")
    # the front axle has no leaves; each rear leaf at most 3 evaluations x 4 Newton iterations
    check(all(r["wheel0_leaf_windup_rad"] == 0 and r["wheel0_leaf_iterations"] == 0 for r in rows),
          "no leaf on the front axle")
    most = max(max(r["wheel2_leaf_iterations"], r["wheel3_leaf_iterations"]) for r in rows)
    check(most <= 12, f"at most {most} leaf Newton iterations per step")


def case_braking_tractor_leaf(s, rows):
    # steady braking 0.8 s after the ramp until 3 m/s; m = 8950 kg (the tractor with cab, engine
    # and seat)
    ev, steady, ax = steady_braking(s, rows, 0.8, 1000, 8950.0, 6)
    # the load moves to the steer axle: m a_x h_CG / wheelbase (8.95 t, CG ~1.1 m over the
    # road, 3.6 m to the tandem centre) within 30 % (the frame's pitch, the cab's lag)
    before = at(rows, ev["brake"] - 0.1)
    front = lambda r: r["wheel0_load_n"] + r["wheel1_load_n"]
    gain = sum(front(r) for r in steady) / len(steady) - front(before)
    transfer = 8950.0 * -ax * 1.1 / 3.6
    check(abs(gain - transfer) < 0.3 * transfer, f"steer axle +{gain:.0f} N, m a h / l {transfer:.0f} N")
    # the steer leaf winds up nose-down (+ about y) under its brake reaction (FE wind-up
    # stiffness 159.6 kN m/rad per leaf) within 50 % of M / k_w (the braking force at the axle
    # centre, 0.10 m under the leaf, winds it further; the heavier load changes it a bit)
    axle2 = lambda r: r["wheel2_load_n"] + r["wheel3_load_n"]
    axle3 = lambda r: r["wheel4_load_n"] + r["wheel5_load_n"]
    for r in steady[::250]:
        moment = -(r["wheel0_brake_torque_nm"] + r["wheel0_drive_torque_nm"])
        windup, alone = r["wheel0_leaf_windup_rad"], moment / 159600.0
        check(0.5 * alone < windup < 1.5 * alone, f"steer wind-up {windup * 1e3:.2f} mrad, M/k_w {alone * 1e3:.2f}")
    # the tandem on its leaf balance with torque rods (config/vehicles/tractor-6x4-leaf.toml):
    # the rods take the brake reactions, the rockers keep the four leaves' loads equal - both
    # axles keep their load (without the rocker the last one lifted off): on average within 1 %
    # of each other; the rocker mode (the axles' differential heave on the tires, damped by the
    # axles' dampers) rings for ~1 s after the brakes come on: each sample within 5 %
    settled = [r for r in steady if r["sim_time_s"] > ev["brake"] + 1.2]
    mean2 = sum(axle2(r) for r in settled) / len(settled)
    mean3 = sum(axle3(r) for r in settled) / len(settled)
    check(abs(mean3 - mean2) < 0.01 * mean2, f"tandem while braking {mean2:.0f} / {mean3:.0f} N")
    for r in settled[::250]:
        check(abs(axle3(r) - axle2(r)) < 0.05 * axle2(r) and axle3(r) > 0.5 * axle3(before),
              f"tandem {axle2(r):.0f} / {axle3(r):.0f} N (before {axle2(before):.0f} / {axle3(before):.0f})")
        # the rocker turns by the axles' heave difference over its 0.1425 m arm (the leaves
        # deflect alike, the pin and the eye take up the difference; the frame's nose-down pitch
        # makes it), both sides alike
        dh = (r["wheel2_axle_heave_m"] - r["wheel4_axle_heave_m"]) - \
             (before["wheel2_axle_heave_m"] - before["wheel4_axle_heave_m"])
        turned = r["wheel2_leaf_rocker_rad"] - before["wheel2_leaf_rocker_rad"]
        check(abs(turned - dh / 0.1425) < 0.1 * abs(dh / 0.1425) + 1e-4,
              f"rocker turned {turned * 1e3:.2f} mrad, (dh_1 - dh_2) / a {dh / 0.1425 * 1e3:.2f}")
        check(r["wheel2_leaf_rocker_rad"] == r["wheel4_leaf_rocker_rad"], "one rocker per side")
        # with no housing moment on them the axles turn with their leaves, which the rocker
        # turns by a beta / L_h (0.1425 m over the eye-to-pin 1.065 m), both alike
        for w in (2, 4):
            turn = 0.1425 / 1.065 * turned
            windup = r[f"wheel{w}_leaf_windup_rad"] - before[f"wheel{w}_leaf_windup_rad"]
            check(abs(windup - turn) < 0.25 * abs(turn) + 1e-4,
                  f"tandem axle wind-up {windup * 1e3:.2f} mrad, a beta / L_h {turn * 1e3:.2f}")
    most = max(max(r[f"wheel{i}_leaf_iterations"] for i in range(6)) for r in rows)
    check(most <= 12, f"at most {most} leaf Newton iterations per step")


case = globals().get("case_" + NAME.replace("-", "_"))  # combination-x-y: case_combination_x_y
if case is None:
    fail(f"no physical check for {NAME}: add case_{NAME.replace('-', '_')} to {__file__}")
case(summary, states)
shutil.rmtree(TMP, ignore_errors=True)  # /tmp fills up; a failure keeps its log for a look
print("PASS", NAME)
