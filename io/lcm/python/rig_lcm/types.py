"""The rig's generated LCM types, found by the fingerprint that starts every encoded message."""
import struct

try:
    import rig as _generated  # lcm-gen -p output, installed beside rig_lcm
except ImportError as error:  # pragma: no cover - a broken installation
    raise ImportError("rig_lcm needs the rig's generated LCM types (Python package 'rig', "
                      "build/python or the installed dist-packages)") from error

TYPES = (_generated.vehicle_state_t, _generated.rig_status_t, _generated.signals_t)
_BY_FINGERPRINT = {struct.unpack(">q", t._get_packed_fingerprint())[0]: t for t in TYPES}


def type_of(payload):
    """The generated class whose fingerprint starts `payload`, or None (another type)."""
    if len(payload) < 8:
        return None
    return _BY_FINGERPRINT.get(struct.unpack_from(">q", payload)[0])


def decode_as(cls, payload):
    """`cls.decode(payload)` with every array a list (lcm-gen's boolean arrays come as map
    objects, which can be read only once)."""
    msg = cls.decode(payload)
    for field in msg.__slots__:
        if isinstance(getattr(msg, field), map):
            setattr(msg, field, list(getattr(msg, field)))
    return msg


def decode(payload):
    """The decoded message, or None if its type is not one of the rig's."""
    cls = type_of(payload)
    return decode_as(cls, payload) if cls is not None else None
