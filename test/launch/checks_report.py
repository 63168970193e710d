"""Runs named checks (each returns None or a failure text), prints one line per check and writes
them as JUnit test cases: the shared end of test/launch/check_package.py and
check_install_space.py."""
import os
import time
import xml.etree.ElementTree as ET


def run_checks(suite_name, checks, junit_path=None):
    """checks: [(name, callable)]. Returns the number of failures."""
    suite = ET.Element("testsuite", name=suite_name)
    failures = 0
    started = time.time()
    for name, check in checks:
        t0 = time.time()
        failure = check()
        seconds = time.time() - t0
        case = ET.SubElement(suite, "testcase", classname=suite_name, name=name,
                             time="%.2f" % seconds)
        if failure:
            failures += 1
            ET.SubElement(case, "failure", message=failure.splitlines()[0]).text = failure
            print("FAIL %s: %s" % (name, failure))
        else:
            print("ok   %s (%.1f s)" % (name, seconds))
    suite.set("tests", str(len(checks)))
    suite.set("failures", str(failures))
    suite.set("time", "%.1f" % (time.time() - started))
    if junit_path:
        os.makedirs(os.path.dirname(os.path.abspath(junit_path)), exist_ok=True)
        ET.ElementTree(suite).write(junit_path, encoding="unicode", xml_declaration=True)
    print("%s: %d passed, %d failed (%.1f s)" % (suite_name, len(checks) - failures, failures,
                                               time.time() - started))
    return failures
