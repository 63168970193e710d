#!/usr/bin/python3
"""Sums the JUnit XML files under a directory (gtest, rostest, launch checks, fuzz) and prints
the line 'N passed, N failed' last (skipped tests, if any, on the line before). Exits 1 if anything failed or errored, or if no test ran.

Extra failures (steps that crashed before writing XML) are passed as --failed-step NAME."""
import argparse
import glob
import os
import sys
import xml.etree.ElementTree as ET


def count(path):
    passed = failed = skipped = 0
    names = []
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        return 0, 1, 0, ["%s: unreadable XML (%s)" % (path, e)]
    for case in root.iter("testcase"):
        if case.find("failure") is not None or case.find("error") is not None:
            failed += 1
            names.append("%s: %s.%s" % (os.path.basename(path), case.get("classname"), case.get("name")))
        elif case.find("skipped") is not None or case.get("status") == "notrun":
            skipped += 1
        else:
            passed += 1
    return passed, failed, skipped, names


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results_dir")
    ap.add_argument("--failed-step", action="append", default=[])
    args = ap.parse_args()
    total = [0, 0, 0]
    failures = []
    for path in sorted(glob.glob(os.path.join(args.results_dir, "**", "*.xml"), recursive=True)):
        p, f, s, names = count(path)
        total[0] += p
        total[1] += f
        total[2] += s
        failures += names
    for step in args.failed_step:
        total[1] += 1
        failures.append("step failed without a result file: " + step)
    for name in failures:
        print("FAILED:", name)
    if total[2]:
        print("%d skipped" % total[2])
    print("%d passed, %d failed" % (total[0], total[1]))
    if total[1] > 0 or total[0] == 0:
        sys.exit(1)


if __name__ == "__main__":
    main()
