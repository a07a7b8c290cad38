#!/usr/bin/env python3
"""Every ctest test carries exactly one of the labels tier:fast and tier:long.

    check_tier_labels.py BUILD_DIR           the tests ctest lists in BUILD_DIR
    check_tier_labels.py --json FILE         the same check on saved `ctest --show-only=json-v1` output

Prints one line per test that breaks the rule ("<test>: no tier label", "<test>: both tier labels")
and exits 1 when there is any; else prints how many tests each tier holds and exits 0.
"""
import json
import subprocess
import sys

TIERS = ("tier:fast", "tier:long")


def listed_tests(argv):
    if len(argv) == 3 and argv[1] == "--json":
        with open(argv[2], encoding="utf-8") as f:
            return json.load(f)["tests"]
    if len(argv) == 2:
        out = subprocess.run(["ctest", "--test-dir", argv[1], "--show-only=json-v1"], capture_output=True,
                             text=True, check=True).stdout
        return json.loads(out)["tests"]
    sys.exit(__doc__)


def labels_of(test):
    for prop in test.get("properties", []):
        if prop.get("name") == "LABELS":
            return prop.get("value", [])
    return []


def main(argv):
    tests = listed_tests(argv)
    counts = {tier: 0 for tier in TIERS}
    wrong = []
    for test in tests:
        tiers = [label for label in labels_of(test) if label in TIERS]
        if not tiers:
            wrong.append(f"{test['name']}: no tier label")
        elif len(tiers) > 1:
            wrong.append(f"{test['name']}: both tier labels")
        else:
            counts[tiers[0]] += 1
    for line in wrong:
        print(line)
    if wrong:
        print(f"{len(wrong)} of {len(tests)} tests break the rule: each carries exactly one of {', '.join(TIERS)}")
        return 1
    print(f"{len(tests)} tests: {counts['tier:fast']} tier:fast, {counts['tier:long']} tier:long")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
