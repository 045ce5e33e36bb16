#!/usr/bin/python3
"""docs/worked-example.md works as written: every `rig check` and offline `rig run` command of
its ```sh blocks is run from the repository root with the built rig, and must exit 0 (checks
print `FILE: KIND: OK`). The restbus warning the guide shows must be the one the rig prints,
and the guide's mapping snippets must be lines of the real mapping file.

Usage: worked_example_test.py --bin BUILD/bin --repo REPO
"""

import argparse
import pathlib
import re
import shlex
import subprocess
import sys


def sh_commands(markdown):
    """The `rig ...` lines of the ```sh blocks."""
    commands, in_sh = [], False
    for line in markdown.splitlines():
        if line.startswith("```"):
            in_sh = line.strip() == "```sh"
            continue
        if in_sh and line.startswith("rig "):
            commands.append(line.split("#")[0].strip())
    return commands


def toml_snippet_lines(markdown):
    """Non-comment lines of the ```toml blocks that show the mapping (they contain `dbc`,
    `message`, `model`, `node` or `name` keys)."""
    lines, in_toml = [], False
    for line in markdown.splitlines():
        if line.startswith("```"):
            in_toml = line.strip() == "```toml"
            continue
        text = line.split("#")[0].strip()
        if in_toml and re.match(r"(dbc|message|model|node|name|set|counter|checksum) = ", text):
            lines.append(text)
    return lines


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--repo", required=True)
    args = ap.parse_args()
    repo = pathlib.Path(args.repo)
    guide = (repo / "docs/worked-example.md").read_text()
    rig = str(pathlib.Path(args.bin) / "rig")
    fails = []
    commands = [c for c in sh_commands(guide)
                if c.startswith("rig check") or (c.startswith("rig run") and "--offline" in c)]
    if len(commands) < 4:
        fails.append(f"only {len(commands)} rig check/offline run commands found in the guide")
    warning = re.search(r"^rig: warning: .*restbus node.*$", guide, re.M)
    for command in commands:
        argv = [rig] + shlex.split(command)[1:]
        p = subprocess.run(argv, cwd=repo, capture_output=True, text=True, timeout=120)
        ok = p.returncode == 0 and (": OK" in p.stdout or command.startswith("rig run"))
        print(f"{'ok' if ok else 'FAIL'}: {command} (exit {p.returncode})")
        if not ok:
            fails.append(f"{command}: exit {p.returncode}\n{p.stdout}{p.stderr}")
        if "mapping" in command or "ecu-bench" in command:
            if warning is None or warning.group(0) not in p.stderr:
                fails.append(f"{command}: the guide's warning is not what the rig prints:\n"
                             f"{p.stderr}")
    mapping = (repo / "tests/io/can/restbus/ecu-mapping.toml").read_text()
    bench = (repo / "tests/io/can/restbus/ecu-bench.toml").read_text()
    real = {l.split("#")[0].strip() for l in (mapping + bench).splitlines()}
    for line in toml_snippet_lines(guide):
        if line not in real:
            fails.append(f"the guide shows `{line}`, which the example files do not have")
    for f in fails:
        print("FAIL: " + f, file=sys.stderr)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
