"""The figures of a run that tell its story (issue 18), called by plot_log.py: signed speed,
wheels by name, slips only where they are slips, the trajectory on the ISO 3888-1 track with the
brake point, yaw rate / sideslip / roll, wheel loads, a combination's articulation and joint
forces; every figure titled with the configuration and the maneuver's KPIs (the summary JSON's
`kpis`, docs/kpis.md). Columns are rig-log2csv's (read_columns of plot_log.py: lists of floats).
"""
import json
import math
import pathlib
import tomllib

import matplotlib.pyplot as plt
import rig_lcm  # build/python (scripts/plot puts it on the path)

SEDAN_WIDTH_M = 1.80  # b of ISO 3888-1 when the vehicle file gives no body points
BRAKE_ON_PA = 1e5     # the brake point: the first sample with a front pressure above 1 bar


# --- the run: configuration, KPIs, names ------------------------------------------------------
class Run:
    """What the titles and the track need: the configuration's name and driver, the vehicle's
    width, the KPIs of the summary."""

    def __init__(self, config_path=None, summary_path=None):
        self.name = "rig run"
        self.driver = {}
        self.width_m = SEDAN_WIDTH_M
        self.kpis = []
        if config_path:
            self._read_config(pathlib.Path(config_path))
        if summary_path:
            summary = json.loads(pathlib.Path(summary_path).read_text())
            self.kpis = summary.get("kpis") or []
            self.name = summary.get("config", self.name) if not config_path else self.name

    def _read_config(self, path):
        self.name = path.stem
        config = tomllib.loads(path.read_text())
        self.driver = config.get("driver", {})
        model = config.get("model", {})
        vehicle = model.get("vehicle") or (model.get("unit") or [{}])[0].get("vehicle")
        if vehicle:
            self.width_m = vehicle_width_m(path.parent / vehicle)

    def title(self):
        """The configuration, then the KPIs three to a line: name = value unit, pass/FAIL."""
        parts = [kpi_text(k) for k in self.kpis]
        lines = [self.name] + ["; ".join(parts[i:i + 3]) for i in range(0, len(parts), 3)]
        return "\n".join(lines)

    def iso3888(self):
        """(start_x_m, lane_offset_m) if the path driver drives the ISO 3888-1 track."""
        if self.driver.get("kind") == "path" and self.driver.get("path", "iso3888-1") == "iso3888-1":
            return self.driver.get("path_start_x_m", 30.0), self.driver.get("lane_offset_m", 3.5)
        return None


def vehicle_width_m(path):
    """The body points' lateral span, else the sedan's width (the vehicle files carry none)."""
    try:
        vehicle = tomllib.loads(path.read_text())
    except (OSError, tomllib.TOMLDecodeError):
        return SEDAN_WIDTH_M
    points = vehicle.get("chassis", {}).get("body_points_m")
    if points:
        ys = [p[1] for p in points]
        return max(ys) - min(ys)
    return SEDAN_WIDTH_M


def kpi_text(kpi):
    value = kpi.get("value")
    shown = "no value" if value is None else f"{value:.4g} {kpi.get('unit', '')}".strip()
    verdict = "pass" if kpi.get("passed") else "FAIL"
    limits = kpi.get("limits") or {}
    low, high = limits.get("min"), limits.get("max")
    if low is None and high is None:
        return f"{kpi['name']} = {shown}"
    bounds = f"[{'-inf' if low is None else f'{low:g}'}, {'inf' if high is None else f'{high:g}'}]"
    return f"{kpi['name']} = {shown} {bounds} {verdict}"


def wheel_names(state):
    """{wheel index: name} from the CSV's wheel<i>_unit columns (rig_lcm.wheel_names: FL/FR/RL/RR
    per two-axle unit, A1L, A1R, ... otherwise, u<k> first with several units)."""
    wheels = indices(state, "wheel", "_unit")
    names = rig_lcm.wheel_names([int(state[f"wheel{w}_unit"][0]) for w in wheels])
    return dict(zip(wheels, names))


def indices(columns, prefix, suffix):
    found = []
    for name in columns:
        if name.startswith(prefix) and name.endswith(suffix):
            middle = name[len(prefix):len(name) - len(suffix)]
            if middle.isdigit():
                found.append(int(middle))
    return sorted(found)


def masked(values, valid):
    return [v if ok == 1 else math.nan for v, ok in zip(values, valid)]


def finish(fig, run, out_dir, name, written):
    fig.suptitle(run.title(), fontsize=9)
    fig.tight_layout()
    path = out_dir / name
    fig.savefig(path, dpi=110)
    plt.close(fig)
    written.append(path)


# --- the figures ------------------------------------------------------------------------------
def plot_trajectory(state, run, out_dir, written):
    fig, ax = plt.subplots(figsize=(11, 5))
    track = run.iso3888()
    if track:
        draw_iso3888(ax, track[0], track[1], run.width_m)
    for u in indices(state, "unit", "_x_m"):
        ax.plot(state[f"unit{u}_x_m"], state[f"unit{u}_y_m"], label=f"unit {u} CG")
    brake = brake_point(state)
    if brake is not None:
        x, y, t = brake
        ax.plot([x], [y], "v", color="black", markersize=9, label=f"brake point (t = {t:.2f} s)")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title("Trajectory (road frame)" + (", ISO 3888-1 track" if track else ""))
    if not track:
        ax.axis("equal")
    ax.grid(True)
    ax.legend(fontsize="small")
    finish(fig, run, out_dir, "trajectory.png", written)


def iso3888_lanes(start_x_m, offset_m, width_m):
    """(x0, x1, centre y, lane width) of lanes 1, 3, 5 of ISO 3888-1 on the rig's centreline
    (rig/driver/path_driver.cpp: lanes 15 / 25 / 15 m at 0-15, 45-70, 95-110 m from the start;
    widths 1.1 b + 0.25, 1.2 b + 0.25, 1.3 b + 0.25 m for the vehicle width b)."""
    return [(start_x_m, start_x_m + 15, 0.0, 1.1 * width_m + 0.25),
            (start_x_m + 45, start_x_m + 70, offset_m, 1.2 * width_m + 0.25),
            (start_x_m + 95, start_x_m + 110, 0.0, 1.3 * width_m + 0.25)]


def draw_iso3888(ax, start_x_m, offset_m, width_m):
    for k, (x0, x1, y, w) in enumerate(iso3888_lanes(start_x_m, offset_m, width_m)):
        n = max(2, int(round((x1 - x0) / 2.5)) + 1)  # a cone every ~2.5 m
        xs = [x0 + (x1 - x0) * i / (n - 1) for i in range(n)]
        for side in (-1, 1):
            ax.plot(xs, [y + side * w / 2] * n, "^", color="darkorange", markersize=5,
                    label=f"ISO 3888-1 cones (b = {width_m:.2f} m)" if k == 0 and side < 0 else None)
        ax.fill_between([x0, x1], y - w / 2, y + w / 2, color="orange", alpha=0.12)


def brake_point(state):
    """(x, y, t) of unit 0 where a front brake pressure first rises above 1 bar."""
    fl, fr = state.get("brake_pressure_fl_pa"), state.get("brake_pressure_fr_pa")
    if not fl or not fr:
        return None
    for i, (a, b) in enumerate(zip(fl, fr)):
        if max(a, b) > BRAKE_ON_PA:
            return state["unit0_x_m"][i], state["unit0_y_m"][i], state["sim_time_s"][i]
    return None


def plot_speed(state, run, out_dir, written):
    t = state["sim_time_s"]
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(9, 6))
    for u in indices(state, "unit", "_vx_mps"):
        ax1.plot(t, state[f"unit{u}_vx_mps"], label=f"unit {u} v_x")
    ax1.axhline(0.0, color="black", linewidth=0.8)
    ax1.set_ylabel("v_x [m/s] (signed: < 0 rolls back)")
    ax1.set_title("Longitudinal speed, body axes")
    ax1.grid(True)
    ax1.legend(fontsize="small")
    kmh = ax1.secondary_yaxis("right", functions=(lambda v: v * 3.6, lambda v: v / 3.6))
    kmh.set_ylabel("[km/h]")
    ax2.plot(t, state["unit0_ax_mps2"], label="a_x longitudinal")
    ax2.plot(t, state["unit0_ay_mps2"], label="a_y lateral")
    ax2.set_xlabel("simulated time [s]")
    ax2.set_ylabel("acceleration [m/s²] (unit 0)")
    ax2.grid(True)
    ax2.legend(fontsize="small")
    finish(fig, run, out_dir, "speed_accel.png", written)


def plot_slips(state, run, out_dir, written):
    t = state["sim_time_s"]
    names = wheel_names(state)
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(9, 6))
    peak = 0.0
    hidden = 0
    for w, name in names.items():
        valid = state.get(f"wheel{w}_slip_valid", [1] * len(t))
        hidden += sum(1 for v in valid if v != 1)
        sx = masked(state[f"wheel{w}_slip_x"], valid)
        sy = masked(state[f"wheel{w}_slip_y"], valid)
        ax1.plot(t, sx, label=name)
        ax2.plot(t, sy, label=name)
        peak = max([peak] + [abs(v) for v in sx + sy if not math.isnan(v)])
    limit = min(1.0, max(0.02, 1.15 * peak))  # a slip is at most 1 in magnitude
    for ax, what in ((ax1, "longitudinal slip s_x [-]"), (ax2, "lateral slip s_y [-]")):
        ax.set_ylim(-limit, limit)
        ax.set_ylabel(what)
        ax.grid(True)
    share = hidden / max(1, len(t) * len(names))
    ax1.set_title(f"Wheel slips (stand-still and creep masked: wheel_slip_valid = 0 in "
                  f"{100 * share:.0f} % of the samples)")
    ax1.legend(fontsize="small", ncol=4)
    ax2.set_xlabel("simulated time [s]")
    finish(fig, run, out_dir, "wheel_slips.png", written)


def plot_dynamics(state, run, out_dir, written):
    t = state["sim_time_s"]
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(9, 8))
    for u in indices(state, "unit", "_wz_radps"):
        vx, vy = state[f"unit{u}_vx_mps"], state[f"unit{u}_vy_mps"]
        beta = [math.degrees(math.atan2(b, a)) if math.hypot(a, b) > 0.5 else math.nan
                for a, b in zip(vx, vy)]
        axes[0].plot(t, [math.degrees(v) for v in state[f"unit{u}_wz_radps"]], label=f"unit {u}")
        axes[1].plot(t, beta, label=f"unit {u}")
        axes[2].plot(t, [math.degrees(v) for v in state[f"unit{u}_roll_rad"]], label=f"unit {u}")
    for ax, what in zip(axes, ("yaw rate [deg/s]", "sideslip β = atan(v_y/v_x) [deg]",
                               "roll angle [deg]")):
        ax.set_ylabel(what)
        ax.grid(True)
        ax.legend(fontsize="small")
    axes[0].set_title("Yaw rate, sideslip (masked below 0.5 m/s), roll")
    axes[2].set_xlabel("simulated time [s]")
    finish(fig, run, out_dir, "dynamics.png", written)


def plot_loads(state, run, out_dir, written):
    t = state["sim_time_s"]
    names = wheel_names(state)
    units = sorted({int(state[f"wheel{w}_unit"][0]) for w in names})
    fig, axes = plt.subplots(len(units), 1, sharex=True, figsize=(9, 3 + 2.5 * len(units)),
                             squeeze=False)
    for row, u in enumerate(units):
        ax = axes[row][0]
        for w, name in names.items():
            if int(state[f"wheel{w}_unit"][0]) == u:
                ax.plot(t, [v / 1e3 for v in state[f"wheel{w}_load_n"]], label=name)
        ax.set_ylabel(f"unit {u} load [kN]")
        ax.grid(True)
        ax.legend(fontsize="small", ncol=4)
    axes[0][0].set_title("Wheel loads (vertical tire force)")
    axes[-1][0].set_xlabel("simulated time [s]")
    finish(fig, run, out_dir, "wheel_loads.png", written)


def plot_combination(state, run, out_dir, written):
    """Articulation (yaw of a unit minus the next one's) and the joint forces on the leading
    unit, in the leading unit's axes (longitudinal, lateral) and vertical."""
    units = indices(state, "unit", "_yaw_rad")
    joints = indices(state, "joint", "_force_x_n")
    if len(units) < 2:
        return
    t = state["sim_time_s"]
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(9, 7))
    for j in range(len(units) - 1):
        a, b = state[f"unit{j}_yaw_rad"], state[f"unit{j + 1}_yaw_rad"]
        angle = [math.degrees(math.remainder(p - q, 2 * math.pi)) for p, q in zip(a, b)]
        ax1.plot(t, angle, label=f"unit {j} - unit {j + 1}")
    ax1.set_ylabel("articulation [deg]")
    ax1.set_title("Articulation and joint forces (on the leading unit)")
    ax1.grid(True)
    ax1.legend(fontsize="small")
    for j in joints:
        yaw = state[f"unit{j}_yaw_rad"]
        fx, fy = state[f"joint{j}_force_x_n"], state[f"joint{j}_force_y_n"]
        lon = [(x * math.cos(p) + y * math.sin(p)) / 1e3 for x, y, p in zip(fx, fy, yaw)]
        lat = [(-x * math.sin(p) + y * math.cos(p)) / 1e3 for x, y, p in zip(fx, fy, yaw)]
        ax2.plot(t, lon, label=f"joint {j} longitudinal")
        ax2.plot(t, lat, label=f"joint {j} lateral")
        ax2.plot(t, [v / 1e3 for v in state[f"joint{j}_force_z_n"]], label=f"joint {j} vertical")
    ax2.set_ylabel("force [kN]")
    ax2.set_xlabel("simulated time [s]")
    ax2.grid(True)
    ax2.legend(fontsize="small", ncol=3)
    finish(fig, run, out_dir, "combination.png", written)


def plot_story(state, run, out_dir, written):
    plot_trajectory(state, run, out_dir, written)
    plot_speed(state, run, out_dir, written)
    plot_slips(state, run, out_dir, written)
    plot_dynamics(state, run, out_dir, written)
    plot_loads(state, run, out_dir, written)
    plot_combination(state, run, out_dir, written)
