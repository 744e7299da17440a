# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The sampler on the pieces of a distributed run: pvbatch under mpiexec with 2 processes.

    mpiexec -n 2 pvbatch TestSamplerMPI.py --plugin BlueNoiseSampling.so

With the default ScalarRange mapping every piece must map a value to the same density (the
range is reduced over the pieces): each point's Density equals DensityScale x (RTData - lo) /
(hi - lo) with [lo, hi] the range of the whole Wavelet; both pieces contribute points, no
voxel is sampled twice (pieces share a plane of points) and the count is the expected one
of the whole volume. A piece with an empty extent gives no error and no points.

The outcome is printed ("all checks passed" or "FAIL: ..." lines), not returned: pvbatch
under MPI must end the script normally.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bluenoise_testing import check, summary  # noqa: E402

from paraview.simple import LoadPlugin, Wavelet  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402
from vtkmodules.vtkParallelCore import vtkMultiProcessController  # noqa: E402


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    args = parser.parse_args()

    controller = vtkMultiProcessController.GetGlobalController()
    processes = controller.GetNumberOfProcesses() if controller else 1
    if processes < 2:
        print("SKIP: run under mpiexec with 2 or more processes (got %d)" % processes)
        return
    check(True, "%d processes" % processes)
    LoadPlugin(args.plugin, remote=False, ns=globals())
    scale = 0.3
    wavelet = Wavelet(WholeExtent=[0, 39, 0, 39, 0, 39])
    wavelet.UpdatePipeline()
    lo, hi = wavelet.PointData["RTData"].GetRange()
    sampler = ErrorDiffusionSampler(Input=wavelet, UseNumberOfPoints=0, DensityScale=scale)  # noqa: F821 (from the plugin)
    sampler.UpdatePipeline()
    points = servermanager.Fetch(sampler)
    n = points.GetNumberOfPoints()
    check(n > 1000, "samples from all pieces: %d points" % n)
    density = points.GetPointData().GetArray("Density")
    value = points.GetPointData().GetArray("RTData")
    worst = 0.0
    for i in range(n):
        expected = scale * (value.GetValue(i) - lo) / (hi - lo)
        worst = max(worst, abs(density.GetValue(i) - expected))
    check(worst < 1e-5, "every piece maps RTData by the whole range [%.3f, %.3f] (largest deviation %.2e)"
          % (lo, hi, worst))
    zs = [points.GetPoint(i)[2] for i in range(n)]
    check(min(zs) < 10 and max(zs) > 29, "points over the whole height: z in [%.1f, %.1f]" % (min(zs), max(zs)))
    cells = set(points.GetPoint(i) for i in range(n))
    check(len(cells) == n, "no voxel sampled by two pieces (%d distinct of %d points)" % (len(cells), n))
    # The expected count: the sum of the densities over the whole volume, computed here alone.
    whole = vtkRTAnalyticSource()
    whole.SetWholeExtent(0, 39, 0, 39, 0, 39)
    whole.Update()
    rt = whole.GetOutput().GetPointData().GetArray("RTData")
    expected_total = sum(scale * (rt.GetValue(i) - lo) / (hi - lo) for i in range(rt.GetNumberOfTuples()))
    check(abs(n - expected_total) < 0.02 * expected_total,
          "count %d near the expected %.0f over the whole volume" % (n, expected_total))

    # One voxel, two pieces: one of them is empty. It must take part in the range reduction
    # (or the other would wait forever) and give no points and no error.
    tiny = Wavelet(WholeExtent=[0, 0, 0, 0, 0, 0])
    tiny_sampler = ErrorDiffusionSampler(Input=tiny, UseNumberOfPoints=0, DensityScale=1.0)  # noqa: F821
    tiny_sampler.UpdatePipeline()
    tiny_points = servermanager.Fetch(tiny_sampler)
    check(tiny_points.GetNumberOfPoints() == 1,
          "a one-voxel volume over %d pieces: %d point (the voxel, density 1)"
          % (processes, tiny_points.GetNumberOfPoints()))
    summary()


# pvbatch under mpiexec: leaving the script normally lets every process finalise MPI (sys.exit
# on the first process would abort the job). CTest reads the printed outcome.
main()
