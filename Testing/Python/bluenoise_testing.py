"""Check reporting shared by the Python tests: every check prints a line, and
finish() exits non-zero when any failed (ctest reads the exit code)."""
import sys

SKIP = 125  # ctest SKIP_RETURN_CODE: a prerequisite is missing
FAILURES = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message, flush=True)
    if not condition:
        FAILURES.append(message)
    return condition


def finish():
    if FAILURES:
        print("\n%d check(s) failed:" % len(FAILURES))
        for f in FAILURES:
            print("  - " + f)
        sys.exit(1)
    print("\nall checks passed")
    sys.exit(0)
