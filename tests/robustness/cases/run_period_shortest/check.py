import json
s = json.load(open("s.json"))
assert s["cycles"] == 100, s["cycles"]
assert s["period_s"] == 1e-5, s["period_s"]
