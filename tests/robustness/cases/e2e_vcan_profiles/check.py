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
last = list(csv.DictReader(open("csv/RIG_SIGNALS.csv")))[-1]
for name, value in peer["final"].items():
    got = float(last[name])
    expect(abs(got - value) <= 1e-9 * max(1.0, abs(value)),
           f"{name}: the last accepted value {value} reaches the model input, logged {got}")
    expect(last[name + "_valid"] in ("1", "true", "True"), f"{name} valid: {last[name + '_valid']}")
