# The summary names the fault (kind, unit, time, value beyond its limit) and counts the cycles run.
import json
s = json.load(open("summary.json"))
f = s["vehicle_fault"]
assert "any" == "any" or f["kind"] == "any", f
assert f["unit"] == 0 and f["value"] > f["limit"] > 0, f
assert s["cycles"] == 1, s["cycles"]
