#!/usr/bin/python3
"""End-to-end tests of the `rig` executable: rig_cli_test.py RIG_BINARY SOURCE_DIR CASE.

Cases: offline, offline_complete, realtime, sigterm, notify, badconfig, usage, check_kinds,
check_not_rig. No absolute timing is asserted (except that a 50 ms injected stall produces a gap
in the watchdog pings)."""

import json
import os
import re
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rig_checks import check, fail  # noqa: E402

RIG, SRC, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
CONFIG = os.path.join(SRC, "config", "rig.toml")
TMP = tempfile.mkdtemp(prefix="rig_cli_")
SUMMARY_KEYS = ["cycles", "deadline_misses", "sim_time_s", "wall_time_s", "lateness_ns", "compute_ns",
                "rt", "policy", "histogram", "can"]



def run(args, **kw):
    return subprocess.run([RIG] + args, capture_output=True, text=True, timeout=60, **kw)


def read_log(path):
    lines = open(path).read().splitlines()
    check(lines, "overrun log is empty")
    return [json.loads(line) for line in lines]  # every line must be valid JSON


def check_summary(summary):
    for key in SUMMARY_KEYS:
        check(key in summary, f"summary lacks key {key}")
    for key in ["p50", "p99", "p999", "max"]:
        check(key in summary["lateness_ns"] and key in summary["compute_ns"], f"missing {key}")
    q = summary["lateness_ns"]
    check(q["p50"] <= q["p99"] <= q["p999"] <= q["max"], f"quantiles not ordered: {q}")
    check(sum(b["count"] for b in summary["histogram"]["lateness_ns"]) == summary["cycles"],
          "histogram counts != cycles")
    check(summary["can"]["bus_state"] == "disabled", "no CAN configured, bus_state must be disabled")


def case_offline():
    outs = []
    for i in range(2):
        sj, log = f"{TMP}/s{i}.json", f"{TMP}/o{i}.jsonl"
        r = run(["run", "--config", CONFIG, "--offline", "--duration", "2", "--summary-json", sj,
                 "--overrun-log", log])
        check(r.returncode == 0, f"exit {r.returncode}: {r.stderr}")
        s = json.load(open(sj))
        check_summary(s)
        check(s["cycles"] == 2000, f"cycles {s['cycles']} != 2000")
        check(s["sim_time_s"] == 2.0, f"sim_time_s {s['sim_time_s']}")
        # The sedan demo after 2 s: the path driver holds 60 km/h up the 10 % grade on the straight
        # before the lane change (x < 55 m).
        v, x, y = (s["outputs"][k] for k in ("vehicle_speed_mps", "position_x_m", "position_y_m"))
        check(15.8 < v < 17.5, f"speed after 2 s {v}")
        check(30.0 < x < 35.0 and abs(y) < 0.01, f"position after 2 s {x}, {y}")
        del s["wall_time_s"]
        events = [{k: e[k] for k in e if k not in ("time", "monotonic_ns")} for e in read_log(log)]
        outs.append((s, events))
    check(outs[0] == outs[1], "two offline runs differ")


def lcm_channel_counts(path):
    """Events per channel of an LCM event log (sync word, event number, timestamp, lengths)."""
    data, pos, counts = open(path, "rb").read(), 0, {}
    while pos < len(data):
        sync, _, _, channel_len, data_len = struct.unpack_from(">IqqII", data, pos)
        check(sync == 0xEDA1DA01, f"bad LCM sync word at byte {pos}")
        pos += 28
        channel = data[pos:pos + channel_len].decode()
        counts[channel] = counts.get(channel, 0) + 1
        pos += channel_len + data_len
    return counts


def case_offline_complete():
    # An offline run ends once its last snapshot is written: every cycle is in the LCM log, for
    # runs shorter than half the snapshot ring, about one ring, and several rings.
    for steps in (1, 10, 300, 1000):
        log, sj = f"{TMP}/c{steps}.lcm", f"{TMP}/c{steps}.json"
        r = run(["run", "--config", CONFIG, "--offline", "--duration", str(steps / 1000),
                 "--lcm-url", "none", "--lcm-log", log, "--summary-json", sj])
        check(r.returncode == 0, f"{steps} steps: exit {r.returncode}: {r.stderr}")
        s = json.load(open(sj))
        check(s["cycles"] == steps and s["snapshots_dropped"] == 0, f"{steps} steps: {s['cycles']}")
        state = lcm_channel_counts(log).get("RIG_STATE", 0)
        check(state == steps, f"{steps} steps: {state} RIG_STATE events in the LCM log")


def case_realtime():
    sj, log = f"{TMP}/s.json", f"{TMP}/o.jsonl"
    r = run(["run", "--config", CONFIG, "--duration", "2", "--summary-json", sj, "--overrun-log", log])
    check(r.returncode == 0, f"exit {r.returncode}: {r.stderr}")
    s = json.load(open(sj))
    check_summary(s)
    check(0 < s["cycles"] <= 2000, f"cycles {s['cycles']}")
    check(s["wall_time_s"] > 1.9, f"wall time {s['wall_time_s']}")
    events = read_log(log)
    names = [e["event"] for e in events]
    check(names[0] == "start" and names[-1] == "stop", f"events {names[:3]}..{names[-2:]}")
    check(("rt_granted" in names) or ("rt_refused" in names), "RT outcome not logged")
    misses = [e for e in events if e["event"] == "deadline_miss"]
    check(len(misses) == s["deadline_misses"], f"{len(misses)} miss lines vs {s['deadline_misses']}")
    for m in misses:
        for k in ["time", "monotonic_ns", "cycle", "sim_time_s", "lateness_ns", "phase_ns", "compute_ns",
                  "total_ns", "consecutive_misses", "action"]:
            check(k in m, f"miss line lacks {k}: {m}")
    check("rig summary" in r.stderr, "no summary on stderr")


def case_sigterm():
    sj, log = f"{TMP}/s.json", f"{TMP}/o.jsonl"
    p = subprocess.Popen([RIG, "run", "--config", CONFIG, "--duration", "1000", "--summary-json", sj,
                          "--overrun-log", log], stderr=subprocess.PIPE, text=True)
    time.sleep(1.0)
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=20)
    check(p.returncode == 0, f"exit {p.returncode} after SIGTERM: {err}")
    s = json.load(open(sj))
    check_summary(s)
    check(s["stop_reason"] == "signal", f"stop_reason {s['stop_reason']}")
    events = read_log(log)
    check(events[-1]["event"] == "stop" and "reason signal" in events[-1]["detail"], f"last {events[-1]}")


def case_notify():
    sock_path = f"{TMP}/notify.sock"
    sock = socket.socket(socket.AF_UNIX, socket.SOCK_DGRAM)
    sock.bind(sock_path)
    sock.settimeout(0.2)
    env = dict(os.environ, NOTIFY_SOCKET=sock_path, WATCHDOG_USEC="20000")
    env.pop("WATCHDOG_PID", None)
    log, sj = f"{TMP}/o.jsonl", f"{TMP}/s.json"
    p = subprocess.Popen([RIG, "run", "--config", CONFIG, "--duration", "1.5", "--overrun-log", log,
                          "--summary-json", sj, "--inject-stall", "500:50"],
                         env=env, stderr=subprocess.PIPE, text=True)
    msgs = []
    while True:
        try:
            data = sock.recv(4096)
            msgs.append((time.monotonic(), data.decode()))
        except socket.timeout:
            if p.poll() is not None:
                break
    _, err = p.communicate(timeout=20)
    check(p.returncode == 0, f"exit {p.returncode}: {err}")
    texts = [m for _, m in msgs]
    check(texts and texts[0] == "READY=1", f"first message {texts[:1]}")
    check("STOPPING=1" in texts, "no STOPPING=1")
    check(any(t.startswith("STATUS=cycles") for t in texts), "no STATUS=")
    pings = [t for t, m in msgs if m == "WATCHDOG=1"]
    check(len(pings) >= 10, f"only {len(pings)} watchdog pings")
    check(texts.index("STOPPING=1") > texts.index("READY=1"), "STOPPING before READY")
    # The stall: in the overrun log, and the pings pause (the loop cannot advance for 50 ms).
    stall = [e for e in read_log(log) if e["event"] == "deadline_miss" and e["cycle"] == 500]
    check(stall and stall[0]["phase_ns"]["model"] >= 50_000_000, f"stall not logged: {stall}")
    gaps = [b - a for a, b in zip(pings, pings[1:])]
    check(max(gaps) >= 0.040, f"largest watchdog gap {max(gaps):.4f} s < 40 ms")
    check("watchdog ping withheld" in err, "withheld ping not reported")


def case_badconfig():
    cases = {
        "unknown_key.toml": ("[rig]\nperiod_s = 0.001\nperoid = 1\n", r":3: .*unknown key 'peroid'"),
        "period.toml": ("[rig]\nperiod_s = -1\n", r":2: .*must be > 0"),
        "policy.toml": ("[rig]\noverrun_policy = \"never\"\n", r":2: .*unknown value 'never'"),
        "malformed.toml": ("[rig\n", r":1:"),
    }
    for name, (text, pattern) in cases.items():
        path = f"{TMP}/{name}"
        open(path, "w").write(text)
        for args in (["run", "--config", path, "--offline", "--duration", "1"], ["check", path]):
            r = run(args)
            check(r.returncode == 2, f"{name} {args[0]}: exit {r.returncode}")
            check(re.search(re.escape(path) + pattern, r.stderr), f"{name}: stderr {r.stderr!r}")
    r = run(["run", "--config", f"{TMP}/missing.toml"])
    check(r.returncode == 2 and f"{TMP}/missing.toml" in r.stderr, f"missing file: {r.returncode} {r.stderr!r}")


def case_usage():
    check(run(["--version"]).returncode == 0, "--version")
    check(run(["run", "--help"]).returncode == 0, "run --help")
    check(run(["run"]).returncode == 2, "run without --config must exit 2")
    check(run(["frobnicate"]).returncode == 2, "unknown subcommand must exit 2")
    r = run(["check", CONFIG])
    check(r.returncode == 0, f"check of the default config: {r.stderr}")


# The kind every file under config/ must check as, by folder (and extension in config/can/). A new
# folder fails here until its kind is registered in rig/check.cpp and named here.
KIND_OF_FOLDER = {"": "run-config", "maneuvers": "run-config", "combinations": "combination",
                  "vehicles": "vehicle", "can/.toml": "can-mapping", "can/.dbc": "dbc",
                  "roads/.xodr": "opendrive", "roads/.crg": "crg", "sweeps": "sweep"}
KINDS = ["run-config", "combination", "vehicle", "can-mapping", "dbc", "crg", "opendrive",
         "leaf-spring", "sweep"]


def config_files():
    files = []
    for root, _, names in os.walk(os.path.join(SRC, "config")):
        for name in sorted(names):
            path = os.path.join(root, name)
            folder = os.path.relpath(root, os.path.join(SRC, "config"))
            folder = "" if folder == "." else folder
            key = folder if folder in KIND_OF_FOLDER else f"{folder}/{os.path.splitext(name)[1]}"
            check(key in KIND_OF_FOLDER, f"{path}: no expected kind for config/{folder}")
            files.append((path, KIND_OF_FOLDER[key]))
    check(len(files) >= 19, f"only {len(files)} files under config/")
    return sorted(files)


def case_check_kinds():
    files = config_files()
    for path, kind in files:
        for args in (["check", path], ["check", "--kind", kind, path]):
            r = run(args)
            check(r.returncode == 0, f"{args}: exit {r.returncode}: {r.stderr}")
            check(f"{path}: {kind}: OK\n" in r.stdout, f"{args}: stdout {r.stdout!r}")
    # All at once: one OK line each, in order.
    r = run(["check"] + [p for p, _ in files])
    check(r.returncode == 0, f"check of all files: exit {r.returncode}: {r.stderr}")
    oks = [line for line in r.stdout.splitlines() if line.endswith(": OK")]
    check(oks == [f"{p}: {k}: OK" for p, k in files], f"check of all files: {oks}")
    # A wrong --kind is a `file:line:` error, exit 2. A combination is a run configuration too.
    for path, kind in files:
        for wrong in KINDS:
            if wrong == kind or (kind, wrong) == ("combination", "run-config"):
                continue
            r = run(["check", "--kind", wrong, path])
            check(r.returncode == 2, f"{path} as {wrong}: exit {r.returncode}")
            check(re.search(re.escape(path) + r":\d+: ", r.stderr), f"{path} as {wrong}: {r.stderr!r}")
            check(": OK" not in r.stdout, f"{path} as {wrong}: {r.stdout!r}")
    r = run(["check", "--kind", "combination", CONFIG])
    check(re.search(re.escape(CONFIG) + r":\d+: \[model\] kind: is \"vehicle\", not \"combination\"",
                    r.stderr), f"rig.toml as combination: {r.stderr!r}")
    r = run(["check", "--kind", "road", CONFIG])
    check(r.returncode == 2 and "road not in" in r.stderr, f"unknown kind: {r.returncode} {r.stderr!r}")


def case_check_not_rig():
    files = {
        "pyproject.toml": b'[project]\nname = "x"\nversion = "1.0"\n[tool.black]\nline-length = 100\n',
        "notes.txt": b"hello\nthis is not a rig file\n",
        "blob.bin": bytes(range(256)) * 4,
        "empty.toml": b"",
        "data.json": b'{"model": {"kind": "vehicle"}}\n',
    }
    for name, data in files.items():
        path = f"{TMP}/{name}"
        open(path, "wb").write(data)
        r = run(["check", path])
        check(r.returncode == 2, f"{name}: exit {r.returncode}")
        check(r.stderr.startswith(f"{path}: not a rig file\n"), f"{name}: stderr {r.stderr!r}")
        for kind in KINDS:
            check(f"    {kind}: " in r.stderr, f"{name}: expected kinds not listed: {r.stderr!r}")
        check(r.stdout == "", f"{name}: stdout {r.stdout!r}")
    both = f"{TMP}/both.toml"
    open(both, "w").write("[rig]\nperiod_s = 0.001\n[chassis]\nmass_kg = 1\n")
    r = run(["check", both])
    check(r.returncode == 2 and "ambiguous: looks like run-config and vehicle" in r.stderr,
          f"ambiguous: {r.returncode} {r.stderr!r}")
    r = run(["check", CONFIG, f"{TMP}/notes.txt"])
    check(r.returncode == 2 and f"{CONFIG}: run-config: OK" in r.stdout, f"good + bad: {r.returncode}")


{"offline": case_offline, "offline_complete": case_offline_complete, "realtime": case_realtime,
 "sigterm": case_sigterm, "notify": case_notify, "badconfig": case_badconfig, "usage": case_usage,
 "check_kinds": case_check_kinds, "check_not_rig": case_check_not_rig}[CASE]()
print("PASS", CASE)
