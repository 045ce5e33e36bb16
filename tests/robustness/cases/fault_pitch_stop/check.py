# The summary names the fault (kind, unit, time, value beyond its limit) and counts the cycles run.
import json
s = json.load(open("summary.json"))
f = s["vehicle_fault"]
assert "pitch" == "any" or f["kind"] == "pitch", f
assert f["unit"] == 0 and f["value"] > f["limit"] > 0, f
assert s["cycles"] == 207, s["cycles"]
