import json
s = json.load(open("s.json"))
assert s["exit_code"] == 3, s
w = s["write_failures"]
assert len(w) == 1 and w[0]["output"].startswith("overrun log disk/events.jsonl: No space"), w
assert w[0]["count"] >= 2, w
