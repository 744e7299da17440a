# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch script: Examples/pbvr_gui_macro.py on a volume as the active source.

    pvbatch PBVRMacroScript.py --examples <source>/Examples --plugin BlueNoiseSampling.so \
        --volume brain-small.vti --count 4000 --out macro.png

Opens the volume, shows it as a volume with an opacity function that is 0
below 40 % of the range, makes it the active source and runs the macro's
setup. Checks that the macro added an ErrorDiffusionSampler on the volume
with DensityMapping TransferFunction bound to the array's opacity function,
a Point Gaussian representation colored by the array with the same color
function, not rescaled, radius h / sqrt(pi * DensityScale), about the
requested number of particles, none where the opacity is 0, the particles
shown jittered by less than half a voxel, and writes a screenshot. Prints MACRO CHECKS PASSED when every check passed.
"""
import argparse
import ctypes
import math
import os
import sys

import numpy as np

import paraview.simple as pvs
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy

from bluenoise_testing import check, summary


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--examples", required=True)
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--volume", required=True)
    parser.add_argument("--count", type=float, default=4000)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()

    pvs.LoadPlugin(args.plugin, remote=False)
    sys.path.insert(0, os.path.abspath(args.examples))
    import pbvr_gui_macro

    reader = pvs.OpenDataFile(args.volume)
    reader.UpdatePipeline()
    info = reader.GetPointDataInformation()
    array = info.GetArray(0).GetName()
    lo, hi = info.GetArray(0).GetRange(0)
    view = pvs.CreateRenderView()
    view.ViewSize = [240, 240]
    vol = pvs.Show(reader, view)
    vol.SetRepresentationType("Volume")
    vol.ColorArrayName = ["POINTS", array]
    lut = pvs.GetColorTransferFunction(array)
    otf = pvs.GetOpacityTransferFunction(array)
    vol.LookupTable = lut
    vol.ScalarOpacityFunction = otf
    threshold = lo + 0.4 * (hi - lo)
    otf_points = [lo, 0.0, 0.5, 0.0, threshold, 0.0, 0.5, 0.0, hi, 0.1, 0.5, 0.0]
    otf.Points = otf_points
    lut.RGBPoints = [lo, 0.0, 0.0, 0.0, hi, 1.0, 0.9, 0.8]
    rgb_points = list(lut.RGBPoints)
    pvs.SetActiveView(view)
    pvs.SetActiveSource(reader)

    sampler, rep = pbvr_gui_macro.setup_pbvr(target=args.count)
    check(sampler.GetXMLName() == "ErrorDiffusionSampler", "the macro made an ErrorDiffusionSampler")
    check(sampler.Input.GetXMLName() == reader.GetXMLName(), "on the active source")
    check(sampler.DensityMapping == "Transfer Function", "DensityMapping Transfer Function")
    check(sampler.TransferFunction.SMProxy is otf.SMProxy, "bound to the array's opacity function")
    check(list(sampler.Scalars)[-1] == array, "Scalars = %s" % list(sampler.Scalars))
    check(rep.Representation == "Point Gaussian", "Point Gaussian representation (%s)" % rep.Representation)
    check(rep.LookupTable.SMProxy is lut.SMProxy and list(rep.ColorArrayName)[-1] == array,
          "colored by %s through its color function" % array)
    check(np.allclose(list(lut.RGBPoints), rgb_points) and np.allclose(list(otf.Points), otf_points),
          "the transfer functions were not rescaled")
    n = sampler.GetDataInformation().GetNumberOfPoints()
    check(abs(n - args.count) <= 0.1 * args.count, "%d particles for %g requested" % (n, args.count))
    h = pbvr_gui_macro._voxel_size(reader)
    radius = h / math.sqrt(math.pi * sampler.DensityScale)
    check(math.isclose(rep.GaussianRadius, radius, rel_tol=1e-9),
          "radius %.4g = h / sqrt(pi * DensityScale) = %.4g" % (rep.GaussianRadius, radius))
    points = servermanager.Fetch(sampler)
    values = vtk_to_numpy(points.GetPointData().GetArray(array)).astype(np.float64)
    check(len(values) == n and values.min() > threshold,
          "no particle where the opacity is 0 (min value %.2f > %.2f)" % (values.min(), threshold))
    # The particles shown are the samples moved by less than half a voxel per axis.
    shown = rep.Input
    check(shown.GetXMLName() in ("WarpVector", "WarpByVector"), "the particles are jittered (%s)" % shown.GetXMLName())
    moved = vtk_to_numpy(servermanager.Fetch(shown).GetPoints().GetData()).astype(np.float64)
    orig = vtk_to_numpy(points.GetPoints().GetData()).astype(np.float64)
    offset = np.abs(moved - orig) if moved.shape == orig.shape else np.full(1, np.inf)
    check(offset.max() <= 0.5 * h + 1e-4 and offset.mean() > 0.1 * h,
          "jitter within half a voxel (max %.3f, mean %.3f, h %.3f)" % (offset.max(), offset.mean(), h))
    pvs.Render(view)
    pvs.SaveScreenshot(args.out, view, ImageResolution=[240, 240])
    check(os.path.exists(args.out), "screenshot %s" % args.out)
    return summary("MACRO CHECKS PASSED")


if __name__ == "__main__":
    status = main()
    sys.stdout.flush()
    # From ParaView 5.13, pvbatch prints through C stdio once paraview.simple is
    # loaded, which os._exit does not flush: without this the output is lost
    # when it is not a terminal.
    ctypes.CDLL(None).fflush(None)
    # Skip ParaView's teardown (it sometimes aborts under xvfb-run with Mesa).
    os._exit(status)
