import json, os, subprocess, sys
def run(n, config="config.toml"):
    r = subprocess.run([os.environ["RIG"], "run", "--config", config, "--offline", "--duration",
                        str(0.001 * n), "--lcm-url", "none", "--summary-json", "s.json",
                        "--overrun-log", "events.jsonl", "--lcm-log", "run.lcm"],
                       capture_output=True, text=True, timeout=20)
    assert r.returncode == 0, r.stderr
def cycles(path):
    return json.load(open(path))["cycles"]

for n in (1, 2, 3, 4):
    run(n)
assert [cycles("s.json"), cycles("s.json.1"), cycles("s.json.2")] == [4, 3, 2]
for name in ("s.json", "events.jsonl", "run.lcm"):
    assert os.path.exists(name + ".2") and not os.path.exists(name + ".3"), name
