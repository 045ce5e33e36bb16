#!/usr/bin/python3
"""Summary plots of a rig sweep (called as `scripts/plot campaign DIR`; rig sweep runs it).

Reads DIR/campaign.csv (rig/sweep/sweep_collect.h: one row per run) and DIR/plan.json (the
varied keys), writes DIR/plots/ and prints the path of each figure:
  status.png        how many runs ended ok, with a failed KPI, failed or missing; and per KPI
                    how many runs passed it, failed it or gave no value
  kpi_<NAME>.png    with two or more numeric [[vary]] keys: the KPI's mean and the share of runs
                    that passed it over the grid of the first two (the other axes averaged);
                    with one: the KPI over it, each run a point (failed ones marked), its
                    limits as dashed lines (from a run's summary); without: over the run number
"""
import csv
import json
import math
import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def number(cell):
    try:
        v = float(cell)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


def kpi_names(header, fixed):
    """The KPI columns: the names before their `NAME.passed` companions."""
    return [h for h in header if h not in fixed and not h.endswith(".passed") and f"{h}.passed" in header]


def limits_of(out, name, rows):
    """A KPI's limits from the first run summary that has it."""
    for r in rows:
        path = out / "runs" / r["id"] / "summary.json"
        if not path.exists():
            continue
        for k in json.load(open(path)).get("kpis", []):
            if k["name"] == name:
                return k["limits"].get("min"), k["limits"].get("max")
    return None, None


def plot_status(out, rows, kpis, figures):
    statuses = sorted({r["status"] for r in rows})
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
    a.bar(statuses, [sum(r["status"] == s for r in rows) for s in statuses], color="tab:blue")
    a.set_title(f"{len(rows)} runs")
    a.set_ylabel("runs")
    passed = [sum(r[f"{k}.passed"] == "1" for r in rows) for k in kpis]
    failed = [sum(r[f"{k}.passed"] == "0" for r in rows) for k in kpis]
    none = [len(rows) - p - f for p, f in zip(passed, failed)]
    b.barh(kpis, passed, color="tab:green", label="passed")
    b.barh(kpis, failed, left=passed, color="tab:red", label="failed")
    b.barh(kpis, none, left=[p + f for p, f in zip(passed, failed)], color="0.7", label="no value")
    b.set_xlabel("runs")
    b.set_title("KPIs")
    b.legend(loc="lower right")
    fig.tight_layout()
    path = out / "plots" / "status.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    figures.append(path)


def plot_kpi(out, rows, name, vary, figures):
    xs_key = vary[0] if vary else None
    colour_key = vary[1] if len(vary) > 1 else None
    pts = []
    for i, r in enumerate(rows):
        y = number(r[name])
        x = number(r[xs_key]) if xs_key else i
        if y is None or x is None:
            continue
        c = number(r[colour_key]) if colour_key else None
        pts.append((x, y, c, r[f"{name}.passed"] == "1"))
    if not pts:
        return
    fig, ax = plt.subplots(figsize=(8, 5))
    ok = [p for p in pts if p[3]]
    bad = [p for p in pts if not p[3]]
    colours = [p[2] for p in pts if p[2] is not None]
    kw = dict(cmap="viridis", vmin=min(colours), vmax=max(colours)) if colours else {}
    sc = None
    if ok:
        sc = ax.scatter([p[0] for p in ok], [p[1] for p in ok], c=[p[2] for p in ok] if colours else
                        "tab:green", marker="o", s=22, label="passed", **kw)
    if bad:
        ax.scatter([p[0] for p in bad], [p[1] for p in bad], c="tab:red", marker="x", s=30,
                   label="failed")
    lo, hi = limits_of(out, name, rows)
    for lim, label in ((lo, "min"), (hi, "max")):
        if lim is not None:
            ax.axhline(lim, color="k", linestyle="--", linewidth=1)
            ax.annotate(f"{label} {lim:g}", (1.0, lim), xycoords=("axes fraction", "data"),
                        ha="right", va="bottom", fontsize=8)
    if colours and sc is not None:
        fig.colorbar(sc, ax=ax, label=colour_key)
    ax.set_xlabel(xs_key or "run")
    ax.set_ylabel(name)
    ax.set_title(f"{name}: {len(ok)} passed, {len(bad)} failed of {len(pts)} runs")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best")
    fig.tight_layout()
    path = out / "plots" / f"kpi_{re.sub(r'[^A-Za-z0-9_.-]', '_', name)}.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    figures.append(path)


def plot_grid(out, rows, name, vary, figures):
    """Mean value and pass share of a KPI over the first two numeric varied keys."""
    kx, ky = vary[0], vary[1]
    xs = sorted({number(r[kx]) for r in rows if number(r[kx]) is not None})
    ys = sorted({number(r[ky]) for r in rows if number(r[ky]) is not None})
    cells = {}
    for r in rows:
        key = (number(r[kx]), number(r[ky]))
        cells.setdefault(key, []).append((number(r[name]), r[f"{name}.passed"] == "1"))
    mean = [[math.nan] * len(xs) for _ in ys]
    share = [[math.nan] * len(xs) for _ in ys]
    for (x, y), vals in cells.items():
        if x is None or y is None:
            continue
        v = [a for a, _ in vals if a is not None]
        mean[ys.index(y)][xs.index(x)] = sum(v) / len(v) if v else math.nan
        share[ys.index(y)][xs.index(x)] = sum(p for _, p in vals) / len(vals)
    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    lo, hi = limits_of(out, name, rows)
    limits = f"limits [{'-' if lo is None else f'{lo:g}'}, {'-' if hi is None else f'{hi:g}'}]"
    for ax, grid, title, cmap in ((axes[0], mean, f"{name}: mean ({limits})", "viridis"),
                                  (axes[1], share, f"{name}: share of runs passed", "RdYlGn")):
        im = ax.imshow(grid, origin="lower", aspect="auto", cmap=cmap,
                       vmin=0 if grid is share else None, vmax=1 if grid is share else None)
        ax.set_xticks(range(len(xs)), [f"{x:g}" for x in xs], rotation=45)
        ax.set_yticks(range(len(ys)), [f"{y:g}" for y in ys])
        ax.set_xlabel(kx)
        ax.set_ylabel(ky)
        ax.set_title(title, fontsize=10)
        fig.colorbar(im, ax=ax)
        if len(xs) * len(ys) <= 144:
            for j, row in enumerate(grid):
                for i, v in enumerate(row):
                    if not math.isnan(v):
                        ax.text(i, j, f"{v:.2g}", ha="center", va="center", fontsize=7)
    others = [k for k in vary[2:]]
    if others:
        fig.suptitle(f"averaged over {', '.join(others)}", fontsize=9)
    fig.tight_layout()
    path = out / "plots" / f"kpi_{re.sub(r'[^A-Za-z0-9_.-]', '_', name)}.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    figures.append(path)


def main():
    if len(sys.argv) != 2:
        print("usage: plot_campaign.py DIR", file=sys.stderr)
        return 2
    out = pathlib.Path(sys.argv[1])
    with open(out / "campaign.csv", newline="") as f:
        reader = csv.DictReader(f)
        header, rows = reader.fieldnames, list(reader)
    vary = json.load(open(out / "plan.json")).get("vary_keys", [])
    fixed = {"id", "maneuver", "road", "seed", "status", "exit_code", "stop_reason", "sim_time_s",
             "wall_time_s", "kpis_failed", "error", *vary}
    kpis = kpi_names(header, fixed)
    (out / "plots").mkdir(exist_ok=True)
    figures = []
    plot_status(out, rows, kpis, figures)
    numeric_vary = [k for k in vary if any(number(r[k]) is not None for r in rows)]
    for name in kpis:
        if len(numeric_vary) >= 2:
            plot_grid(out, rows, name, numeric_vary, figures)
        else:
            plot_kpi(out, rows, name, numeric_vary, figures)
    for path in figures:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
