import json
import sys

can = json.load(open("summary.json"))["can"]
events = [json.loads(line) for line in open("events.jsonl")]


def expect(ok, what):
    if not ok:
        print(what, "| can:", can, "| events:",
              [(e["event"], e.get("detail")) for e in events if e["event"] != "deadline_miss"])
        sys.exit(1)


# Every frozen frame is rejected, also those after a timeout (before: 1 in 4 passed, as a
# timeout started a new counter sequence).
expect(can["counter_failures"] == 30, "30 frozen frames, 30 counter failures")
expect(can["checksum_failures"] == 0 and can["bad_frames"] == 0, "only counter failures")
