# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Distributed sampling, 1 to N processes: time and blue-noise quality.

    for n in 1 2 4; do mpiexec -n $n pvbatch --symmetric mpi_scaling.py [--edge 256]; done

Each process asks a constant source of edge^3 voxels (a Wavelet without its
waves) for its piece (so no process holds the whole volume), samples it with
vtkPErrorDiffusionSampler (default settings but for the identity mapping: relaxed
error diffusion, a budget of 2 % of the voxels), and process 0 gathers the points and measures
them with vtkBlueNoiseSpectrum. Process 0 prints one Markdown row:
processes, seconds (the slowest process, from its update request to its
points), points, L(g) and the mean anisotropy (dB, shells 1 .. edge/2) of the
gathered set.
No thresholds: figures for the README.
"""
import argparse
import time

from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkFiltersCore import vtkAppendPolyData
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.util.numpy_support import vtk_to_numpy
from bluenoise import vtkBlueNoiseSpectrum, vtkPErrorDiffusionSampler


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--edge", type=int, default=256)
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
    sampler.SetNumberOfPoints(int(0.02 * args.edge ** 3))
    controller.Barrier()
    start = time.perf_counter()
    sampler.UpdatePiece(rank, ranks, 0)
    seconds = time.perf_counter() - start
    mine = vtkPolyData()
    mine.ShallowCopy(sampler.GetOutput())
    if rank == 0:
        append = vtkAppendPolyData()
        append.AddInputData(mine)
        for other in range(1, ranks):
            piece = vtkPolyData()
            controller.Receive(piece, other, 77)
            append.AddInputData(piece)
            theirs = vtkDoubleArray()
            controller.Receive(theirs, other, 78)
            seconds = max(seconds, theirs.GetValue(0))
        append.Update()
        points = append.GetOutput()
        points.GetFieldData().ShallowCopy(mine.GetFieldData())  # the sampling grid
        spectrum = vtkBlueNoiseSpectrum()
        spectrum.SetInputData(points)
        spectrum.Update()
        table = spectrum.GetOutput()
        aniso = vtk_to_numpy(table.GetColumnByName("AnisotropyDB"))
        low = table.GetFieldData().GetArray("LowFrequencyRatio").GetValue(0)
        print("| %d | %.2f | %d | %.4f | %.2f |" % (
            ranks, seconds, points.GetNumberOfPoints(), low, aniso[1:args.edge // 2 + 1].mean()),
            flush=True)
    else:
        controller.Send(mine, 0, 77)
        theirs = vtkDoubleArray()
        theirs.InsertNextValue(seconds)
        controller.Send(theirs, 0, 78)


if __name__ == "__main__":
    main()
