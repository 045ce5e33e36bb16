#!/usr/bin/python3
"""Finite-element reference for the five-link leaf spring (issue 17 item 2).

The same leaf as model/vehicle/leaf_spring (the [axle.leaf_spring] table of a TOML file), built
independently as a geometrically nonlinear beam: 2-D co-rotational Euler-Bernoulli elements
(Crisfield, "Non-linear Finite Element Analysis of Solids and Structures", vol. 1, sec. 7.3: a
linear beam in a frame that follows the element's chord), along the free arc of each arm. The
front eye sits on the bushing (two translational springs to the frame, free to rotate), the rear
eye hangs on the shackle (a pinned two-force link, an axial element 1e10 N/m stiff), the axle
is clamped to the leaf over the seat length (a rigid block of stiff beams: seat edges, seat
centre, axle centre). Loads on the axle centre are applied in increments, each solved by Newton
with the consistent tangent; the tangent stiffness at the axle follows by static condensation.

Load cases (the working range): vertical load on the axle from -1.5 kN (rebound: the leaf
pulled down) to 1.5 x 7.5 kN with no fore-aft force and no moment (the axle free to find its
fore-aft travel and wind-up); and wind-up: the static 7.5 kN plus a moment about +y (a brake
torque) from -2 to +2 kN m.

    /usr/bin/python3 leaf_fe_reference.py van_leaf.toml --out leaf_fe_reference.json
    /usr/bin/python3 leaf_fe_reference.py van_leaf.toml --check leaf_fe_reference.json

--check recomputes and compares with the file (so the committed numbers cannot go stale);
--self-test checks the element against textbook values first (always run).
"""

import argparse
import json
import math
import sys
import tomllib

import numpy as np

STATIC_LOAD_N = 7500.0
VERTICAL_LOADS_N = [-1500.0 + 750.0 * k for k in range(18)]  # -1.5 .. 11.25 kN
WINDUP_MOMENTS_NM = [-2000.0 + 500.0 * k for k in range(9)]


def scale_loads(static_load_n):
    """--static-load-n: the same load cases scaled to another leaf's static load (a truck's)."""
    global STATIC_LOAD_N, VERTICAL_LOADS_N, WINDUP_MOMENTS_NM
    f = static_load_n / STATIC_LOAD_N
    STATIC_LOAD_N = static_load_n
    VERTICAL_LOADS_N = [f * x for x in VERTICAL_LOADS_N]
    WINDUP_MOMENTS_NM = [f * x for x in WINDUP_MOMENTS_NM]
RIGID_FACTOR = 1e4  # the seat block's beams: this much stiffer in bending than the leaf
RIGID_AXIAL_FACTOR = 1e2  # and this much axially (more only adds round-off)
SHACKLE_AXIAL_NPM = 1e10
LEAF_THICKNESS_M = 0.012  # for EA = 12 EI / t^2 of the equivalent leaf (axial strain is tiny)


def beam_element(x1, x2, d1, d2, ei, ea):
    """Internal force (6) and tangent (6x6) of a co-rotational beam, nodes (ux, uz, theta)."""
    dx0, dz0 = x2 - x1
    l0 = math.hypot(dx0, dz0)
    c0, s0 = dx0 / l0, dz0 / l0
    dx, dz = (x2 - x1) + (d2[:2] - d1[:2])  # chord from the displacements: less round-off
    l = math.hypot(dx, dz)
    c, s = dx / l, dz / l
    alpha = math.atan2(c0 * s - s0 * c, c0 * c + s0 * s)  # rigid rotation of the chord
    u_l = (l * l - l0 * l0) / (l + l0)
    t1, t2 = d1[2] - alpha, d2[2] - alpha
    n = ea * u_l / l0
    m1 = ei / l0 * (4.0 * t1 + 2.0 * t2)
    m2 = ei / l0 * (2.0 * t1 + 4.0 * t2)
    r = np.array([-c, -s, 0.0, c, s, 0.0])
    z = np.array([s, -c, 0.0, -s, c, 0.0])
    b = np.vstack([r, np.eye(6)[2] - z / l, np.eye(6)[5] - z / l])
    d = np.zeros((3, 3))
    d[0, 0] = ea / l0
    d[1:, 1:] = ei / l0 * np.array([[4.0, 2.0], [2.0, 4.0]])
    f = b.T @ np.array([n, m1, m2])
    k = b.T @ d @ b + n / l * np.outer(z, z) + (m1 + m2) / l**2 * (np.outer(r, z) + np.outer(z, r))
    return f, k


class Structure:
    """Nodes (free positions), beams, nodal springs to the frame, and one shackle."""

    def __init__(self):
        self.nodes = []
        self.beams = []  # (i, j, ei, ea)
        self.springs = []  # (node, kx, kz)
        self.shackle = None  # (node, pin, length, axial stiffness)

    def node(self, x, z):
        self.nodes.append(np.array([x, z], dtype=float))
        return len(self.nodes) - 1

    def ndof(self):
        return 3 * len(self.nodes)

    def forces(self, u):
        """Internal forces and tangent at displacements u."""
        f = np.zeros(self.ndof())
        k = np.zeros((self.ndof(), self.ndof()))
        for i, j, ei, ea in self.beams:
            idx = np.r_[3 * i:3 * i + 3, 3 * j:3 * j + 3]
            fe, ke = beam_element(self.nodes[i], self.nodes[j], u[3 * i:3 * i + 3],
                                  u[3 * j:3 * j + 3], ei, ea)
            f[idx] += fe
            k[np.ix_(idx, idx)] += ke
        for i, kx, kz in self.springs:
            f[3 * i:3 * i + 2] += np.array([kx, kz]) * u[3 * i:3 * i + 2]
            k[3 * i, 3 * i] += kx
            k[3 * i + 1, 3 * i + 1] += kz
        if self.shackle is not None:
            i, pin, length, axial = self.shackle
            v = self.nodes[i] + u[3 * i:3 * i + 2] - pin
            l = np.linalg.norm(v)
            e = v / l
            n = axial * (l - length)
            f[3 * i:3 * i + 2] += n * e
            k[3 * i:3 * i + 2, 3 * i:3 * i + 2] += axial * np.outer(e, e) + n / l * (
                np.eye(2) - np.outer(e, e))
        return f, k


def newton(structure, u, load, fixed=(), tol=None, max_iter=50):
    """Solves f_int(u) = load with the dofs in `fixed` held at their values in u; by default to
    1e-9 of the largest load (at least 1e-4 N: the stiff rigid-seat and shackle elements
    leave round-off near 1e-5 N; 1e-4 N moves the leaf by 1e-9 m)."""
    if tol is None:
        tol = 1e-9 * max(1e5, np.max(np.abs(load)))
    free = np.setdiff1d(np.arange(structure.ndof()), np.array(fixed, dtype=int))
    for _ in range(max_iter):
        f, k = structure.forces(u)
        r = (f - load)[free]
        if np.max(np.abs(r)) < tol:
            return u
        u = u.copy()
        u[free] -= np.linalg.solve(k[np.ix_(free, free)], r)
    raise RuntimeError("Newton did not converge")


def arc_points(edge, span, rise, direction, count):
    """`count` + 1 points at equal arc length on the arm's circular arc (from the seat edge)."""
    radius = (span * span + rise * rise) / (2.0 * rise)
    end = math.atan2(span, radius - rise)
    phis = np.linspace(0.0, end, count + 1)
    pts = [(edge[0] + direction * radius * math.sin(p), edge[1] + radius * (1.0 - math.cos(p)))
           for p in phis]
    return pts, radius * end


class Leaf:
    """The leaf of `params` meshed with `elements` beam elements along its two arms."""

    def __init__(self, p, elements=40):
        self.p = p
        s = Structure()
        h, half = p["leaf_above_axle_m"], 0.5 * p["seat_length_m"]
        front_span = p["seat_from_front_eye_m"] - half
        rear_span = p["eye_to_eye_m"] - p["seat_from_front_eye_m"] - half
        f_pts, f_arc = arc_points((half, h), front_span, p["free_camber_m"], 1.0, 1)
        r_pts, r_arc = arc_points((-half, h), rear_span, p["free_camber_m"], -1.0, 1)
        n_front = round(elements * f_arc / (f_arc + r_arc))
        f_pts, _ = arc_points((half, h), front_span, p["free_camber_m"], 1.0, n_front)
        r_pts, _ = arc_points((-half, h), rear_span, p["free_camber_m"], -1.0, elements - n_front)
        self.axle = s.node(0.0, 0.0)
        centre = s.node(0.0, h)
        ei_max = max(p["front_bending_stiffness_nm2"], p["rear_bending_stiffness_nm2"])
        rigid = (RIGID_FACTOR * ei_max, RIGID_AXIAL_FACTOR * 12.0 * ei_max / LEAF_THICKNESS_M**2)
        s.beams.append((self.axle, centre) + rigid)
        for pts, ei in ((f_pts, p["front_bending_stiffness_nm2"]),
                        (r_pts, p["rear_bending_stiffness_nm2"])):
            ea = 12.0 * ei / LEAF_THICKNESS_M**2
            prev = s.node(*pts[0])
            s.beams.append((centre, prev) + rigid)
            for q in pts[1:]:
                cur = s.node(*q)
                s.beams.append((prev, cur, ei, ea))
                prev = cur
            if pts is f_pts:
                self.eye = prev
            else:
                self.rear_eye = prev
        s.springs.append((self.eye, p["eye_bushing_x_npm"], p["eye_bushing_z_npm"]))
        psi0, ls = p["shackle_angle_free_rad"], p["shackle_length_m"]
        self.pin = s.nodes[self.rear_eye] + ls * np.array([math.sin(psi0), math.cos(psi0)])
        s.shackle = (self.rear_eye, self.pin, ls, SHACKLE_AXIAL_NPM)
        self.s = s
        self.u = np.zeros(s.ndof())

    def axle_dofs(self):
        return np.arange(3 * self.axle, 3 * self.axle + 3)

    def solve(self, fx, fz, my, steps=1):
        """Loads the axle centre (force x, z; moment about +y) from the current state."""
        start = self.s.forces(self.u)[0][self.axle_dofs()]
        target = np.array([fx, fz, -my])  # the node's rotation turns x towards z: -pitch
        for k in range(1, steps + 1):
            load = np.zeros(self.s.ndof())
            load[self.axle_dofs()] = start + (target - start) * k / steps
            self.u = newton(self.s, self.u, load)

    def result(self):
        a = self.u[self.axle_dofs()]
        f, k = self.s.forces(self.u)
        i = self.axle_dofs()
        o = np.setdiff1d(np.arange(self.s.ndof()), i)
        kc = k[np.ix_(i, i)] - k[np.ix_(i, o)] @ np.linalg.solve(k[np.ix_(o, o)], k[np.ix_(o, i)])
        t = np.diag([1.0, 1.0, -1.0])
        kc = t @ kc @ t  # (x, z, pitch)
        c = np.linalg.inv(kc)
        eye = self.s.nodes[self.rear_eye] + self.u[3 * self.rear_eye:3 * self.rear_eye + 2]
        return {
            "x_m": a[0], "z_m": a[1], "pitch_rad": -a[2],
            "shackle_rad": math.atan2(self.pin[0] - eye[0], self.pin[1] - eye[1]),
            "rate_npm": 1.0 / c[1, 1], "stiffness_zz_npm": kc[1, 1],
            "windup_free_nmprad": 1.0 / c[2, 2], "windup_held_nmprad": kc[2, 2],
            "stiffness": kc.tolist(),
        }


def self_test():
    """The element against the textbook before it is trusted."""
    rng = np.random.default_rng(1)
    x1, x2 = np.array([0.1, 0.2]), np.array([0.5, 0.35])
    d = rng.normal(scale=0.02, size=6)
    f, k = beam_element(x1, x2, d[:3], d[3:], 3000.0, 2e8)
    k_fd = np.zeros((6, 6))
    for j in range(6):
        e = np.zeros(6)
        e[j] = 1e-7
        fp, _ = beam_element(x1, x2, (d + e)[:3], (d + e)[3:], 3000.0, 2e8)
        fm, _ = beam_element(x1, x2, (d - e)[:3], (d - e)[3:], 3000.0, 2e8)
        k_fd[:, j] = (fp - fm) / 2e-7
    assert np.allclose(k, k_fd, rtol=1e-5, atol=1e-3 * np.max(np.abs(k))), "tangent != FD"
    # cantilever, tip load: P L^2 / EI = 0.01 -> P L^3 / 3 EI; P L^2 / EI = 1 -> the elastica's tip
    # deflection 0.30172 L down and 0.05643 L in (Mattiasson 1981, Int. J. Num. Meth. Eng. 17)
    for load_factor, w_ref, u_ref in ((1e-2, 1e-2 / 3.0, 0.0), (1.0, 0.30172, 0.05643)):
        s = Structure()
        n = 40
        for j in range(n + 1):
            s.node(j / n, 0.0)
        s.beams = [(j, j + 1, 1.0, 1e5) for j in range(n)]
        load = np.zeros(s.ndof())
        u = np.zeros(s.ndof())
        for step in range(1, 11):
            load[3 * n + 1] = -load_factor * step / 10
            u = newton(s, u, load, fixed=(0, 1, 2), tol=1e-8)
        assert abs(-u[3 * n + 1] - w_ref) < 2e-3 * w_ref, (load_factor, u[3 * n + 1])
        assert abs(-u[3 * n] - u_ref) < 2e-3 * max(u_ref, w_ref), (load_factor, u[3 * n])


def compute(params, elements):
    leaf = Leaf(params, elements)
    out = {"vertical": {}, "windup": {}}
    rows = []
    for fz in VERTICAL_LOADS_N:  # from free: rebound first, then up the load range
        if fz == VERTICAL_LOADS_N[0]:
            leaf.solve(0.0, fz, 0.0, steps=4)
        else:
            leaf.solve(0.0, fz, 0.0)
        rows.append(dict(load_n=fz, **leaf.result()))
    for key in rows[0]:
        out["vertical"][key] = [r[key] for r in rows]
    rows = []
    leaf = Leaf(params, elements)
    leaf.solve(0.0, STATIC_LOAD_N, 0.0, steps=10)
    for my in WINDUP_MOMENTS_NM:
        leaf.solve(0.0, STATIC_LOAD_N, my, steps=2)
        rows.append(dict(moment_nm=my, **leaf.result()))
    for key in rows[0]:
        out["windup"][key] = [r[key] for r in rows]
    return out


def flat(params, result, elements):
    """One flat JSON object (keys section_quantity), easy to read from C++."""
    doc = {"elements": elements, "static_load_n": STATIC_LOAD_N}
    doc.update({"param_" + k: v for k, v in params.items()})
    for section, values in result.items():
        for key, column in values.items():
            if key != "stiffness":
                doc[section + "_" + key] = column
    doc["vertical_stiffness"] = [x for m in result["vertical"]["stiffness"] for x in sum(m, [])]
    return doc


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("params", help="TOML with [axle.leaf_spring]")
    ap.add_argument("--elements", type=int, default=40)
    ap.add_argument("--out")
    ap.add_argument("--check")
    ap.add_argument("--static-load-n", type=float, default=STATIC_LOAD_N,
                    help="the leaf's static load (default the van's 7500 N); scales all cases")
    args = ap.parse_args()
    if args.static_load_n != STATIC_LOAD_N:
        scale_loads(args.static_load_n)
    self_test()
    with open(args.params, "rb") as fh:
        params = tomllib.load(fh)["axle"]["leaf_spring"]
    doc = flat(params, compute(params, args.elements), args.elements)
    if args.out:
        with open(args.out, "w") as fh:
            json.dump(doc, fh, indent=1)
            fh.write("\n")
    if args.check:
        with open(args.check) as fh:
            ref = json.load(fh)
        bad = [k for k in doc if k not in ref or not np.allclose(
            np.atleast_1d(doc[k]), np.atleast_1d(ref[k]), rtol=1e-6, atol=1e-9)]
        if bad:
            print("leaf_fe_reference: stale reference, recompute with --out:", bad)
            return 1
        print("leaf_fe_reference: %s reproduced (%d keys)" % (args.check, len(doc)))
    v = doc
    for j, fz in enumerate(v["vertical_load_n"]):
        print("Fz %7.0f N: z %.5f x %.5f pitch %.5f psi %.4f rate %.0f wind-up free %.0f held %.0f"
              % (fz, v["vertical_z_m"][j], v["vertical_x_m"][j], v["vertical_pitch_rad"][j],
                 v["vertical_shackle_rad"][j], v["vertical_rate_npm"][j],
                 v["vertical_windup_free_nmprad"][j], v["vertical_windup_held_nmprad"][j]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
