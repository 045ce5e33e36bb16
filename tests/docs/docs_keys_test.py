#!/usr/bin/python3
"""Every configuration key the rig reads for [can], the CAN mapping, [lcm], [[kpi]], [[event]] and
the sweep specification is in the guide.

Greps the key names out of the sources (the first string argument of each StrictTable reader,
`error` and `location` call, and the values of each `choice`) and fails on any that the guide
(docs/*.md, as `key` in backticks) does not name. Keys of io/can go in docs/can.md (or the pages
of the mapping's later parts: e2e.md, restbus.md, signals.md); keys of io/lcm in docs/lcm.md.

    docs_keys_test.py SOURCE_DIR
"""
import pathlib
import re
import sys

READERS = ("number|number_in|integer|integer_in|boolean|string|choice|existing_path|numbers|"
           "integers|number_rows|tables|table|optional_table|has|error|location")
KEY = re.compile(r"\.(?:%s)\(\s*\"([A-Za-z_][A-Za-z_0-9]*)\"" % READERS)
CHOICE = re.compile(r"\.choice\(\s*\"\w+\"\s*,\s*\"[^\"]*\"\s*,\s*\{([^}]*)\}")

# source folder -> the guide pages its keys may be documented in
ROOMS = {
    "io/can": ["can.md", "e2e.md", "restbus.md", "signals.md"],
    "io/lcm": ["lcm.md"],
    "rig/kpi": ["kpis.md"],
    "rig/driver/scenario_events.cpp": ["scenarios.md"],
    "rig/sweep/sweep_spec.cpp": ["sweeps.md"],
}
# sections of the run configuration (rig/config.cpp) -> their page
SECTIONS = {"can": "can.md", "lcm": "lcm.md", "routing": "routing.md"}


def keys_in(source: str) -> set[str]:
    keys = set(KEY.findall(source))
    for values in CHOICE.findall(source):
        keys |= set(re.findall(r"\"([A-Za-z_][A-Za-z_0-9]*)\"", values))
    return keys


def documented(docs: pathlib.Path, pages: list[str]) -> set[str]:
    text = "".join((docs / p).read_text() for p in pages if (docs / p).exists())
    return set(re.findall(r"`([^`\n]+)`", text))


def missing_keys(root: pathlib.Path) -> list[str]:
    docs = root / "docs"
    problems = []
    for folder, pages in ROOMS.items():
        named = documented(docs, pages)
        place = root / folder
        for src in [place] if place.is_file() else sorted(place.rglob("*.cpp")):
            for key in sorted(keys_in(src.read_text())):
                # `key`, `"key"`, `key = ...`, `[key]`, `[[key]]`, `[[rx.key]]` all name it
                if not any(re.fullmatch(r"\[*(\w+\.)?\"?%s\"?\]*( = .*)?" % re.escape(key), n)
                           for n in named):
                    problems.append(f"{src.relative_to(root)}: key '{key}' is not in "
                                    f"docs/{' or docs/'.join(pages)}")
    config_keys = keys_in((root / "rig/config.cpp").read_text())
    for section, page in SECTIONS.items():
        if section not in config_keys:
            problems.append(f"rig/config.cpp no longer reads [{section}]: update this test")
        elif f"[{section}]" not in documented(docs, [page]):
            problems.append(f"docs/{page} does not name the section `[{section}]`")
    index = (docs / "README.md").read_text()
    for page in ["can.md", "lcm.md", "routing.md", "signals.md", "restbus.md", "e2e.md",
                 "worked-example.md", "kpis.md", "scenarios.md", "sweeps.md"]:
        if f"({page})" not in index:
            problems.append(f"docs/README.md does not link {page}")
    if "docs/README.md" not in (root / "README.md").read_text():
        problems.append("README.md does not link docs/README.md")
    return problems


def main() -> int:
    root = pathlib.Path(sys.argv[1])
    # The grep must find the keys at all (a reader renamed would silently pass every doc).
    found = set().union(*(keys_in(src.read_text())
                          for src in (root / "io/can/mapping").glob("*.cpp")))
    for expected in ["message", "timeout_ms", "modulus", "fallback", "invalid", "crc8_sae_j1850"]:
        if expected not in found:
            print(f"docs_keys_test: the grep no longer finds '{expected}' in io/can/mapping")
            return 1
    problems = missing_keys(root)
    for p in problems:
        print(p)
    print(f"docs_keys_test: {len(problems)} undocumented key(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
