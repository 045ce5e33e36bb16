#!/usr/bin/python3
"""scripts/plot_story.py against independent references: the ISO 3888-1 lane widths (1.1 b +
0.25, 1.2 b + 0.25, 1.3 b + 0.25 m) and places (lanes at 0-15, 45-70, 95-110 m), the brake
point of a hand-made run, the wheel names of a sedan, a truck and a combination, the slips of
a wheel below the stand-still mask hidden in the figure while its raw values are large, and a
title carrying the configuration and the KPIs of a summary in the shape of docs/kpis.md.

usage: plot_story_test.py SOURCEDIR PYTHONDIR
"""
import json
import math
import pathlib
import sys
import tempfile

SOURCE = pathlib.Path(sys.argv[1])
sys.path.insert(0, sys.argv[2])
sys.path.insert(0, str(SOURCE / "scripts"))
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import plot_story  # noqa: E402


def close(a, b, tol=1e-12):
    assert abs(a - b) <= tol, (a, b)


lanes = plot_story.iso3888_lanes(30.0, 3.5, 1.80)
for (x0, x1, y, w), (e0, e1, ey, ew) in zip(lanes, [(30, 45, 0, 2.23), (75, 100, 3.5, 2.41),
                                                    (125, 140, 0, 2.59)]):
    close(x0, e0), close(x1, e1), close(y, ey), close(w, ew, 1e-9)

n = 100
state = {"sim_time_s": [0.01 * i for i in range(n)], "unit0_x_m": [0.5 * i for i in range(n)],
         "unit0_y_m": [0.0] * n, "brake_pressure_fl_pa": [0.0] * 60 + [2e5] * 40,
         "brake_pressure_fr_pa": [0.0] * 59 + [0.5e5] + [2e5] * 40}
x, y, t = plot_story.brake_point(state)
close(x, 30.0), close(t, 0.60)

sedan = {f"wheel{w}_unit": [0] for w in range(4)}
assert list(plot_story.wheel_names(sedan).values()) == ["FL", "FR", "RL", "RR"]
truck = {f"wheel{w}_unit": [0] for w in range(6)}
assert list(plot_story.wheel_names(truck).values()) == ["A1L", "A1R", "A2L", "A2R", "A3L", "A3R"]
combo = {f"wheel{w}_unit": [0 if w < 4 else 1] for w in range(6)}
assert list(plot_story.wheel_names(combo).values()) == ["u0 FL", "u0 FR", "u0 RL", "u0 RR",
                                                        "u1 A1L", "u1 A1R"]

# slips: wheel 1 creeps (raw 1500, flagged invalid) for the first half
sl = {"sim_time_s": [0.01 * i for i in range(n)]}
for w in range(2):
    sl[f"wheel{w}_unit"] = [0] * n
    sl[f"wheel{w}_slip_x"] = [0.05] * n if w == 0 else [1500.0] * 50 + [-0.08] * 50
    sl[f"wheel{w}_slip_y"] = [0.01] * n
    sl[f"wheel{w}_slip_valid"] = [1] * n if w == 0 else [0] * 50 + [1] * 50
kpis = [{"name": "peak_rack_force_n", "value": 4312.5, "unit": "N",
         "limits": {"min": None, "max": 6000}, "passed": True},
        {"name": "ay_peak_mps2", "value": None, "unit": "m/s^2",
         "limits": {"min": 1.8, "max": 2.2}, "passed": False}]
with tempfile.TemporaryDirectory() as tmp_name:
    tmp = pathlib.Path(tmp_name)
    (tmp / "s.json").write_text(json.dumps({"kpis": kpis}))
    run = plot_story.Run(SOURCE / "config/maneuvers/parking-effort.toml", tmp / "s.json")
    assert run.title() == ("parking-effort\npeak_rack_force_n = 4312 N [-inf, 6000] pass; "
                           "ay_peak_mps2 = no value [1.8, 2.2] FAIL"), run.title()
    captured = {}
    real_finish = plot_story.finish

    def keep(fig, run_, out_dir, name, written):
        captured[name] = [[list(line.get_ydata()) for line in ax.get_lines()] for ax in fig.axes]
        captured[name + ":ylim"] = fig.axes[0].get_ylim()
        real_finish(fig, run_, out_dir, name, written)
        captured[name + ":title"] = fig._suptitle.get_text()

    plot_story.finish = keep
    written = []
    plot_story.plot_slips(sl, run, tmp, written)
    wheel1_sx = captured["wheel_slips.png"][0][1]
    assert all(math.isnan(v) for v in wheel1_sx[:50]), "stand-still slips must be hidden"
    assert wheel1_sx[50:] == [-0.08] * 50
    low, high = captured["wheel_slips.png:ylim"]
    close(high, 1.15 * 0.08, 1e-12)  # the largest valid slip sets the range, not 1500
    assert captured["wheel_slips.png:title"] == run.title()
    assert written == [tmp / "wheel_slips.png"] and written[0].stat().st_size > 0
print("PASS: lanes, brake point, wheel names, masked slips, KPI title")
