# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The Python wrapping in plain VTK (no ParaView): `from bluenoise import ...`.

Run with the Python of the VTK the module was built against and
PYTHONPATH=<build>/lib/python3/dist-packages (BLUENOISE_PYTHONPATH). Checks a
vtkRTAnalyticSource -> vtkErrorDiffusionSampler -> vtkBlueNoiseSpectrum
pipeline against values computed here with numpy, the determinism of Seed,
and every property through its Set/Get pair. Exits non-zero on any failure.
"""
import math
import sys

import numpy as np

from bluenoise import vtkBlueNoiseSpectrum, vtkErrorDiffusionSampler
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource

from bluenoise_testing import check, finish



class ErrorCatcher:
    """Collects vtkErrorMacro/vtkWarningMacro messages of one object."""

    def __init__(self, obj):
        self.errors = []
        self.warnings = []
        obj.AddObserver(vtkCommand.ErrorEvent, self._error)
        obj.AddObserver(vtkCommand.WarningEvent, self._warning)

    def _error(self, obj, event, message=None):
        self.errors.append(message)

    _error.CallDataType = 8  # VTK_STRING

    def _warning(self, obj, event, message=None):
        self.warnings.append(message)

    _warning.CallDataType = 8


def field_value(data, name):
    array = data.GetFieldData().GetArray(name)
    if array is None:
        return None
    return array.GetTuple(0)[0] if array.GetNumberOfComponents() == 1 else array.GetTuple(0)


# ---------------------------------------------------------------------------
# The input: the usual wavelet, 41^3 voxels.
source = vtkRTAnalyticSource()
source.SetWholeExtent(-20, 20, -20, 20, -20, 20)
source.Update()
image = source.GetOutput()
dims = image.GetDimensions()
rt = vtk_to_numpy(image.GetPointData().GetArray("RTData")).astype(np.float64)
lo, hi = rt.min(), rt.max()
SCALE = 0.08


def expected_density(values, scale, lo=lo, hi=hi):
    return np.clip((values - lo) / (hi - lo) * scale, 0.0, 1.0)


expected_count = expected_density(rt, SCALE).sum()
print("input: %s voxels, RTData in [%g, %g], expected %.1f points" % (rt.size, lo, hi, expected_count))

# ---------------------------------------------------------------------------
# The sampler with a DensityScale instead of the point budget: active scalars, ScalarRange.
sampler = vtkErrorDiffusionSampler()
sampler_errors = ErrorCatcher(sampler)
sampler.SetInputConnection(source.GetOutputPort())
sampler.UseNumberOfPointsOff()
sampler.SetDensityScale(SCALE)
sampler.GenerateMaskOn()
sampler.Update()
points = sampler.GetOutput()
n = points.GetNumberOfPoints()
check(not sampler_errors.errors, "sampler ran without errors %s" % sampler_errors.errors)
check(n > 1000, "a few thousand points (%d)" % n)
check(abs(n - expected_count) <= max(2.0, 5e-4 * expected_count),
      "count %d equals the sum of densities %.1f" % (n, expected_count))
check(points.GetNumberOfVerts() == n, "one vertex cell per point (%d verts)" % points.GetNumberOfVerts())

# Points sit on voxel centers (origin 0, spacing 1: integer coordinates in the extent).
xyz = vtk_to_numpy(points.GetPoints().GetData()).astype(np.float64)
ijk = np.rint(xyz).astype(int)
check(np.abs(xyz - ijk).max() < 1e-5 and ijk.min() >= -20 and ijk.max() <= 20,
      "points at voxel centers inside the extent")
ids = (ijk[:, 0] + 20) + dims[0] * ((ijk[:, 1] + 20) + dims[1] * (ijk[:, 2] + 20))
check(len(np.unique(ids)) == n, "at most one point per voxel")

# Arrays: the input array carried over, plus Density.
pd = points.GetPointData()
out_rt = pd.GetArray("RTData")
out_density = pd.GetArray("Density")
if check(out_rt is not None and out_density is not None, "point arrays RTData and Density present"):
    check(np.allclose(vtk_to_numpy(out_rt), rt[ids]), "RTData values are those of the sampled voxels")
    check(np.allclose(vtk_to_numpy(out_density), expected_density(rt[ids], SCALE), atol=1e-5),
          "Density values are the densities of the sampled voxels")

# The sampling grid in field data.
check(field_value(points, "SamplingGridOrigin") == (0.0, 0.0, 0.0), "SamplingGridOrigin")
check(field_value(points, "SamplingGridSpacing") == (1.0, 1.0, 1.0), "SamplingGridSpacing")
check(field_value(points, "SamplingGridExtent") == (-20.0, 20.0, -20.0, 20.0, -20.0, 20.0),
      "SamplingGridExtent %s" % (field_value(points, "SamplingGridExtent"),))
check(field_value(points, "SamplingGridDirection") == (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
      "SamplingGridDirection")

# The mask on port 1 marks exactly the sampled voxels.
mask = sampler.GetMaskOutput()
mask_array = mask.GetPointData().GetArray("SampleMask")
if check(mask_array is not None and mask.GetDimensions() == dims, "mask image with SampleMask on the input grid"):
    m = vtk_to_numpy(mask_array)
    check(int(m.sum()) == n, "mask counts the points (%d)" % int(m.sum()))
    check(np.array_equal(np.flatnonzero(m), np.sort(ids)), "mask is set exactly at the sampled voxels")

# ---------------------------------------------------------------------------
# The spectrum of the points.
spectrum = vtkBlueNoiseSpectrum()
spectrum_errors = ErrorCatcher(spectrum)
spectrum.SetInputConnection(sampler.GetOutputPort())
spectrum.Update()
table = spectrum.GetOutput()
check(not spectrum_errors.errors, "spectrum ran without errors %s" % spectrum_errors.errors)
columns = ["Frequency", "RadialPower", "Anisotropy", "AnisotropyDB", "SRAPS_XY", "SRAPS_XZ", "SRAPS_YZ",
           "ShellCount"]
check(all(table.GetColumnByName(c) is not None for c in columns), "table columns %s" % columns)
rows = table.GetNumberOfRows()
freq = None
check(rows >= 20, "one row per shell (%d rows for a 41^3 grid)" % rows)
if rows and all(table.GetColumnByName(c) is not None for c in columns):
    freq = vtk_to_numpy(table.GetColumnByName("Frequency"))
    power = vtk_to_numpy(table.GetColumnByName("RadialPower"))
    check(np.all(np.diff(freq) > 0) and freq[0] > 0, "Frequency increases from above 0")
    check(np.all(np.isfinite(power)) and np.all(power >= 0), "RadialPower finite and non-negative")
    check(np.all(vtk_to_numpy(table.GetColumnByName("ShellCount")) > 0), "every shell has samples")
check(field_value(table, "NumberOfPoints") == n, "NumberOfPoints %s == %d" % (field_value(table, "NumberOfPoints"), n))
check(field_value(table, "GridDimensions") == (41.0, 41.0, 41.0), "GridDimensions from the sampling grid")
check(field_value(table, "Realizations") == 1, "one realization")
density = field_value(table, "Density")
check(density is not None and math.isclose(density, n / rt.size, rel_tol=1e-9),
      "Density %s == N / voxels %.6f" % (density, n / rt.size))
L = field_value(table, "LowFrequencyRatio")
C = field_value(table, "SymmetryCorrelation")
S = field_value(table, "Symmetry")
T = field_value(table, "TargetValue")
check(L is not None and 0 < L < 1, "LowFrequencyRatio %s in (0, 1)" % L)
check(S is not None and C is not None and math.isclose(S, 1 - C, abs_tol=1e-12), "Symmetry = 1 - C")
check(T is not None and math.isclose(T, 0.02 * L + 0.98 * S, rel_tol=1e-9, abs_tol=1e-12),
      "TargetValue = 0.02 L + 0.98 S")
pf = field_value(table, "PrincipalFrequency")
check(pf is not None and freq is not None and 0 < pf <= freq[-1], "PrincipalFrequency %s within the shells" % pf)
image_out = spectrum.GetSpectrumImageOutput()
check(image_out.GetDimensions() == (41, 41, 41) and image_out.GetPointData().GetArray("Power") is not None,
      "spectrum image 41^3 with Power")

# The mask, read as counts on its own grid, is the same signal: same metric.
mask_spectrum = vtkBlueNoiseSpectrum()
mask_spectrum.SetInputConnection(sampler.GetOutputPort(1))
mask_spectrum.Update()
check(math.isclose(field_value(mask_spectrum.GetOutput(), "LowFrequencyRatio"), L, rel_tol=1e-9),
      "spectrum of the mask image equals the spectrum of the points")

# ---------------------------------------------------------------------------
# Determinism: same seed, same points; another seed, other points, same count.
def sample(seed, **settings):
    s = vtkErrorDiffusionSampler()
    s.SetInputConnection(source.GetOutputPort())
    s.UseNumberOfPointsOff()
    s.SetDensityScale(SCALE)
    s.SetSeed(seed)
    for name, value in settings.items():
        getattr(s, "Set" + name)(value)
    s.Update()
    return vtk_to_numpy(s.GetOutput().GetPoints().GetData()).copy()


a, b, c = sample(7), sample(7), sample(8)
check(np.array_equal(a, b), "Seed 7 twice gives the same points")
check(a.shape != c.shape or not np.array_equal(a, c), "Seed 8 gives other points")
check(abs(len(c) - expected_count) <= max(2.0, 5e-4 * expected_count), "Seed 8 count %d exact" % len(c))
check(np.array_equal(sample(0), vtk_to_numpy(points.GetPoints().GetData())), "default Seed is 0")

# Two realizations averaged by the spectrum.
other = vtkErrorDiffusionSampler()
other.SetInputConnection(source.GetOutputPort())
other.UseNumberOfPointsOff()
other.SetDensityScale(SCALE)
other.SetSeed(8)
spectrum.AddInputConnection(other.GetOutputPort())
spectrum.Update()
check(field_value(spectrum.GetOutput(), "Realizations") == 2, "two realizations")
check(math.isclose(field_value(spectrum.GetOutput(), "NumberOfPoints"), (n + len(c)) / 2.0),
      "NumberOfPoints is the mean over realizations")

# Identity and transfer-function mappings follow their definitions.
ident = vtkErrorDiffusionSampler()
ident.SetInputConnection(source.GetOutputPort())
ident.SetDensityMappingToIdentity()
ident.UseNumberOfPointsOff()
ident.SetDensityScale(0.0005)  # RTData ~ 40..280 -> densities ~ 0.02..0.14
ident.Update()
exp_ident = np.clip(rt * 0.0005, 0, 1).sum()
check(abs(ident.GetOutput().GetNumberOfPoints() - exp_ident) <= max(2.0, 5e-4 * exp_ident),
      "Identity mapping: %d points, expected %.1f" % (ident.GetOutput().GetNumberOfPoints(), exp_ident))

threshold = 150.0
tf = vtkPiecewiseFunction()
tf.AddPoint(lo, 0.0)
tf.AddPoint(threshold, 0.0)
tf.AddPoint(hi, 0.2)
tfs = vtkErrorDiffusionSampler()
tfs.SetInputConnection(source.GetOutputPort())
tfs.SetDensityMappingToTransferFunction()
tfs.UseNumberOfPointsOff()
tfs.SetTransferFunction(tf)
tfs.Update()
tf_out = tfs.GetOutput()
exp_tf = np.interp(rt, [lo, threshold, hi], [0.0, 0.0, 0.2]).sum()
check(abs(tf_out.GetNumberOfPoints() - exp_tf) <= max(2.0, 5e-4 * exp_tf),
      "TransferFunction mapping: %d points, expected %.1f" % (tf_out.GetNumberOfPoints(), exp_tf))
if tf_out.GetNumberOfPoints():
    check(vtk_to_numpy(tf_out.GetPointData().GetArray("RTData")).min() > threshold,
          "no point where the transfer function is 0")
# The transfer function's modification re-executes the sampler.
n_tf = tf_out.GetNumberOfPoints()
tf.AddPoint(hi, 0.4)
tfs.Update()
check(tfs.GetOutput().GetNumberOfPoints() > 1.5 * n_tf,
      "editing the transfer function re-executes the sampler")

# The point budget: the expected count is NumberOfPoints, the count exact.
budget = vtkErrorDiffusionSampler()
budget.SetInputConnection(source.GetOutputPort())
budget.SetNumberOfPoints(5000)
budget.Update()
nb = budget.GetOutput().GetNumberOfPoints()
check(abs(nb - 5000) <= 5, "NumberOfPoints 5000: %d points" % nb)
check(math.isclose(field_value(budget.GetOutput(), "ExpectedNumberOfPoints"), 5000.0, rel_tol=1e-6),
      "ExpectedNumberOfPoints in the field data")
scale = field_value(budget.GetOutput(), "DensityScale")
check(math.isclose(expected_density(rt, scale).sum(), 5000.0, rel_tol=1e-4),
      "the DensityScale in the field data gives 5000 expected points (%g)" % scale)

# Jitter: points inside their voxels, the same voxels.
jittered = vtkErrorDiffusionSampler()
jittered.SetInputConnection(source.GetOutputPort())
jittered.SetNumberOfPoints(5000)
jittered.JitterOn()
jittered.Update()
jxyz = vtk_to_numpy(jittered.GetOutput().GetPoints().GetData()).astype(np.float64)
bxyz = vtk_to_numpy(budget.GetOutput().GetPoints().GetData()).astype(np.float64)
check(jxyz.shape == bxyz.shape and np.array_equal(np.floor(jxyz + 0.5), bxyz),
      "jittered points stay in the voxels of the points without jitter")
check(np.abs(jxyz - bxyz).max() > 0.3 and np.abs(jxyz - bxyz).max() <= 0.5,
      "jitter moves points by up to half a voxel")
offsets = jxyz - bxyz  # uniform in [-0.5, 0.5) on each axis, the axes independent
check(np.abs(offsets.mean(axis=0)).max() < 0.03 and np.abs(offsets.std(axis=0) - math.sqrt(1 / 12)).max() < 0.02,
      "jitter offsets of mean 0 and the spread of a uniform variable: %s, %s"
      % (offsets.mean(axis=0), offsets.std(axis=0)))
correlation = np.corrcoef(offsets.T)[np.triu_indices(3, 1)]
check(np.abs(correlation).max() < 0.06, "jitter offsets independent across axes: %s" % correlation)

# Bad input: an error and empty outputs, not a crash.
bad = vtkErrorDiffusionSampler()
bad_errors = ErrorCatcher(bad)
bad.SetInputConnection(source.GetOutputPort())
bad.UseNumberOfPointsOff()
bad.SetDensityScale(float("nan"))
print("(a vtkExecutive error about the failed request is expected next)", flush=True)
bad.Update()
check(bad_errors.errors and bad.GetOutput().GetNumberOfPoints() == 0,
      "NaN DensityScale: error and no points")

# ---------------------------------------------------------------------------
# Every property through Set/Get (values different from the defaults).
s = vtkErrorDiffusionSampler()
defaults = {
    "Component": 0, "DensityMapping": 1, "ScalarRange": (0.0, 1.0), "UseCustomScalarRange": False,
    "UseNumberOfPoints": True, "NumberOfPoints": 100000, "DensityScale": 1.0, "ParameterSet": 3,
    "ParameterFile": "", "ModulationScale": 0.5, "Seed": 0, "WarmUpLayers": 8, "Jitter": False,
    "GenerateMask": False, "OutputPointsPrecision": 0, "UseWorkerThread": True, "NumberOfSlabs": 1,
    "OverlapLayers": 8,
}
for name, value in defaults.items():
    got = getattr(s, "Get" + name)()
    check(got == value or (got is None and value == ""), "sampler default %s = %r (got %r)" % (name, value, got))
check(s.GetTransferFunction() is None, "sampler default TransferFunction is None")
values = {
    "Component": -1, "DensityMapping": 2, "ScalarRange": (-3.5, 12.25), "UseCustomScalarRange": True,
    "UseNumberOfPoints": False, "NumberOfPoints": 777, "DensityScale": 0.375, "ParameterSet": 2,
    "ParameterFile": "/tmp/some table.txt", "ModulationScale": 1.25, "Seed": 12345, "WarmUpLayers": 100,
    "Jitter": True, "GenerateMask": True, "OutputPointsPrecision": 1, "UseWorkerThread": False,
    "NumberOfSlabs": 4, "OverlapLayers": 3,
}
for name, value in values.items():
    getattr(s, "Set" + name)(value)
    check(getattr(s, "Get" + name)() == value, "sampler Set/Get%s %r" % (name, value))
s.SetTransferFunction(tf)
check(s.GetTransferFunction() is tf, "sampler Set/GetTransferFunction")
s.SetDensityMappingToIdentity()
check(s.GetDensityMapping() == vtkErrorDiffusionSampler.DENSITY_IDENTITY == 0, "SetDensityMappingToIdentity")
s.SetDensityMappingToScalarRange()
check(s.GetDensityMapping() == vtkErrorDiffusionSampler.DENSITY_SCALAR_RANGE == 1, "SetDensityMappingToScalarRange")
s.SetDensityMappingToTransferFunction()
check(s.GetDensityMapping() == vtkErrorDiffusionSampler.DENSITY_TRANSFER_FUNCTION == 2,
      "SetDensityMappingToTransferFunction")
check((vtkErrorDiffusionSampler.PARAMETERS_PAPER, vtkErrorDiffusionSampler.PARAMETERS_FIXED,
       vtkErrorDiffusionSampler.PARAMETERS_CUSTOM) == (0, 1, 2), "ParameterSets enum")
check((vtkErrorDiffusionSampler.METHOD_ERROR_DIFFUSION, vtkErrorDiffusionSampler.METHOD_WHITE_NOISE) == (0, 1),
      "Methods enum")
s.SetMethodToEnergyRelaxedErrorDiffusion()
check(s.GetMethod() == vtkErrorDiffusionSampler.METHOD_ENERGY_RELAXED_ERROR_DIFFUSION == 5,
      "SetMethodToEnergyRelaxedErrorDiffusion")
s.UseCustomScalarRangeOff()
s.GenerateMaskOff()
check(not s.GetUseCustomScalarRange() and not s.GetGenerateMask(), "boolean Off macros")
# Clamped setters.
s.SetDensityMapping(7)
s.SetComponent(-5)
s.SetWarmUpLayers(100000)
s.SetParameterSet(-2)
s.SetDensityScale(-1.0)
s.SetModulationScale(1e300)
s.SetSeed(-4)
s.SetNumberOfPoints(-3)
s.SetNumberOfSlabs(0)
check((s.GetDensityMapping(), s.GetComponent(), s.GetWarmUpLayers(), s.GetParameterSet(), s.GetDensityScale(),
       s.GetModulationScale(), s.GetSeed(), s.GetNumberOfPoints(), s.GetNumberOfSlabs())
      == (s.DENSITY_COLOR_MAP_OPACITY, -1, 4096, 0, 0.0, 2.0, 0, 0, 1), "clamped setters clamp")

sp = vtkBlueNoiseSpectrum()
sdefaults = {"Weight": 0.02, "UseInputGrid": True, "GridDimensions": (64, 64, 64),
             "GridBounds": (0.0, 1.0, 0.0, 1.0, 0.0, 1.0), "UseGridBounds": False, "GenerateSpectrumImage": True}
for name, value in sdefaults.items():
    check(getattr(sp, "Get" + name)() == value, "spectrum default %s = %r" % (name, value))
svalues = {"Weight": 0.75, "UseInputGrid": False, "GridDimensions": (17, 19, 23),
           "GridBounds": (-1.0, 2.0, -3.0, 4.0, -5.0, 6.0), "UseGridBounds": True, "GenerateSpectrumImage": False}
for name, value in svalues.items():
    getattr(sp, "Set" + name)(value)
    check(getattr(sp, "Get" + name)() == value, "spectrum Set/Get%s %r" % (name, value))
sp.SetWeight(1.5)
check(sp.GetWeight() == 1.0, "Weight clamped to 1")

# The spectrum honors UseInputGrid off + GridDimensions (+ GridBounds).
sp.SetWeight(0.02)
sp.SetUseGridBounds(False)
sp.SetInputConnection(sampler.GetOutputPort())
sp.Update()
check(field_value(sp.GetOutput(), "GridDimensions") == (17.0, 19.0, 23.0), "GridDimensions used with UseInputGrid off")
# GridBounds over the sampled extent with one grid point per voxel: the same
# binning as the sampling grid, hence the same metric.
sp.SetGridDimensions(41, 41, 41)
sp.SetGridBounds(-20, 20, -20, 20, -20, 20)
sp.SetUseGridBounds(True)
sp.Update()
check(math.isclose(field_value(sp.GetOutput(), "LowFrequencyRatio"), L, rel_tol=1e-9),
      "GridBounds equal to the sampling grid give the same metric")

check("paraview" not in sys.modules and "paraview.simple" not in sys.modules, "ran without paraview")

finish()
