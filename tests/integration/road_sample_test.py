#!/usr/bin/python3
"""`rig road sample` end to end: road_sample_test.py RIG_BINARY SOURCE_DIR OPENCRG_DIR CASE.

The road a configuration gives its tires, sampled through the command line, against numbers this
script computes itself from the OpenCRG sample files (../shared/testdata/opencrg, read in place)
and from ISO 8608:

  nodes      every handmade sample's grid nodes, at positions this script integrates from the
             file's heading channel (x_i = x_i-1 + du cos phi_i; cross sections along the chord
             normals): the file's heights (float32) plus the integrated slope and banking*v;
             with a 5 % error in curvature the same points miss (the check can fail)
  slope_bank the known slope (handmade_sloped) and banking (handmade_banked) recovered from the
             normals in flat grid cells: n = (-dz/dx, -dz/dy, 1) / |.|
  curvature  handmade_curved_banked_sloped: the reference line's heading recovered in each flat
             cell from the normal (the gradient is slope t + banking n, rotated by the heading),
             its change per metre against the heading channel's
  placement  [road.placement] moves and turns a sample: its nodes where the placement puts them
  iso8608    class C and E roads: the displacement PSD of two tracks has slope -2 +- 0.2 and
             G_d(0.1 cycles/m) inside the class band, fitted over 0.05-2.83 cycles/m (Welch,
             scipy); the tracks' coherence follows the isotropic model 2 pi n d K1(2 pi n d);
             the same seed gives the same road, another seed another
  plane      the [model] road_* plane (split mu on y < 0) and a [road] plane with a grade
  opendrive  an OpenDRIVE road (tests/io/config/opendrive/test_track.xodr, road "2": a 5 % grade
             and 0.04 rad superelevation) placed at the origin, with a cleat, a bump, a mu-split
             and a mu-jump: heights, normals and mu against this script's own formulas, the
             cleat's edges exactly where they are
  bad_input  bad POINTS.csv and bad [road] sections: exit 2, `file:line: what`, nothing on stdout
"""

import math
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy import signal, special

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rig_checks import check, fail  # noqa: E402

RIG, SRC, SAMPLES, CASE = sys.argv[1], os.path.abspath(sys.argv[2]), sys.argv[3], sys.argv[4]
TMP = tempfile.mkdtemp(prefix="rig_road_")
SEDAN = os.path.join(SRC, "config", "vehicles", "sedan.toml")


# ---- running the command

def config(road, model_extra=""):
    path = os.path.join(TMP, f"c{abs(hash(road + model_extra))}.toml")
    with open(path, "w") as f:
        f.write(f'[model]\nkind = "vehicle"\nvehicle = "{SEDAN}"\n{model_extra}\n{road}\n')
    return path


def run_sample(cfg, points_text):
    pts = os.path.join(TMP, "points.csv")
    with open(pts, "w") as f:
        f.write(points_text)
    return subprocess.run([RIG, "road", "sample", "--config", cfg, "--xy", pts],
                          capture_output=True, text=True, timeout=120), pts


def sample(cfg, xy):
    text = "x,y\n" + "".join(f"{x!r},{y!r}\n" for x, y in xy)
    r, _ = run_sample(cfg, text)
    check(r.returncode == 0, f"rig road sample: exit {r.returncode}: {r.stderr}")
    lines = r.stdout.splitlines()
    check(lines[0] == "x,y,z,nx,ny,nz,mu", f"header {lines[0]!r}")
    rows = np.array([[float(v) for v in line.split(",")] for line in lines[1:]])
    check(rows.shape == (len(xy), 7), f"{rows.shape} rows for {len(xy)} points")
    check(np.allclose(rows[:, :2], np.array(xy)), "x,y not echoed")
    return rows


def crg_road(name, placement=""):
    return f'[road]\nkind = "crg"\nfile = "{os.path.join(SAMPLES, name)}"\n{placement}'


# ---- the sample files, read here

class Crg:
    """A text sample: $ROAD_CRG keys, channels, rows; the grid's u, v and heights."""

    def __init__(self, name):
        lines = open(os.path.join(SAMPLES, name)).read().splitlines()
        sep = next(i for i, line in enumerate(lines) if line.startswith("$$"))
        self.keys, self.channels = {}, []
        for line in lines[:sep]:
            body = line[:72].split("!")[0].strip()
            if body.startswith("D:"):
                self.channels.append(body[2:].split(",")[0].strip())
            elif "=" in body and not body.startswith(("*", "%")):
                k, v = body.split("=", 1)
                try:
                    self.keys[k.strip().upper()] = float(v)
                except ValueError:
                    pass  # not a $ROAD_CRG number (e.g. ASAM's `2.000000000+e00`)
        width = 20 if any("#:LDFI" in line for line in lines[:sep]) else 10
        values = []
        for line in lines[sep + 1:]:
            line = line.rstrip()
            for f in range(0, len(line), width):
                field = line[f:f + width]
                values.append(math.nan if "*" in field else float(field))
        n = len(self.channels)
        self.rows = np.array(values).reshape(-1, n)
        self.du = self.keys["REFERENCE_LINE_INCREMENT"]
        z_cols = [i for i, c in enumerate(self.channels) if c.startswith("long section")]
        self.z = self.rows[:, z_cols].astype(np.float32).astype(float)
        if "at v" in self.channels[z_cols[0]]:
            self.v = np.array([float(self.channels[i].split("=")[1]) for i in z_cols])
        else:
            inc = self.keys["LONG_SECTION_V_INCREMENT"]
            right = self.keys.get("LONG_SECTION_V_RIGHT", -inc * (len(z_cols) - 1) / 2)
            self.v = right + inc * np.arange(len(z_cols))
        self.fill_nans()

    def fill_nans(self):
        for row in self.z:  # GRID_NAN_MODE 2: the nearest valid value of the cross section
            ok = np.flatnonzero(~np.isnan(row))
            row[:ok[0]] = row[ok[0]]
            row[ok[-1] + 1:] = row[ok[-1]]

    def channel(self, name):
        col = [i for i, c in enumerate(self.channels) if c == "reference line " + name]
        return self.rows[:, col[0]] if col else None

    def ref_z(self):
        s = self.channel("slope")
        if s is None:
            return np.zeros(len(self.rows))
        return np.concatenate([[0.0], np.cumsum(s[1:] * self.du)])

    def bank(self):
        b = self.channel("banking")
        return np.zeros(len(self.rows)) if b is None else b

    def points(self, curvature_scale=1.0):
        """Reference points integrated from the heading channel (phi scaled about phi_1)."""
        phi = self.channel("phi")
        n = len(self.rows)
        if phi is None:
            phi = np.full(n, self.keys.get("REFERENCE_LINE_START_PHI", 0.0))
        phi = phi[1] + curvature_scale * (phi - phi[1])
        x = np.concatenate([[0.0], np.cumsum(self.du * np.cos(phi[1:]))])
        y = np.concatenate([[0.0], np.cumsum(self.du * np.sin(phi[1:]))])
        return x, y

    def node_xy(self, curvature_scale=1.0):
        """(x, y) of every node: P_i + v m_i, m_i along the chord normal, its part normal to the
        segment 1."""
        x, y = self.points(curvature_scale)
        n = len(x)
        out = np.zeros((n, len(self.v), 2))
        for i in range(n):
            lo, hi = max(i - 1, 0), min(i + 1, n - 1)
            cx, cy = x[hi] - x[lo], y[hi] - y[lo]
            m = np.array([-cy, cx]) / math.hypot(cx, cy)
            k = min(i, n - 2)
            sx, sy = x[k + 1] - x[k], y[k + 1] - y[k]
            seg_n = np.array([-sy, sx]) / math.hypot(sx, sy)
            m = m / (m @ seg_n)
            out[i] = np.stack([x[i] + self.v * m[0], y[i] + self.v * m[1]], axis=1)
        return out

    def node_heights(self):
        return self.z + self.ref_z()[:, None] + self.bank()[:, None] * self.v[None, :]

    def flat_cells(self):
        """(i, j) of cells whose four heights are equal (the grid adds no gradient there)."""
        z = self.z
        return [(i, j) for i in range(len(z) - 1) for j in range(len(self.v) - 1)
                if z[i, j] == z[i + 1, j] == z[i, j + 1] == z[i + 1, j + 1]]


HANDMADE = ["handmade_straight", "handmade_straight_minimalist", "handmade_straight_double",
            "handmade_vtest", "handmade_curved", "handmade_curved_minimalist", "handmade_arc",
            "handmade_circle", "handmade_banked", "handmade_sloped", "handmade_sloped_opts",
            "handmade_curved_banked_sloped", "handmade_platform"]


def case_nodes():
    for name in HANDMADE:
        crg = Crg(name + ".crg")
        cfg = config(crg_road(name + ".crg"))
        xy = crg.node_xy().reshape(-1, 2)
        want = crg.node_heights().reshape(-1)
        got = sample(cfg, [tuple(p) for p in xy])[:, 2]
        err = np.max(np.abs(got - want) / (1e-9 + np.abs(want) * 6e-8 + 1e-12))
        check(np.all(np.abs(got - want) <= 1e-12 + 6e-8 * np.abs(want)),
              f"{name}: node heights off by up to {np.max(np.abs(got - want)):.3g} m ({err:.3g})")
        if crg.channel("phi") is not None:  # a curvature 5 % off misses the nodes
            wrong = crg.node_xy(1.05).reshape(-1, 2)
            miss = sample(cfg, [tuple(p) for p in wrong])[:, 2]
            check(np.max(np.abs(miss - want)) > 1e-3, f"{name}: wrong curvature not noticed")
        print(f"ok: {name}: {len(want)} nodes within float32 rounding")


def cell_centres(crg, cells, xy):
    return [tuple(xy[i:i + 2, j:j + 2].reshape(-1, 2).mean(axis=0)) for i, j in cells]


def case_slope_bank():
    for name, what in (("handmade_sloped.crg", "slope"), ("handmade_banked.crg", "banking")):
        crg = Crg(name)
        cells = crg.flat_cells()
        check(len(cells) >= 10, f"{name}: only {len(cells)} flat cells")
        rows = sample(config(crg_road(name)), cell_centres(crg, cells, crg.node_xy()))
        g = -rows[:, 3:5] / rows[:, 5:6]  # (dz/dx, dz/dy)
        s, b = crg.channel("slope"), crg.bank()
        for (i, j), (gx, gy) in zip(cells, g):
            vc = (crg.v[j] + crg.v[j + 1]) / 2
            if what == "slope":  # within segment i the reference line rises by slope_i+1 per m
                check(abs(gx - s[i + 1]) < 1e-9 and abs(gy) < 1e-9,
                      f"{name} cell {i},{j}: dz/dx {gx} vs slope {s[i + 1]}")
            else:  # banking, linear between cross sections, times v
                bc = (b[i] + b[i + 1]) / 2
                check(abs(gy - bc) < 1e-9 and abs(gx - (b[i + 1] - b[i]) / crg.du * vc) < 1e-9,
                      f"{name} cell {i},{j}: dz/dy {gy} vs banking {bc}")
        print(f"ok: {name}: {what} recovered in {len(cells)} flat cells within 1e-9")


def case_curvature():
    """Just left of the reference line (v = 1e-6) halfway along segment i, where the curvature is
    constant around the segment (the cross sections at its ends lean by opposite angles, so u's
    gradient there is the segment's direction t), the gradient is A t + B n with
    A = slope_i+1 + the grid's dz/du + v dbanking/du, B = banking + the grid's dz/dv (bilinear in cell (i, j0),
    j0 the long section at v = 0). The heading follows from the gradient's direction, the
    curvature from the headings."""
    name = "handmade_curved_banked_sloped.crg"
    crg = Crg(name)
    phi, s, b, z, v = crg.channel("phi"), crg.channel("slope"), crg.bank(), crg.z, crg.v
    j = int(np.flatnonzero(v == 0.0)[0])
    eps = 1e-6
    fv = eps / (v[j + 1] - v[j])
    segs, points, gradient = [], [], []
    x, y = crg.points()
    for i in range(1, len(phi) - 2):
        if abs((phi[i + 1] - phi[i]) - (phi[i + 2] - phi[i + 1])) > 1e-12:
            continue
        twist = z[i + 1, j + 1] - z[i + 1, j] - z[i, j + 1] + z[i, j]
        a = s[i + 1] + (z[i + 1, j] - z[i, j] + twist * fv + (b[i + 1] - b[i]) * eps) / crg.du
        bb = (b[i] + b[i + 1]) / 2 + (z[i, j + 1] - z[i, j] + twist * 0.5) / (v[j + 1] - v[j])
        if math.hypot(a, bb) < 0.02:
            continue
        t = np.array([x[i + 1] - x[i], y[i + 1] - y[i]]) / crg.du
        mid = np.array([x[i] + x[i + 1], y[i] + y[i + 1]]) / 2 + eps * np.array([-t[1], t[0]])
        segs.append(i)
        points.append(tuple(mid))
        gradient.append((a, bb))
    check(len(segs) >= 10, f"only {len(segs)} segments to recover the heading in: {segs}")
    rows = sample(config(crg_road(name)), points)
    heading = {}
    for i, row, (a, bb) in zip(segs, rows, gradient):
        heading[i] = math.atan2(-row[4] / row[5], -row[3] / row[5]) - math.atan2(bb, a)
        check(abs(heading[i] - phi[i + 1]) < 1e-8, f"segment {i}: heading {heading[i]} vs phi {phi[i + 1]}")
    curv = [((heading[c] - heading[a]) / ((c - a) * crg.du), (phi[c + 1] - phi[a + 1]) / ((c - a) * crg.du))
            for a, c in zip(segs, segs[1:])]
    worst = max(abs(got - want) for got, want in curv)
    check(worst < 1e-8, f"curvature off by {worst}")
    print(f"ok: {name}: the heading of {len(segs)} segments and the curvature between them "
          f"({', '.join(f'{c:+.4f}' for c, _ in curv)} 1/m) recovered within 1e-8")


def case_placement():
    crg = Crg("handmade_straight.crg")
    place = "[road.placement]\nu_m = 11.0\nv_m = 0.5\nx_m = 5.0\ny_m = -2.0\nz_m = 0.3\nheading_rad = 1.5707963267948966\n"
    cfg = config(crg_road("handmade_straight.crg", place))
    # (u, v) -> (x, y) = (5, -2) + R(pi/2) (u - 11, v - 0.5) = (5 - (v - 0.5), -2 + (u - 11))
    u = np.arange(len(crg.rows)) * crg.du
    pts = [(5.0 - (v - 0.5), -2.0 + (uu - 11.0)) for uu in u for v in crg.v]
    got = sample(cfg, pts)[:, 2]
    z_ref = crg.z[11, 4]  # the file's height at (u, v) = (11, 0.5)
    want = (crg.node_heights() - z_ref + 0.3).reshape(-1)
    check(np.max(np.abs(got - want)) < 1e-6, f"placed nodes off by {np.max(np.abs(got - want))}")
    print(f"ok: placement: {len(pts)} nodes where it puts them")


# ---- ISO 8608

def iso_road(road_class, seed, length_m=4000):
    return (f'[road]\nkind = "iso8608"\nclass = "{road_class}"\nseed = {seed}\nlength_m = {length_m}\n'
            'width_m = 4\nspacing_m = 0.05\n')


def fit_psd(z, dx):
    """Welch PSD, averaged in 10 bins a decade over 0.05-2.83 cycles/m, a line fitted in log-log:
    its slope and its value at n0 = 0.1 cycles/m."""
    n, g = signal.welch(z - z.mean(), fs=1 / dx, nperseg=4096, detrend="linear")
    edges = np.logspace(np.log10(0.05), np.log10(2.83), 18)
    ln, lg = [], []
    for a, b in zip(edges, edges[1:]):
        m = (n >= a) & (n < b)
        if m.any():
            ln.append(np.log10(n[m]).mean())
            lg.append(np.log10(g[m].mean()))
    slope, intercept = np.polyfit(ln, lg, 1)
    return slope, 10 ** (intercept + slope * np.log10(0.1))


def case_iso8608():
    dx, d = 0.1, 1.5  # every second grid node (Nyquist 5 cycles/m) of 4 km
    x = np.arange(10.0, 3990.0, dx)
    bands = {"C": (128e-6, 512e-6, 11), "E": (2048e-6, 8192e-6, 23)}
    for road_class, (lo, hi, seed) in bands.items():
        cfg = config(iso_road(road_class, seed))
        rows = sample(cfg, [(xx, d / 2) for xx in x] + [(xx, -d / 2) for xx in x])
        left, right = rows[:len(x), 2], rows[len(x):, 2]
        for track, z in (("left", left), ("right", right)):
            slope, g0 = fit_psd(z, dx)
            check(abs(slope + 2) <= 0.2, f"class {road_class} {track}: PSD slope {slope:.3f}")
            check(lo <= g0 < hi, f"class {road_class} {track}: G_d(n0) {g0:.3g} outside [{lo}, {hi})")
            print(f"ok: class {road_class} {track}: PSD slope {slope:.3f}, G_d(0.1) {g0 * 1e6:.1f}e-6 m^3")
        n, coh = signal.coherence(left, right, fs=1 / dx, nperseg=2048)
        model = (2 * np.pi * n * d * special.k1(2 * np.pi * n * d + 1e-300)) ** 2
        seen = []
        for a, b in ((0.03, 0.1), (0.1, 0.2), (0.2, 0.4), (0.4, 1.0)):
            m = (n >= a) & (n < b)
            check(abs(coh[m].mean() - model[m].mean()) < 0.1,  # 4 km: ~2 sd of the estimate
                  f"class {road_class}: coherence {coh[m].mean():.3f} vs model {model[m].mean():.3f} in {a}-{b}")
            seen.append(f"{a}-{b}: {coh[m].mean():.3f}/{model[m].mean():.3f}")
        print(f"ok: class {road_class}: squared coherence of tracks {d} m apart (measured/model "
              f"(2 pi n d K1(2 pi n d))^2) {', '.join(seen)}")
        check(np.std(left - right) > 0.2 * np.std(left), "the tracks are alike: no roll input")
    few = [(xx, 0.75) for xx in x[:200]]
    again = sample(config(iso_road("C", 11, 100)), few)
    check(np.array_equal(again[:, 2], sample(config(iso_road("C", 11, 100)), few)[:, 2]),
          "the same seed gave another road")
    other = sample(config(iso_road("C", 12, 100)), few)
    check(not np.allclose(again[:, 2], other[:, 2]), "another seed gave the same road")


# ---- the plane and bad input

def case_plane():
    rows = sample(config("", 'road_friction = 0.8\nroad_friction_right = 0.3'), [(3.0, 1.0), (3.0, -1.0)])
    check(list(rows[0, 2:]) == [0, 0, 0, 1, 0.8] and list(rows[1, 2:]) == [0, 0, 0, 1, 0.3],
          f"[model] plane: {rows}")
    rows = sample(config('[road]\nkind = "plane"\ngrade = 0.1\nfriction = 0.6\n'), [(10.0, 2.0)])
    n = np.array([-0.1, 0.0, 1.0]) / math.sqrt(1.01)
    check(abs(rows[0, 2] - 1.0) < 1e-15 and np.allclose(rows[0, 3:6], n, atol=1e-15) and rows[0, 6] == 0.6,
          f"[road] plane with grade 0.1: {rows}")
    print("ok: planes")


def case_opendrive():
    track = os.path.join(SRC, "tests", "io", "config", "opendrive", "test_track.xodr")
    road = (f'[road]\nkind = "opendrive"\nfile = "{track}"\nroad_id = "2"\nfriction = 0.9\n'
            '[road.placement]\nu_m = 20.0\nv_m = -1.75\n'
            '[[road.obstacle]]\nkind = "cleat"\ns_m = 5.0\nlength_m = 0.02\nwidth_m = 2.0\n'
            'height_m = 0.02\n'
            '[[road.obstacle]]\nkind = "bump"\ns_m = 10.0\nlength_m = 2.0\nheight_m = 0.1\n'
            '[[road.friction_zone]]\nmu = 0.2\nv_to_m = 0.0\n'
            '[[road.friction_zone]]\nmu = 0.5\ns_from_m = 30.0\n')
    xy = [(x, y) for x in (-3.0, 0.0, 4.999, 5.0, 5.01, 5.02, 5.021, 10.5, 11.0, 11.7, 29.9, 30.0,
                           60.0, 130.0) for y in (-2.0, -1.0, 0.0, 0.5, 1.0, 1.001)]
    rows = sample(config(road), xy)
    tan_phi = math.tan(0.04)
    for (x, y), row in zip(xy, rows):
        # the road point (s, t) = (20 + x, -1.75 + y) at height 1 + 0.05 s + t tan(phi), shifted
        # so that the placement's reference point is at z = 0; held beyond the road's end s = 100
        s = min(20.0 + x, 100.0)
        z = 0.05 * (s - 20.0) + y * tan_phi
        dz_dx = 0.05 if 20.0 + x < 100.0 else 0.0
        if 5.0 <= x <= 5.02 and abs(y) <= 1.0:
            z += 0.02  # the cleat: a block with vertical walls, on top at its edges
        if 10.0 <= x <= 12.0:
            z += 0.05 * (1 - math.cos(math.pi * (x - 10.0)))
            dz_dx += 0.05 * math.pi * math.sin(math.pi * (x - 10.0))
        n = np.array([-dz_dx, -tan_phi, 1.0])
        n /= np.linalg.norm(n)
        mu = 0.5 if x >= 30.0 else (0.2 if y <= 0.0 else 0.9)
        check(abs(row[2] - z) < 1e-9, f"z at ({x}, {y}): {row[2]} != {z}")
        check(np.allclose(row[3:6], n, atol=1e-9), f"normal at ({x}, {y}): {row[3:6]} != {n}")
        check(row[6] == mu, f"mu at ({x}, {y}): {row[6]} != {mu}")
    print(f"ok: OpenDRIVE road with obstacles and friction zones, {len(xy)} points")


def expect_error(cfg, points_text, *parts):
    r, pts = run_sample(cfg, points_text)
    check(r.returncode == 2, f"exit {r.returncode} for {parts}: {r.stderr}")
    check(r.stdout == "", f"stdout {r.stdout!r}")
    for part in parts:
        text = part.replace("POINTS", pts).replace("CONFIG", cfg)
        check(text in r.stderr, f"{text!r} not in {r.stderr!r}")


def case_bad_input():
    good = config(crg_road("handmade_straight.crg"))
    expect_error(good, "", "POINTS:1: expected the header x,y, not ''")
    expect_error(good, "x;y\n1;2\n", "POINTS:1: expected the header x,y")
    expect_error(good, "x,y\n1,2\n3,four\n", "POINTS:3: 'four' is not a finite number")
    expect_error(good, "x,y\n1,2,3\n", "POINTS:2: expected x,y (two numbers), not '1,2,3'")
    expect_error(good, "x,y\n1,nan\n", "POINTS:2: 'nan' is not a finite number")
    expect_error(good, "x,y\n1\n", "POINTS:2: expected x,y (two numbers), not '1'")
    pts = "x,y\n0,0\n"
    expect_error(config('[road]\nkind = "plane"\n', "road_grade = 0.1"), pts,
                 "CONFIG:4: [model] road_grade: the road is given by the [road] section")
    expect_error(config('[road]\nkind = "opendrive"\nfile = "x.xodr"\n'), pts,
                 "CONFIG:7: [road] file: file not found")
    expect_error(config('[road]\nkind = "plane"\n[[road.obstacle]]\nkind = "cleat"\n'), pts,
                 "CONFIG:7: [road].obstacle[0] length_m: missing required key")
    expect_error(config('[road]\nkind = "iso8608"\nclass = "F"\n'), pts,
                 "[road] class: \"F\": ISO 8608 classes are \"A\" to \"E\"")
    expect_error(config('[road]\nkind = "crg"\nfile = "nowhere.crg"\n'), pts, "CONFIG:7: [road] file")
    expect_error(config('[road]\nkind = "crg"\nfile = "' + os.path.join(SAMPLES, "fileref.crg") + '"\n'),
                 pts, "fileref.crg:46: $ROAD_CRG_FILE '../crg-txt/handmade_curved_banked_sloped.crg' not found")
    expect_error(config(crg_road("handmade_straight.crg") + "wobble = 1\n"), pts, "[road]", "wobble")
    qc = os.path.join(TMP, "qc.toml")
    open(qc, "w").write('[model]\nkind = "quarter-car"\n[road]\nkind = "plane"\n')
    expect_error(qc, pts, "[road]: needs [model] kind = \"vehicle\" or \"combination\"")
    print("ok: bad POINTS.csv and [road] sections: exit 2 with file:line")


CASES = {"nodes": case_nodes, "slope_bank": case_slope_bank, "curvature": case_curvature,
         "placement": case_placement, "iso8608": case_iso8608, "plane": case_plane,
         "bad_input": case_bad_input, "opendrive": case_opendrive}
if CASE not in CASES:
    fail(f"unknown case {CASE}")
CASES[CASE]()
