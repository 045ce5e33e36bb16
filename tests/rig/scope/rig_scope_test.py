#!/usr/bin/python3
"""rig-scope in headless Chromium against replayed LCM logs (in a network namespace of its own):
two rigs, the sedan's demo (config/rig.toml, no prefix) and the car + trailer
(config/combinations/car-trailer.toml, its channels renamed to the prefix RIG2_), each run
offline for 4 s into an LCM log and replayed by Debian's lcm-logplayer at once. The page must
load and draw; after the replay every plotted signal's latest value, the data-value of its
data-signal element, must equal the last message of its channel in the log (read with
rig_lcm.read_log, rig-log2csv's columns): exactly, the JSON between carries doubles unchanged.
A screenshot of the whole page is written to OUTPNG.

usage: rig_scope_test.py BINDIR PYTHONDIR SOURCEDIR OUTPNG
"""
import json
import math
import pathlib
import struct
import subprocess
import sys
import tempfile
import time

BIN, PYTHON, SOURCE, OUTPNG = (pathlib.Path(a) for a in sys.argv[1:5])
sys.path.insert(0, str(PYTHON))
sys.path.insert(0, str(SOURCE / "tests" / "support"))
from netns import in_netns  # noqa: E402

import rig_lcm  # noqa: E402
from cdp import Chromium, chromium_path  # noqa: E402

RIGS = {"": "config/rig.toml", "RIG2_": "config/combinations/car-trailer.toml"}
# what each rig's page must show at least (besides the status and CAN tables)
MUST_SHOW = ["RIG_STATE.unit0_vx_mps", "RIG_STATE.unit0_ax_mps2", "RIG_STATE.unit0_ay_mps2",
             "RIG_STATE.unit0_wz_radps", "RIG_STATE.steering_wheel_angle_rad",
             "RIG_STATE.steering_wheel_torque_nm", "RIG_STATE.torsion_bar_torque_nm",
             "RIG_STATE.assist_torque_nm", "RIG_STATE.rack_force_n",
             "RIG_STATE.wheel0_spin_radps", "RIG_STATE.wheel3_load_n", "RIG_STATE.unit0_x_m",
             "RIG_STATUS.deadline_misses", "RIG_STATUS.lateness_p99_ns", "RIG_STATUS.bus_state",
             "RIG_STATUS.can_frames_received",
             "RIG_STATUS.input_valid_steering_wheel_angle_cmd_rad"]


def write_log(path, events, prefix):
    with open(path, "wb") as f:
        for e in events:
            name = (prefix + e.channel).encode()
            f.write(struct.pack(">IqqII", 0xEDA1DA01, e.number, e.timestamp_us, len(name),
                                len(e.data)) + name + e.data)


def record(tmp, prefix, config):
    raw = tmp / f"raw{prefix}.lcm"
    subprocess.run([BIN / "rig", "run", "--config", SOURCE / config, "--offline", "--duration",
                    "4", "--lcm-url", "none", "--lcm-log", raw], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    log = tmp / f"log{prefix or 'RIG1_'}.lcm"
    write_log(log, rig_lcm.read_events(raw), prefix)
    return log


def last_messages(tmp, logs):
    last = {}
    for log in logs:
        for e in rig_lcm.read_events(log):
            last[e.channel] = e
    events = []
    for k in range(3):
        for channel, e in last.items():
            events.append(e._replace(number=len(events), timestamp_us=100_000 * len(events)))
    path = tmp / "last.lcm"
    write_log(path, events, "")
    return path


def expected_latest(logs):
    """{data-signal name: the value of the channel's last message} from the logs."""
    want = {}
    for log in logs:
        for channel, df in rig_lcm.read_log(log).items():
            last = df.iloc[-1]
            for column in df.columns:
                value = last[column]
                want[f"{channel}.{column}"] = value.item() if hasattr(value, "item") else value
    return want


def same(shown, value):
    if isinstance(value, str):
        return shown == value
    if shown == "null":
        return value is None or (isinstance(value, float) and math.isnan(value))
    return float(shown) == float(value)


def main():
    in_netns()
    if chromium_path() is None:
        print("SKIP: chromium missing (scripts/setup installs it)")
        return 77
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = pathlib.Path(tmp_name)
        logs = [record(tmp, prefix, config) for prefix, config in RIGS.items()]
        scope = subprocess.Popen([BIN / "rig-scope", "--port", "0", "--prefix", "",
                                  "--prefix", "RIG2_"], stdout=subprocess.PIPE, text=True)
        browser = None
        try:
            url = scope.stdout.readline().split()[1]
            assert url.startswith("http://127.0.0.1:"), url
            browser = Chromium()
            browser.navigate(url)
            assert browser.wait_for("window.rigScope && window.rigScope.connected"), \
                "the page did not connect to /events"
            players = [subprocess.Popen(["lcm-logplayer", str(log)], stdout=subprocess.DEVNULL)
                       for log in logs]
            fps = []
            while any(p.poll() is None for p in players):
                time.sleep(0.5)
                fps.append(browser.evaluate("window.rigScope.fps || 0"))
            for p in players:
                assert p.wait() == 0
            # the last message of every channel once more, three times (udpm may lose one on a
            # loaded machine): the page's latest values are then the logs' last messages
            subprocess.run(["lcm-logplayer", str(last_messages(tmp, logs))], check=True,
                           stdout=subprocess.DEVNULL)
            time.sleep(1.5)  # the last datagrams, a frame, a draw
            shown = browser.evaluate(
                "Object.fromEntries([...document.querySelectorAll('[data-signal]')]"
                ".map(e => [e.dataset.signal, e.dataset.value]))")
            want = expected_latest(logs)
            for prefix in RIGS:
                missing = [prefix + n for n in MUST_SHOW if prefix + n not in shown]
                assert not missing, f"not on the page: {missing}"
            bad = {n: (v, want.get(n)) for n, v in shown.items()
                   if n not in want or not same(v, want[n])}
            assert not bad, f"{len(bad)} of {len(shown)} signals differ from the log: " \
                            f"{dict(list(bad.items())[:8])}"
            stats = browser.evaluate("({frames: rigScope.frames, draws: rigScope.draws})")
            assert stats["draws"] > 10, stats
            OUTPNG.parent.mkdir(parents=True, exist_ok=True)
            browser.screenshot(OUTPNG)
            assert OUTPNG.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
            print(f"PASS: {len(shown)} signals on the page equal the logs' last messages; "
                  f"{stats['frames']} frames, {stats['draws']} draws; draws/s during the "
                  f"replay {json.dumps(fps[1:-1])}; screenshot {OUTPNG}")
        finally:
            if browser:
                browser.close()
            scope.terminate()
            scope.wait(10)
    return 0


if __name__ == "__main__":
    sys.exit(main())
