#!/usr/bin/python3
"""The field table, the LCM types and rig-log2csv agree.

usage: field_table_test.py LCM_GEN LCMTYPES_DIR BIN_DIR PYTHONPATH_OF_GENERATED_TYPES

1. lcm-gen's own reading of vehicle_state_t.lcm (`lcm-gen -d`) against the field table
   (rig-lcm-fields prints io/lcm/vehicle_state_fields.h): every LCM field is a table row (or part
   of the message's frame) and every row an LCM field, of the same type and array dimension.
2. Messages of all three rig types, built with the lcm-gen Python bindings with a distinct value
   in every field, go through rig-log2csv: every LCM field (every element of an array) has its CSV
   column holding that value, and every CSV column is an LCM field. The expected columns are
   derived from the LCM fields here, independently of the table.
"""
import csv
import pathlib
import re
import struct
import subprocess
import sys
import tempfile

LCM_GEN, TYPES_DIR, BIN_DIR = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
sys.path.insert(0, sys.argv[4])
import rig  # noqa: E402  (the lcm-gen -p package)

failures = []


def fail(message):
    failures.append(message)
    print("FAIL:", message)


def lcm_fields(type_name):
    """[(lcm type, name, dimension or None)] as lcm-gen parses TYPES_DIR/<type_name>.lcm."""
    out = subprocess.run([LCM_GEN, "-d", TYPES_DIR / f"{type_name}.lcm"], check=True,
                         capture_output=True, text=True).stdout
    fields = []
    for line in out.splitlines():
        m = re.match(r"\t(\w+)\s+(\w+)(?: \[ \(var\) (\w+) \])?$", line)
        if m:
            fields.append((m.group(1), m.group(2), m.group(3)))
        elif line.startswith("\t"):
            fail(f"{type_name}.lcm: lcm-gen -d line not understood: {line!r}")
    return fields


def check_table():
    out = subprocess.run([BIN_DIR / "rig-lcm-fields"], check=True, capture_output=True,
                         text=True).stdout
    rows = {}
    for line in out.splitlines():
        group, name, lcm_type, unit = line.split("\t")
        if name in rows:
            fail(f"field table: {name} twice")
        rows[name] = (group, lcm_type, unit)
    fields = {name: (lcm_type, dim) for lcm_type, name, dim in lcm_fields("vehicle_state_t")}
    for name in fields:
        if name not in rows:
            fail(f"vehicle_state_t.lcm: field {name} has no row in io/lcm/vehicle_state_fields.h")
    for name, (group, lcm_type, _) in rows.items():
        if name not in fields:
            fail(f"io/lcm/vehicle_state_fields.h: row {name} is not a field of vehicle_state_t.lcm")
            continue
        if group == "frame":
            continue
        field_type, dim = fields[name]
        if lcm_type != field_type:
            fail(f"{name}: {lcm_type} in the table, {field_type} in vehicle_state_t.lcm")
        expected_dim = None if group == "vehicle" else (
            "num_bodies" if group == "body" else f"num_{group}s")
        if dim != expected_dim:
            fail(f"{name}: a {group} row, but its .lcm dimension is {dim}")
    print(f"field table: {len(rows)} rows, vehicle_state_t: {len(fields)} fields")


class Values:
    """A distinct value per call, of the LCM type asked for."""

    def __init__(self):
        self.n = 0

    def __call__(self, lcm_type):
        self.n += 1
        n = self.n
        return {"double": n * 1.25 + 1.0 / 3.0, "float": n * 0.5, "int64_t": n * 1_000_003_000,
                "int32_t": n * 1001, "int16_t": n * 11, "int8_t": n % 100,
                "boolean": n % 2 == 1, "string": f"text {n}"}[lcm_type]


def build(type_name, counts, values, preset=None):
    """A message of rig.<type_name> with distinct values; arrays sized by `counts`."""
    preset = preset or {}
    msg = getattr(rig, type_name)()
    for lcm_type, name, dim in lcm_fields(type_name):
        if name in counts:
            value = counts[name]
        elif name in preset:
            value = preset[name]
        elif dim is None:
            value = values(lcm_type)
        else:
            value = [values(lcm_type) for _ in range(counts[dim])]
        setattr(msg, name, value)
    return msg


def write_log(path, events):
    """An LCM event log: per event sync word, event number, time [us], channel, data."""
    with open(path, "wb") as f:
        for number, (utime, channel, data) in enumerate(events):
            f.write(struct.pack(">IqqII", 0xEDA1DA01, number, utime, len(channel), len(data)))
            f.write(channel.encode() + data)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def same(cell, value):
    if isinstance(value, bool):
        return cell == ("1" if value else "0")
    if isinstance(value, float):
        return float(cell) == value  # rig-log2csv writes 17 significant digits
    return cell == str(value)


def element_column(name, i):
    group, rest = name.split("_", 1)
    return f"{group}{i}_{rest}"


def expected_columns(type_name, msg):
    """{CSV column: value} for every LCM field of `msg`, by rig-log2csv's naming rules."""
    fields = lcm_fields(type_name)
    columns = {}
    if type_name == "vehicle_state_t":  # arrays flattened: wheel_load_n[3] -> wheel3_load_n
        for _, name, dim in fields:
            value = getattr(msg, name)
            if dim is None:
                columns[name] = value
            else:
                columns.update({element_column(name, i): v for i, v in enumerate(value)})
    elif type_name == "rig_status_t":  # input_valid[i] -> input_valid_<input_name[i]>
        names = {"BUS_DISABLED": "disabled", "BUS_UP": "up", "BUS_DOWN": "down",
                 "BUS_ERROR_PASSIVE": "error-passive", "BUS_OFF": "bus-off"}
        bus = {getattr(rig.rig_status_t, k): v for k, v in names.items()}
        special = {"num_inputs", "input_name", "input_valid", "bus_state"}
        for _, name, dim in fields:
            if name in special:
                continue
            if dim is not None:
                fail(f"rig_status_t.lcm: array {name} has no CSV rule in rig-log2csv")
            columns[name] = getattr(msg, name)
        columns["bus_state"] = bus[msg.bus_state]
        for name, valid in zip(msg.input_name, msg.input_valid):
            columns[f"input_valid_{name}"] = valid
    elif type_name == "signals_t":  # per signal: <name>, <name>_valid, inputs <name>_source
        sources = {rig.signals_t.SOURCE_MODEL: "model", rig.signals_t.SOURCE_DRIVER: "driver",
                   rig.signals_t.SOURCE_CAN: "can"}
        per_signal = {"num_signals", "name", "unit", "value", "valid", "is_input", "source"}
        for _, name, dim in fields:
            if name not in per_signal:
                if dim is not None:
                    fail(f"signals_t.lcm: array {name} has no CSV rule in rig-log2csv")
                columns[name] = getattr(msg, name)
        for i, name in enumerate(msg.name):
            columns[name] = msg.value[i]
            columns[f"{name}_valid"] = msg.valid[i]
            if msg.is_input[i]:
                columns[f"{name}_source"] = sources[msg.source[i]]
    return columns


def check_csv(type_name, csv_file, messages):
    header, rows = read_csv(csv_file)
    if len(set(header)) != len(header):
        fail(f"{csv_file.name}: duplicate columns {sorted({c for c in header if header.count(c) > 1})}")
    if len(rows) != len(messages):
        fail(f"{csv_file.name}: {len(rows)} rows for {len(messages)} messages")
    expected = expected_columns(type_name, messages[0])
    got = set(header) - {"timestamp_us"}
    for column in sorted(set(expected) - got):
        fail(f"{type_name}: LCM field {column} has no column in {csv_file.name}")
    for column in sorted(got - set(expected)):
        fail(f"{type_name}: column {column} of {csv_file.name} is no LCM field")
    for k, (msg, cells) in enumerate(zip(messages, rows)):
        expected = expected_columns(type_name, msg)
        row = dict(zip(header, cells))
        for column, value in expected.items():
            if column in row and not same(row[column], value):
                fail(f"{type_name} message {k}: {column} = {row[column]}, sent {value!r}")
    print(f"{type_name}: {len(header)} columns, {len(messages)} messages checked")


def check_log2csv():
    values = Values()
    state_counts = {"num_units": 2, "num_wheels": 5, "num_joints": 3, "num_diffs": 2,
                    "num_bodies": 2}
    # Wheel i of unit wheel_unit[i]: small values, as the rig writes them (int8).
    wheel_unit = {"wheel_unit": [0, 0, 0, 1, 1]}
    messages = {
        "vehicle_state_t": [build("vehicle_state_t", state_counts, values, wheel_unit)
                            for _ in range(2)],
        "rig_status_t": [build("rig_status_t", {"num_inputs": 3}, values,
                               {"input_name": ["a_nm", "b_rad", "c"],
                                "bus_state": rig.rig_status_t.BUS_UP})
                         for _ in range(2)],
        "signals_t": [build("signals_t", {"num_signals": 3}, values,
                            {"name": ["x_m", "y_mps", "z"], "is_input": [True, False, True],
                             "source": [rig.signals_t.SOURCE_CAN, rig.signals_t.SOURCE_MODEL,
                                        rig.signals_t.SOURCE_DRIVER]})
                      for _ in range(2)],
    }
    channels = {"vehicle_state_t": "RIG_STATE", "rig_status_t": "RIG_STATUS",
                "signals_t": "RIG_SIGNALS"}
    with tempfile.TemporaryDirectory() as tmp:
        log = pathlib.Path(tmp) / "synthetic.lcm"
        events = [(1000 * k, channels[t], msg.encode())
                  for k, (t, msgs) in enumerate(messages.items()) for msg in msgs]
        events.append((5000, "OTHER_TOOL", b"\x01\x02\x03"))  # a type rig-log2csv does not know
        write_log(log, events)
        out = pathlib.Path(tmp) / "csv"
        subprocess.run([BIN_DIR / "rig-log2csv", log, out], check=True, capture_output=True)
        for type_name, msgs in messages.items():
            check_csv(type_name, out / f"{channels[type_name]}.csv", msgs)
        header, rows = read_csv(out / "OTHER_TOOL.csv")
        if header != ["timestamp_us", "channel", "size_bytes"] or rows != [["5000", "OTHER_TOOL", "3"]]:
            fail(f"OTHER_TOOL.csv: {header} {rows}")


check_table()
check_log2csv()
if failures:
    sys.exit(1)
print("PASS: field table, LCM types and rig-log2csv agree")
