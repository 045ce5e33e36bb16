#!/usr/bin/python3
"""`rig run --junit FILE`, `--fail-on-kpi` and `--set` end to end (issue 18, item 4).

Usage: kpi_junit_test.py RIG_BINARY SOURCE_DIR CASE
CASE:
  junit     the step steer with one KPI's limit tightened by --set: the JUnit XML has the shape of
            the (Ant) JUnit schema - checked element by element with xml.etree - one <testsuite>,
            one <testcase> per KPI of the summary, a <failure> exactly for each failed KPI
  exit      exit codes: a failed KPI is exit 0 without --fail-on-kpi and 3 with it; all passing
            is 0 with it; a run failure (a vehicle fault) stays 1 with it, its KPIs JUnit
            <error>s; a --junit path in a missing folder is 2 before the run
  set       --set changes the run (the sedan 300 kg heavier: a lower yaw gain, and the summary
            names the overrides); a key of the vehicle file through `vehicle.`; bad keys and
            values are exit 2 naming the --set
"""

import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from junit_schema import check_junit  # noqa: E402
from rig_checks import check, fail  # noqa: E402

RIG, SRC, CASE = sys.argv[1:4]
TMP = tempfile.mkdtemp(prefix=f"rig_kpi_junit_{CASE}_")
STEP = os.path.join(SRC, "config", "maneuvers", "step-steer-iso7401.toml")


def run(*args, config=STEP):
    r = subprocess.run([RIG, "run", "--config", config, "--offline", "--lcm-url", "none", *args],
                       capture_output=True, text=True, timeout=120)
    return r.returncode, r.stderr


def summary(path):
    return json.load(open(path))


def case_junit():
    xml, js = f"{TMP}/junit.xml", f"{TMP}/s.json"
    code, err = run("--set", "kpi[0].max=0.1", "--junit", xml, "--summary-json", js)
    check(code == 0, f"exit {code} (a failed KPI without --fail-on-kpi)")
    suites = check_junit(xml)
    check(len(suites) == 1, "one <testsuite> for the run")
    suite = suites[0]
    check(suite.get("name") == "step-steer-iso7401", f"suite named after the file ({suite.get('name')})")
    kpis = summary(js)["kpis"]
    cases = suite.findall("testcase")
    check([c.get("name") for c in cases] == [k["name"] for k in kpis],
          "one <testcase> per KPI of the summary, in order")
    for c, k in zip(cases, kpis):
        failed = c.find("failure") is not None
        check(failed == (not k["passed"]), f"{k['name']}: <failure> iff not passed")
        check(c.get("classname") == "rig.step-steer-iso7401", f"classname {c.get('classname')}")
    bad = [k for k in kpis if not k["passed"]]
    check(len(bad) == 1 and bad[0]["name"] == "yaw_rate_response_time_s", "the tightened KPI fails")
    msg = cases[0].find("failure").get("message")
    check(f"{bad[0]['value']:.9g}" in msg and "outside [-, 0.1]" in msg, f"failure message {msg!r}")
    props = {p.get("name"): p.get("value") for p in suite.find("properties")}
    check(props.get("set") == "kpi[0].max=0.1" and props.get("stop_reason") == "duration",
          f"properties name the --set and the stop ({props})")
    check("rig: kpi yaw_rate_response_time_s failed: " in err, "stderr names the failed KPI")


def case_exit():
    code, _ = run("--set", "kpi[0].max=0.1", "--fail-on-kpi")
    check(code == 3, f"a failed KPI with --fail-on-kpi: exit {code} (3)")
    code, _ = run("--fail-on-kpi")
    check(code == 0, f"every KPI within its limits with --fail-on-kpi: exit {code} (0)")
    # a vehicle fault (the speed limit below the run's 22 m/s) is a run failure: 1, not 3
    xml, js = f"{TMP}/fault.xml", f"{TMP}/fault.json"
    code, err = run("--set", "rig.fault_speed_limit_mps=10", "--set", "kpi[0].max=0.1",
                    "--fail-on-kpi", "--junit", xml, "--summary-json", js)
    check(code == 1, f"a vehicle fault with --fail-on-kpi: exit {code} (1)")
    check(summary(js)["exit_code"] == 1, "the summary's exit_code 1")
    suite = check_junit(xml)[0]
    check(int(suite.get("errors")) == int(suite.get("tests")) > 0 and suite.get("failures") == "0",
          "a failed run's KPIs are <error>s")
    check("vehicle fault" in suite.find("system-err").text, "system-err says why")
    code, err = run("--junit", f"{TMP}/nowhere/j.xml")
    check(code == 2 and "--junit" in err and "does not exist" in err, f"--junit in a missing folder: "
          f"exit {code}: {err.strip()}")


def case_set():
    base, heavy = f"{TMP}/base.json", f"{TMP}/heavy.json"
    code, _ = run("--summary-json", base)
    check(code == 0, "base run")
    code, _ = run("--set", "vehicle.chassis.mass_kg=1800", "--set", "rig.duration_s=5.5",
                  "--summary-json", heavy)
    check(code == 0, f"heavy run exit {code}")
    b, h = summary(base), summary(heavy)
    check(h["set"] == ["vehicle.chassis.mass_kg=1800", "rig.duration_s=5.5"] and h["config"] == STEP,
          f"the summary names the config and the overrides ({h['set']})")
    check(abs(h["sim_time_s"] - 5.5) < 2e-3, f"rig.duration_s=5.5 ran {h['sim_time_s']} s")
    gain = {s["name"]: s["value"] for s in b["kpis"]}["yaw_rate_gain_1ps"]
    gain_h = {s["name"]: s["value"] for s in h["kpis"]}["yaw_rate_gain_1ps"]
    # more mass at the same speed: more understeer, a lower steady yaw-rate gain
    check(gain_h < gain, f"heavier sedan: yaw gain {gain_h:.4f} < {gain:.4f} 1/s")
    for args, words in (
            (["--set", "vehicle.chassis.mass_kg=0"], ["--set vehicle.chassis.mass_kg=0:", "mass_kg",
                                                      "out of range"]),
            (["--set", "vehicle.chassis.mass=1500"], ["--set vehicle.chassis.mass=1500:",
                                                      "unknown key 'mass'"]),
            (["--set", "rig.duration_s=fast"], ["--set rig.duration_s=fast:", "expected a number"]),
            (["--set", "unit2.chassis.mass_kg=1"], ["has 1 unit"]),
            (["--set", "duration_s=1"], ["is not SECTION.KEY"]),
            (["--set", "vehicle.axle[2].track_m=1"], ["axle in", "has 2 entries"])):
        code, err = run(*args)
        check(code == 2 and all(w in err for w in words), f"{args}: exit {code}, {err.strip()!r}")


{"junit": case_junit, "exit": case_exit, "set": case_set}.get(CASE, lambda: fail(f"no case {CASE}"))()
print("PASS", CASE)
