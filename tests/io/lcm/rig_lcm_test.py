#!/usr/bin/python3
"""rig_lcm (io/lcm/python) against independent references:
  read_log   the rig's log (rig-lcm-feed's log writer, and `rig run --offline` of a combination)
             read by read_log equals rig-log2csv's CSVs (C++, the generated C++ types) cell for
             cell; a cut last event ends the log, a bad sync word is an error naming the byte
  logger     a live udpm publisher (rig-lcm-feed) recorded by Debian's lcm-logger: read_log of
             that file equals rig-log2csv's CSVs of it and the publisher's own log
  subscribe  rig_lcm.subscribe receives the live publisher: every message equals the one of
             the same cycle in the publisher's own log, none is missing
  fragments  lcm-logplayer (Debian's C LCM) replays a log with a 120 kB message (sent in LC03
             fragments) and small ones: subscribe gives each back byte for byte

usage: rig_lcm_test.py BINDIR PYTHONDIR SOURCEDIR CASE   (logger, subscribe, fragments: root, in
a network namespace of their own)
"""
import math
import pathlib
import struct
import subprocess
import sys
import tempfile
import threading
import time

BIN = pathlib.Path(sys.argv[1])
sys.path.insert(0, sys.argv[2])
SOURCE = pathlib.Path(sys.argv[3])
CASE = sys.argv[4]
sys.path.insert(0, str(SOURCE / "tests" / "support"))

import pandas as pd  # noqa: E402

import rig  # noqa: E402  (lcm-gen -p)
import rig_lcm  # noqa: E402
from rig_lcm.rows import flatten  # noqa: E402

URL = "udpm://239.255.76.67:7667?ttl=0"


def same_cell(a, b):
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    return a == b


def assert_equals_csv(tables, csv_dir):
    """Every channel of read_log equals rig-log2csv's CSV of it, column for column."""
    files = sorted(p.stem for p in csv_dir.glob("*.csv"))
    assert sorted(tables) == files, (sorted(tables), files)
    for channel, df in tables.items():
        csv = pd.read_csv(csv_dir / f"{channel}.csv", keep_default_na=False, na_values=[""],
                          float_precision="round_trip")
        assert set(csv.columns) == set(df.columns), (channel, set(csv.columns) ^ set(df.columns))
        assert len(csv) == len(df), (channel, len(csv), len(df))
        for column in csv.columns:
            for i, (a, b) in enumerate(zip(csv[column].tolist(), df[column].tolist())):
                assert same_cell(a, b), f"{channel}.{column} row {i}: csv {a!r}, read_log {b!r}"
    return {channel: len(df) for channel, df in tables.items()}


def log2csv(log, out):
    subprocess.run([BIN / "rig-log2csv", log, out], check=True, stdout=subprocess.DEVNULL)
    return out


def case_read_log(tmp):
    log = tmp / "feed.lcm"
    subprocess.run([BIN / "rig-lcm-feed", "--url", "none", "--fast", "--duration", "0.5",
                    "--log", log], check=True, stdout=subprocess.DEVNULL)
    counts = assert_equals_csv(rig_lcm.read_log(log), log2csv(log, tmp / "feed"))
    assert counts == {"RIG_STATE": 500, "RIG_SIGNALS": 50, "RIG_STATUS": 5}, counts
    state = rig_lcm.read_log(log)["RIG_STATE"]
    # the synthetic feed's own formulas (tests/io/lcm/lcm_feed.cpp)
    assert (abs(state.sim_time_s - 0.001 * state.cycle) < 1e-12).all()
    assert (abs(state.wheel4_spin_radps - (30.0 + 0.01 * state.cycle + 10)) < 1e-9).all()

    combo = tmp / "combo.lcm"
    subprocess.run([BIN / "rig", "run", "--config",
                    SOURCE / "config/combinations/car-trailer.toml", "--offline", "--duration",
                    "0.3", "--lcm-url", "none", "--lcm-log", combo], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    counts = assert_equals_csv(rig_lcm.read_log(combo), log2csv(combo, tmp / "combo"))
    assert counts["RIG_STATE"] == 300, counts

    whole = log.read_bytes()
    cut = tmp / "cut.lcm"
    cut.write_bytes(whole[:-10])
    assert len(list(rig_lcm.read_events(cut))) == len(list(rig_lcm.read_events(log))) - 1
    bad = tmp / "bad.lcm"
    first = next(rig_lcm.read_events(log))
    second = 28 + len(first.channel) + len(first.data)  # where the second event starts
    bad.write_bytes(whole[:second] + b"\0" * 4 + whole[second + 4:])
    try:
        list(rig_lcm.read_events(bad))
    except ValueError as error:
        assert f"byte {second}: not an LCM log event" in str(error), error
    else:
        raise AssertionError("a bad sync word must be an error")
    print("PASS read_log:", counts)


def start_logger(path):
    logger = subprocess.Popen(["lcm-logger", "-q", "-f", str(path)])
    for _ in range(100):
        if path.exists():
            break
        time.sleep(0.05)
    time.sleep(0.3)  # subscribed
    return logger


def stop(proc):
    time.sleep(0.5)  # the last datagrams
    proc.send_signal(2)
    proc.wait(10)


def publish(tmp, seconds="1"):
    own = tmp / "own.lcm"
    subprocess.run([BIN / "rig-lcm-feed", "--url", URL, "--duration", seconds, "--log", own],
                   check=True, stdout=subprocess.DEVNULL)
    return own


def case_logger(tmp):
    recorded = tmp / "recorded.lcm"
    logger = start_logger(recorded)
    own = publish(tmp)
    stop(logger)
    tables = rig_lcm.read_log(recorded)
    counts = assert_equals_csv(tables, log2csv(recorded, tmp / "recorded"))
    # lcm-logger may lose datagrams on a loaded machine (its loss, not rig_lcm's): what it
    # recorded must be the publisher's messages, cell for cell
    mine = rig_lcm.read_log(own)
    for channel in mine:
        key = "cycle" if "cycle" in mine[channel] else "cycles"
        a = mine[channel].drop(columns="timestamp_us").set_index(key)
        b = tables[channel].drop(columns="timestamp_us").set_index(key)
        assert len(b) >= 0.5 * len(a), f"{channel}: lcm-logger kept {len(b)} of {len(a)}"
        assert a.loc[b.index].equals(b), f"{channel}: lcm-logger's record differs"
    print("PASS logger:", counts)


def collect(channel, out, timeout_s=3.0):
    for msg in rig_lcm.subscribe(URL, channel, timeout_s=timeout_s):
        out.append(msg)


def case_subscribe(tmp):
    got = []
    reader = threading.Thread(target=collect, args=("RIG_STATE|RIG_STATUS", got))
    reader.start()
    time.sleep(0.5)  # joined
    own = publish(tmp)
    reader.join()
    state = [m for m in got if isinstance(m, rig.vehicle_state_t)]
    status = [m for m in got if isinstance(m, rig.rig_status_t)]
    mine = rig_lcm.read_log(own)
    expected = {int(r["cycle"]): r for r in mine["RIG_STATE"].to_dict("records")}
    assert len(expected) == 1000 and len(state) >= 900, (len(state), len(expected))
    assert [m.cycle for m in state] == sorted(m.cycle for m in state), "out of order"
    for msg in state:
        row = flatten(msg)
        want = expected[msg.cycle]
        for column, value in row.items():
            assert same_cell(value, want[column]), (msg.cycle, column, value, want[column])
    assert set(m.cycles for m in status) <= set(mine["RIG_STATUS"].cycles.tolist())
    print(f"PASS subscribe: {len(state)} RIG_STATE, {len(status)} RIG_STATUS")


def write_log(path, events):
    with open(path, "wb") as f:
        for number, (channel, payload) in enumerate(events):
            name = channel.encode()
            f.write(struct.pack(">IqqII", 0xEDA1DA01, number, 1_000_000 + 10_000 * number,
                                len(name), len(payload)))
            f.write(name + payload)


def big_signals(n, cycle):
    m = rig.signals_t()
    m.sim_time_s, m.monotonic_ns, m.cycle = 0.001 * cycle, 10**9 + cycle, cycle
    m.num_signals = n
    m.name = [f"signal_{i:05d}_m" for i in range(n)]
    m.unit = ["m"] * n
    m.value = [i * 0.25 - cycle for i in range(n)]
    m.valid = [i % 3 != 0 for i in range(n)]
    m.is_input = [i % 2 == 0 for i in range(n)]
    m.source = [i % 3 for i in range(n)]
    return m


def small_status(cycle):
    m = rig.rig_status_t()
    m.cycles, m.period_s, m.overrun_policy, m.bus_state = cycle, 0.001, "skip", 1
    m.num_inputs, m.input_name, m.input_valid = 2, ["a_m", "b_m"], [True, False]
    return m


def case_fragments(tmp):
    sent = []
    for k in range(3):
        sent.append(("RIG_SIGNALS", big_signals(4000, k).encode()))
        sent.append(("RIG_STATUS", small_status(k).encode()))
    assert len(sent[0][1]) > 100_000  # beyond one datagram: LC03 fragments
    log = tmp / "big.lcm"
    write_log(log, sent)
    got = []
    reader = threading.Thread(target=collect, args=("RIG_.*", got))
    reader.start()
    time.sleep(0.5)
    recorded = tmp / "recorded.lcm"
    logger = start_logger(recorded)
    subprocess.run(["lcm-logplayer", str(log)], check=True)
    reader.join()
    stop(logger)
    assert [m.encode() for m in got] == [payload for _, payload in sent], \
        f"{len(got)} messages back, {len(sent)} sent"
    tables = rig_lcm.read_log(recorded)
    signals = tables["RIG_SIGNALS"]
    assert signals.shape == (3, 4 + 4000 * 2 + 2000), signals.shape
    assert signals["signal_03999_m"].tolist() == [3999 * 0.25 - k for k in range(3)]
    assert signals["signal_00002_m_source"].tolist() == ["can"] * 3
    print(f"PASS fragments: {len(got)} messages, {len(sent[0][1])} bytes the largest")


if __name__ == "__main__":
    if CASE != "read_log":
        from netns import in_netns
        in_netns()
    with tempfile.TemporaryDirectory() as tmp:
        globals()[f"case_{CASE}"](pathlib.Path(tmp))
