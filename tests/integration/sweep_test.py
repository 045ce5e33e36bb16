#!/usr/bin/python3
"""`rig sweep` on this machine (issue 18, item 5).

Usage: sweep_test.py RIG_BINARY SOURCE_DIR CASE
CASE:
  matrix     a spec over maneuvers x roads x two [[vary]] keys x seeds: the runs are the product in
             the documented order with their ids; each DIR/runs/<id>/ holds its summary, JUnit
             XML, rig.log and status and nothing else (no logs without --keep-logs); each
             campaign.csv row holds what its run's summary says (the overrides applied, its
             KPIs); DIR/junit.xml has one <testsuite> per run (the JUnit schema's structure);
             the plots exist; two sweeps of the same spec give identical KPIs (deterministic);
             --collect writes the same campaign.csv again; --fail-on-kpi is exit 3
  keep_logs  --keep-logs: each run's LCM log, overrun log, CSVs and figures
  bad        a bad spec or value is exit 2 before any run (file:line; the run and value named);
             an --out holding an earlier sweep is exit 2
  stop       SIGTERM during a sweep of long runs: the running runs end cleanly ("interrupted"),
             the rest are "missing", campaign.csv has every row, exit 1
"""

import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from junit_schema import check_junit  # noqa: E402
from rig_checks import check, fail  # noqa: E402

RIG, SRC, CASE = sys.argv[1:4]
TMP = tempfile.mkdtemp(prefix=f"rig_sweep_{CASE}_")
MANEUVERS = os.path.abspath(os.path.join(SRC, "config", "maneuvers"))


def spec(text, name="spec.toml"):
    path = os.path.join(TMP, name)
    open(path, "w").write(text)
    return path


def sweep(spec_path, *args, timeout=600):
    r = subprocess.run([RIG, "sweep", spec_path, *args], capture_output=True, text=True, timeout=timeout)
    return r.returncode, r.stderr


def rows_of(out):
    return list(csv.DictReader(open(os.path.join(out, "campaign.csv"), newline="")))


MATRIX = f"""
name = "matrix"
maneuvers = ["{MANEUVERS}/step-steer-iso7401.toml", "{MANEUVERS}/double-lane-change-iso3888.toml"]
duration_s = 3.0
set = {{ "rig.keep_logs" = 0 }}
seeds = [7, 8]
seed_key = "rig.status_interval_s"     # a harmless key: the main branch has no random road yet

[[roads]]
name = "dry"
set = {{ model.road_friction = 1.0 }}

[[roads]]
name = "wet"
set = {{ model.road_friction = 0.5 }}

[[vary]]
key = "vehicle.chassis.mass_kg"
values = [1400, 1600.5]

[[vary]]
key = "kpi[0].unit"
values = ["1", "u"]
"""


def expected_order():
    """The product maneuvers x roads x vary[0] x vary[1] x seeds, the last fastest."""
    out = []
    for m in ("step-steer-iso7401", "double-lane-change-iso3888"):
        for road, mu in (("dry", "1.0"), ("wet", "0.5")):
            for mass in ("1400", "1600.5"):
                for unit in ("1", "u"):
                    for seed in ("7", "8"):
                        out.append((m, road, mu, mass, unit, seed))
    return out


def case_matrix():
    path = spec(MATRIX)
    out = os.path.join(TMP, "a")
    code, err = sweep(path, "--out", out, "--workers", "2")
    check(code == 0, f"exit {code}: {err[-800:]}")
    rows = rows_of(out)
    order = expected_order()
    check(len(rows) == len(order) == 32, f"{len(rows)} rows = 2 x 2 x 2 x 2 x 2")
    check([r["id"] for r in rows] == [f"{i:04d}" for i in range(32)], "ids 0000..0031 in order")
    header = list(rows[0].keys())
    check(header[:13] == ["id", "maneuver", "road", "seed", "vehicle.chassis.mass_kg", "kpi[0].unit",
                          "status", "exit_code", "stop_reason", "sim_time_s", "wall_time_s",
                          "kpis_failed", "error"], f"campaign.csv header {header[:13]}")
    for r, (m, road, mu, mass, unit, seed) in zip(rows, order):
        where = f"run {r['id']}"
        check((r["maneuver"], r["road"], r["seed"]) == (m, road, seed), f"{where}: axes {m} {road} {seed}")
        check(r["vehicle.chassis.mass_kg"] == mass and r["kpi[0].unit"] == unit,
              f"{where}: vary values {mass} {unit}")
        run = os.path.join(out, "runs", r["id"])
        check(sorted(os.listdir(run)) == ["junit.xml", "rig.log", "status.json", "summary.json"],
              f"{where}: only summary, junit, rig.log, status ({sorted(os.listdir(run))})")
        s = json.load(open(os.path.join(run, "summary.json")))
        want = ["rig.keep_logs=0", f"model.road_friction={mu}", f"vehicle.chassis.mass_kg={mass}",
                f'kpi[0].unit="{unit}"', f"rig.status_interval_s={seed}"]
        check(s["set"] == want, f"{where}: the run got --set {s['set']} ({want})")
        check(s["kpis"][0]["unit"] == unit, f"{where}: the string value reached the KPI's unit")
        check(s["offline"] and abs(s["sim_time_s"] - 3.0) < 2e-3, f"{where}: offline, 3 s")
        check(r["status"] == ("ok" if all(k["passed"] for k in s["kpis"]) else "kpi_failed") and r["exit_code"] == "0",
              f"{where}: status {r['status']}")
        for k in s["kpis"]:
            cell = r[k["name"]]
            check((cell == "" and k["value"] is None) or abs(float(cell) - k["value"]) <= 1e-8 * max(1, abs(k["value"])),
                  f"{where}: {k['name']} {cell} = the summary's {k['value']}")
            check(r[k["name"] + ".passed"] == ("" if k["value"] is None else "1" if k["passed"] else "0"),
                  f"{where}: {k['name']}.passed")
    # 3 s is too short for the lane change's track: its lanes_kept fails (0 of 3, min 3)
    dlc = [r for r in rows if r["maneuver"].startswith("double")]
    check(all(r["status"] == "kpi_failed" and r["lanes_kept"] == "0" for r in dlc),
          "every lane change of 3 s fails lanes_kept (the track is not through)")
    suites = check_junit(os.path.join(out, "junit.xml"))
    check([s.get("name") for s in suites] == [r["id"] for r in rows], "junit.xml: a <testsuite> per run")
    check(sum(int(s.get("failures")) for s in suites) == sum(int(r["kpis_failed"]) for r in rows),
          "junit failures = the campaign's failed KPIs")
    plots = sorted(os.listdir(os.path.join(out, "plots")))
    check("status.png" in plots and "kpi_lanes_kept.png" in plots and
          "kpi_yaw_rate_response_time_s.png" in plots, f"summary plots {plots}")
    # the same spec again: the same KPIs (deterministic offline runs)
    out2 = os.path.join(TMP, "b")
    code, _ = sweep(path, "--out", out2, "--workers", "1", "--no-plots")
    check(code == 0, "second sweep")
    strip = ("wall_time_s",)
    a = [{k: v for k, v in r.items() if k not in strip} for r in rows]
    b = [{k: v for k, v in r.items() if k not in strip} for r in rows_of(out2)]
    check(a == b, "a second sweep (one worker) gives the same campaign.csv but for wall times")
    # --collect writes it again from the runs' files
    before = open(os.path.join(out, "campaign.csv")).read()
    os.remove(os.path.join(out, "campaign.csv"))
    code, _ = sweep(path, "--out", out, "--collect", "--no-plots")
    check(code == 0 and open(os.path.join(out, "campaign.csv")).read() == before, "--collect: the same campaign.csv")
    code, _ = sweep(path, "--out", out, "--collect", "--no-plots", "--fail-on-kpi")
    check(code == 3, f"--fail-on-kpi with failed KPIs: exit {code} (3)")


def case_keep_logs():
    path = spec(f"""
base = "{MANEUVERS}/braking-100-0.toml"
[[vary]]
key = "event[0].do.set.brake_pressure_front_pa"
values = [6.0e6, 8.0e6]
""")
    out = os.path.join(TMP, "k")
    code, err = sweep(path, "--out", out, "--keep-logs")
    check(code == 0, f"exit {code}: {err[-500:]}")
    rows = rows_of(out)
    for r in rows:
        run = os.path.join(out, "runs", r["id"])
        names = set(os.listdir(run))
        check({"run.lcm", "overrun.jsonl", "csv", "figures", "summary.json"} <= names, f"{r['id']}: logs kept {names}")
        check(os.path.exists(os.path.join(run, "csv", "RIG_STATE.csv")) and
              os.path.exists(os.path.join(run, "figures", "trajectory.png")), f"{r['id']}: CSV and figures")
        check(r["stop_reason"] == "event", f"{r['id']}: the stop event ended it")
    d = [float(r["braking_distance_m"]) for r in rows]
    check(d[0] > d[1], f"60 bar brakes longer than 80 bar ({d[0]:.1f} > {d[1]:.1f} m)")


def case_bad():
    cases = (
        ("base = \"nowhere.toml\"\n", ["spec.toml:1:", "file not found"]),
        (f"base = \"{MANEUVERS}/step-steer-iso7401.toml\"\nworkers = 2\n", ["spec.toml:2:", "unknown key 'workers'"]),
        (f"base = \"{MANEUVERS}/step-steer-iso7401.toml\"\n[[vary]]\nkey = \"vehicle.chassis.mass_kg\"\nvalues = []\n",
         ["spec.toml:", "'values' is empty"]),
        (f"base = \"{MANEUVERS}/step-steer-iso7401.toml\"\n[[vary]]\nkey = \"mass_kg\"\nvalues = [1]\n",
         ["spec.toml:3:", "is not SECTION.KEY"]),
        (f"base = \"{MANEUVERS}/step-steer-iso7401.toml\"\n[[vary]]\nkey = \"vehicle.chassis.mass_kg\"\n"
         "values = [1500, 0, 1600]\n",
         ["rig sweep: run 0001 (step-steer-iso7401, vehicle.chassis.mass_kg=0)", "--set vehicle.chassis.mass_kg=0:",
          "out of range"]),
        (f"base = \"{MANEUVERS}/step-steer-iso7401.toml\"\n[[vary]]\nkey = \"vehicle.chassis.mas_kg\"\nvalues = [1]\n",
         ["run 0000", "unknown key 'mas_kg'"]),
        (f"maneuvers = [\"{MANEUVERS}/step-steer-iso7401.toml\", \"{MANEUVERS}/paper-quarter-car.toml\"]\n"
         "[[vary]]\nkey = \"vehicle.chassis.mass_kg\"\nvalues = [1500]\n",
         ["run 0001 (paper-quarter-car", "has no vehicle file"]),
    )
    for i, (text, words) in enumerate(cases):
        out = os.path.join(TMP, f"bad{i}")
        code, err = sweep(spec(text), "--out", out)
        check(code == 2 and all(w in err for w in words), f"bad spec {i}: exit {code}, {err.strip()!r}")
        check(not os.path.exists(os.path.join(out, "runs")), f"bad spec {i}: nothing ran")
    good = spec(f"base = \"{MANEUVERS}/step-steer-iso7401.toml\"\nduration_s = 0.5\n", "good.toml")
    out = os.path.join(TMP, "again")
    code, _ = sweep(good, "--out", out)
    check(code == 0, "a one-run sweep")
    code, err = sweep(good, "--out", out)
    check(code == 2 and "holds an earlier sweep" in err, f"the same --out again: exit {code}, {err.strip()!r}")


def case_stop():
    path = spec(f"""
base = "{MANEUVERS}/circle-iso4138.toml"
[[vary]]
key = "vehicle.chassis.mass_kg"
values = [{", ".join(str(1300 + 10 * i) for i in range(20))}]
""")
    out = os.path.join(TMP, "s")
    p = subprocess.Popen([RIG, "sweep", path, "--out", out, "--workers", "2", "--no-plots"],
                         stderr=subprocess.PIPE, text=True)
    while not os.path.exists(os.path.join(out, "runs", "0000", "rig.log")):
        time.sleep(0.05)
    time.sleep(0.5)
    p.send_signal(signal.SIGTERM)
    err = p.communicate(timeout=120)[1]
    check(p.returncode == 1, f"an interrupted sweep: exit {p.returncode}: {err[-400:]}")
    rows = rows_of(out)
    statuses = [r["status"] for r in rows]
    check(len(rows) == 20, "campaign.csv has every run")
    check("interrupted" in statuses and "missing" in statuses and set(statuses) <= {"ok", "kpi_failed", "interrupted", "missing"},
          f"statuses {statuses}")
    for r in rows:
        if r["status"] == "interrupted":
            s = json.load(open(os.path.join(out, "runs", r["id"], "summary.json")))
            check(s["stop_reason"] == "signal" and s["sim_time_s"] < 136, f"{r['id']}: stopped by the signal at {s['sim_time_s']} s")


{"matrix": case_matrix, "keep_logs": case_keep_logs, "bad": case_bad, "stop": case_stop}.get(
    CASE, lambda: fail(f"no case {CASE}"))()
shutil.rmtree(TMP, ignore_errors=True)
print("PASS", CASE)
