"""The structure of the (Ant) JUnit XML schema, which Jenkins and GitLab read, checked element by
element with xml.etree: what `rig run --junit` and `rig sweep`'s junit.xml must have.

  <testsuites name tests failures errors time>          (the sums of its suites)
    <testsuite id package name timestamp hostname tests failures errors time>
      <properties><property name value/>...</properties>
      <testcase name classname time> [<failure message type>|<error message type>] </testcase>*
      <system-out/> <system-err/>
"""
import re
import xml.etree.ElementTree as ET

from rig_checks import check

TIMESTAMP = re.compile(r"^\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}$")  # ISO 8601, no zone
DECIMAL = re.compile(r"^-?\d+(\.\d+)?$")


def check_attrs(el, required, where):
    missing = [a for a in required if a not in el.attrib]
    check(not missing, f"{where}: attributes {required} present (missing {missing})")


def check_int(el, name, where):
    check(re.fullmatch(r"\d+", el.get(name, "")) is not None, f"{where} {name}={el.get(name)} is an int")
    return int(el.get(name))


def check_suite(suite, where):
    """<testsuite>: id package name timestamp hostname tests failures errors time; children
    properties, testcase*, system-out, system-err, in that order."""
    check_attrs(suite, ["id", "package", "name", "timestamp", "hostname", "tests", "failures",
                        "errors", "time"], where)
    check(TIMESTAMP.match(suite.get("timestamp")) is not None, f"{where}: timestamp "
          f"{suite.get('timestamp')} is ISO 8601 without a zone")
    check(suite.get("hostname") != "", f"{where}: hostname not empty")
    check(DECIMAL.match(suite.get("time")) is not None, f"{where}: time is a decimal")
    tags = [c.tag for c in suite]
    check(tags and tags[0] == "properties" and tags[-2:] == ["system-out", "system-err"] and
          all(t == "testcase" for t in tags[1:-2]),
          f"{where}: children properties, testcase*, system-out, system-err ({tags})")
    for p in suite.find("properties"):
        check(p.tag == "property" and set(p.attrib) == {"name", "value"}, f"{where}: property "
              f"{p.attrib} has name and value")
    cases = suite.findall("testcase")
    n_fail = n_err = 0
    for c in cases:
        check_attrs(c, ["name", "classname", "time"], f"{where} testcase")
        check(DECIMAL.match(c.get("time")) is not None, f"{where} testcase time is a decimal")
        kids = list(c)
        check(len(kids) <= 1 and all(k.tag in ("failure", "error") for k in kids),
              f"{where} testcase {c.get('name')}: at most one failure or error ({[k.tag for k in kids]})")
        for k in kids:
            check_attrs(k, ["message", "type"], f"{where} {k.tag}")
            n_fail += k.tag == "failure"
            n_err += k.tag == "error"
    check(check_int(suite, "tests", where) == len(cases), f"{where}: tests = {len(cases)} testcases")
    check(check_int(suite, "failures", where) == n_fail, f"{where}: failures = {n_fail}")
    check(check_int(suite, "errors", where) == n_err, f"{where}: errors = {n_err}")
    return cases


def check_junit(path):
    """The whole document; returns its <testsuite>s."""
    root = ET.parse(path).getroot()
    check(root.tag == "testsuites", f"root <testsuites> ({root.tag})")
    check_attrs(root, ["name", "tests", "failures", "errors", "time"], "testsuites")
    suites = root.findall("testsuite")
    check(len(suites) == len(list(root)), "testsuites holds only testsuite elements")
    for key in ("tests", "failures", "errors"):
        total = sum(int(s.get(key)) for s in suites)
        check(check_int(root, key, "testsuites") == total, f"testsuites {key} = the suites' sum {total}")
    for i, s in enumerate(suites):
        check_suite(s, f"testsuite {i}")
        check(s.get("id") == str(i), f"testsuite ids from 0 ({s.get('id')})")
    return suites
