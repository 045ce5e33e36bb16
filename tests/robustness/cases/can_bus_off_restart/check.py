import json
import sys

can = json.load(open("summary.json"))["can"]
events = [json.loads(line) for line in open("events.jsonl")]


def expect(ok, what):
    if not ok:
        print(what, "| can:", can, "| events:",
              [(e["event"], e.get("detail")) for e in events if e["event"] != "deadline_miss"])
        sys.exit(1)


expect(can["bus_state"] == "up", "up again after the restart")
expect(can["error_frames"] == 2, "two error frames")
names = [e["event"] for e in events if e["event"].startswith("can_")]
expect(names == ["can_bus_off", "can_bus_up"], "bus-off, then up")
