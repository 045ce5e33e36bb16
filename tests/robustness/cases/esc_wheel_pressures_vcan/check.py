"""ESC bench: align the CAN run by the logged input validity (the first cycle all four wheel
pressures are valid from CAN), rerun the same pressures from the table driver offline with its
step at that simulated time, and compare the yaw rate 0.5 s (50 cycles of 10 ms) later."""
import csv
import json
import subprocess
from pathlib import Path

from case_checks import can, expect

BIN = Path(open("bin.path").read().strip())
PA = 30.0e5
WHEELS = ["unit1.axle1.left", "unit1.axle1.right", "unit1.axle2.left", "unit1.axle2.right"]
LATER = 50  # cycles of 10 ms: 0.5 s


def rows(path):
    return list(csv.DictReader(open(path)))


def first_valid(signals):
    for i, r in enumerate(signals):
        name = WHEELS[0] + ".brake_pressure_pa"
        if all(r[w + ".brake_pressure_pa_valid"] == "1" for w in WHEELS) and float(r[name]) > 0:
            return i
    return None


peer = json.load(open("peer.json"))
expect(can["frames_received"] == peer["sent"], f"the rig received all {peer['sent']} frames")
expect(can["bad_frames"] == 0 and can["unknown_frames"] == 0, "no frame rejected")
sig, state = rows("csv/RIG_SIGNALS.csv"), rows("csv/RIG_STATE.csv")
i0 = first_valid(sig)
expect(i0 is not None and i0 > 10, f"the pressures became valid after some coasting (row {i0})")
expect(i0 + LATER < len(sig), f"{len(sig) - i0} rows after the first valid frame")
run = sig[i0:i0 + LATER + 1]
expect([int(r["cycle"]) for r in run] == list(range(int(run[0]["cycle"]), int(run[0]["cycle"]) + LATER + 1)),
       "no cycle missing from the log in the 50 cycles compared")
for r in run:
    for w, want in zip(WHEELS, [PA, 0.0, PA, 0.0]):
        got = float(r[w + ".brake_pressure_pa"])
        expect(r[w + ".brake_pressure_pa_valid"] == "1" and abs(got - want) <= 1e-6 * PA,
               f"cycle {r['cycle']}: {w} input {got} Pa, from CAN {want} Pa")
t0 = float(sig[i0]["sim_time_s"])  # the cycle reads its inputs at t0 - 0.01 (the step before)

# The reference: the same sedan, start and pressures, from the table driver, stepping between the
# last cycle without and the first with pressure.
step = t0 - 0.01
text = open("reference.toml").read().replace("T0_ROWS", (
    f"[[0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [{step - 0.005!r}, 0.0, 0.0, 0.0, 0.0, 0.0], "
    f"[{step - 0.004!r}, 0.0, {PA!r}, 0.0, {PA!r}, 0.0], [{step + 10.0!r}, 0.0, {PA!r}, 0.0, {PA!r}, 0.0]]"))
open("reference_run.toml", "w").write(text)
subprocess.run([BIN / "rig", "run", "--config", "reference_run.toml", "--offline", "--lcm-url", "none",
                "--lcm-log", "ref.lcm", "--duration", f"{t0 + 1.0:.3f}"], check=True, capture_output=True)
subprocess.run([BIN / "rig-log2csv", "ref.lcm", "refcsv"], check=True, capture_output=True)
ref_sig, ref_state = rows("refcsv/RIG_SIGNALS.csv"), rows("refcsv/RIG_STATE.csv")
j0 = next(j for j, r in enumerate(ref_state) if abs(float(r["wheel0_brake_pressure_pa"]) - PA) < 1.0)
expect(abs(float(ref_sig[j0]["sim_time_s"]) - t0) < 1e-9,
       f"aligned: the reference brakes from t {ref_sig[j0]['sim_time_s']}, the CAN run from {t0}")


def at(state_rows, i, col):
    return float(state_rows[i][col])


# Before the pressures: both runs coasted the same way (deterministic model, same start).
for col in ("unit0_vx_mps", "unit0_wz_radps"):
    a, b = at(state, i0 - 1, col), at(ref_state, j0 - 1, col)
    expect(abs(a - b) <= 1e-9 * max(1.0, abs(b)), f"coasting {col}: CAN run {a}, reference {b}")
# The brake torque includes the rolling resistance (about 10-16 N m here, vehicle_workspace.h).
for k in range(LATER + 1):
    s = state[i0 + k]
    for w, braked in zip(range(4), [True, False, True, False]):
        p = float(s[f"wheel{w}_brake_pressure_pa"])
        t = float(s[f"wheel{w}_brake_torque_nm"])
        expect((abs(p - PA) < 1.0 and abs(t) > 300.0) if braked else (p == 0.0 and abs(t) < 50.0),
               f"cycle {s['cycle']}: wheel{w} applied {p} Pa, brake torque {t} N m")
yaw_can, yaw_ref = at(state, i0 + LATER, "unit0_wz_radps"), at(ref_state, j0 + LATER, "unit0_wz_radps")
dev = abs(yaw_can - yaw_ref) / abs(yaw_ref)
print(f"t0 {t0:.2f} s (cycle {sig[i0]['cycle']}), yaw rate 0.5 s later: CAN {yaw_can:.9f} rad/s, "
      f"table driver {yaw_ref:.9f} rad/s, deviation {100 * dev:.3g} %")
expect(yaw_ref > 0.05, f"one-sided (left) braking yaws left: {yaw_ref} rad/s")
expect(dev <= 0.05, f"yaw rate within 5 %: CAN {yaw_can}, table driver {yaw_ref}")
json.dump({"t0_s": t0, "cycle0": int(sig[i0]["cycle"]), "yaw_can_radps": yaw_can,
           "yaw_table_radps": yaw_ref, "deviation": dev}, open("esc_result.json", "w"))
