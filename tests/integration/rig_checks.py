"""The integration scripts' verdicts: a failed check prints FAIL and exits 1."""
import sys


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def check(cond, msg, verbose=False):
    if not cond:
        fail(msg)
    if verbose:
        print("ok:", msg)
