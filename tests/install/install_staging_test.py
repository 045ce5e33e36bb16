#!/usr/bin/python3
"""The staging install (issue 14, item 4): `cmake --install` of the existing build into a
DESTDIR stage, for --prefix /usr and /opt/rig, and what the installed service needs.

For each prefix: the staged unit's ExecStart binary, its --config file and its Documentation=
file exist in the stage; `systemd-analyze verify` of the staged unit exits 0 with an empty
stderr; `systemd-analyze security --offline=true --threshold=30` exits 0 and rates it at most
3.0 (both by unit name under --root=STAGE; the /opt unit linked into STAGE/etc/systemd/system
as `systemctl link` does); the udev rule holds exactly the cpu_dma_latency line; no vcan file
is installed; the staged `rig check` accepts the staged configuration. Then `--component vcan` installs the four vcan
files and nothing else. Everything offline: PID 1 need not be systemd.

    install_staging_test.py BUILD_DIR
"""
import os
import pathlib
import re
import shlex
import subprocess
import sys
import tempfile

UDEV_LINE = 'KERNEL=="cpu_dma_latency", GROUP="rig", MODE="0660"'
UDEV_RULE = "lib/udev/rules.d/60-rig-cpu-dma-latency.rules"
VCAN_FILES = {"vcan0.netdev", "vcan0.network", "vcan1.netdev", "vcan1.network"}
MAX_EXPOSURE = 3.0

failures: list[str] = []


def expect(ok: bool, what: str) -> None:
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(cmd: list[str], **kw) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def install(build: str, stage: pathlib.Path, prefix: str, component: str | None = None) -> None:
    cmd = ["cmake", "--install", build, "--prefix", prefix]
    if component:
        cmd += ["--component", component]
    r = run(cmd, env=dict(os.environ, DESTDIR=str(stage)))
    expect(r.returncode == 0, f"{' '.join(cmd)} (DESTDIR={stage}) exits 0: {r.stderr.strip()}")


def staged(stage: pathlib.Path, path: str) -> pathlib.Path:
    return stage / path.lstrip("/")


def unit_entries(unit: pathlib.Path) -> dict[str, str]:
    entries = {}
    for line in unit.read_text().splitlines():
        if "=" in line and not line.startswith(("#", "[")):
            key, value = line.split("=", 1)
            entries.setdefault(key.strip(), value.strip())
    return entries


def check_unit_paths(stage: pathlib.Path, unit: pathlib.Path, prefix: str) -> str:
    """Returns the staged configuration's absolute (installed) path."""
    e = unit_entries(unit)
    argv = shlex.split(e["ExecStart"])
    expect(argv[0] == f"{prefix.rstrip('/')}/bin/rig", f"ExecStart runs {prefix}/bin/rig: {argv[0]}")
    expect(os.access(staged(stage, argv[0]), os.X_OK), f"ExecStart binary {argv[0]} is in the stage")
    config = argv[argv.index("--config") + 1]
    expect(staged(stage, config).is_file(), f"--config {config} is in the stage")
    doc = e["Documentation"]
    expect(doc.startswith("file:/"), f"Documentation= is an installed file: {doc}")
    expect(staged(stage, doc[len("file:"):]).is_file(), f"Documentation= {doc} is in the stage")
    expect("/dev/cpu_dma_latency rw" == e.get("DeviceAllow"), "DeviceAllow=/dev/cpu_dma_latency rw")
    return config


# Where systemd looks for units (under --root): the unit of a prefix outside these is linked
# into /etc/systemd/system, as `systemctl link` does (README "Installing as a service").
UNIT_PATH = ["/etc/systemd/system", "/usr/local/lib/systemd/system", "/usr/lib/systemd/system",
             "/lib/systemd/system"]


def link_unit(stage: pathlib.Path, unit_path: str) -> None:
    if str(pathlib.PurePath(unit_path).parent) in UNIT_PATH:
        return
    link = staged(stage, "/etc/systemd/system/rig.service")
    link.parent.mkdir(parents=True, exist_ok=True)
    # Relative, so that it resolves inside the stage (systemctl link writes an absolute one).
    link.symlink_to(os.path.relpath(staged(stage, unit_path), link.parent))
    print(f"     linked {unit_path} as /etc/systemd/system/rig.service (systemctl link)")


def check_systemd_analyze(stage: pathlib.Path, unit: pathlib.Path) -> None:
    # verify exits 0 on many errors: first prove that it reports a bad key on stderr here.
    bad = staged(stage, "/etc/systemd/system/rig-bad.service")
    bad.parent.mkdir(parents=True, exist_ok=True)
    bad.write_text(unit.read_text().replace("[Service]\n", "[Service]\nBogusKey=1\n", 1))
    r = run(["systemd-analyze", "verify", f"--root={stage}", "--recursive-errors=no",
             "rig-bad.service"])
    bad.unlink()
    expect("BogusKey" in r.stderr, "systemd-analyze verify reports a bad key on stderr")
    r = run(["systemd-analyze", "verify", f"--root={stage}", "--recursive-errors=no",
             "rig.service"])
    expect(r.returncode == 0 and r.stderr == "",
           f"systemd-analyze verify exits 0 ({r.returncode}) with empty stderr: {r.stderr!r}")
    r = run(["systemd-analyze", "security", "--offline=true", "--threshold=30", f"--root={stage}",
             "rig.service"])
    m = re.search(r"Overall exposure level for \S+: (\d+\.\d+) (\w+)", r.stdout)
    level = float(m.group(1)) if m else 99.0
    print(f"     systemd-analyze security: {m.group(0) if m else r.stdout[-300:]}")
    expect(r.returncode == 0 and level <= MAX_EXPOSURE and r.stderr == "",
           f"systemd-analyze security exits 0 ({r.returncode}), exposure {level} <= {MAX_EXPOSURE}"
           f"{', stderr: ' + r.stderr.strip() if r.stderr else ''}")


def check_prefix(build: str, prefix: str) -> None:
    print(f"--- prefix {prefix}")
    with tempfile.TemporaryDirectory(prefix="rig-stage-") as tmp:
        stage = pathlib.Path(tmp)
        install(build, stage, prefix)
        unit_path = f"{prefix.rstrip('/')}/lib/systemd/system/rig.service"
        unit = staged(stage, unit_path)
        expect(unit.is_file(), f"unit {unit_path} installed")
        if not unit.is_file():
            return
        config = check_unit_paths(stage, unit, prefix)
        link_unit(stage, unit_path)
        check_systemd_analyze(stage, unit)
        rule = staged(stage, f"{prefix}/{UDEV_RULE}")
        lines = [l for l in rule.read_text().splitlines() if l and not l.startswith("#")] \
            if rule.is_file() else []
        expect(lines == [UDEV_LINE], f"udev rule {UDEV_RULE} holds exactly {UDEV_LINE}: {lines}")
        vcan = [p.name for p in stage.rglob("vcan*")]
        expect(vcan == [], f"no vcan file without the component: {vcan}")
        rig = staged(stage, f"{prefix}/bin/rig")
        r = run([str(rig), "check", str(staged(stage, config))])
        print("     " + (r.stdout + r.stderr).strip().replace("\n", "\n     "))
        expect(r.returncode == 0 and ": run-config: OK" in r.stdout,
               f"staged rig check of the staged {config} passes ({r.returncode})")
        expect("duration_s = 0.0" in staged(stage, config).read_text(),
               f"{config} is the bench configuration (runs until stopped)")


def check_vcan_component(build: str) -> None:
    print("--- component vcan")
    with tempfile.TemporaryDirectory(prefix="rig-stage-vcan-") as tmp:
        stage = pathlib.Path(tmp)
        install(build, stage, "/usr", component="vcan")
        files = {p.relative_to(stage).as_posix() for p in stage.rglob("*") if p.is_file()}
        expect(files == {f"usr/lib/systemd/network/{f}" for f in VCAN_FILES},
               f"--component vcan installs the vcan netdevs/networks only: {sorted(files)}")


def main() -> int:
    build = sys.argv[1]
    for prefix in ["/usr", "/opt/rig"]:
        check_prefix(build, prefix)
    check_vcan_component(build)
    print(f"install_staging: {len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
