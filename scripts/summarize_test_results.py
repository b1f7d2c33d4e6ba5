#!/usr/bin/python3
"""Summarise the gtest / rostest JUnit XML files under a catkin test_results directory.

Prints one line per suite (file), the failed test cases with the first line of their message, and,
as the very last line, `N passed, M failed` (`, K skipped` appended when some were skipped).
Exit status: 0 when at least one test case ran and none failed, 1 otherwise.

Usage: summarize_test_results.py RESULTS_DIR [EXPECTED_SUITE ...]
An EXPECTED_SUITE (e.g. gtest-test_unit, the result file's name without .xml) that has no result
file counts as one failed test case: its executable did not build or its test did not run. A result
file without any test case counts as one failed test case too.
"""

import os
import sys
import xml.etree.ElementTree as ET


# rostest writes one <testcase> of this class per test node into rostest-*.xml: it fails when the
# node did not run or report, and passes otherwise. The node's own cases are in a rosunit-*.xml
# file, so a passing launch case is not counted again.
ROSTEST_LAUNCH_CLASS = "rostest.runner.RosTest"


def iter_xml_files(root):
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames.sort()
        for name in sorted(filenames):
            if name.endswith(".xml"):
                yield os.path.join(dirpath, name)


def short_message(text, limit=300):
    """The message on one line (gtest puts file:line first, then the expectation), shortened."""
    lines = []
    for line in (text or "").strip().splitlines():
        line = line.strip()
        if line.startswith(("Traceback", 'File "')):
            break  # a Python traceback follows the message
        if line:
            lines.append(line)
    message = " | ".join(lines)
    return message if len(message) <= limit else message[: limit - 3] + "..."


def classify(case):
    """Returns ('passed' | 'failed' | 'skipped', message) for one <testcase> element."""
    for tag in ("failure", "error"):
        child = case.find(tag)
        if child is not None:
            return "failed", short_message(child.get("message") or child.text)
    if case.find("skipped") is not None:
        return "skipped", ""
    # gtest marks disabled tests with status="notrun" and GTEST_SKIP with result="skipped".
    if case.get("status") == "notrun" or case.get("result") in ("skipped", "suppressed"):
        return "skipped", ""
    return "passed", ""


def summarize_file(path):
    """Returns (suite label, passed, failed, skipped, [failure lines])."""
    label = os.path.splitext(os.path.basename(path))[0]
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError) as exc:
        return label, 0, 1, 0, ["unreadable result file %s: %s" % (path, exc)]
    passed = failed = skipped = 0
    failures = []
    cases = list(root.iter("testcase"))
    for case in cases:
        outcome, message = classify(case)
        if case.get("classname") == ROSTEST_LAUNCH_CLASS and outcome == "passed":
            continue
        if outcome == "passed":
            passed += 1
        elif outcome == "skipped":
            skipped += 1
        else:
            failed += 1
            name = "%s.%s" % (case.get("classname", "?"), case.get("name", "?"))
            failures.append("%s: %s" % (name, message) if message else name)
    # A suite-level error with no test case (e.g. a crash before any test ran) still counts.
    if passed + failed + skipped == 0:
        errors = int(root.get("errors", "0") or 0) + int(root.get("failures", "0") or 0)
        if errors:
            failed += errors
            failures.append("suite reported %d error(s) without test cases" % errors)
    # A gtest run that selected no test writes an empty file: a rostest whose --gtest_filter names no suite
    # of its executable (test/integration/*.test) would otherwise pass.
    if not cases and failed == 0:
        failed = 1
        failures.append("no test case ran (a --gtest_filter that matches no test?)")
    return label, passed, failed, skipped, failures


def suite_key(name):
    """gtest-test_unit.xml -> gtest-test_unit; rostest-test_integration_case.test -> rostest-test_integration_case."""
    return name.split(".")[0]


def main(argv):
    if len(argv) < 2:
        print("usage: summarize_test_results.py RESULTS_DIR [EXPECTED_SUITE ...]", file=sys.stderr)
        return 2
    root = argv[1]
    expected = argv[2:]
    total_passed = total_failed = total_skipped = 0
    files = list(iter_xml_files(root)) if os.path.isdir(root) else []
    if not os.path.isdir(root):
        print("error: no test results directory %s" % root, file=sys.stderr)
    elif not files:
        print("error: no test result XML files under %s" % root, file=sys.stderr)
    found = set()
    for path in files:
        label = os.path.basename(path)
        found.add(suite_key(label[len("MISSING-"):] if label.startswith("MISSING-") else label))
    results = [summarize_file(path) for path in files]
    for suite in expected:
        if suite_key(suite) not in found:
            results.append((suite, 0, 1, 0, ["no result: the test executable did not build or did not run"]))
    for label, passed, failed, skipped, failures in results:
        status = "FAILED" if failed else "ok"
        line = "%-6s %s: %d passed, %d failed" % (status, label, passed, failed)
        if skipped:
            line += ", %d skipped" % skipped
        if passed + failed + skipped == 0 and label.startswith("rostest-"):
            line = "%-6s %s: test nodes ran (their cases are in the rosunit-* results)" % (status, label)
        print(line)
        for failure in failures:
            print("         - %s" % failure)
        total_passed += passed
        total_failed += failed
        total_skipped += skipped
    if total_passed + total_failed == 0:
        print("error: no test case ran", file=sys.stderr)
    sys.stderr.flush()
    summary = "%d passed, %d failed" % (total_passed, total_failed)
    if total_skipped:
        summary += ", %d skipped" % total_skipped
    print(summary)
    sys.stdout.flush()
    return 0 if total_failed == 0 and total_passed > 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
