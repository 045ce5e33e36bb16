#!/usr/bin/python3
"""scripts/virtual-ecu's modes without CAN (issue 15 item 7): the rack model's static
equilibrium under a tie-rod load against a hand calculation from the vehicle file, the lka
overlay, the park-assist controller's limits, the rack bench's frames (counter, CRC-8, scaling).

    virtual_ecu_modes_test.py SOURCE_DIR
"""
import importlib.machinery
import importlib.util
import math
import pathlib
import sys
import types


def load_script(src):
    path = str(src / "scripts" / "virtual-ecu")
    loader = importlib.machinery.SourceFileLoader("virtual_ecu", path)
    spec = importlib.util.spec_from_loader("virtual_ecu", loader)
    module = importlib.util.module_from_spec(spec)
    loader.exec_module(module)
    return module


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    return ok


def rack_statics(ecu, src):
    """Held at the robot angle A against a tie-rod load F, the rack comes to rest where
    (T_tb + T_max tanh(G T_tb / T_max)) / i = F (friction 0 at rest), c_r (A - th) = T_tb and
    T_tb = c (th - u / i)."""
    p = ecu.load_rack_params(src / "config" / "vehicles" / "sedan.toml")
    i, c = p["rack_per_pinion_m_per_rad"], p["torsion_bar_stiffness_nmpr"]
    cr, tmax, g = p["robot_stiffness_nmpr"], p["assist_max_nm"], p["assist_gain"]
    a, f = 0.5, 800.0
    lo, hi = -50.0, 50.0
    for _ in range(200):  # bisection on T_tb
        mid = 0.5 * (lo + hi)
        if (mid + tmax * math.tanh(g * mid / tmax)) / i > f:
            hi = mid
        else:
            lo = mid
    tb = 0.5 * (lo + hi)
    th = a - tb / cr
    u = i * (th - tb / c)
    rack = ecu.Rack(p)
    args = types.SimpleNamespace(robot_angle_rad=a, step_time_s=0.0, ramp_s=0.1)
    for k in range(8000):
        rack.step(1e-3, ecu.robot_angle(args, k * 1e-3), f)
    print(f"rack statics: u {rack.y[1]:.6e} m (hand {u:.6e}), wheel {rack.y[0]:.5f} rad "
          f"(hand {th:.5f}), T_tb {tb:.4f} N m, speed {rack.z[1]:.2e} m/s")
    ok = check(abs(rack.y[1] - u) < 1e-3 * abs(u), "rack travel within 0.1 % of the hand value")
    ok &= check(abs(rack.y[0] - th) < 1e-3 * abs(th), "wheel angle within 0.1 %")
    ok &= check(u < a * i, "the load pushes the rack back (u < A i_SB)")
    return ok


def lka_and_park(ecu):
    args = types.SimpleNamespace(lka_torque_nm=2.0, lka_period_s=2.0, lka_start_s=1.0)
    ok = check(ecu.lka_overlay_nm(args, 0.5) == 0.0, "lka: no overlay before its start")
    ok &= check(abs(ecu.lka_overlay_nm(args, 1.5) - 2.0) < 1e-12, "lka: sine peak a quarter period in")
    args.lka_period_s = 0.0
    ok &= check(ecu.lka_overlay_nm(args, 1.0) == 2.0, "lka: period 0 is a step")
    pa = types.SimpleNamespace(target_angle_rad=1.0, kp=20.0, ki=10.0, kd=1.0, max_torque_nm=5.0)
    ctl = ecu.AngleController(pa)
    ok &= check(ctl.torque_nm(0.0, 0.0, 0.01) == 5.0, "park-assist: torque limited")
    ctl = ecu.AngleController(pa)
    t = ctl.torque_nm(0.9, 0.0, 0.01)
    ok &= check(abs(t - (20 * 0.1 + 10 * 0.1 * 0.01)) < 1e-12, "park-assist: PI on the error")
    ok &= check(ctl.torque_nm(1.0, 2.0, 0.01) < 0, "park-assist: the D term damps the speed")
    return ok


def rack_frames(ecu, src):
    import canmatrix.formats
    db = canmatrix.formats.loadp_flat(str(src / "config" / "can" / "rack-bench.dbc"))
    frame, pos = ecu.find_signal(db, r"RackPositionMeasured", None)
    speed = ecu.find_in_frame(frame, r"RackSpeedMeasured", None)
    args = types.SimpleNamespace(checksum="crc8")
    w = ecu.FrameWriter(frame, args)
    m0 = w.message({pos: 0.012345, speed: -0.0421})
    m1 = w.message({pos: 0.0, speed: 0.0})
    d = frame.decode(bytes(m0.data))
    ok = check(abs(float(d["RackPositionMeasured"].phys_value) - 0.012345) <= 0.5e-5,
               "position to 1e-5 m")
    ok &= check(abs(float(d["RackSpeedMeasured"].phys_value) + 0.0421) <= 0.5e-4, "speed to 1e-4 m/s")
    ok &= check((m1.data[6] & 0x0F) == ((m0.data[6] & 0x0F) + 1) % 16, "alive counter advances")
    ok &= check(m0.data[7] == ecu.crc8_sae_j1850(bytes(m0.data[:7])), "CRC-8 over bytes 0..6")
    ok &= check(frame.arbitration_id.id == 384 and ecu.cycle_time_s(frame, 10.0) == 0.001,
                "RACK_Position: id 0x180, 1 ms")
    return ok


def main(argv):
    src = pathlib.Path(argv[1])
    ecu = load_script(src)
    ok = rack_statics(ecu, src)
    ok &= lka_and_park(ecu)
    ok &= rack_frames(ecu, src)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
