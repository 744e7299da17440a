# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Distributed sampling without seams: vtkPErrorDiffusionSampler on N processes.

    mpiexec -n N pvbatch --symmetric TestSamplerSeamsMPI.py

Every process samples its z-slab of a 96^3 volume (after scanning the overlap layers above
it) and sends its points to process 0, which compares them with a serial run of the same
filter: the count (the pieces draw their own expectation to a point each), the density of
the 16-layer slabs centered on each seam (within 2 % of the expectation), and the spectrum of
the whole point set (mean anisotropy within 0.5 dB of the serial run's, L within 3 %). A
second run with a point budget checks that the statistics are reduced over the processes:
the pieces' counts add up to NumberOfPoints, and each process read only its own slab.

The outcome is printed ("all checks passed" or "FAIL: ..." lines): pvbatch under MPI must
end the script normally.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bluenoise_testing import check, summary  # noqa: E402

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: E402
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData  # noqa: E402
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource  # noqa: E402
from vtkmodules.vtkParallelCore import vtkMultiProcessController  # noqa: E402
from bluenoise import vtkBlueNoiseSpectrum, vtkPErrorDiffusionSampler  # noqa: E402

N = 96
G = 0.02


def constant_volume():
    image = vtkImageData()
    image.SetDimensions(N, N, N)
    values = numpy_to_vtk(np.full(N ** 3, G, np.float32), deep=1)
    values.SetName("g")
    image.GetPointData().SetScalars(values)
    return image


def sample(image, controller, pieces, piece):
    sampler = vtkPErrorDiffusionSampler()
    sampler.SetInputData(image)
    sampler.SetController(controller if pieces > 1 else None)
    sampler.SetDensityMappingToIdentity()
    sampler.UseNumberOfPointsOff()
    sampler.SetSeed(5)
    sampler.UpdatePiece(piece, pieces, 0)
    out = sampler.GetOutput()
    if out.GetNumberOfPoints() == 0:
        return np.zeros((0, 3), np.float32)
    return vtk_to_numpy(out.GetPoints().GetData()).copy()


def gather(controller, points):
    """Every process's points on process 0 (None elsewhere)."""
    rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
    if rank != 0:
        controller.Send(numpy_to_vtk(points.astype(np.float32), deep=1), 0, 3117)
        return None
    parts = [points]
    for p in range(1, size):
        received = vtkFloatArray()
        controller.Receive(received, p, 3117)
        parts.append(vtk_to_numpy(received).reshape(-1, 3) if received.GetNumberOfTuples() else
                     np.zeros((0, 3), np.float32))
    return np.concatenate(parts)


def spectrum_figures(points):
    data = vtkPolyData()
    xyz = vtkPoints()
    xyz.SetData(numpy_to_vtk(points.astype(np.float32), deep=1))
    data.SetPoints(xyz)
    spectrum = vtkBlueNoiseSpectrum()
    spectrum.SetUseInputGrid(False)
    spectrum.SetGridDimensions(N, N, N)
    spectrum.UseGridBoundsOn()
    spectrum.SetGridBounds(0, N - 1, 0, N - 1, 0, N - 1)
    spectrum.SetInputData(data)
    spectrum.Update()
    table = spectrum.GetOutput()
    anisotropy = vtk_to_numpy(table.GetColumnByName("AnisotropyDB"))[: N // 2].mean()
    low = table.GetFieldData().GetArray("LowFrequencyRatio").GetValue(0)
    return anisotropy, low


def check_seams(controller):
    rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
    image = constant_volume()
    points = gather(controller, sample(image, controller, size, rank))
    if rank != 0:
        return
    serial = sample(image, None, 1, 0)
    expected = G * N ** 3
    check(abs(len(points) - expected) <= max(2.0, size), "%d pieces: %d points, expected %.0f"
          % (size, len(points), expected))
    z = points[:, 2]
    for p in range(1, size):
        seam = N * p // size
        count = np.count_nonzero((z >= seam - 8) & (z < seam + 8))
        relative = count / (G * N * N * 16) - 1.0
        check(abs(relative) <= 0.02, "seam at z = %d: %d points in the 16 layers around it (%+.2f %%)"
              % (seam, count, 100 * relative))
    anisotropy, low = spectrum_figures(points)
    serial_anisotropy, serial_low = spectrum_figures(serial)
    check(abs(anisotropy - serial_anisotropy) <= 0.5,
          "mean anisotropy %.3f dB, serial %.3f dB" % (anisotropy, serial_anisotropy))
    check(abs(low / serial_low - 1.0) <= 0.03, "L %.4f, serial %.4f" % (low, serial_low))


def check_budget(controller):
    rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
    source = vtkRTAnalyticSource()
    source.SetWholeExtent(0, 47, 0, 47, 0, 47)
    sampler = vtkPErrorDiffusionSampler()
    sampler.SetInputConnection(source.GetOutputPort())
    sampler.SetController(controller)
    sampler.SetNumberOfPoints(5000)
    sampler.UpdatePiece(rank, size, 0)
    layers = source.GetOutput().GetExtent()
    read = layers[5] - layers[4] + 1
    check(read <= 48 // size + 2 * sampler.GetOverlapLayers() + 1,
          "process %d read %d of 48 layers" % (rank, read))
    points = gather(controller, vtk_to_numpy(sampler.GetOutput().GetPoints().GetData()).copy()
                    if sampler.GetOutput().GetNumberOfPoints() else np.zeros((0, 3), np.float32))
    if rank == 0:
        check(abs(len(points) - 5000) <= max(2.0, size), "the pieces' counts add up to the budget: %d"
              % len(points))


def main():
    controller = vtkMultiProcessController.GetGlobalController()
    size = controller.GetNumberOfProcesses() if controller else 1
    if size < 2:
        print("SKIP: run under mpiexec with 2 or more processes, pvbatch --symmetric")
        return
    check_seams(controller)
    check_budget(controller)
    if controller.GetLocalProcessId() == 0:
        summary()


main()
