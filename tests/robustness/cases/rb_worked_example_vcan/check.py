from case_checks import can, events, expect  # noqa: F401

# 2 s of 1 ms cycles: 3 x 200 (10 ms) + 2 x 100 (20 ms) + 40 + 20 + 2 = 862 frames at most
# (fewer if the slow VM skipped periods); the ECU is absent: no frame in, at most one timeout.
expect(can["bus_state"] == "up", "bus up")
expect(431 <= can["frames_sent"] <= 870, "frames_sent between half of 862 and 862 + one cycle")
expect(can["send_dropped"] == 0 and can["checksum_failures"] == 0, "nothing dropped or bad")
expect(can["frames_received"] == 0 and can["timeouts"] <= 1, "the ECU is absent")
ids = set()
for line in open("candump.log"):
    parts = line.split()
    if len(parts) == 3:
        ids.add(parts[2].split("#")[0])
want = {"0C0", "1A0", "100", "180", "200", "280", "3E0", "2C0"}
expect(ids == want, f"ids on the bus {sorted(ids)}, expected {sorted(want)} (no 7DF: GW_Diag)")
