# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""DensityMapping TransferFunction, as particle-based volume rendering uses it.

    PYTHONPATH=<build>/lib/python3/dist-packages python3 TestTransferFunctionDensity.py

A 40^3 volume whose value runs 0..100 (a ramp along x plus a wave along y and
z) and an opacity-like transfer function that is 0 below 40 and on a band
[62, 72] in the middle, positive elsewhere. For both methods and several
DensityScales (one that clamps), checks:
- zero opacity gives no particles: no sample has a value where the function
  is 0 (below 40 or in the band);
- particles do appear where it is positive, in each positive range;
- Density = min(1, DensityScale * f(value)) for every sample;
- the count is within 3 % (error diffusion) / 4 binomial standard deviations
  (hit-and-miss) of the sum of the densities;
- changing the function (the band moved) re-executes the sampler (the filter
  includes the function's modification time) and the new zero band is empty.
Exits 1 when a check fails.
"""
import math
import sys

import numpy as np

from bluenoise import vtkErrorDiffusionSampler
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction

from bluenoise_testing import check, summary


def volume(n=40):
    ax = np.arange(n, dtype=np.float64)
    z, y, x = np.meshgrid(ax, ax, ax, indexing="ij")
    v = 100.0 * x / (n - 1) + 4.0 * np.sin(2 * math.pi * y / (n - 1)) * np.cos(2 * math.pi * z / (n - 1))
    v = np.clip(v, 0.0, 100.0)
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    arr = numpy_to_vtk(np.ascontiguousarray(v.ravel().astype(np.float32)), deep=1)
    arr.SetName("value")
    image.GetPointData().SetScalars(arr)
    return image, v.ravel().astype(np.float32).astype(np.float64)


def make_function(band):
    lo, hi = band
    f = vtkPiecewiseFunction()
    f.AllowDuplicateScalarsOn()
    for x, y in [(0.0, 0.0), (40.0, 0.0), (50.0, 0.3), (lo - 6.0, 0.3), (lo, 0.0), (hi, 0.0),
                 (hi + 8.0, 0.4), (100.0, 0.5)]:
        f.AddPoint(x, y)
    return f


def evaluate(f, values):
    table = np.array([f.GetValue(float(v)) for v in np.unique(values)])
    return np.interp(values, np.unique(values), table)


def run(sampler):
    sampler.Update()
    out = sampler.GetOutput()
    if out.GetNumberOfPoints() == 0:
        return np.zeros(0), np.zeros(0)
    return (vtk_to_numpy(out.GetPointData().GetArray("value")).astype(np.float64),
            vtk_to_numpy(out.GetPointData().GetArray("Density")).astype(np.float64))


def main():
    image, values = volume()
    band = (62.0, 72.0)
    f = make_function(band)
    fv = evaluate(f, values)
    check(np.count_nonzero(fv == 0) > 0.4 * values.size and np.count_nonzero(fv > 0) > 0.3 * values.size,
          "the function is 0 on %d voxels and positive on %d"
          % (np.count_nonzero(fv == 0), np.count_nonzero(fv > 0)))
    for method, name in ((vtkErrorDiffusionSampler.METHOD_ERROR_DIFFUSION, "ED"),
                         (vtkErrorDiffusionSampler.METHOD_WHITE_NOISE, "WN")):
        for scale in (0.1, 1.0, 3.0):
            what = "%s scale %g" % (name, scale)
            s = vtkErrorDiffusionSampler()
            s.SetInputData(image)
            s.SetMethod(method)
            s.SetDensityMappingToTransferFunction()
            s.SetTransferFunction(f)
            s.UseNumberOfPointsOff()
            s.SetDensityScale(scale)
            s.SetSeed(3)
            v, d = run(s)
            g = np.minimum(1.0, scale * fv)
            expected = g.sum()
            sigma = math.sqrt(np.sum(g * (1 - g)))
            fs = evaluate(f, v)
            check(len(v) > 0 and np.all(fs > 0),
                  "%s: %d particles, none where the function is 0 (min f at samples %.3g)"
                  % (what, len(v), fs.min() if len(fs) else float("nan")))
            check(not np.any((v <= 40.0) | ((v >= band[0]) & (v <= band[1]))),
                  "%s: no sample below 40 or in the band %s" % (what, band))
            check(np.count_nonzero((v > 40) & (v < band[0])) > 0 and np.count_nonzero(v > band[1]) > 0,
                  "%s: samples in both positive ranges" % what)
            check(np.allclose(d, np.minimum(1.0, scale * fs), atol=1e-5),
                  "%s: Density = min(1, scale * f(value))" % what)
            tol = 0.03 * expected if name == "ED" else max(4 * sigma, 1.0)
            check(abs(len(v) - expected) <= tol,
                  "%s: %d particles, expected %.1f (tolerance %.1f)" % (what, len(v), expected, tol))
            if scale == 1.0:
                # Move the band: the sampler follows the function.
                f2 = make_function((50.0, 58.0))
                f.DeepCopy(f2)
                v2, _ = run(s)
                check(len(v2) > 0 and not np.any((v2 >= 50.0) & (v2 <= 58.0))
                      and np.any((v2 > 64.0) & (v2 < 72.0)),
                      "%s: after the function changed, the new band [50, 58] is empty and the old "
                      "one sampled" % what)
                f.DeepCopy(make_function(band))
    return summary()


if __name__ == "__main__":
    sys.exit(main())
