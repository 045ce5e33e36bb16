import json
s = json.load(open("s.json"))
assert s["stop_reason"] == "duration", s["stop_reason"]
