import json
text = open("kept.jsonl").read()
assert text.endswith("\n"), "the log does not end after a whole line"
lines = text.splitlines()
records = [json.loads(line) for line in lines]  # every line is whole JSON
assert records[0]["event"] == "start", records[0]
s = json.load(open("s.json"))
w = s["write_failures"]
assert s["exit_code"] == 3 and w and w[0]["output"].startswith("overrun log disk/events.jsonl"), s
print(f"{len(lines)} whole lines kept, {w[0]['count']} not written")
