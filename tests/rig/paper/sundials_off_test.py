#!/usr/bin/python3
"""Without SUNDIALS the rig still configures and builds; rig-paper and what needs it are skipped.

usage: sundials_off_test.py SOURCE_DIR MAIN_BUILD_DIR OFF_BUILD_DIR [--full]

Configures SOURCE_DIR into OFF_BUILD_DIR with -DCMAKE_DISABLE_FIND_PACKAGE_SUNDIALS=ON (the build
type of MAIN_BUILD_DIR, tests and benchmarks on), then checks:
  - the configure step says SUNDIALS was not found, and no target of rig/paper (rig-paper,
    rig_paper_runs, rig_paper_reference) nor paper_test exists; no build line names SUNDIALS;
  - `rig` builds, and so does solver_bench (without its CVODE benchmark).
Building `rig` from scratch takes minutes here (more than the rest of the suite), so by default
the build is checked against the main build: every command `ninja -t commands` lists for the
target in OFF_BUILD_DIR must be one MAIN_BUILD_DIR ran (the same compiler command, up to the
build folder), except the target's own link, which is run here on the main build's objects
into OFF_BUILD_DIR/bin. The linked programs then run. Where a command differs, or with --full,
the target is built in OFF_BUILD_DIR by ninja instead.
"""
import pathlib
import re
import shlex
import subprocess
import sys
import time

SRC, MAIN, OFF = (pathlib.Path(p).resolve() for p in sys.argv[1:4])
FULL = "--full" in sys.argv[4:]
BENCHMARKS = None  # whether the main build (and so this one) builds benchmarks
PAPER_TARGETS = ["rig-paper", "rig_paper_runs", "rig_paper_reference", "paper_test"]


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        fail(f"{cmd if isinstance(cmd, str) else shlex.join(map(str, cmd))}: exit {r.returncode}\n"
             f"{r.stdout[-3000:]}{r.stderr[-3000:]}")
    return r.stdout


def cache_value(build_dir, key):
    m = re.search(rf"^{key}:\w+=(.*)$", (build_dir / "CMakeCache.txt").read_text(), re.M)
    return m.group(1) if m else ""


def configure():
    global BENCHMARKS
    build_type = cache_value(MAIN, "CMAKE_BUILD_TYPE") or "Release"
    BENCHMARKS = cache_value(MAIN, "RIG_BUILD_BENCHMARKS").upper() not in ("OFF", "0", "FALSE")
    out = run(["cmake", "-S", SRC, "-B", OFF, "-G", "Ninja", f"-DCMAKE_BUILD_TYPE={build_type}",
               "-DCMAKE_DISABLE_FIND_PACKAGE_SUNDIALS=ON", "-DRIG_BUILD_TESTS=ON",
               f"-DRIG_BUILD_BENCHMARKS={'ON' if BENCHMARKS else 'OFF'}"])
    if "SUNDIALS 6 (CVODE) not found" not in out:
        fail(f"configure did not report SUNDIALS as missing:\n{out[-2000:]}")
    targets = {line.split(":")[0] for line in run(["ninja", "-C", OFF, "-t", "targets", "all"])
               .splitlines()}
    for name in PAPER_TARGETS:
        if name in targets:
            fail(f"target {name} exists without SUNDIALS")
    for name in ["rig", "rig-log2csv", "lcm_test"] + (["solver_bench"] if BENCHMARKS else []):
        if name not in targets:
            fail(f"target {name} is missing without SUNDIALS")
    build_ninja = (OFF / "build.ninja").read_text().replace(str(OFF), "<build>")
    for text in ["libsundials", "cvode"]:
        if text in build_ninja:
            fail(f"{OFF}/build.ninja mentions {text}")
    tests = set(re.findall(r"Test +#\d+: (\S+)", run(["ctest", "--test-dir", OFF, "-N"])))
    # paper_test's cases are discovered when it is built: until then ctest lists a placeholder.
    if ("solver_bench_smoke" not in tests and BENCHMARKS) or "paper_test_NOT_BUILT" in tests:
        fail(f"ctest -N without SUNDIALS: {sorted(tests)}")


def commands(build_dir, target):
    out = run(["ninja", "-C", build_dir, "-t", "commands", target])
    return [line.replace(str(build_dir), "<build>") for line in out.splitlines()]


def build(target, output):
    """Builds `target` (bin/<output>) of OFF_BUILD_DIR, from the main build's objects if it can."""
    off, main = commands(OFF, target), set(commands(MAIN, target))
    *steps, link = off
    differ = [c for c in steps if c not in main]
    if FULL or differ:
        if differ:
            print(f"{target}: {len(differ)} commands differ from the main build's, e.g.\n  "
                  f"{differ[0][:300]}\nbuilding {target} here")
        run(["ninja", "-C", OFF, target])
        return
    if f"-o bin/{output} " not in link:
        fail(f"{target}: unexpected link command {link[:300]}")
    (OFF / "bin").mkdir(exist_ok=True)
    run(link.replace(f"-o bin/{output} ", f"-o {OFF}/bin/{output} ").replace("<build>", str(MAIN)),
        shell=True, cwd=MAIN)
    print(f"{target}: {len(steps)} commands as in the main build, linked into {OFF}/bin")


start = time.monotonic()
configure()
build("rig", "rig")
if "sundials" in run(["ldd", OFF / "bin" / "rig"]):
    fail("bin/rig is linked against SUNDIALS")
print(run([OFF / "bin" / "rig", "check", SRC / "config" / "rig.toml"]).strip())
if BENCHMARKS:
    build("solver_bench", "solver_bench")
    benchmarks = run([OFF / "bin" / "solver_bench", "--benchmark_list_tests"]).split()
    if "BM_PendulumDaeStep" not in benchmarks or "BM_PendulumCpuPerSimulatedSecond" in benchmarks:
        fail(f"solver_bench without SUNDIALS: {benchmarks}")
print(f"PASS: without SUNDIALS rig builds, rig-paper is skipped ({time.monotonic() - start:.1f} s)")
