#!/usr/bin/env python3
"""Checks that every test ctest knows runs with PW_DEVICE=cpu and PW_VALIDATION=1: what
its ENVIRONMENT and ENVIRONMENT_MODIFICATION properties make of the caller's environment,
each variable on its own (an over-escaped ';' once made one variable of two).

Usage: check_test_environment.py CTEST BUILD_DIR
"""
import json
import subprocess
import sys

REQUIRED = {"PW_DEVICE": "cpu", "PW_VALIDATION": "1"}


def effective_environment(test):
    """The variables the test's properties set (None: unset), as ctest applies them."""
    env = {}
    props = {p["name"]: p["value"] for p in test.get("properties", [])}
    for entry in props.get("ENVIRONMENT", []):
        name, _, value = entry.partition("=")
        env[name] = value
    for entry in props.get("ENVIRONMENT_MODIFICATION", []):
        name, _, rest = entry.partition("=")
        op, _, value = rest.partition(":")
        if op == "set":
            env[name] = value
        elif op in ("unset", "reset"):
            env[name] = None
        else:  # appends and prepends depend on the caller: not a fixed value
            env[name] = f"<{op}:{value}>"
    return env


def main():
    ctest, build_dir = sys.argv[1], sys.argv[2]
    listing = subprocess.run([ctest, "--test-dir", build_dir, "--show-only=json-v1"],
                             capture_output=True, text=True, check=True).stdout
    tests = json.loads(listing)["tests"]
    wrong = []
    for test in tests:
        env = effective_environment(test)
        missing = [f"{k}={v}" for k, v in REQUIRED.items() if env.get(k) != v]
        if missing:
            wrong.append(f"{test['name']}: lacks {' '.join(missing)} (sets {env or 'nothing'})")
    print(f"{len(tests)} tests, {len(wrong)} without PW_DEVICE=cpu and PW_VALIDATION=1")
    for line in wrong:
        print("  " + line)
    if not tests:
        print("error: ctest lists no tests")
        return 1
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
