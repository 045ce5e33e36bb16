import json
import sys

can = json.load(open("summary.json"))["can"]
events = [json.loads(line) for line in open("events.jsonl")]


def expect(ok, what):
    if not ok:
        print(what, "| can:", can, "| events:",
              [(e["event"], e.get("detail")) for e in events if e["event"] != "deadline_miss"])
        sys.exit(1)


expect(can["error_frames"] == 1, "one error frame")
expect(can["bus_state"] == "error-passive", "an error frame sets error-passive")
e = [e for e in events if e["event"] == "can_error_passive"]
expect(len(e) == 1 and e[0]["detail"].startswith("vcan0: bus up -> error-passive"), "one event")
