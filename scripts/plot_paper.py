#!/usr/bin/python3
"""Figures of a rig-paper CSV (called as `scripts/plot paper CSV [OUTDIR]`).

quarter car (t,x,v,omega,x_e,F_x,T_drive,T_brake): a Fig.-6-like figure - velocities v and
r*omega, drive and brake torques, tire force and deflection.
pendulums (t,phi1,phi2,lambda,g,newton_iterations): angles, rod force, constraint violation and
Newton iterations. Prints the path of every PNG it writes.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

WHEEL_RADIUS_M = 0.3  # QuarterCarParams{}.wheel_radius_m


def read(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        cols = {name.strip(): [] for name in reader.fieldnames}
        for row in reader:
            for k, v in row.items():
                cols[k.strip()].append(float(v))
    return cols


def quarter_car(c, stem, outdir):
    fig, ax = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    ax[0].plot(c["t"], c["v"], label="v [m/s]")
    ax[0].plot(c["t"], [WHEEL_RADIUS_M * w for w in c["omega"]], "--", label="r omega [m/s]")
    ax[0].set_ylabel("velocities [m/s]")
    ax[0].legend()
    ax[1].plot(c["t"], [x / 1000 for x in c["T_drive"]], label="driving")
    ax[1].plot(c["t"], [-x / 1000 for x in c["T_brake"]], label="braking")
    ax[1].set_ylabel("torque [kN m]")
    ax[1].legend()
    ax[2].plot(c["t"], [f / 1000 for f in c["F_x"]], label="F_x [kN]")
    ax2 = ax[2].twinx()
    ax2.plot(c["t"], [x * 1000 for x in c["x_e"]], "r:", label="x_e [mm]")
    ax2.set_ylabel("tire deflection x_e [mm]")
    ax[2].set_ylabel("tire force F_x [kN]")
    ax[2].set_xlabel("time [s]")
    ax[0].set_title("Quarter car on a 10 % grade (paper Fig. 6)")
    for a in ax:
        a.grid(True)
    fig.tight_layout()
    out = os.path.join(outdir, stem + "_quarter_car.png")
    fig.savefig(out, dpi=110)
    print(out)


def pendulums(c, stem, outdir):
    fig, ax = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    ax[0].plot(c["t"], c["phi1"], label="phi1")
    ax[0].plot(c["t"], c["phi2"], label="phi2")
    ax[0].set_ylabel("angles [rad]")
    ax[0].legend()
    ax[1].plot(c["t"], c["lambda"])
    ax[1].set_ylabel("rod force [N]")
    ax[2].plot(c["t"], [g * 1000 for g in c["g"]])
    ax[2].set_ylabel("l - s [mm]")
    ax[3].step(c["t"], c["newton_iterations"], where="post")
    ax[3].set_ylabel("Newton iterations")
    ax[3].set_xlabel("time [s]")
    ax[0].set_title("Coupled pendulums (paper sec. 3.4)")
    for a in ax:
        a.grid(True)
    fig.tight_layout()
    out = os.path.join(outdir, stem + "_pendulums.png")
    fig.savefig(out, dpi=110)
    print(out)


def main(argv):
    if len(argv) not in (2, 3):
        print("usage: scripts/plot paper CSV [OUTDIR]", file=sys.stderr)
        return 2
    path = argv[1]
    outdir = argv[2] if len(argv) == 3 else os.path.dirname(os.path.abspath(path))
    os.makedirs(outdir, exist_ok=True)
    stem = os.path.splitext(os.path.basename(path))[0]
    c = read(path)
    if "T_drive" in c:
        quarter_car(c, stem, outdir)
    elif "phi1" in c:
        pendulums(c, stem, outdir)
    else:
        print(f"plot_paper: {path}: neither a quarter-car nor a pendulum CSV", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
