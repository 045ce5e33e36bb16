import json, os, subprocess, sys
def run(n, config="config.toml"):
    r = subprocess.run([os.environ["RIG"], "run", "--config", config, "--offline", "--duration",
                        str(0.001 * n), "--lcm-url", "none", "--summary-json", "s.json",
                        "--overrun-log", "events.jsonl", "--lcm-log", "run.lcm"],
                       capture_output=True, text=True, timeout=20)
    assert r.returncode == 0, r.stderr
def cycles(path):
    return json.load(open(path))["cycles"]

for n in range(1, 13):
    run(n)
assert cycles("s.json") == 12 and cycles("s.json.1") == 11 and cycles("s.json.10") == 2
assert not os.path.exists("s.json.11")
