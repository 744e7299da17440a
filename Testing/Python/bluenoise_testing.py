# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Check reporting shared by the Python tests (Testing/Python, Testing/Applications): every check prints a line, and
finish() exits non-zero when any failed (ctest reads the exit code). Also the process's memory, which the
memory tests and the pvpython benchmark read."""
import sys

SKIP = 125  # ctest SKIP_RETURN_CODE: a prerequisite is missing
FAILURES = []


def check(condition, message):
    print(("ok:   " if condition else "FAIL: ") + message, flush=True)
    if not condition:
        FAILURES.append(message)
    return condition


def summary(passed="all checks passed"):
    """Prints the outcome; returns the exit status (1 when a check failed)."""
    if FAILURES:
        print("\n%d check(s) failed:" % len(FAILURES))
        for f in FAILURES:
            print("  - " + f)
        return 1
    print("\n" + passed)
    return 0


def finish():
    sys.exit(summary())


def resident_bytes(field="VmRSS:"):
    """A memory field of this process (/proc/self/status; VmHWM: is the peak), in bytes."""
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith(field):
                return int(line.split()[1]) * 1024
    return 0
