# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The BlueNoiseSampling plugin in pvpython, as a Python user drives it.

    pvpython TestPluginPVPython.py --plugin BlueNoiseSampling.so --part wavelet
    pvpython TestPluginPVPython.py --plugin BlueNoiseSampling.so --part mri \
        --mri ch2bet.nii.gz [--nifti-plugin AnalyzeNIfTIReaderWriter.so]

wavelet: ErrorDiffusionSampler on Wavelet() (counts, arrays, field data, mask
port), BlueNoiseSpectrum on it (table columns and metrics), the
Transfer Function mapping with an opacity function, the Scalars default
(active scalars); executions (StartEvent) per UpdatePipeline, per Apply-like
show of every port and per display change; the spectrum view and chart series;
Component "Magnitude"; an abort from a progress observer.
mri: the sampler and the spectrum on the MRI volume read by ParaView's NIfTI
reader. Exits 125 (skip) when the MRI file is absent.

Every check prints ok/FAIL; the exit code is 1 when any check failed.
"""
import argparse
import gzip
import math
import os
import shutil
import sys
import tempfile
import time

import numpy as np

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy

from bluenoise_testing import SKIP, FAILURES, check, finish

try:
    # Not needed to use the plugin; with it, GetClientSideObject() returns the
    # sampler with its own methods rather than a vtkPolyDataAlgorithm.
    import bluenoise  # noqa: F401
    BLUENOISE_WRAPPED = True
except ImportError:
    print("note: the bluenoise Python package is not on PYTHONPATH; skipping client-side object checks")
    BLUENOISE_WRAPPED = False


def field(data, name):
    array = data.GetFieldData().GetArray(name)
    if array is None:
        return None
    values = tuple(array.GetTuple(0))
    return values[0] if len(values) == 1 else values


def point_array_names(data):
    pd = data.GetPointData()
    return [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]


def points_of(proxy, port=0):
    """Fetched output of a port as a vtkDataObject (a copy owned by the client)."""
    return servermanager.Fetch(proxy, idx=port)


def check_counts(data, expected, what):
    """Error diffusion draws the expected count: within max(2 points, 0.05 %)."""
    n = data.GetNumberOfPoints()
    check(abs(n - expected) <= max(2.0, 5e-4 * expected),
          "%s: %d points, expected %.1f" % (what, n, expected))
    return n


def check_sampling_grid(points, image, what):
    origin = tuple(image.GetOrigin())
    spacing = tuple(image.GetSpacing())
    extent = tuple(float(e) for e in image.GetExtent())
    check(field(points, "SamplingGridOrigin") == origin,
          "%s: SamplingGridOrigin %s == %s" % (what, field(points, "SamplingGridOrigin"), origin))
    check(field(points, "SamplingGridSpacing") == spacing,
          "%s: SamplingGridSpacing %s == %s" % (what, field(points, "SamplingGridSpacing"), spacing))
    check(field(points, "SamplingGridExtent") == extent,
          "%s: SamplingGridExtent %s == %s" % (what, field(points, "SamplingGridExtent"), extent))
    direction = field(points, "SamplingGridDirection")
    check(direction is not None and len(direction) == 9, "%s: SamplingGridDirection (9 values)" % what)


SPECTRUM_COLUMNS = ["Frequency", "RadialPower", "Anisotropy", "AnisotropyDB", "SRAPS_XY", "SRAPS_XZ",
                    "SRAPS_YZ", "ShellCount"]


def check_spectrum(spectrum_proxy, n, voxels, grid, what):
    table = points_of(spectrum_proxy)
    check(table.IsA("vtkTable"), "%s: spectrum output is a vtkTable (%s)" % (what, table.GetClassName()))
    names = [table.GetColumnName(i) for i in range(table.GetNumberOfColumns())]
    check(all(c in names for c in SPECTRUM_COLUMNS), "%s: table columns %s" % (what, names))
    rows = table.GetNumberOfRows()
    check(rows >= min(grid) // 2, "%s: %d shells" % (what, rows))
    if rows and all(c in names for c in SPECTRUM_COLUMNS):
        freq = vtk_to_numpy(table.GetColumnByName("Frequency"))
        power = vtk_to_numpy(table.GetColumnByName("RadialPower"))
        check(freq[0] > 0 and np.all(np.diff(freq) > 0), "%s: Frequency increasing" % what)
        check(np.all(np.isfinite(power)) and np.all(power >= 0), "%s: RadialPower finite, >= 0" % what)
        check(np.all(vtk_to_numpy(table.GetColumnByName("ShellCount")) > 0), "%s: ShellCount > 0" % what)
    check(field(table, "NumberOfPoints") == n,
          "%s: spectrum NumberOfPoints %s == sampler count %d" % (what, field(table, "NumberOfPoints"), n))
    check(field(table, "GridDimensions") == tuple(float(g) for g in grid),
          "%s: spectrum GridDimensions %s == %s" % (what, field(table, "GridDimensions"), grid))
    density = field(table, "Density")
    check(density is not None and math.isclose(density, n / voxels, rel_tol=1e-9),
          "%s: Density %s == N / voxels %.6g" % (what, density, n / voxels))
    L = field(table, "LowFrequencyRatio")
    C = field(table, "SymmetryCorrelation")
    S = field(table, "Symmetry")
    T = field(table, "TargetValue")
    pf = field(table, "PrincipalFrequency")
    check(L is not None and 0 < L < 1, "%s: LowFrequencyRatio %s in (0, 1)" % (what, L))
    check(C is not None and -1 <= C <= 1, "%s: SymmetryCorrelation %s in [-1, 1]" % (what, C))
    check(S is not None and C is not None and math.isclose(S, 1 - C, abs_tol=1e-12), "%s: Symmetry = 1 - C" % what)
    w = spectrum_proxy.Weight
    check(T is not None and L is not None and S is not None
          and math.isclose(T, w * L + (1 - w) * S, rel_tol=1e-9, abs_tol=1e-12),
          "%s: TargetValue %s = w L + (1 - w) S" % (what, T))
    check(pf is not None and 0 < pf < 1, "%s: PrincipalFrequency %s" % (what, pf))
    return table


# ---------------------------------------------------------------------------
def run_wavelet():
    w = Wavelet(WholeExtent=[-20, 20, -20, 20, -20, 20])
    w.UpdatePipeline()
    image = points_of(w)
    rt = vtk_to_numpy(image.GetPointData().GetArray("RTData")).astype(np.float64)
    lo, hi = float(rt.min()), float(rt.max())
    scale = 0.08
    expected = np.clip((rt - lo) / (hi - lo) * scale, 0, 1).sum()

    s = ErrorDiffusionSampler(Input=w)
    check(list(s.Scalars) == ["POINTS", "RTData"], "Scalars defaults to the active scalars: %s" % (s.Scalars,))
    check(s.DensityMapping == "Scalar Range", "DensityMapping defaults to Scalar Range")
    check(s.UseNumberOfPoints == 1 and s.NumberOfPoints == 100000 and s.Jitter == 1,
          "a point budget of 100000 and jittered points by default")
    s.UseNumberOfPoints = 0
    s.DensityScale = scale
    s.GenerateMask = 1
    s.UpdatePipeline()
    out = points_of(s)
    n = check_counts(out, expected, "Wavelet")
    check(n > 1000, "a few thousand points")
    names = point_array_names(out)
    check("RTData" in names and "Density" in names, "arrays carried: %s" % names)
    if "RTData" in names and "Density" in names:
        # The points are at voxel centers (integer coordinates): look their values up.
        xyz = vtk_to_numpy(out.GetPoints().GetData()).astype(np.float64)
        ijk = np.rint(xyz).astype(int) + 20
        ids = ijk[:, 0] + 41 * (ijk[:, 1] + 41 * ijk[:, 2])
        check(np.allclose(vtk_to_numpy(out.GetPointData().GetArray("RTData")), rt[ids]),
              "RTData of the points is that of their voxels")
        g = np.clip((rt[ids] - lo) / (hi - lo) * scale, 0, 1)
        check(np.allclose(vtk_to_numpy(out.GetPointData().GetArray("Density")), g, atol=1e-5),
              "Density of the points is that of their voxels")
    check_sampling_grid(out, image, "Wavelet")

    mask = points_of(s, 1)
    check(mask.IsA("vtkImageData") and tuple(mask.GetDimensions()) == (41, 41, 41),
          "GenerateMask=1: mask image on port 1 (%s %s)" % (mask.GetClassName(), mask.GetDimensions()))
    mask_array = mask.GetPointData().GetArray("SampleMask")
    check(mask_array is not None and int(vtk_to_numpy(mask_array).sum()) == n,
          "SampleMask counts the %d points" % n)

    sp = BlueNoiseSpectrum(Input=s, GenerateSpectrumImage=1)
    sp.UpdatePipeline()
    check_spectrum(sp, n, rt.size, (41, 41, 41), "Wavelet")
    power = points_of(sp, 1)
    check(power.IsA("vtkImageData") and tuple(power.GetDimensions()) == (41, 41, 41)
          and power.GetPointData().GetArray("Power") is not None, "spectrum image with Power on port 1")

    s.GenerateMask = 0
    s.UpdatePipeline()
    check(points_of(s, 1).GetNumberOfPoints() == 0, "GenerateMask=0: empty port 1")

    # TransferFunction: the opacity function of RTData, 0 below the threshold.
    threshold = 150.0
    otf = GetOpacityTransferFunction("RTData")
    otf.Points = [lo, 0.0, 0.5, 0.0, threshold, 0.0, 0.5, 0.0, hi, 0.25, 0.5, 0.0]
    s.DensityMapping = "Transfer Function"
    s.TransferFunction = otf
    s.UseNumberOfPoints = 0
    s.DensityScale = 1.0
    s.UpdatePipeline()
    tf_out = points_of(s)
    if BLUENOISE_WRAPPED:
        check(s.GetClientSideObject().GetTransferFunction() is otf.GetClientSideObject(),
              "the opacity function reached the sampler")
    expected_tf = np.interp(rt, [lo, threshold, hi], [0.0, 0.0, 0.25]).sum()
    n_tf = check_counts(tf_out, expected_tf, "TransferFunction")
    if n_tf:
        values = vtk_to_numpy(tf_out.GetPointData().GetArray("RTData"))
        check(values.min() > threshold, "no point where the opacity is 0 (min RTData %.2f > %g)"
              % (values.min(), threshold))
    # Editing the function (as in the GUI's opacity editor) re-executes the sampler.
    otf.Points = [lo, 0.0, 0.5, 0.0, threshold, 0.0, 0.5, 0.0, hi, 0.5, 0.5, 0.0]
    s.UpdatePipeline()
    n_tf2 = points_of(s).GetNumberOfPoints()
    check(n_tf2 > 1.6 * n_tf, "editing the opacity function re-executes the sampler (%d -> %d)" % (n_tf, n_tf2))

    # The Scalars default: the active scalars, whichever array that is.
    calc = Calculator(Input=w, Function="300-RTData", ResultArrayName="Inverted")
    calc.UpdatePipeline()
    calc_data = points_of(calc)
    check(calc_data.GetPointData().GetScalars().GetName() == "Inverted", "Calculator result is the active scalars")
    explicit = ErrorDiffusionSampler(Input=calc, UseNumberOfPoints=0, DensityScale=scale)
    check(list(explicit.Scalars) == ["POINTS", "Inverted"],
          "Scalars domain default picks the active scalars: %s" % (explicit.Scalars,))
    explicit.UpdatePipeline()
    explicit_points = vtk_to_numpy(points_of(explicit).GetPoints().GetData())
    by_rt = ErrorDiffusionSampler(Input=calc, UseNumberOfPoints=0, DensityScale=scale, Scalars=["POINTS", "RTData"])
    by_rt.UpdatePipeline()
    by_rt_points = vtk_to_numpy(points_of(by_rt).GetPoints().GetData())
    # An input not yet updated when the filter is made: the property stays unset.
    calc2 = Calculator(Input=w, Function="300-RTData", ResultArrayName="Inverted")
    unset = ErrorDiffusionSampler(Input=calc2, UseNumberOfPoints=0, DensityScale=scale)
    check(not unset.Scalars[1], "Scalars left unset: %s" % (unset.Scalars,))
    unset.UpdatePipeline()
    unset_data = points_of(unset)
    check(unset_data.GetNumberOfPoints() > 0, "no explicit Scalars: the sampler runs")
    if unset_data.GetNumberOfPoints():
        unset_points = vtk_to_numpy(unset_data.GetPoints().GetData())
        check(np.array_equal(unset_points, explicit_points),
              "no explicit Scalars: same points as Scalars=Inverted (the active scalars)")
        check(unset_points.shape != by_rt_points.shape or not np.array_equal(unset_points, by_rt_points),
              "... and not those of RTData")


# ---------------------------------------------------------------------------
class Counter:
    """StartEvent count of the VTK object behind a proxy (builtin session)."""

    def __init__(self, proxy):
        self.count = 0
        proxy.GetClientSideObject().AddObserver("StartEvent", self.on_start)

    def on_start(self, obj, event):
        self.count += 1


def show_as_apply_does(proxy, view):
    """What the GUI's Apply does (pqApplyBehavior::showData): every output port in its
    preferred view; returns the views made or used per port."""
    controller = servermanager.vtkSMParaViewPipelineControllerWithRendering()
    views = []
    for port in range(proxy.GetNumberOfOutputPorts()):
        views.append(controller.ShowInPreferredView(proxy.SMProxy, port, view.SMProxy if view else None))
    return views


def run_executions():
    """One execution per UpdatePipeline and per Apply, whatever ports are shown; a
    display change executes nothing; the spectrum chart shows its series."""
    w = Wavelet(WholeExtent=[-24, 23, -24, 23, -24, 23])
    s = ErrorDiffusionSampler(Input=w, NumberOfPoints=8000)
    sampler = Counter(s)
    s.UpdatePipeline()
    check(sampler.count == 1, "UpdatePipeline executes the sampler once (%d)" % sampler.count)

    view = CreateView("RenderView")
    views = show_as_apply_does(s, view)
    display = GetDisplayProperties(s, view)
    Render(view)
    check(sampler.count == 1, "showing the samples as Apply does executes nothing more (%d)" % sampler.count)
    check(views[0] is not None and views[1] is None,
          "Apply shows the samples and not the mask (%s)" % [v.GetXMLName() if v else None for v in views])
    check(display.Representation == "Points", "samples shown as Points (%s)" % display.Representation)

    sp = BlueNoiseSpectrum(Input=s)
    spectrum = Counter(sp)
    views = show_as_apply_does(sp, view)
    for v in views:
        if v is not None:
            Render(servermanager._getPyProxy(v))
    check(sampler.count == 1 and spectrum.count == 1,
          "showing the spectrum as Apply does: sampler %d, spectrum %d execution(s) (1, 1)"
          % (sampler.count, spectrum.count))
    chart_view = views[0]
    check(chart_view is not None and chart_view.GetXMLName() == "BlueNoiseSpectrumView" and views[1] is None,
          "Apply shows the table in a Blue Noise Spectrum View, not the 3D spectrum (%s)"
          % [v.GetXMLName() if v else None for v in views])
    if chart_view is not None:
        chart = servermanager._getPyProxy(chart_view)
        check(chart.LeftAxisLogScale == 1 and chart.LeftAxisTitle == "Radial power"
              and chart.RightAxisTitle == "Anisotropy (dB)"
              and chart.BottomAxisTitle == "Frequency (cycles per voxel)",
              "spectrum view: log power axis, titled axes (%s, %r, %r, %r)"
              % (chart.LeftAxisLogScale, chart.LeftAxisTitle, chart.RightAxisTitle, chart.BottomAxisTitle))
        rep = GetDisplayProperties(sp, chart)
        corners = dict(zip(rep.SeriesPlotCorner[0::2], rep.SeriesPlotCorner[1::2]))
        markers = dict(zip(rep.SeriesMarkerStyle[0::2], rep.SeriesMarkerStyle[1::2]))
        check(corners.get("AnisotropyDB") == "1" and corners.get("RadialPower") == "0",
              "anisotropy on the right axis, power on the left (%s)" % corners)
        check(markers.get("PrincipalFrequencyMarker") not in (None, "0"),
              "f_g drawn as a marker (%s)" % markers)

    # A display-only change executes nothing.
    display.PointSize = 4
    display.Opacity = 0.5
    Render(view)
    check(sampler.count == 1 and spectrum.count == 1,
          "a display change executes nothing (sampler %d, spectrum %d)" % (sampler.count, spectrum.count))

    # Shown from Python into a plain line chart view: the series are there.
    line = CreateView("XYChartView")
    line_display = Show(sp, line)
    Render(line)
    visible = [n for n, v in zip(line_display.SeriesVisibility[0::2], line_display.SeriesVisibility[1::2])
               if v == "1"]
    check("RadialPower" in visible and "AnisotropyDB" in visible and not line_display.UseIndexForXAxis
          and line_display.XArrayName == "Frequency",
          "Show(spectrum, CreateView('XYChartView')) shows RadialPower and AnisotropyDB against "
          "Frequency (%s)" % visible)
    table = points_of(sp)
    marker = vtk_to_numpy(table.GetColumnByName("PrincipalFrequencyMarker"))
    freq = vtk_to_numpy(table.GetColumnByName("Frequency"))
    power = vtk_to_numpy(table.GetColumnByName("RadialPower"))
    fg = field(table, "PrincipalFrequency")
    at = np.flatnonzero(np.isfinite(marker))
    check(len(at) == 1 and at[0] == np.argmin(np.abs(freq - fg)) and marker[at[0]] == power[at[0]],
          "PrincipalFrequencyMarker: RadialPower at the shell nearest f_g = %s only (rows %s)" % (fg, at))
    check(sampler.count == 1 and spectrum.count == 1,
          "a second view of the spectrum executes nothing (sampler %d, spectrum %d)"
          % (sampler.count, spectrum.count))
    for v in (line, chart_view and servermanager._getPyProxy(chart_view), view):
        if v is not None:
            Delete(v)


def run_component():
    """Component "Magnitude" (ParaView's component selector) samples by the vector's magnitude."""
    w = Wavelet(WholeExtent=[-16, 16, -16, 16, -16, 16])
    w.UpdatePipeline()
    g = Gradient(Input=w, ScalarArray=["POINTS", "RTData"])
    g.UpdatePipeline()
    name = [n for n in g.PointData.keys() if n != "RTData"][0]
    vectors = vtk_to_numpy(points_of(g).GetPointData().GetArray(name)).astype(np.float64)
    magnitude = np.linalg.norm(vectors, axis=1)
    s = ErrorDiffusionSampler(Input=g, Scalars=["POINTS", name], UseNumberOfPoints=0, DensityScale=0.1)
    texts = list(s.GetProperty("Component").Available) if hasattr(s.GetProperty("Component"), "Available") else []
    check(texts[-1:] == ["Magnitude"] and len(texts) == 4, "Component offers %s" % texts)
    s.Component = "Magnitude"
    s.UpdatePipeline()
    lo, hi = magnitude.min(), magnitude.max()
    expected = np.clip((magnitude - lo) / (hi - lo) * 0.1, 0, 1).sum()
    check_counts(points_of(s), expected, "Component Magnitude")
    s.Component = texts[1] if len(texts) > 1 else 1
    s.UpdatePipeline()
    y = vectors[:, 1]
    expected_y = np.clip((y - y.min()) / (y.max() - y.min()) * 0.1, 0, 1).sum()
    check_counts(points_of(s), expected_y, "Component %s" % s.Component)


def run_abort(n):
    """An observer that aborts on progress ends the run at once: empty output, no error, and
    the next update works."""
    w = Wavelet(WholeExtent=[0, n - 1, 0, n - 1, 0, n - 1])
    s = ErrorDiffusionSampler(Input=w, NumberOfPoints=100000)
    w.UpdatePipeline()
    obj = s.GetClientSideObject()
    messages = []
    for o in (obj, obj.GetExecutive()):
        o.AddObserver("ErrorEvent", lambda caller, event: messages.append(event))
    state = {"aborted_at": None, "last": 0.0}

    def on_progress(caller, event):
        p = caller.GetProgress()
        state["last"] = p
        if state["aborted_at"] is None and p >= 0.2:
            state["aborted_at"] = time.perf_counter()
            caller.SetAbortExecuteAndUpdateTime()
    tag = obj.AddObserver("ProgressEvent", on_progress)
    s.UpdatePipeline()
    ended = time.perf_counter()
    out = points_of(s)
    check(state["aborted_at"] is not None, "the run reported progress to abort on")
    if state["aborted_at"] is not None:
        # A figure, not a pass/fail threshold (timings go to the benchmarks).
        print("note: %d^3 run ended %.3f s after the abort" % (n, ended - state["aborted_at"]))
    check(out.GetNumberOfPoints() == 0, "aborted run: empty output (%d points)" % out.GetNumberOfPoints())
    check(not messages, "aborted run: no error (%s)" % messages)
    obj.RemoveObserver(tag)
    obj.SetAbortExecute(0)
    s.UpdatePipeline()
    n_after = points_of(s).GetNumberOfPoints()
    check(abs(n_after - 100000) <= 100, "the next update samples again (%d points)" % n_after)
    sp = BlueNoiseSpectrum(Input=s)
    sp.UpdatePipeline()
    check(not messages, "no error after the abort, spectrum included (%s)" % messages)
    for proxy in (sp, s, w):
        Delete(proxy)


# ---------------------------------------------------------------------------
def open_nifti(path, plugin, workdir):
    """The MRI volume through ParaView's NIfTI reader (AnalyzeNIfTIReaderWriter plugin)."""
    reader_ctor = None
    if plugin and os.path.exists(plugin):
        LoadPlugin(plugin, remote=False, ns=globals())
    else:
        try:
            LoadDistributedPlugin("AnalyzeNIfTIReaderWriter", remote=False, ns=globals())
        except RuntimeError as error:
            print("note: %s" % error)
    reader_ctor = globals().get("NIfTIVolumereader")
    if reader_ctor is None:
        print("SKIP: ParaView's NIfTI reader (AnalyzeNIfTIReaderWriter plugin) is not available")
        sys.exit(SKIP)
    # That reader reads .nii but not .nii.gz: give it a decompressed copy.
    if path.endswith(".gz"):
        plain = os.path.join(workdir, os.path.basename(path)[:-3])
        with gzip.open(path, "rb") as src, open(plain, "wb") as dst:
            shutil.copyfileobj(src, dst)
        path = plain
    reader = reader_ctor(FileName=path)
    check(reader.GetXMLName() == "NIfTIReader", "reader proxy NIfTIReader (%s)" % reader.GetXMLName())
    return reader


def run_mri(mri, nifti_plugin):
    if not mri or not os.path.exists(mri):
        print("SKIP: MRI volume %r not found (Debian package mricron-data)" % mri)
        sys.exit(SKIP)
    with tempfile.TemporaryDirectory(prefix="bluenoise-mri-") as workdir:
        reader = open_nifti(mri, nifti_plugin, workdir)
        reader.UpdatePipeline()
        image = points_of(reader)
        dims = tuple(image.GetDimensions())
        check(dims == (181, 217, 181), "MRI dimensions %s" % (dims,))
        scalars = image.GetPointData().GetScalars()
        if not check(scalars is not None, "MRI has active point scalars"):
            finish()
        name = scalars.GetName()
        x = vtk_to_numpy(scalars).astype(np.float64)
        lo, hi = float(x.min()), float(x.max())
        scale = 0.05
        expected = np.clip((x - lo) / (hi - lo) * scale, 0, 1).sum()
        print("MRI: %s voxels, %s in [%g, %g], expected %.1f points" % (x.size, name, lo, hi, expected))

        s = ErrorDiffusionSampler(Input=reader)
        check(list(s.Scalars) == ["POINTS", name], "Scalars defaults to %s: %s" % (name, s.Scalars))
        s.DensityMapping = "Scalar Range"
        s.UseNumberOfPoints = 0
        s.DensityScale = scale
        s.UpdatePipeline()
        out = points_of(s)
        n = check_counts(out, expected, "MRI")
        names = point_array_names(out)
        check(name in names and "Density" in names, "arrays carried: %s" % names)
        if name in names:
            values = vtk_to_numpy(out.GetPointData().GetArray(name))
            check(values.min() > lo, "no point in the background (min %s %g > %g)" % (name, values.min(), lo))
        check_sampling_grid(out, image, "MRI")
        bounds = out.GetBounds()
        ib = image.GetBounds()
        check(all(bounds[2 * a] >= ib[2 * a] - 1e-4 and bounds[2 * a + 1] <= ib[2 * a + 1] + 1e-4 for a in range(3)),
              "points inside the volume bounds")

        sp = BlueNoiseSpectrum(Input=s)
        sp.UpdatePipeline()
        check_spectrum(sp, n, x.size, dims, "MRI")
        # Free the proxies before the temporary copy goes.
        Delete(sp)
        Delete(s)
        Delete(reader)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--part", choices=("wavelet", "mri"), required=True)
    parser.add_argument("--mri", default="/usr/share/mricron/templates/ch2bet.nii.gz")
    parser.add_argument("--nifti-plugin", default="")
    parser.add_argument("--abort-size", type=int, default=128, help="voxels per side of the aborted run")
    args = parser.parse_args()

    if not check(os.path.exists(args.plugin), "plugin file %s exists" % args.plugin):
        finish()
    LoadPlugin(args.plugin, remote=False, ns=globals())
    check("ErrorDiffusionSampler" in globals() and "BlueNoiseSpectrum" in globals(),
          "LoadPlugin defines ErrorDiffusionSampler and BlueNoiseSpectrum")
    if FAILURES:
        finish()
    if args.part == "wavelet":
        run_wavelet()
        run_executions()
        run_component()
        run_abort(args.abort_size)
    else:
        run_mri(args.mri, args.nifti_plugin)
    finish()


if __name__ == "__main__":
    main()
