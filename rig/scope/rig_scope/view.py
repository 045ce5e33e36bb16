"""What the page shows of one rig (one channel prefix), fed with decoded messages on the
receiving thread and read as frames by the server. Names of plotted signals are
`<prefix><CHANNEL>.<column>` with rig-log2csv's columns (RIG_STATE.unit0_vx_mps), the page's
`data-signal` attributes."""
import math

from rig_lcm import wheel_names
from rig_lcm.rows import BUS_STATES

SAMPLE_PERIOD_S = 0.005  # plotted samples: 200 per simulated second (RIG_STATE is 1 kHz)
WINDOW_S = 20.0          # history a new page gets
TRACE_STEP_M = 0.25      # the top view's trace: a point per this much travel
TRACE_POINTS = 20000
HIST_BIN_US = 25.0       # lateness histogram: bins of 25 us up to two periods, then overflow

STATUS_FIELDS = ("sim_time_s", "cycles", "deadline_misses", "consecutive_misses",
                 "max_consecutive_misses", "snapshots_dropped", "window_misses",
                 "lateness_p50_ns", "lateness_p99_ns", "lateness_p999_ns", "lateness_max_ns",
                 "compute_p99_ns", "period_s", "offline", "sched_fifo", "priority",
                 "memory_locked", "cpu", "overrun_policy")
CAN_FIELDS = ("bus_state", "can_frames_received", "can_frames_sent", "can_timeouts",
              "can_checksum_failures", "can_counter_failures", "can_bad_frames",
              "can_error_frames", "can_out_of_range", "can_send_dropped", "can_reopens",
              "can_rx_overflows")


def finite(value):
    """JSON has no NaN or infinity: null instead."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def state_panels(units, wheels):
    """The plot panels of RIG_STATE: (title, unit, [(column, label)])."""
    names = wheel_names(wheels)
    per_unit = [(f"unit{u}_wz_radps", f"unit {u}") for u in range(units)]
    return [
        ("Speed v_x (signed, body axes)", "m/s", [("unit0_vx_mps", "v_x")]),
        ("Accelerations", "m/s²", [("unit0_ax_mps2", "a_x"), ("unit0_ay_mps2", "a_y")]),
        ("Yaw rate", "rad/s", per_unit),
        ("Steering wheel angle", "rad", [("steering_wheel_angle_rad", "angle")]),
        ("Steering torques", "N m", [("steering_wheel_torque_nm", "hand"),
                                     ("torsion_bar_torque_nm", "torsion bar"),
                                     ("assist_torque_nm", "assist")]),
        ("Rack force", "N", [("rack_force_n", "rack force")]),
        ("Wheel speeds", "rad/s", [(f"wheel{i}_spin_radps", n) for i, n in enumerate(names)]),
        ("Wheel loads", "N", [(f"wheel{i}_load_n", n) for i, n in enumerate(names)]),
    ]


class RigView:
    def __init__(self, prefix):
        self.prefix = prefix
        self.state_channel = prefix + "RIG_STATE"
        self.status_channel = prefix + "RIG_STATUS"
        self.generation = 0  # counts layouts: a new run (time going back, other sizes)
        self.layout = None
        self.latest = {}
        self.status = {}
        self.last_message_s = None
        self._sent_generation = 0
        self._reset_series()

    def _reset_series(self):
        self.samples = []        # [sim_time_s, v...] in the order of self.columns, all kept
        self.pending = []        # samples not yet in a frame
        self.trace = []          # [unit, x, y]
        self.pending_trace = []
        self.misses = []         # [sim_time_s, deadline_misses, window_misses] of RIG_STATUS
        self.pending_misses = []
        self.hist_counts = None
        self.period_s = None
        self._last_sample_t = -math.inf
        self._last_trace = {}

    # --- receiving thread ---------------------------------------------------------------------
    def on_state(self, msg, now_s):
        self.last_message_s = now_s
        shape = (msg.num_units, tuple(msg.wheel_unit))
        if self.layout is None or shape != self._shape or msg.sim_time_s < self._last_sample_t:
            self._new_layout(msg, shape)
        values = [finite(float(getattr(msg, f) if i is None else getattr(msg, f)[i]))
                  for f, i in self._picks]
        for name, value in zip(self.columns, values):
            self.latest[self.state_channel + "." + name] = value
        self._histogram(msg.lateness_ns)
        if msg.sim_time_s - self._last_sample_t >= SAMPLE_PERIOD_S - 1e-9:
            self._last_sample_t = msg.sim_time_s
            sample = [msg.sim_time_s] + values
            self.samples.append(sample)
            self.pending.append(sample)
            cut = msg.sim_time_s - WINDOW_S
            if self.samples[0][0] < cut - 5.0:  # trim in chunks, not every sample
                self.samples = [s for s in self.samples if s[0] >= cut]
        self._poses(msg)

    def _new_layout(self, msg, shape):
        self._shape = shape
        self.generation += 1
        self._reset_series()
        panels = state_panels(msg.num_units, list(msg.wheel_unit))
        self.columns = []
        self._picks = []
        for _, _, series in panels:
            for column, _ in series:
                if column not in self.columns:
                    self.columns.append(column)
        for u in range(msg.num_units):
            self.columns += [f"unit{u}_x_m", f"unit{u}_y_m", f"unit{u}_yaw_rad"]
        for column in self.columns:
            self._picks.append(_pick(column))
        self.latest = {k: v for k, v in self.latest.items()
                       if not k.startswith(self.state_channel + ".")}
        self.layout = {"prefix": self.prefix, "generation": self.generation,
                       "state_channel": self.state_channel,
                       "status_channel": self.status_channel,
                       "units": msg.num_units, "columns": self.columns,
                       "panels": [{"title": t, "unit": u, "series": [list(s) for s in series]}
                                  for t, u, series in panels],
                       "wheels": wheel_names(list(msg.wheel_unit)),
                       "status_fields": list(STATUS_FIELDS), "can_fields": list(CAN_FIELDS),
                       "hist_bin_us": HIST_BIN_US}

    def _histogram(self, lateness_ns):
        if self.hist_counts is None:
            period_s = self.period_s or 0.001
            self.hist_counts = [0] * (int(round(2e6 * period_s / HIST_BIN_US)) + 1)
        k = min(max(int(lateness_ns / 1e3 / HIST_BIN_US), 0), len(self.hist_counts) - 1)
        self.hist_counts[k] += 1

    def _poses(self, msg):
        for u in range(msg.num_units):
            x, y = msg.unit_x_m[u], msg.unit_y_m[u]
            last = self._last_trace.get(u)
            if last is None or math.hypot(x - last[0], y - last[1]) >= TRACE_STEP_M:
                self._last_trace[u] = (x, y)
                point = [u, finite(x), finite(y)]
                self.trace.append(point)
                self.pending_trace.append(point)
        if len(self.trace) > TRACE_POINTS:
            self.trace = self.trace[-TRACE_POINTS // 2:]

    def on_status(self, msg, now_s):
        self.last_message_s = now_s
        if self.period_s != msg.period_s:
            self.period_s = msg.period_s
            self.hist_counts = None  # bins follow the period
        for field in STATUS_FIELDS + CAN_FIELDS:
            value = getattr(msg, field)
            if field == "bus_state":
                value = BUS_STATES.get(value, "disabled")
            elif isinstance(value, bool):
                value = int(value)
            self.status[field] = finite(value)
            self.latest[self.status_channel + "." + field] = finite(value)
        inputs = {}
        for name, valid in zip(msg.input_name, msg.input_valid):
            inputs[name] = int(valid)
            self.latest[f"{self.status_channel}.input_valid_{name}"] = int(valid)
        self.status["inputs"] = inputs
        point = [msg.sim_time_s, msg.deadline_misses, msg.window_misses]
        self.misses.append(point)
        self.pending_misses.append(point)
        if len(self.misses) > 4 * WINDOW_S * 10:
            self.misses = self.misses[-int(WINDOW_S * 10):]

    # --- server thread (under the same lock) ---------------------------------------------------
    def frame(self, now_s, full):
        """What changed since the last frame (`full`: everything, for a new page)."""
        if self.layout is None and not self.status:
            return None
        out = {"latest": dict(self.latest), "status": dict(self.status),
               "age_s": None if self.last_message_s is None else now_s - self.last_message_s,
               "generation": self.generation, "hist": self.hist_counts}
        if full:  # what earlier frames carried; the pending rest follows in the next frame
            out.update(layout=self.layout,
                       samples=self.samples[:len(self.samples) - len(self.pending)],
                       trace=self.trace[:len(self.trace) - len(self.pending_trace)],
                       misses=self.misses[:len(self.misses) - len(self.pending_misses)])
        else:
            out.update(samples=self.pending, trace=self.pending_trace, misses=self.pending_misses)
            if self._sent_generation != self.generation:
                out["layout"] = self.layout
        return out

    def frame_sent(self):
        self.pending, self.pending_trace, self.pending_misses = [], [], []
        self._sent_generation = self.generation


def _pick(column):
    """(field, element index or None) of a rig-log2csv column of vehicle_state_t."""
    head, _, rest = column.partition("_")
    digits = head.lstrip("abcdefghijklmnopqrstuvwxyz")
    if digits.isdigit():
        return head[:-len(digits)] + "_" + rest, int(digits)
    return column, None
