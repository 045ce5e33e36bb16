import json
s = json.load(open("s.json"))
assert s["exit_code"] == 3, s
w = s["write_failures"]
assert len(w) == 1 and w[0]["output"].startswith("LCM log disk/run.lcm"), w
assert w[0]["count"] > 0, w
ev = [json.loads(l) for l in open("events.jsonl")]
assert any(e.get("event") == "write_failed" and "LCM log disk/run.lcm" in e["detail"] for e in ev), ev
