"""What the CAN cases' check.py scripts share: the run's CAN counters (summary.json), its events
(events.jsonl) and `expect`, which fails the case with both shown. run_cases.py puts this folder
on PYTHONPATH for every check script."""
import json
import sys

can = json.load(open("summary.json"))["can"]
events = [json.loads(line) for line in open("events.jsonl")]


def expect(ok, what):
    if not ok:
        print(what, "| can:", can, "| events:",
              [(e["event"], e.get("detail")) for e in events if e["event"] != "deadline_miss"])
        sys.exit(1)
