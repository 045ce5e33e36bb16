#!/usr/bin/python3
"""Figures of a rig run from the CSVs of rig-log2csv:

    scripts/plot log CSVDIR [OUTDIR] [--config FILE] [--summary FILE]

Reads CSVDIR/*RIG_STATE.csv (any channel prefix), *RIG_STATUS.csv and *RIG_SIGNALS.csv, writes
PNGs to OUTDIR (default CSVDIR) and prints the path of each. Titles name the configuration
(--config: the run configuration; its path driver on the ISO 3888-1 track draws the lanes) and
the maneuver's KPIs (--summary: rig run's --summary-json, its `kpis`). plot_story.py:
  trajectory.png    CG path of every unit; the ISO 3888-1 lanes and cones; the brake point
  speed_accel.png   signed v_x of every unit; a_x, a_y
  wheel_slips.png   slips of every wheel by name (FL, FR, ...), stand-still masked
  dynamics.png      yaw rate, sideslip, roll of every unit
  wheel_loads.png   wheel loads by name, per unit
  combination.png   (several units) articulation and joint forces
here:
  steering.png      steering wheel angle; hand, torsion bar and assist torques; rack force
  road.png          the road under every wheel along the distance travelled: its height (what
                    each wheel rolled over; the front wheels' traces lead the rear ones' by the
                    wheelbase), its slopes along x and y from the normal, its friction scale mu
                    (logs written before the wheel_road_ columns existed have no such figure)
  lateness.png      histogram of loop lateness with the deadline (one period) marked
  misses.png        timeline of deadline misses
"""
import argparse
import csv
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot_story import Run, plot_story  # noqa: E402


def find(csv_dir, channel):
    """The CSV of `channel`, with or without a channel prefix; None if absent."""
    exact = csv_dir / f"{channel}.csv"
    if exact.exists():
        return exact
    matches = sorted(csv_dir.glob(f"*{channel}.csv"))
    return matches[0] if matches else None


def read_columns(path):
    """Columns of a CSV as lists of floats (cells that are not numbers become NaN)."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        columns = {name: [] for name in header}
        for row in reader:
            for name, cell in zip(header, row):
                try:
                    columns[name].append(float(cell))
                except ValueError:
                    columns[name].append(math.nan)
    return columns


def indices(columns, prefix, suffix):
    """The i of every column named prefix<i>suffix, sorted."""
    found = []
    for name in columns:
        if name.startswith(prefix) and name.endswith(suffix):
            middle = name[len(prefix):len(name) - len(suffix)]
            if middle.isdigit():
                found.append(int(middle))
    return sorted(found)


def save(fig, out_dir, name, written):
    path = out_dir / name
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    written.append(path)


def plot_steering(state, run, out_dir, written):
    t = state["sim_time_s"]
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, sharex=True, figsize=(8, 8))
    ax1.plot(t, [math.degrees(a) for a in state["steering_wheel_angle_rad"]])
    ax1.set_ylabel("steering wheel angle [deg]")
    ax1.set_title("Steering")
    ax1.grid(True)
    for column, label in (("steering_wheel_torque_nm", "hand torque"),
                          ("torsion_bar_torque_nm", "torsion bar torque"),
                          ("assist_torque_nm", "assist torque")):
        ax2.plot(t, state[column], label=label)
    ax2.set_ylabel("torque [N m]")
    ax2.grid(True)
    ax2.legend()
    ax3.plot(t, [f / 1e3 for f in state["rack_force_n"]])
    ax3.set_ylabel("rack force [kN]")
    ax3.set_xlabel("simulated time [s]")
    ax3.grid(True)
    fig.suptitle(run.title(), fontsize=9)
    save(fig, out_dir, "steering.png", written)



def travelled_m(state):
    """Distance travelled by unit 0's CG at each row [m] (trapezoidal in its speed)."""
    t = state["sim_time_s"]
    v = [math.hypot(vx, vy) for vx, vy in zip(state["unit0_vx_mps"], state["unit0_vy_mps"])]
    s = [0.0]
    for k in range(1, len(t)):
        s.append(s[-1] + 0.5 * (v[k] + v[k - 1]) * (t[k] - t[k - 1]))
    return s


def plot_road(state, out_dir, written):
    """The road under the wheels: height, slopes (from the local plane's normal) and mu."""
    wheels = indices(state, "wheel", "_road_z_m")
    if not wheels:
        return
    s = travelled_m(state)
    heights = [z for w in wheels for z in state[f"wheel{w}_road_z_m"] if math.isfinite(z)]
    metres = bool(heights) and max(heights) - min(heights) > 0.5  # a hill: m, else mm
    scale, unit = (1.0, "m") if metres else (1e3, "mm")
    fig, (ax1, ax2, ax3) = plt.subplots(3, 1, sharex=True, figsize=(9, 8))
    for w in wheels:
        unit = int(state[f"wheel{w}_unit"][0]) if f"wheel{w}_unit" in state else 0
        label = f"wheel {w} (unit {unit})"
        color = f"C{w % 10}"
        ax1.plot(s, [scale * z for z in state[f"wheel{w}_road_z_m"]], label=label, linewidth=0.8,
                 color=color)
        nx, ny, nz = (state[f"wheel{w}_road_normal_{c}"] for c in "xyz")
        ax2.plot(s, [-100 * a / c for a, c in zip(nx, nz)], linewidth=0.8, color=color,
                 label=f"wheel {w}: along x (solid), y (dashed)")
        ax2.plot(s, [-100 * b / c for b, c in zip(ny, nz)], linestyle="--", linewidth=0.8,
                 color=color)
        ax3.plot(s, state[f"wheel{w}_road_mu"], label=label, color=color)
    ax1.set_ylabel(f"road height [{unit}]")
    ax1.set_title("The road under each wheel (its local plane: TMeasy's four probes)")
    ax1.grid(True)
    ax1.legend(fontsize="small", ncol=2)
    ax2.set_ylabel("road slope [%]")
    ax2.grid(True)
    ax2.legend(fontsize="x-small", ncol=2)
    ax3.set_ylabel("friction scale mu [-]")
    ax3.set_xlabel("distance travelled by the CG of unit 0 [m]")
    ax3.grid(True)
    save(fig, out_dir, "road.png", written)


def plot_timing(state, status, out_dir, written):
    period_s = 0.001
    if status and status["period_s"]:
        period_s = status["period_s"][0]
    period_us = period_s * 1e6

    fig, ax = plt.subplots(figsize=(8, 5))
    lateness_us = [v / 1e3 for v in state["lateness_ns"]]
    end_us = [(a + b) / 1e3 for a, b in zip(state["lateness_ns"], state["compute_ns"])]
    top = max(max(end_us, default=0.0), period_us) * 1.05
    bins = [top * i / 100 for i in range(101)]
    ax.hist(lateness_us, bins=bins, log=True, alpha=0.7, label="wake-up lateness")
    ax.hist(end_us, bins=bins, log=True, alpha=0.5, label="lateness + compute (work end)")
    ax.axvline(period_us, color="red", linestyle="--", label=f"deadline: next cycle ({period_us:g} µs)")
    ax.set_xlabel("time after the cycle's deadline [µs]")
    ax.set_ylabel("cycles")
    ax.set_title(f"Loop lateness ({len(lateness_us)} cycles)")
    ax.grid(True)
    ax.legend()
    save(fig, out_dir, "lateness.png", written)

    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(8, 5))
    t = state["sim_time_s"]
    miss_t = [ti for ti, m in zip(t, state["deadline_miss"]) if m == 1]
    ax1.eventplot([miss_t], colors="red", lineoffsets=0.5, linelengths=0.8)
    ax1.set_yticks([])
    ax1.set_title(f"Deadline misses ({len(miss_t)} among the cycles published)")
    ax1.grid(True, axis="x")
    if status:
        ax2.step(status["sim_time_s"], status["deadline_misses"], where="post", label="total")
        ax2.step(status["sim_time_s"], status["window_misses"], where="post",
                 label="in the last second")
        ax2.legend()
    ax2.set_xlabel("simulated time [s]")
    ax2.set_ylabel("misses")
    ax2.grid(True)
    save(fig, out_dir, "misses.png", written)


def main(argv):
    parser = argparse.ArgumentParser(prog="scripts/plot log")
    parser.add_argument("csv_dir", metavar="CSVDIR")
    parser.add_argument("out_dir", metavar="OUTDIR", nargs="?")
    parser.add_argument("--config", help="the run configuration (title, ISO 3888-1 track)")
    parser.add_argument("--summary", help="rig run's --summary-json (the KPIs in the titles)")
    args = parser.parse_args(argv[1:])
    csv_dir = pathlib.Path(args.csv_dir)
    out_dir = pathlib.Path(args.out_dir) if args.out_dir else csv_dir
    try:
        run = Run(args.config, args.summary)
    except (OSError, ValueError) as error:  # tomllib's and json's errors are ValueErrors
        print(f"plot log: {error}", file=sys.stderr)
        return 2
    out_dir.mkdir(parents=True, exist_ok=True)
    state_csv = find(csv_dir, "RIG_STATE")
    if state_csv is None:
        print(f"plot log: no RIG_STATE.csv in {csv_dir} (made by rig-log2csv?)", file=sys.stderr)
        return 1
    state = read_columns(state_csv)
    if not state["sim_time_s"]:
        print(f"plot log: {state_csv} has no rows", file=sys.stderr)
        return 1
    status_csv = find(csv_dir, "RIG_STATUS")
    status = read_columns(status_csv) if status_csv else None
    written = []
    plot_story(state, run, out_dir, written)
    plot_steering(state, run, out_dir, written)
    plot_road(state, out_dir, written)
    plot_timing(state, status, out_dir, written)
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
