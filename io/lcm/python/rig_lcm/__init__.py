"""rig_lcm: the rig's LCM data in Python, without an LCM Python module (Debian has none).

    read_log(path)          -> {channel: pandas.DataFrame}, the columns of rig-log2csv
    subscribe(url, channel) -> yields decoded messages live from udpm multicast

Pure Python on top of the types lcm-gen generates for the rig (package `rig`, installed beside
this package): the LCM log file and the udpm wire format are read here (rig_lcm/logfile.py,
rig_lcm/udpm.py), the messages decoded by the generated classes (rig_lcm/types.py) and flattened
to rows as rig-log2csv does (rig_lcm/rows.py).
"""
from .logfile import Event, read_events, read_log
from .names import wheel_names
from .types import decode, type_of
from .udpm import DEFAULT_URL, Datagrams, subscribe

__all__ = ["DEFAULT_URL", "Datagrams", "Event", "decode", "read_events", "read_log",
           "subscribe", "type_of", "wheel_names"]
