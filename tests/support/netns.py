"""Runs a Python test inside a network namespace of its own, with multicast routed over lo
(as tests/integration/lcm/common.sh does for the shell tests): `in_netns()` re-executes the
calling script inside a fresh namespace and returns only there; the outer process exits with
the inner one's code and removes the namespace. Not root or no `ip`: exit 77 (skipped)."""
import os
import random
import shutil
import subprocess
import sys

SKIP = 77


def in_netns():
    if os.environ.get("RIG_TEST_NETNS"):
        return
    if os.geteuid() != 0 or shutil.which("ip") is None:
        print("SKIP: needs root and iproute2 for a network namespace")
        sys.exit(SKIP)
    name = f"rig-py-{os.getpid()}-{random.randrange(1 << 16)}"
    if subprocess.run(["ip", "netns", "add", name]).returncode != 0:
        print("SKIP: cannot create a network namespace")
        sys.exit(SKIP)
    try:
        ns = ["ip", "netns", "exec", name]
        subprocess.run(ns + ["sysctl", "-q", "-w", "net.core.rmem_max=8388608"],
                       stderr=subprocess.DEVNULL)
        subprocess.run(["ip", "-n", name, "link", "set", "lo", "up"], check=True)
        subprocess.run(["ip", "-n", name, "route", "add", "224.0.0.0/4", "dev", "lo"], check=True)
        env = dict(os.environ, RIG_TEST_NETNS=name)
        code = subprocess.run(ns + [sys.executable] + sys.argv, env=env).returncode
    finally:
        subprocess.run(["ip", "netns", "del", name])
    sys.exit(code)
