import csv
import json

from case_checks import can, events, expect  # noqa: F401

peer = json.load(open("peer.json"))
expect(peer["bad"] == [], f"every rig frame passes the Python E2E/CRC check: {peer['bad'][:5]}")
expect(all(n >= 20 for n in peer["checked"].values()), f"frames checked: {peer['checked']}")
expect(peer["counter_gaps"] == 0, "the rig's counters advance by one per frame sent")
# Per E2E message 1 wrong Data ID, per the generic CRC message 1 wrong CRC; per E2E message a
# repeated and a skipped counter.
expect(can["checksum_failures"] == 5, "4 wrong Data IDs + 1 wrong generic CRC")
expect(can["counter_failures"] == 8, "4 x (one repeated + one skipped counter)")
expect(can["bad_frames"] == 0 and can["unknown_frames"] == 0, "no other rejection")
expect(can["frames_received"] == peer["sent"], f"the rig received all {peer['sent']} frames")
rows = list(csv.DictReader(open("csv/RIG_SIGNALS.csv")))
for name, value in peer["final"].items():
    # The last value the model had from CAN before the peer fell silent (then the message times
    # out and its fallback applies, flagged invalid).
    valid = [r for r in rows if r[name + "_valid"] == "1"]
    expect(len(valid) > 0, f"{name} was valid at some cycle")
    got = float(valid[-1][name])
    expect(abs(got - value) <= 1e-9 * max(1.0, abs(value)),
           f"{name}: the last accepted value {value} reaches the model input, logged {got}")
