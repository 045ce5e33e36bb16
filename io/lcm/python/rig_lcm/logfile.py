"""LCM event log files (the format lcm-logger writes and the rig's --lcm-log). Each event: sync
word 0xEDA1DA01, int64 event number, int64 timestamp [us], int32 channel length, int32 data
length, the channel's bytes, the data; all big endian."""
import collections
import struct

from . import rows as _rows
from .types import type_of

SYNC = 0xEDA1DA01
_HEADER = struct.Struct(">IqqII")

Event = collections.namedtuple("Event", "number timestamp_us channel data")


def read_events(path):
    """Yields every Event of the log at `path`. A bad sync word is a ValueError naming the byte;
    an event cut short at the end (a logger killed while writing) ends the log, as LCM's own
    reader does."""
    with open(path, "rb") as f:
        data = f.read()
    pos = 0
    while pos + _HEADER.size <= len(data):
        sync, number, utime, channel_len, data_len = _HEADER.unpack_from(data, pos)
        if sync != SYNC:
            raise ValueError(f"{path}: byte {pos}: not an LCM log event (sync word "
                             f"0x{sync:08X}, expected 0x{SYNC:08X})")
        start = pos + _HEADER.size
        end = start + channel_len + data_len
        if end > len(data):
            return
        channel = data[start:start + channel_len].decode("utf-8", "replace")
        yield Event(number, utime, channel, data[start + channel_len:end])
        pos = end


def read_log(path):
    """{channel: pandas.DataFrame} of the log at `path`: one row per message, the columns of
    rig-log2csv's CHANNEL.csv (timestamp_us first; arrays per element, wheel_load_n ->
    wheel0_load_n, ...). Channels of other types get timestamp_us, channel, size_bytes."""
    import pandas as pd

    tables = {}
    for event in read_events(path):
        table = tables.get(event.channel)
        if table is None:
            table = tables[event.channel] = _rows.table_for(type_of(event.data))
        table.add(event.timestamp_us, event.channel, event.data)
    return {channel: pd.DataFrame.from_records(t.records, columns=t.columns)
            for channel, t in tables.items()}
