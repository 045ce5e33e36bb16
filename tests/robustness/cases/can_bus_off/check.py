import json
import sys

can = json.load(open("summary.json"))["can"]
events = [json.loads(line) for line in open("events.jsonl")]


def expect(ok, what):
    if not ok:
        print(what, "| can:", can, "| events:",
              [(e["event"], e.get("detail")) for e in events if e["event"] != "deadline_miss"])
        sys.exit(1)


expect(can["bus_state"] == "bus-off", "bus-off in the summary")
e = [e for e in events if e["event"] == "can_bus_off"]
expect(len(e) == 1 and e[0]["detail"].startswith("vcan0: bus up -> bus-off"), "one event")
status = [l.rstrip() for l in open("rig.err") if l.startswith("rig: cycles")]
expect(any(l.endswith(", CAN bus-off") for l in status), f"status lines: {status}")
