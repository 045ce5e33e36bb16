#!/usr/bin/python3
"""The bad-input suite (issue 13): runs every case in tests/robustness/cases/NAME/.

A case is a folder with its inputs, a `case.toml` (what to run) and an `expect.toml` (the exact
outcome). Each case runs in a fresh copy of its folder (the working directory), so it may write
anything there.

case.toml:
  description = "what the hostile input is"
  args = ["run", "--config", "config.toml", "--offline"]   # arguments of `rig` ...
  command = "..."          # ... or a bash command ($RIG, $BIN, $REPO, $CASE_DIR are set)
  needs = ["vcan"]         # optional: "vcan" (run by the vcan suite), "root", "unshare"
  timeout_s = 30           # optional; a case that exceeds it fails as a hang
  signal = "SIGHUP"        # optional: sent to the process group after `signal_after`
  signal_after = "start"   # "start" (the first "start" event in events.jsonl) or seconds
  stdin = "null"           # optional: "null" (default) or "pipe" (never written)

expect.toml:
  exit = 2                                  # the exit status (required)
  stderr_contains = ["config.toml:3", "period_s"]   # substrings, in any order
  stderr_not_contains = ["Segmentation"]
  stdout_contains = [...]
  event = "vehicle_fault"                   # or a list: events in any *.jsonl of the work dir
  no_event = [...]
  files_exist = ["out.log.1"]               # paths relative to the work dir
  files_absent = [...]
  json_valid = ["summary.json"]             # must parse as strict JSON (no NaN/inf)
  check = "check.py"                        # optional script run after (cwd = work dir), exit 0;
                                            # it may import case_checks (this folder)

Every case also fails on a death by signal that `exit` does not name (exit = -11 would name
SIGSEGV) and on a sanitizer report in stderr.

Usage: run_cases.py --bin BIN_DIR --repo REPO [--needs vcan|--skip-needs vcan] [--only NAME...]
                    [--min-cases N] [--list]
"""
import argparse
import json
import os
import shutil
import signal as signals
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

HERE = Path(__file__).resolve().parent
CASES = HERE / "cases"


def load_toml(path):
    with open(path, "rb") as f:
        return tomllib.load(f)


def as_list(value):
    if value is None:
        return []
    return value if isinstance(value, list) else [value]


def events_in(work):
    names = []
    for path in sorted(work.rglob("*.jsonl")):
        for line in path.read_text(errors="replace").splitlines():
            try:
                record = json.loads(line)
            except json.JSONDecodeError:
                continue
            if isinstance(record, dict) and "event" in record:
                names.append(record["event"])
    return names


def wait_for_start(work, proc, deadline):
    while time.monotonic() < deadline and proc.poll() is None:
        if "start" in events_in(work):
            return True
        time.sleep(0.01)
    return False


def launch(case, work, env, bin_dir):
    rig = str(bin_dir / "rig")
    if "command" in case:
        argv = ["bash", "-c", case["command"]]
    else:
        argv = [rig] + [str(a) for a in case["args"]]
    stdin = subprocess.PIPE if case.get("stdin") == "pipe" else subprocess.DEVNULL
    return subprocess.Popen(argv, cwd=work, env=env, stdin=stdin, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True, text=True,
                            errors="replace")


def run_case(name, src, bin_dir, repo):
    case = load_toml(src / "case.toml")
    expect = load_toml(src / "expect.toml")
    problems = []
    with tempfile.TemporaryDirectory(prefix=f"rig-robust-{name}-") as tmp:
        work = Path(tmp) / "case"
        shutil.copytree(src, work, symlinks=True)
        env = dict(os.environ, RIG=str(bin_dir / "rig"), BIN=str(bin_dir), REPO=str(repo),
                   CASE_DIR=str(src))
        timeout = float(case.get("timeout_s", 30))
        t0 = time.monotonic()
        proc = launch(case, work, env, bin_dir)
        if "signal" in case:
            after = case.get("signal_after", "start")
            if after == "start":
                if not wait_for_start(work, proc, t0 + timeout):
                    problems.append("no start event before the signal")
            else:
                time.sleep(float(after))
            try:
                os.killpg(proc.pid, getattr(signals, case["signal"]))
            except ProcessLookupError:
                problems.append("the process was gone before the signal")
        try:
            out, err = proc.communicate(timeout=max(0.1, t0 + timeout - time.monotonic()))
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signals.SIGKILL)
            out, err = proc.communicate()
            problems.append(f"hang: still running after {timeout:g} s")
        rc = proc.returncode
        problems += judge(expect, rc, out, err, work)
        if problems:
            tail = "\n".join(err.splitlines()[-15:])
            problems.append(f"exit {rc}; stderr (last lines):\n{tail}")
    return problems


def judge(expect, rc, out, err, work):
    problems = []
    if rc != expect["exit"]:
        problems.append(f"exit {rc}, expected {expect['exit']}")
    if rc < 0 and rc != expect["exit"]:
        problems.append(f"killed by signal {-rc}")
    for bad in ("AddressSanitizer", "UndefinedBehaviorSanitizer", "runtime error:"):
        if bad in err:
            problems.append(f"sanitizer report ({bad})")
    for text in as_list(expect.get("stderr_contains")):
        if text not in err:
            problems.append(f"stderr lacks {text!r}")
    for text in as_list(expect.get("stderr_not_contains")):
        if text in err:
            problems.append(f"stderr has {text!r}")
    for text in as_list(expect.get("stdout_contains")):
        if text not in out:
            problems.append(f"stdout lacks {text!r}")
    events = events_in(work)
    for name in as_list(expect.get("event")):
        if name not in events:
            problems.append(f"no event {name!r} (events: {sorted(set(events))})")
    for name in as_list(expect.get("no_event")):
        if name in events:
            problems.append(f"unexpected event {name!r}")
    for rel in as_list(expect.get("files_exist")):
        if not (work / rel).exists():
            problems.append(f"missing file {rel}")
    for rel in as_list(expect.get("files_absent")):
        if (work / rel).exists() or (work / rel).is_symlink():
            problems.append(f"file {rel} should not exist")
    for rel in as_list(expect.get("json_valid")):
        try:
            json.loads((work / rel).read_text(),
                       parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
        except (OSError, ValueError) as e:
            problems.append(f"{rel} is not valid JSON: {e}")
    if "check" in expect:
        env = dict(os.environ, PYTHONPATH=str(HERE))  # case_checks.py, shared by the checks
        check = subprocess.run(["/usr/bin/python3", str(work / expect["check"])], cwd=work,
                               env=env, capture_output=True, text=True, timeout=60)
        if check.returncode != 0:
            problems.append(f"check failed: {check.stdout}{check.stderr}".strip())
    return problems


def selected(args):
    names = []
    for src in sorted(p for p in CASES.iterdir() if (p / "case.toml").exists()):
        needs = set(as_list(load_toml(src / "case.toml").get("needs")))
        if args.only and src.name not in args.only:
            continue
        if args.needs and args.needs not in needs:
            continue
        if args.skip_needs and args.skip_needs in needs:
            continue
        names.append(src)
    return names


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", type=Path, required=True)
    parser.add_argument("--repo", type=Path, default=HERE.parent.parent)
    parser.add_argument("--needs")
    parser.add_argument("--skip-needs")
    parser.add_argument("--only", nargs="*")
    parser.add_argument("--min-cases", type=int, default=0)
    parser.add_argument("--list", action="store_true")
    args = parser.parse_args()
    cases = selected(args)
    if args.list:
        for src in cases:
            print(f"{src.name}: {load_toml(src / 'case.toml').get('description', '')}")
        return 0
    if len(cases) < args.min_cases:
        print(f"only {len(cases)} cases, expected at least {args.min_cases}")
        return 1
    failed = 0
    t0 = time.monotonic()
    for src in cases:
        started = time.monotonic()
        problems = run_case(src.name, src, args.bin.resolve(), args.repo.resolve())
        status = "FAIL" if problems else "ok"
        print(f"[{status:4}] {src.name} ({time.monotonic() - started:.1f} s)", flush=True)
        for p in problems:
            print("       " + p.replace("\n", "\n       "))
        failed += bool(problems)
    print(f"{len(cases) - failed}/{len(cases)} cases passed in {time.monotonic() - t0:.0f} s")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
