# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin gives the host's memory back, and stays sound over a long session.

    pvpython TestPluginMemory.py --plugin BlueNoiseSampling.so --part delete [--size 256]
    pvpython TestPluginMemory.py --plugin BlueNoiseSampling.so --part parts
    pvpython TestPluginMemory.py --plugin BlueNoiseSampling.so --part soak [--cycles 300]

delete: a volume sampled twice (millions of points), its spectrum computed, then
  both filters deleted: the process's resident memory is back within 10 % + 50 MB
  of what it was before the filters were made.
parts: a volume of 16 z-parts, few points: the sampler's peak memory is that of
  the parts a thread scans at a time, not of all 16 (each part's buffers exist
  from its first layer to its last).
soak: Apply cycles over random settings (method, budget, mapping, seed, slabs,
  jitter, mask), with aborts in the middle of runs and bad settings among them
  (an empty scalar range, a missing parameter file, an array the input lacks).
  Every good run draws its count, every bad one reports an error and leaves an
  empty output, and resident memory grows by less than 5 % from cycle 20 to the
  last.

Every check prints ok/FAIL; the exit code is 1 when any check failed.
"""
import argparse
import os
import random

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING

from bluenoise_testing import check, finish, resident_bytes

MB = 1024.0 * 1024.0


def run_parts():
    # 256^2 x 1024 (float): 16 parts of 64 layers. A part's relaxation, error
    # layers and layer slots take about 90 bytes a voxel of a layer, 5.8 MB
    # here: 16 parts at once would be 94 MB, the few a thread scans at a time
    # about 20, with the output, the charge curves and the statistics besides.
    n, layers = 256, 1024
    os.environ["VTK_SMP_MAX_THREADS"] = "2"  # the limit is for two threads, on any machine
    wavelet = Wavelet(WholeExtent=[0, n - 1, 0, n - 1, 0, layers - 1])
    wavelet.UpdatePipeline()
    sampler = ErrorDiffusionSampler(Input=wavelet, NumberOfPoints=100000)  # noqa: F821
    before = resident_bytes()
    peak_before = resident_bytes("VmHWM:")
    sampler.UpdatePipeline()
    growth = resident_bytes("VmHWM:") - max(before, peak_before)
    parts = min(layers // sampler.PartLayers, n * n * layers // sampler.PartVoxels)
    per_part = 90.0 * n * n
    limit = parts * per_part / 2
    check(growth <= limit,
          "peak growth of a run in %d parts: %.1f MB (at most %.1f MB; all parts at "
          "once would be %.1f MB)" % (parts, growth / MB, limit / MB, parts * per_part / MB))
    Delete(sampler)
    Delete(wavelet)


def points_of(proxy):
    return servermanager.Fetch(proxy).GetNumberOfPoints()


class Messages:
    """Errors and warnings the filter's object and executive report."""

    def __init__(self, proxy):
        self.errors = []
        self.warnings = []
        obj = proxy.GetClientSideObject()

        @calldata_type(VTK_STRING)
        def on_error(caller, event, text):
            self.errors.append(text.strip())

        @calldata_type(VTK_STRING)
        def on_warning(caller, event, text):
            self.warnings.append(text.strip())
        for o in (obj, obj.GetExecutive()):
            o.AddObserver("ErrorEvent", on_error)
            o.AddObserver("WarningEvent", on_warning)

    def clear(self):
        del self.errors[:]
        del self.warnings[:]


# ---------------------------------------------------------------------------
def run_delete(size):
    wavelet = Wavelet(WholeExtent=[0, size - 1, 0, size - 1, 0, size - 1])
    wavelet.UpdatePipeline()
    before = resident_bytes()
    budget = int(0.3 * size ** 3)
    sampler = ErrorDiffusionSampler(Input=wavelet, NumberOfPoints=budget)  # noqa: F821
    sampler.UpdatePipeline()
    first = sampler.GetDataInformation().GetNumberOfPoints()
    sampler.Seed = 2  # a re-execution: the last output's memory is reused or given back
    sampler.UpdatePipeline()
    second = sampler.GetDataInformation().GetNumberOfPoints()
    spectrum = BlueNoiseSpectrum(Input=sampler)  # noqa: F821
    spectrum.UpdatePipeline()
    rows = spectrum.GetDataInformation().GetNumberOfRows()
    peak = resident_bytes()
    Delete(spectrum)
    del spectrum
    Delete(sampler)
    del sampler
    after = resident_bytes()
    check(abs(first - budget) <= max(2, 5e-4 * budget) and abs(second - budget) <= max(2, 5e-4 * budget),
          "%d^3: two runs drew %d and %d points (budget %d)" % (size, first, second, budget))
    check(rows > 0, "the spectrum of the samples has %d rows" % rows)
    limit = 1.1 * before + 50 * MB
    check(after <= limit,
          "after Delete of the sampler and the spectrum: resident %.0f MB, before them %.0f MB, "
          "with them %.0f MB (at most %.0f MB)" % (after / MB, before / MB, peak / MB, limit / MB))
    Delete(wavelet)


# ---------------------------------------------------------------------------
METHODS = ["Relaxed Error Diffusion", "Error Diffusion", "White Noise", "Poisson Disk",
           "Sample Elimination", "Energy Relaxed Error Diffusion"]


def count_ok(method, n, budget):
    if method in ("Relaxed Error Diffusion", "Error Diffusion", "Energy Relaxed Error Diffusion"):
        return abs(n - budget) <= max(2, 5e-4 * budget)
    if method == "White Noise":  # a binomial draw
        return abs(n - budget) <= 6 * budget ** 0.5 + 2
    return abs(n - budget) <= 0.03 * budget + 2  # the peers' own budget rule


def run_soak(cycles, seed):
    rng = random.Random(seed)
    wavelet = Wavelet(WholeExtent=[0, 39, 0, 39, 0, 39])
    wavelet.UpdatePipeline()
    lo, hi = wavelet.PointData["RTData"].GetRange()
    sampler = ErrorDiffusionSampler(Input=wavelet, Scalars=["POINTS", "RTData"])  # noqa: F821
    spectrum = BlueNoiseSpectrum(Input=sampler)  # noqa: F821
    sampler_messages = Messages(sampler)
    obj = sampler.GetClientSideObject()
    abort_at = [None]

    def on_progress(caller, event):
        if abort_at[0] is not None and caller.GetProgress() >= abort_at[0]:
            abort_at[0] = None
            caller.SetAbortExecuteAndUpdateTime()
    obj.AddObserver("ProgressEvent", on_progress)

    memory = []
    bad_counts = []
    failures = {"good": 0, "bad": 0, "abort": 0}
    kinds = {"good": 0, "bad": 0, "abort": 0}
    bad_kinds = {}
    for cycle in range(cycles):
        method = rng.choice(METHODS)
        budget = rng.randint(1, 12000)
        sampler.Method = method
        sampler.NumberOfPoints = budget
        sampler.DensityMapping = rng.choice(["Identity", "Scalar Range"])
        sampler.UseCustomScalarRange = 0
        sampler.Seed = rng.randint(0, 1000)
        sampler.Jitter = rng.randint(0, 1)
        sampler.GenerateMask = rng.randint(0, 1)
        sampler.NumberOfSlabs = rng.choice([1, 1, 2, 3])
        sampler.UseWorkerThread = rng.randint(0, 1)
        sampler.ParameterSet = "Optimized"
        sampler.Scalars = ["POINTS", "RTData"]
        kind = rng.choice(["good"] * 6 + ["bad", "abort"])
        if kind == "bad":
            bad = rng.choice(["empty scalar range", "missing parameter file", "missing array"])
            bad_kinds[bad] = bad_kinds.get(bad, 0) + 1
            if bad == "empty scalar range":  # the mapping is undefined
                sampler.DensityMapping = "Scalar Range"
                sampler.UseCustomScalarRange = 1
                sampler.ScalarRange = [hi, lo]
            elif bad == "missing parameter file":
                sampler.Method = method = rng.choice(METHODS[:2])
                sampler.ParameterSet = "Custom"
                sampler.ParameterFile = "/nonexistent/table.txt"
            else:
                sampler.Scalars = ["POINTS", "NoSuchArray"]
        sampler_messages.clear()
        obj.SetAbortExecute(0)
        abort_at[0] = rng.uniform(0.05, 0.8) if kind == "abort" else None
        spectrum.UpdatePipeline() if kind == "good" and cycle % 10 == 0 else sampler.UpdatePipeline()
        if kind == "abort" and abort_at[0] is not None:
            kind = "good"  # the run ended before its progress reached the abort
        kinds[kind] += 1
        n = points_of(sampler)
        if kind == "good":
            ok = count_ok(method, n, budget) and not sampler_messages.errors
            if not ok:
                bad_counts.append((cycle, method, budget, n, list(sampler_messages.errors)))
        elif kind == "bad":
            ok = n == 0 and len(sampler_messages.errors) > 0
        else:
            ok = n == 0 and not sampler_messages.errors
        failures[kind] += 0 if ok else 1
        memory.append(resident_bytes())
    obj.SetAbortExecute(0)
    print("cycles: %r, bad settings: %r" % (kinds, bad_kinds))
    check(failures["good"] == 0, "%d good runs drew their counts without an error (%d did not: %s)"
          % (kinds["good"], failures["good"], bad_counts[:5]))
    check(failures["bad"] == 0, "%d runs with bad settings: an error and an empty output (%d not)"
          % (kinds["bad"], failures["bad"]))
    check(failures["abort"] == 0, "%d runs aborted mid-run: an empty output, no error (%d not)"
          % (kinds["abort"], failures["abort"]))
    first = min(20, len(memory) - 1)
    growth = (memory[-1] - memory[first]) / float(memory[first])
    check(growth < 0.05, "resident memory from cycle %d to %d: %.1f MB -> %.1f MB (%+.1f %%, under 5 %%)"
          % (first, len(memory) - 1, memory[first] / MB, memory[-1] / MB, 100 * growth))
    for proxy in (spectrum, sampler, wavelet):
        Delete(proxy)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--part", choices=("delete", "parts", "soak"), required=True)
    parser.add_argument("--size", type=int, default=256, help="delete: the volume's side")
    parser.add_argument("--cycles", type=int, default=300, help="soak: Apply cycles")
    parser.add_argument("--seed", type=int, default=1, help="soak: the settings' random seed")
    args = parser.parse_args()
    LoadPlugin(args.plugin, remote=False, ns=globals())
    if args.part == "delete":
        run_delete(args.size)
    elif args.part == "parts":
        run_parts()
    else:
        run_soak(args.cycles, args.seed)
    finish()


if __name__ == "__main__":
    main()
