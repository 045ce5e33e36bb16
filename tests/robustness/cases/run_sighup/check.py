import json
s = json.load(open("s.json"))
assert s["stop_reason"] == "signal", s["stop_reason"]
