import json
import sys

can = json.load(open("summary.json"))["can"]
events = [json.loads(line) for line in open("events.jsonl")]


def expect(ok, what):
    if not ok:
        print(what, "| can:", can, "| events:",
              [(e["event"], e.get("detail")) for e in events if e["event"] != "deadline_miss"])
        sys.exit(1)


rx = [e for e in events if e["event"] == "out_of_range" and e["detail"].startswith("rx ")]
expect(len(rx) == 1, "the first clamp at once; the other 4 within the second are counted")
expect(rx[0]["detail"] == "rx EPS_Status.EPS_MotorTorque: 20 outside [-15, 15], clamped to 15;"
       " 1 since the last report", "message, signal, value, range, clamp")
