# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Runs the particle-based volume rendering examples under pvbatch and checks their output.

    python3 TestPBVR.py --mode compare --pvbatch pvbatch [--xvfb-run xvfb-run] \
        --examples <source>/Examples --plugin BlueNoiseSampling.so \
        --volume <source>/Data/brain-small.vti --out <dir>
    python3 TestPBVR.py --mode macro ... (same arguments)

compare: Examples/pbvr_compare.py on the small brain, one particle count, a
small image. Checks the exit code, the PNG (written, 3 panels wide, not
blank), the reference coverage it prints, and the RESULT lines: one per
method, finite RMSE values, particle counts near the requested one.
macro: Testing/Applications/PBVRMacroScript.py, which runs
Examples/pbvr_gui_macro.py on the small brain as the active source and checks
the pipeline it sets up.

A failure to reach the X server (Xvfb failing to start, a display number
taken by another job between xvfb-run's check and the start of Xvfb) repeats
the run (up to 3 times), only for that failure. Exits 125 (skip) when pvbatch or the files are missing.
"""
import argparse
import math
import os
import re
import subprocess
import sys
import time

from bluenoise_testing import check, summary

SKIP = 125
# Loguru stack-trace lines ("  7  0x7f... symbol") are left out of the echoed output.
STACK_LINE = re.compile(r"^\s*\d+\s+0x[0-9a-f]+")
X_FAILURES = ("bad X server connection", "cannot open display", "Xvfb failed to start",
              "xvfb-run: error: Xvfb failed")


def run(cmd, timeout):
    for attempt in range(3):
        print("running: " + " ".join(cmd), flush=True)
        start = time.time()
        try:
            proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  timeout=timeout, universal_newlines=True)
        except subprocess.TimeoutExpired as error:
            out = error.stdout or ""
            if isinstance(out, bytes):
                out = out.decode("utf-8", "replace")
            return None, out, time.time() - start
        out = proc.stdout
        if proc.returncode != 0 and any(x in out for x in X_FAILURES):
            print("note: the X server did not come up (attempt %d), retrying" % (attempt + 1))
            time.sleep(2 + 3 * attempt)
            continue
        return proc.returncode, out, time.time() - start
    return proc.returncode, out, time.time() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--mode", choices=["compare", "macro"], default="compare")
    parser.add_argument("--pvbatch", required=True)
    parser.add_argument("--xvfb-run", default="")
    parser.add_argument("--examples", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--volume", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--count", type=float, default=4000)
    parser.add_argument("--size", type=int, default=160)
    parser.add_argument("--timeout", type=float, default=55)
    args = parser.parse_args()
    for path in (args.pvbatch, args.plugin, args.volume):
        if not os.path.exists(path):
            print("SKIP: %s not found" % path)
            return SKIP
    os.makedirs(args.out, exist_ok=True)
    sys.path.insert(0, os.path.abspath(args.examples))
    from png_arrays import read_png
    # -noreset: a connection opened while the server resets (after its last
    # client left) fails with "bad X server connection".
    prefix = [args.xvfb_run, "-a", "-s", "-screen 0 1024x768x24 -noreset"] if args.xvfb_run else []
    here = os.path.dirname(os.path.abspath(__file__))

    if args.mode == "compare":
        png = os.path.join(args.out, "pbvr_compare.png")
        if os.path.exists(png):
            os.remove(png)
        cmd = prefix + [args.pvbatch, os.path.join(args.examples, "pbvr_compare.py"),
                        "--plugin", args.plugin, "--volume", args.volume,
                        "--counts", "%g" % args.count, "--size", str(args.size), "--out", png,
                        "--keep-panels", os.path.join(args.out, "panels")]
        rc, out, seconds = run(cmd, args.timeout)
        print("---- output ----\n" + "\n".join(
            line for line in out.splitlines() if not STACK_LINE.match(line))[-4000:]
            + "\n----------------")
        check(rc == 0, "pbvr_compare.py exited with 0 (%s) in %.1f s" % (rc, seconds))
        check(os.path.exists(png), "the PNG was written: %s" % png)
        if os.path.exists(png):
            a = read_png(png)
            h, w = a.shape[:2]
            check(w == 4 * args.size and h > args.size, "the PNG is 4 panels wide: %dx%d" % (w, h))
            panels = [a[:, i * args.size:(i + 1) * args.size, :3] for i in range(4)]
            lit = [float((p.max(axis=2) > 8 / 255.0).mean()) for p in panels]
            check(all(x > 0.02 for x in lit),
                  "every panel shows something (non-black fractions %s)"
                  % ", ".join("%.3f" % x for x in lit))
        m = re.search(r"reference: ([0-9.]+) % of the pixels covered", out)
        check(m is not None and float(m.group(1)) > 2.0,
              "the reference covers part of the image (%s %%)" % (m.group(1) if m else "?"))
        results = {}
        for line in out.splitlines():
            if line.startswith("RESULT "):
                fields = dict(kv.split("=", 1) for kv in line.split()[1:])
                results[fields["method"]] = fields
        check(sorted(results) == ["ED", "RED", "WN"], "RESULT lines for RED, ED and WN: %s" % sorted(results))
        for method, fields in sorted(results.items()):
            numbers = {k: float(fields[k]) for k in ("rmse", "rmse_covered", "rmse_lowpass", "bias",
                                                     "particles", "radius")}
            check(all(math.isfinite(v) for v in numbers.values()),
                  "%s: finite numbers %s" % (method, numbers))
            check(0 < numbers["rmse"] < 255 and 0 <= numbers["rmse_lowpass"] <= numbers["rmse"],
                  "%s: 0 < rmse %.2f < 255, low-pass rmse %.2f <= rmse"
                  % (method, numbers["rmse"], numbers["rmse_lowpass"]))
            check(abs(numbers["particles"] - args.count) <= 0.1 * args.count,
                  "%s: %.0f particles for %g requested" % (method, numbers["particles"], args.count))
    else:
        cmd = prefix + [args.pvbatch, os.path.join(here, "PBVRMacroScript.py"),
                        "--examples", args.examples, "--plugin", args.plugin,
                        "--volume", args.volume, "--count", "%g" % args.count,
                        "--out", os.path.join(args.out, "pbvr_macro.png")]
        rc, out, seconds = run(cmd, args.timeout)
        print("---- output ----\n" + "\n".join(
            line for line in out.splitlines() if not STACK_LINE.match(line))[-4000:]
            + "\n----------------")
        check(rc == 0, "the macro script exited with 0 (%s) in %.1f s" % (rc, seconds))
        check("MACRO CHECKS PASSED" in out, "the macro script's checks passed")

    return summary()


if __name__ == "__main__":
    sys.exit(main())
