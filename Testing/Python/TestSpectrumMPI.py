# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The spectrum of a distributed run: pvbatch --symmetric under mpiexec with 2 processes.

    mpiexec -n 2 pvbatch --symmetric TestSpectrumMPI.py --plugin BlueNoiseSampling.so

Every process runs this script: the sampler samples one piece of a Wavelet per process and the
plugin's spectrum (vtkPBlueNoiseSpectrum) bins each process's points and computes once, on
process 0. Checked on process 0, with what the other processes send it:
- the pieces' SamplingGridExtent differ from the whole extent, their union is the whole extent,
  and the spectrum's grid is the whole volume's;
- the spectrum's table (every column and every field value) equals, to the last bit, that of the
  serial vtkBlueNoiseSpectrum on the points of all pieces appended in process order with the
  sampler's grid of the whole volume;
- the spectrum of the sampler's mask (image pieces, each voxel sent by one piece) equals that of
  its points to the last bit;
- over three UpdatePipeline calls (each updates output port 0, then port 1), the spectrum's
  RequestData ran once on every process; the transform ran on process 0 only (NumberOfTransformedRealizations 1
  there, 0 elsewhere) and the other processes' table and image are empty.

Needs the bluenoise Python package (PYTHONPATH) for the serial spectrum and the count of
transforms. Only process 0 prints the outcome ("all checks passed" or "FAIL: ..." lines); the
script ends normally on every process so that each one finalizes MPI.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bluenoise_testing import check, summary  # noqa: E402

from paraview.simple import LoadPlugin, OutputPort, Wavelet  # noqa: E402
from vtkmodules.vtkCommonCore import vtkIntArray  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPolyData  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkAppendPolyData  # noqa: E402
from vtkmodules.vtkParallelCore import vtkMultiProcessController  # noqa: E402

WHOLE = [0, 31, 0, 29, 0, 27]
POINTS_TAG = 4711
REPORT_TAG = 4712


def whole_extent_points(pieces):
    """The pieces' points appended in process order, with the sampler's grid of the whole
    volume (origin, spacing and direction of the first piece, the whole extent)."""
    append = vtkAppendPolyData()
    for piece in pieces:
        append.AddInputData(piece)
    append.Update()
    merged = vtkPolyData()
    merged.ShallowCopy(append.GetOutput())
    merged.GetFieldData().Initialize()
    fd = pieces[0].GetFieldData()
    for name in ("SamplingGridOrigin", "SamplingGridSpacing", "SamplingGridDirection"):
        merged.GetFieldData().AddArray(fd.GetArray(name))
    extent = vtkIntArray()
    extent.SetName("SamplingGridExtent")
    extent.SetNumberOfComponents(6)
    extent.InsertNextTuple(WHOLE)
    merged.GetFieldData().AddArray(extent)
    return merged


def same_tables(a, b, ignore=()):
    """Names of the columns and field arrays that differ (values compared exactly), but those
    in `ignore`."""
    differ = []
    for getter, count in (("GetColumnByName", a.GetNumberOfColumns()),
                          ("GetFieldData", a.GetFieldData().GetNumberOfArrays())):
        for i in range(count):
            if getter == "GetColumnByName":
                name = a.GetColumnName(i)
                x, y = a.GetColumnByName(name), b.GetColumnByName(name)
            else:
                name = a.GetFieldData().GetArrayName(i)
                # GetAbstractArray: the SpectrumGrid field data is a string array.
                x = a.GetFieldData().GetAbstractArray(name)
                y = b.GetFieldData().GetAbstractArray(name)
            if name in ignore:
                continue
            n = x.GetNumberOfValues()
            # NaN (the marker column off f_g) equals NaN here.
            if y is None or y.GetNumberOfValues() != n or any(
                    x.GetValue(k) != y.GetValue(k) and not (x.GetValue(k) != x.GetValue(k)
                                                          and y.GetValue(k) != y.GetValue(k))
                    for k in range(n)):
                differ.append(name)
    if a.GetNumberOfColumns() != b.GetNumberOfColumns():
        differ.append("number of columns")
    return differ


def check_root(spectrum, mask_spectrum, pieces, reports):
    from bluenoise import vtkBlueNoiseSpectrum
    extents = [list(p.GetFieldData().GetArray("SamplingGridExtent").GetTuple(0)) for p in pieces]
    union = [min(e[i] for e in extents) if i % 2 == 0 else max(e[i] for e in extents)
             for i in range(6)]
    check(all(e != WHOLE for e in extents) and union == WHOLE,
          "pieces sample %s, together the whole extent %s" % (extents, WHOLE))
    check(all(p.GetNumberOfPoints() > 0 for p in pieces),
          "every piece has points: %s" % [p.GetNumberOfPoints() for p in pieces])

    table = spectrum.GetOutputDataObject(0)
    serial = vtkBlueNoiseSpectrum()
    serial.SetInputData(whole_extent_points(pieces))
    serial.Update()
    expected = serial.GetOutput()
    grid = [table.GetFieldData().GetArray("GridDimensions").GetComponent(0, c) for c in range(3)]
    check(grid == [WHOLE[1] + 1, WHOLE[3] + 1, WHOLE[5] + 1],
          "the distributed grid is the whole volume's: %s" % grid)
    check(expected.GetNumberOfRows() > 0 and table.GetNumberOfRows() == expected.GetNumberOfRows(),
          "%d shells, serial %d" % (table.GetNumberOfRows(), expected.GetNumberOfRows()))
    differ = same_tables(table, expected)
    check(not differ, "the distributed table equals the serial one on the appended points%s"
          % (" (differ: %s)" % differ if differ else ""))
    # The same spectrum; SpectrumGrid names the image's own grid for the mask.
    differ = same_tables(mask_spectrum.GetOutputDataObject(0), table, ignore=("SpectrumGrid",))
    check(not differ, "the spectrum of the distributed mask equals that of the points%s"
          % (" (differ: %s)" % differ if differ else ""))
    target = table.GetFieldData().GetArray("TargetValue").GetValue(0)
    points = table.GetFieldData().GetArray("NumberOfPoints").GetValue(0)
    print("       T = %.17g over %d points" % (target, points))
    for rank, (executions, transformed, rows, image_points) in enumerate(reports):
        check(executions == 1, "process %d: RequestData ran %d time(s)" % (rank, executions))
        check(transformed == (1 if rank == 0 else 0),
              "process %d transformed %d realization(s)" % (rank, transformed))
        if rank > 0:
            check(rows == 0 and image_points == 0,
                  "process %d: empty outputs (%d rows, %d image points)" % (rank, rows, image_points))
        else:
            check(rows > 0 and image_points == grid[0] * grid[1] * grid[2],
                  "process 0: %d rows, spectrum image of %d points" % (rows, image_points))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--plugin", required=True, help="the BlueNoiseSampling plugin library")
    plugin = parser.parse_args().plugin
    controller = vtkMultiProcessController.GetGlobalController()
    rank, processes = (controller.GetLocalProcessId(), controller.GetNumberOfProcesses()) \
        if controller else (0, 1)
    if processes < 2:
        print("SKIP: run under mpiexec with 2 or more processes and pvbatch --symmetric (got %d)"
              % processes)
        return
    try:
        import bluenoise  # noqa: F401 (GetClientSideObject() then returns the wrapped filters)
    except ImportError as error:
        if rank == 0:
            check(False, "import bluenoise (PYTHONPATH must hold the package): %s" % error)
            summary()
        return

    LoadPlugin(plugin, remote=False, ns=globals())
    wavelet = Wavelet(WholeExtent=WHOLE)
    sampler = ErrorDiffusionSampler(Input=wavelet, DensityScale=0.3, GenerateMask=1)  # noqa: F821
    proxy = BlueNoiseSpectrum(Input=sampler, GenerateSpectrumImage=1)  # noqa: F821 (the plugin)
    mask_proxy = BlueNoiseSpectrum(Input=OutputPort(sampler, 1))  # noqa: F821
    spectrum = proxy.GetClientSideObject()
    executions = [0]
    spectrum.AddObserver("StartEvent", lambda obj, event: executions.__setitem__(0, executions[0] + 1))
    # Each updates output port 0, then port 1; with a time, even when nothing changed.
    proxy.UpdatePipeline()
    proxy.UpdatePipeline(0.0)
    proxy.UpdatePipeline(0.0)
    # After the points: the sampler reads the piece request of its points port only, so the
    # mask's update must not be the one that executes it.
    mask_proxy.UpdatePipeline()

    local = vtkPolyData()
    local.ShallowCopy(sampler.GetClientSideObject().GetOutputDataObject(0))
    report = vtkIntArray()
    for value in (executions[0], spectrum.GetNumberOfTransformedRealizations(),
                  spectrum.GetOutputDataObject(0).GetNumberOfRows(),
                  spectrum.GetOutputDataObject(1).GetNumberOfPoints()):
        report.InsertNextValue(value)
    if rank > 0:
        controller.Send(local, 0, POINTS_TAG)
        controller.Send(report, 0, REPORT_TAG)
        return
    pieces = [local]
    reports = [[report.GetValue(i) for i in range(4)]]
    for other in range(1, processes):
        pieces.append(controller.ReceiveDataObject(other, POINTS_TAG))
        received = vtkIntArray()
        controller.Receive(received, other, REPORT_TAG)
        reports.append([received.GetValue(i) for i in range(4)])
    check_root(spectrum, mask_proxy.GetClientSideObject(), pieces, reports)
    summary()


# pvbatch under mpiexec: leaving the script normally lets every process finalize MPI (sys.exit
# on the first process would abort the job). CTest reads the printed outcome.
main()
