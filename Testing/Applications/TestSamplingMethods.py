# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Hit-and-miss (WhiteNoise) against error diffusion (ErrorDiffusion) in vtkErrorDiffusionSampler.

    PYTHONPATH=<build>/lib/python3/dist-packages python3 TestSamplingMethods.py

A smooth 48^3 volume (sum of sines, density from the value, ScalarRange
mapping) at three DensityScales. Checks:
- same expected count: both methods within 3 % of the sum of the densities
  (and white noise within 4 binomial standard deviations);
- the Density array is the mapped density of each sample's voxel, for both;
- determinism: the same Seed gives the same points bit for bit, another Seed
  different points, for both methods;
- the methods differ as they should: hit-and-miss is unbiased over seeds
  (mean count within 3 standard errors of the expectation), and error
  diffusion spreads its points evenly (mean nearest-neighbor distance larger
  than white noise's, fewer close pairs).
Exits 1 when a check fails.
"""
import math
import sys

import numpy as np

from bluenoise import vtkErrorDiffusionSampler
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData, vtkStaticPointLocator

from bluenoise_testing import check, summary


def volume(n=48):
    ax = np.arange(n, dtype=np.float64)
    z, y, x = np.meshgrid(ax, ax, ax, indexing="ij")
    w = 2 * math.pi / (n - 1)
    v = 0.5 + (np.sin(1.5 * w * x) + np.sin(w * y + 0.5) + np.sin(1.2 * w * z + 1.0)) / 6.0
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    arr = numpy_to_vtk(np.ascontiguousarray(v.ravel().astype(np.float32)), deep=1)
    arr.SetName("value")
    image.GetPointData().SetScalars(arr)
    return image, v.ravel()


def nearest_neighbor_distances(pts):
    """Distance of every point to its nearest other point (vtkStaticPointLocator)."""
    data = vtkPolyData()
    vp = vtkPoints()
    vp.SetData(numpy_to_vtk(np.ascontiguousarray(pts.astype(np.float64)), deep=1))
    data.SetPoints(vp)
    locator = vtkStaticPointLocator()
    locator.SetDataSet(data)
    locator.BuildLocator()
    ids = vtkIdList()
    out = np.empty(len(pts))
    for i, p in enumerate(pts.astype(np.float64)):
        locator.FindClosestNPoints(2, p, ids)
        j = ids.GetId(1) if ids.GetId(0) == i else ids.GetId(0)
        out[i] = np.linalg.norm(pts[j].astype(np.float64) - p)
    return out


def sample(image, method, scale, seed):
    s = vtkErrorDiffusionSampler()
    s.SetInputData(image)
    s.SetMethod(method)
    s.SetDensityMappingToScalarRange()
    s.UseNumberOfPointsOff()
    s.SetDensityScale(scale)
    s.SetSeed(seed)
    s.Update()
    out = s.GetOutput()
    pts = vtk_to_numpy(out.GetPoints().GetData()).copy() if out.GetNumberOfPoints() else \
        np.zeros((0, 3), np.float32)
    dens = vtk_to_numpy(out.GetPointData().GetArray("Density")).copy() if out.GetNumberOfPoints() \
        else np.zeros(0)
    return pts, dens


def main():
    image, values = volume()
    n = image.GetDimensions()[0]
    g0 = (values - values.min()) / (values.max() - values.min())
    ED = vtkErrorDiffusionSampler.METHOD_ERROR_DIFFUSION
    WN = vtkErrorDiffusionSampler.METHOD_WHITE_NOISE
    names = {ED: "ED", WN: "WN"}
    for scale in (0.05, 0.2, 1.0):
        g = np.minimum(1.0, scale * g0)
        expected = g.sum()
        sigma = math.sqrt(np.sum(g * (1 - g)))
        nn = {}
        for method in (ED, WN):
            what = "%s scale %g" % (names[method], scale)
            pts, dens = sample(image, method, scale, 7)
            count = len(pts)
            check(abs(count - expected) <= 0.03 * expected,
                  "%s: %d points, expected %.1f (within 3 %%)" % (what, count, expected))
            if method == WN:
                check(abs(count - expected) <= 4 * sigma,
                      "%s: within 4 sigma = %.1f of the expectation" % (what, 4 * sigma))
            ijk = np.rint(pts).astype(np.int64)
            vox = ijk[:, 0] + n * (ijk[:, 1] + n * ijk[:, 2])
            check(np.allclose(dens, g[vox], atol=1e-6),
                  "%s: Density is the voxel's mapped density" % what)
            check(np.all(g[vox] > 0), "%s: no point where the density is 0" % what)
            # Determinism.
            again, _ = sample(image, method, scale, 7)
            check(np.array_equal(pts, again), "%s: same Seed, same points bit for bit" % what)
            other, _ = sample(image, method, scale, 8)
            check(not np.array_equal(pts, other), "%s: another Seed, other points" % what)
            if scale <= 0.2:
                nn[method] = nearest_neighbor_distances(pts)
        if scale <= 0.2:
            # Blue noise: larger nearest-neighbor distances, fewer close pairs.
            close = {m: float(np.mean(nn[m] <= 1.5)) for m in nn}
            check(nn[ED].mean() > 1.1 * nn[WN].mean(),
                  "scale %g: mean nearest-neighbor distance ED %.3f > 1.1 x WN %.3f"
                  % (scale, nn[ED].mean(), nn[WN].mean()))
            check(close[ED] < close[WN],
                  "scale %g: fraction of points with a neighbor within 1.5 voxels ED %.3f < WN %.3f"
                  % (scale, close[ED], close[WN]))

    # Hit-and-miss is unbiased: the mean count over seeds.
    scale = 0.1
    g = np.minimum(1.0, scale * g0)
    expected = g.sum()
    sigma = math.sqrt(np.sum(g * (1 - g)))
    counts = [len(sample(image, WN, scale, seed)[0]) for seed in range(8)]
    check(abs(np.mean(counts) - expected) <= 3 * sigma / math.sqrt(len(counts)),
          "WN mean count over 8 seeds %.1f, expected %.1f (3 standard errors %.1f)"
          % (np.mean(counts), expected, 3 * sigma / math.sqrt(len(counts))))
    check(np.std(counts) > 0.2 * sigma,
          "WN counts vary between seeds like a binomial draw (std %.1f, binomial %.1f)"
          % (np.std(counts), sigma))

    return summary()


if __name__ == "__main__":
    sys.exit(main())
