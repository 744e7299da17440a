# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Distributed sampling, 1 to N processes: time and blue-noise quality.

    for n in 1 2 4; do mpiexec -n $n pvbatch --symmetric mpi_scaling.py [--edge 256]; done

Each process asks a constant source of edge^3 voxels (a Wavelet without its
waves) for its piece (so no process holds the whole volume), samples it with
vtkPErrorDiffusionSampler (default settings but for the identity mapping: relaxed
error diffusion, a budget of 2 % of the voxels), and vtkPBlueNoiseSpectrum measures the points
of all processes once (gathered to process 0). Process 0 prints one Markdown row:
processes, seconds (the slowest process, from its update request to its
points), points, L(g) and the mean anisotropy (dB, shells 1 .. edge/2) of the
gathered set.
No thresholds: figures for Documentation/Results.md (scripts/results.py).
"""
import argparse
import time

from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIdTypeArray
from vtkmodules.vtkParallelCore import vtkCommunicator
from vtkmodules.util.numpy_support import vtk_to_numpy
from bluenoise import vtkPBlueNoiseSpectrum, vtkPErrorDiffusionSampler


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--edge", type=int, default=256)
    parser.add_argument("--method", type=int, default=2, help="the sampler's Method (2: default)")
    args, _ = parser.parse_known_args()
    controller = vtkMultiProcessController.GetGlobalController()
    ranks, rank = controller.GetNumberOfProcesses(), controller.GetLocalProcessId()
    half = args.edge // 2
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(-half, args.edge - half - 1, -half, args.edge - half - 1,
                          -half, args.edge - half - 1)
    for wave in (source.SetXMag, source.SetYMag, source.SetZMag):
        wave(0.0)
    source.SetStandardDeviation(1e9)  # the Gaussian flat: a constant volume
    sampler = vtkPErrorDiffusionSampler()
    sampler.SetController(controller if ranks > 1 else None)
    sampler.SetInputConnection(source.GetOutputPort())
    sampler.SetDensityMappingToIdentity()
    sampler.SetMethod(args.method)
    sampler.SetNumberOfPoints(int(0.02 * args.edge ** 3))
    controller.Barrier()
    start = time.perf_counter()
    sampler.UpdatePiece(rank, ranks, 0)
    seconds = time.perf_counter() - start
    # The spectrum of the gathered points, as the plugin computes it.
    spectrum = vtkPBlueNoiseSpectrum()
    spectrum.SetController(controller if ranks > 1 else None)
    spectrum.SetInputConnection(sampler.GetOutputPort())
    spectrum.UpdatePiece(rank, ranks, 0)
    slowest = vtkDoubleArray()
    controller.Reduce(_value(seconds), slowest,
                      vtkCommunicator.MAX_OP, 0)
    points = vtkIdTypeArray()
    controller.Reduce(_count(sampler.GetOutput().GetNumberOfPoints()), points,
                      vtkCommunicator.SUM_OP, 0)
    if rank == 0:
        table = spectrum.GetOutput()
        aniso = vtk_to_numpy(table.GetColumnByName("AnisotropyDB"))
        low = table.GetFieldData().GetArray("LowFrequencyRatio").GetValue(0)
        print("| %d | %.2f | %d | %.4f | %.2f |" % (
            ranks, slowest.GetValue(0), points.GetValue(0), low,
            aniso[1:args.edge // 2 + 1].mean()), flush=True)


def _value(x):
    array = vtkDoubleArray()
    array.InsertNextValue(x)
    return array


def _count(n):
    array = vtkIdTypeArray()
    array.InsertNextValue(n)
    return array


if __name__ == "__main__":
    main()
