"""Messages flattened to table rows with rig-log2csv's column names (rig/log2csv/): the first
message of a channel fixes its columns, as there; a later message that lacks an element leaves
its cells empty (NaN)."""
import math

from .types import _generated, decode_as

BUS_STATES = {0: "disabled", 1: "up", 2: "down", 3: "error-passive", 4: "bus-off"}
SOURCES = {1: "driver", 2: "can"}  # else "model"


def element_column(field, i):
    """Element `i` of array field `field`: wheel_load_n, 3 -> wheel3_load_n (the group is the
    name up to its first underscore, io/lcm/field_table.h group_of)."""
    group, _, rest = field.partition("_")
    return f"{group}{i}_{rest}"


def _cell(value):
    return int(value) if isinstance(value, bool) else value


class StructTable:
    """Any generated struct: scalars as they are, arrays per element, element-major per group
    (unit0_x_m, unit0_y_m, ..., unit1_x_m, ...)."""

    def __init__(self, cls):
        self.cls = cls
        self.columns = None
        self.records = []
        self._picks = []  # (field, index or None) per column after timestamp_us

    def _layout(self, msg):
        arrays = {f: len(getattr(msg, f)) for f in msg.__slots__
                  if isinstance(getattr(msg, f), (list, tuple))}
        groups = {}
        order = []
        for f in msg.__slots__:
            if f in arrays:
                key = (f.partition("_")[0], arrays[f])
                if key not in groups:
                    groups[key] = []
                    order.append(("group", key))
                groups[key].append(f)
            else:
                order.append(("scalar", f))
        for kind, item in order:
            if kind == "scalar":
                # free bodies: no num_bodies column without any (as rig-log2csv)
                if not (item == "num_bodies" and getattr(msg, item) == 0):
                    self._picks.append((item, None))
                continue
            for i in range(item[1]):
                self._picks.extend((f, i) for f in groups[item])
        self.columns = ["timestamp_us"] + [f if i is None else element_column(f, i)
                                           for f, i in self._picks]

    def add(self, timestamp_us, channel, payload):
        self.add_message(timestamp_us, decode_as(self.cls, payload))

    def add_message(self, timestamp_us, msg):
        if self.columns is None:
            self._layout(msg)
        row = [timestamp_us]
        for field, i in self._picks:
            value = getattr(msg, field)
            if i is not None:
                value = value[i] if i < len(value) else math.nan
            row.append(_cell(value))
        self.records.append(row)


class StatusTable(StructTable):
    """rig_status_t: bus_state by name, input_valid_<input name> per input."""

    def _layout(self, msg):
        super()._layout(msg)
        keep = [p for p in self._picks if p[0] not in ("num_inputs", "input_name", "input_valid")]
        self._picks = keep
        self.inputs = list(msg.input_name)
        self.columns = (["timestamp_us"] + [f for f, _ in keep]
                        + [f"input_valid_{n}" for n in self.inputs])

    def add(self, timestamp_us, channel, payload):
        self.add_message(timestamp_us, decode_as(self.cls, payload))

    def add_message(self, timestamp_us, msg):
        if self.columns is None:
            self._layout(msg)
        row = [timestamp_us]
        for field, _ in self._picks:
            value = getattr(msg, field)
            row.append(BUS_STATES.get(value, "disabled") if field == "bus_state" else _cell(value))
        for i, name in enumerate(self.inputs):
            ok = i < len(msg.input_valid) and msg.input_name[i] == name
            row.append(int(msg.input_valid[i]) if ok else math.nan)
        self.records.append(row)


class SignalsTable:
    """signals_t: per signal NAME, NAME_valid and, for inputs, NAME_source."""

    def __init__(self, cls):
        self.cls = cls
        self.columns = None
        self.records = []

    def add(self, timestamp_us, channel, payload):
        self.add_message(timestamp_us, decode_as(self.cls, payload))

    def add_message(self, timestamp_us, msg):
        if self.columns is None:
            self.names = list(msg.name)
            self.is_input = list(msg.is_input)
            self.columns = ["timestamp_us", "sim_time_s", "monotonic_ns", "cycle"]
            for name, is_input in zip(self.names, self.is_input):
                self.columns += [name, f"{name}_valid"] + ([f"{name}_source"] if is_input else [])
        row = [timestamp_us, msg.sim_time_s, msg.monotonic_ns, msg.cycle]
        for i, name in enumerate(self.names):
            ok = i < len(msg.value) and msg.name[i] == name
            row += [msg.value[i], int(msg.valid[i])] if ok else [math.nan, math.nan]
            if self.is_input[i]:
                row.append(SOURCES.get(msg.source[i], "model") if ok else math.nan)
        self.records.append(row)


class RawTable:
    """A type that is not the rig's: when, where, how big."""

    def __init__(self):
        self.columns = ["timestamp_us", "channel", "size_bytes"]
        self.records = []

    def add(self, timestamp_us, channel, payload):
        self.records.append([timestamp_us, channel, len(payload)])


def table_for(cls):
    if cls is None:
        return RawTable()
    if cls is _generated.rig_status_t:
        return StatusTable(cls)
    if cls is _generated.signals_t:
        return SignalsTable(cls)
    return StructTable(cls)


def flatten(msg):
    """{column: value} of one decoded message (rig-log2csv's names, without timestamp_us)."""
    table = table_for(type(msg))
    table.add_message(0, msg)
    return dict(zip(table.columns[1:], table.records[0][1:]))
