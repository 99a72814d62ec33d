#!/usr/bin/env python3
"""What did not run: reads CTest's JUnit report (ctest --output-junit FILE) and lists every test
that CTest skipped or did not run, and every test whose output has a "SKIPPED (kind): why" line
(a doctest case that returned early, tests/skip.hpp; a script run through tests/run_test.sh).

    skip_report.py JUNIT_XML

Outside CI it only lists them. Under CI=true it fails (exit 1) when anything did not run for a
reason FIELDCODEC_CI_MAY_SKIP does not list (.ci/run keeps that list and says why): a test
skipped or disabled without a "SKIPPED (kind)" line, or with a kind not in the list. The tests
themselves already fail under CI=true (run_test.sh, skip.hpp); this is the second check, on what
CTest reports, so that a test that skips some other way cannot pass CI either.
"""

import os
import re
import sys
import xml.etree.ElementTree as ET

MARK = re.compile(r"SKIPPED \(([A-Za-z0-9_-]+)\): ?(.*)")


def main(argv):
    if len(argv) != 2:
        print("usage: skip_report.py JUNIT_XML", file=sys.stderr)
        return 2
    try:
        root = ET.parse(argv[1]).getroot()
    except (OSError, ET.ParseError) as e:
        print(f"skip_report: cannot read {argv[1]}: {e}", file=sys.stderr)
        return 2
    ci = os.environ.get("CI") == "true"
    allowed = set(re.split(r"[ ,]+", os.environ.get("FIELDCODEC_CI_MAY_SKIP", "").strip())) - {""}

    cases = root.findall(".//testcase")
    rows = []  # (test, status, kinds, reasons)
    for case in cases:
        name = case.get("name", "?")
        status = case.get("status", "run")
        out = case.findtext("system-out") or ""
        marks = [MARK.search(line) for line in out.splitlines()]
        marks = [m for m in marks if m]
        if status not in ("notrun", "disabled") and not marks:
            continue  # ran (passed, or failed: CTest says so)
        kinds = sorted({m.group(1) for m in marks})
        reasons = [m.group(2) for m in marks] or [status]
        rows.append((name, status, kinds, reasons))

    bad = []
    for name, status, kinds, reasons in rows:
        what = {"notrun": "skipped", "disabled": "disabled", "run": "ran, skipped a case"}.get(
            status, status)
        ok = status != "disabled" and kinds and all(k in allowed for k in kinds)
        if ci and not ok:
            bad.append(name)
        flag = "" if not ci else ("  [allowed under CI]" if ok else "  [NOT allowed under CI]")
        print(f"skip_report: {name}: {what} ({', '.join(kinds) or 'no kind'}){flag}")
        for r in dict.fromkeys(reasons):
            print(f"    {r}")
    print(f"skip_report: {len(cases)} tests, {len(rows)} with something that did not run"
          + (f"; CI may skip: {' '.join(sorted(allowed)) or 'nothing'}" if ci else ""))
    if bad:
        print("skip_report: FAILED: under CI=true these did not run for a reason "
              "FIELDCODEC_CI_MAY_SKIP does not list: " + ", ".join(bad))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
