"""3-unit TX = LCM: decode every recorded frame by hand (units.dbc: Intel, unsigned except the
yaw rates), find the logged cycle its unit1.position_x_m tag names, and compare each signal with
that cycle's RIG_SIGNALS value (by catalogue name) and RIG_STATE unit/wheel arrays within half a
DBC step (the rig rounds to nearest)."""
import csv
import json

from case_checks import can, expect

# id: [(catalogue name, RIG_STATE column, start bit, length, signed, factor)]
MESSAGES = {
    0x300: [("unit1.position_x_m", "unit0_x_m", 0, 24, False, 0.001),
            ("unit2.yaw_rate_radps", "unit1_wz_radps", 24, 16, True, 0.0001),
            ("unit3.speed_x_mps", "unit2_vx_mps", 40, 12, False, 0.01),
            ("unit2.axle1.left.load_n", "wheel4_load_n", 52, 12, False, 5.0)],
    0x301: [("unit1.position_x_m", "unit0_x_m", 0, 24, False, 0.001),
            ("unit3.yaw_rate_radps", "unit2_wz_radps", 24, 16, True, 0.0001),
            ("unit2.speed_x_mps", "unit1_vx_mps", 40, 12, False, 0.01),
            ("unit3.wheel_rr.load_n", "wheel11_load_n", 52, 12, False, 5.0)],
}


def decode(data, start, length, signed, factor):
    raw = (int.from_bytes(data, "little") >> start) & ((1 << length) - 1)
    if signed and raw >> (length - 1):
        raw -= 1 << length
    return raw * factor


sig = list(csv.DictReader(open("csv/RIG_SIGNALS.csv")))
state = list(csv.DictReader(open("csv/RIG_STATE.csv")))
expect(len(sig) == len(state) and all(a["cycle"] == b["cycle"] for a, b in zip(sig, state)),
       "RIG_SIGNALS and RIG_STATE have the same cycles")
pos = [float(r["unit1.position_x_m"]) for r in sig]
frames = [json.loads(line) for line in open("frames.jsonl")]
cycles = {0x300: [], 0x301: []}
worst = {}
for f in frames:
    expect(f["id"] in MESSAGES, f"only the mapping's messages on the bus: {f}")
    data = bytes.fromhex(f["data"])
    spec = MESSAGES[f["id"]]
    tag = decode(data, *spec[0][2:])
    i = min(range(len(pos)), key=lambda k: abs(pos[k] - tag))
    expect(abs(pos[i] - tag) <= 0.0005 + 1e-9, f"frame {f}: tag {tag} m names no logged cycle")
    cycles[f["id"]].append(int(sig[i]["cycle"]))
    for name, column, start, length, signed, factor in spec[1:]:
        got = decode(data, start, length, signed, factor)
        logged, arrays = float(sig[i][name]), float(state[i][column])
        expect(logged == arrays, f"cycle {sig[i]['cycle']}: {name} {logged} = {column} {arrays}")
        err = abs(got - logged)
        worst[name] = max(worst.get(name, 0.0), err / factor)
        expect(err <= 0.5 * factor + 1e-9,
               f"cycle {sig[i]['cycle']}: {name} on CAN {got}, logged {logged} (step {factor})")
n_a, n_b = len(cycles[0x300]), len(cycles[0x301])
expect(n_a >= 50 and n_b >= 25,  # 139..200 and 125..126 seen (skipped periods in the VM)
       f"frames compared: {n_a} RIG_UnitsA, {n_b} RIG_UnitsB")
expect(can["frames_sent"] == n_a + n_b and can["send_dropped"] == 0,
       f"every sent frame recorded: {n_a + n_b} of {can['frames_sent']}")
gaps_a = {b - a for a, b in zip(cycles[0x300], cycles[0x300][1:])}
gaps_b = {b - a for a, b in zip(cycles[0x301], cycles[0x301][1:])}
print(f"frames {n_a} + {n_b}, cycle gaps A {sorted(gaps_a)} B {sorted(gaps_b)}, "
      f"worst |CAN - LCM| in DBC steps {worst}")
expect(min(gaps_a) >= 1 and min(gaps_b) >= 1, "one frame per message per cycle at most")
json.dump({"frames_a": n_a, "frames_b": n_b, "gaps_a": sorted(gaps_a), "gaps_b": sorted(gaps_b),
           "worst_steps": worst}, open("units_result.json", "w"))
