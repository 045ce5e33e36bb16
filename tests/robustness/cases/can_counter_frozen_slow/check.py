import json
import sys

can = json.load(open("summary.json"))["can"]
events = [json.loads(line) for line in open("events.jsonl")]


def expect(ok, what):
    if not ok:
        print(what, "| can:", can, "| events:",
              [(e["event"], e.get("detail")) for e in events if e["event"] != "deadline_miss"])
        sys.exit(1)


# Before the latch each of these frames opened a new sequence and read valid.
expect(can["counter_failures"] == 12, "12 frozen frames, 12 counter failures")
