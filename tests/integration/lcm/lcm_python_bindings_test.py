#!/usr/bin/python3
"""The generated Python bindings decode the rig's own LCM log, read by an independent reader of
the LCM event log format (written here from the format's public description: per event a sync
word 0xEDA1DA01, int64 event number, int64 timestamp in us, int32 channel length, int32 data
length, channel, data; big endian).

usage: lcm_python_bindings_test.py BINDIR PYTHONPATH_OF_GENERATED_TYPES
"""
import pathlib
import struct
import subprocess
import sys
import tempfile

bin_dir = pathlib.Path(sys.argv[1])
sys.path.insert(0, sys.argv[2])
import rig  # noqa: E402  (the lcm-gen -p package)


def events(path):
    data = pathlib.Path(path).read_bytes()
    pos = 0
    while pos < len(data):
        sync, num, utime, clen, dlen = struct.unpack_from(">IqqII", data, pos)
        assert sync == 0xEDA1DA01, f"bad sync word at byte {pos}"
        pos += 28
        channel = data[pos:pos + clen].decode()
        pos += clen
        yield num, utime, channel, data[pos:pos + dlen]
        pos += dlen


with tempfile.TemporaryDirectory() as tmp:
    log = pathlib.Path(tmp) / "run.lcm"
    subprocess.run([bin_dir / "rig-lcm-feed", "--url", "none", "--fast", "--duration", "0.5",
                    "--log", log], check=True, stdout=subprocess.DEVNULL)
    counts = {}
    numbers = []
    for num, utime, channel, payload in events(log):
        numbers.append(num)
        counts[channel] = counts.get(channel, 0) + 1
        if channel == "RIG_STATE":
            m = rig.vehicle_state_t.decode(payload)
            c = m.cycle
            assert abs(m.sim_time_s - 0.001 * c) < 1e-12
            assert m.num_wheels == 6 and list(m.wheel_unit) == [0, 0, 0, 0, 1, 1]
            assert abs(m.wheel_spin_radps[4] - (30.0 + 0.01 * c + 10)) < 1e-9
            assert m.gear == 1 + c // 1000
        elif channel == "RIG_SIGNALS":
            m = rig.signals_t.decode(payload)
            i = m.name.index("vehicle_speed_mps")
            assert abs(m.value[i] - (7.0 + 0.001 * m.cycle)) < 1e-12  # the synthetic speed
            assert m.source[1] == rig.signals_t.SOURCE_CAN
        elif channel == "RIG_STATUS":
            m = rig.rig_status_t.decode(payload)
            assert m.bus_state == rig.rig_status_t.BUS_UP
            assert m.input_name[0] == "steering_wheel_angle_cmd_rad"
    assert counts == {"RIG_STATE": 500, "RIG_SIGNALS": 50, "RIG_STATUS": 5}, counts
    assert numbers == list(range(len(numbers))), "event numbers must count up from 0"
print("PASS: Python bindings decode", counts)
