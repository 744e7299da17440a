# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Density Mapping = Color Map Opacity in pvpython: sample where the data is seen.

    pvpython TestPluginColorMapOpacity.py --plugin BlueNoiseSampling.so

The sampler's TransferFunction becomes the opacity function of the selected
array's colour map (the one GetOpacityTransferFunction returns and the Color
Map Editor edits); editing that function re-samples: with the opacity 0 below
the middle of the range and 1 above, every sample lies above the middle, and
the other way round after the next edit. Another mapping leaves the function
alone. Every check prints ok/FAIL; the exit code is 1 when any check failed.
"""
import argparse

import numpy as np

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy

from bluenoise_testing import check, finish


def sampled_values(proxy):
    data = servermanager.Fetch(proxy)
    array = data.GetPointData().GetArray("RTData")
    return vtk_to_numpy(array) if array is not None else np.zeros(0)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    args = parser.parse_args()
    LoadPlugin(args.plugin, remote=False, ns=globals())

    wavelet = Wavelet(WholeExtent=[-20, 20, -20, 20, -20, 20])
    wavelet.UpdatePipeline()
    lo, hi = wavelet.PointData["RTData"].GetRange()
    middle = 0.5 * (lo + hi)
    sampler = ErrorDiffusionSampler(Input=wavelet, Scalars=["POINTS", "RTData"],  # noqa: F821
                                    NumberOfPoints=3000, DensityMapping="Color Map Opacity")
    opacity = GetOpacityTransferFunction("RTData")
    check(sampler.TransferFunction is not None and
          sampler.TransferFunction.SMProxy is opacity.SMProxy,
          "Color Map Opacity: TransferFunction is the opacity function of RTData's color map")

    executions = [0]
    sampler.GetClientSideObject().AddObserver(
        "StartEvent", lambda obj, event: executions.__setitem__(0, executions[0] + 1))
    for label, points, above in (("opacity 1 above the middle", [lo, 0, 0.5, 0, middle, 0, 0.5, 0,
                                                                 middle + 1e-3, 1, 0.5, 0, hi, 1, 0.5, 0], True),
                                 ("opacity 1 below the middle", [lo, 1, 0.5, 0, middle, 1, 0.5, 0,
                                                                 middle + 1e-3, 0, 0.5, 0, hi, 0, 0.5, 0], False)):
        before = executions[0]
        opacity.Points = points  # the user's edit in the Color Map Editor
        sampler.UpdatePipeline()
        values = sampled_values(sampler)
        check(executions[0] == before + 1, "%s: the edit re-sampled (%d execution(s))"
              % (label, executions[0] - before))
        check(abs(len(values) - 3000) <= 2, "%s: 3000 points (%d)" % (label, len(values)))
        inside = np.all(values >= middle) if above else np.all(values <= middle + 1e-3)
        check(len(values) > 0 and inside, "%s: every sample where the opacity is 1 (values %.1f to %.1f, "
              "middle %.1f)" % (label, values.min() if len(values) else 0, values.max() if len(values) else 0,
                                middle))

    # Another mapping: the function stays as the user left it, and is not used.
    sampler.DensityMapping = "Scalar Range"
    sampler.UpdatePipeline()
    values = sampled_values(sampler)
    check(len(values) > 0 and values.min() < middle < values.max(),
          "Scalar Range: samples on both sides of the middle again")
    check(sampler.TransferFunction.SMProxy is opacity.SMProxy,
          "Scalar Range leaves TransferFunction alone")
    finish()


if __name__ == "__main__":
    main()
