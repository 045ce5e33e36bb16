"""Starts the rig with SIGTERM pending (blocked, raised before exec): it must still stop cleanly."""
import json, os, signal, subprocess, sys
def pending_sigterm():
    signal.pthread_sigmask(signal.SIG_BLOCK, [signal.SIGTERM])
    os.kill(os.getpid(), signal.SIGTERM)
args = [os.environ["RIG"], "run", "--config", "config.toml", "--duration", "30",
        "--overrun-log", "events.jsonl", "--summary-json", "s.json", "--lcm-url", "none"]
p = subprocess.run(args, preexec_fn=pending_sigterm, stderr=subprocess.PIPE, text=True,
                   timeout=20)
sys.stderr.write(p.stderr)
s = json.load(open("s.json"))
assert s["stop_reason"] == "signal", s["stop_reason"]
sys.exit(p.returncode)
