"""Runs the rig in real time with its stderr on a full pipe that nobody reads."""
import json, os, subprocess, sys
r, w = os.pipe()
os.set_blocking(w, False)
try:
    while True:
        os.write(w, b"x" * 4096)
except BlockingIOError:
    pass
os.set_blocking(w, True)  # as a parent that never reads: full and blocking
args = [os.environ["RIG"], "run", "--config", "config.toml", "--duration", "1",
        "--overrun-log", "events.jsonl", "--summary-json", "s.json", "--lcm-url", "none"]
p = subprocess.Popen(args, stderr=w, stdout=subprocess.DEVNULL)
os.close(w)
rc = p.wait(timeout=20)
s = json.load(open("s.json"))
print(f"exit {rc}, stop {s['stop_reason']}, cycles {s['cycles']}", file=sys.stderr)
sys.exit(0 if rc == 0 and s["stop_reason"] == "duration" and s["cycles"] > 0 else 1)
