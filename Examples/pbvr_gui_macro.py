# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""ParaView macro: particle-based volume rendering of the active volume.

Particles drawn by the BlueNoiseSampling plugin's Error Diffusion Sampler with
the opacity transfer function as density (Sakamoto's particle-based volume
rendering, with blue-noise instead of hit-and-miss particles), shown as opaque
Point Gaussian discs colored by the color transfer function.

Use in the ParaView GUI:
1. Tools > Manage Plugins > Load New: BlueNoiseSampling.so (once; tick Auto Load).
2. Macros > Import new macro...: this file (it appears in the Macros toolbar).
3. Open a volume (image data), color it by the array you want (e.g. the Volume
   representation) and edit its color and opacity transfer functions.
4. Select the volume in the Pipeline Browser and run the macro. It adds an
   "Error Diffusion Sampler" (Density Mapping = Transfer Function, the array's
   opacity function) shown as Point Gaussian particles in the active render
   view, and hides the volume there.

The relation (see pbvr_compare.py): a voxel of opacity alpha holds a particle
with probability g = DensityScale * alpha, and particles of radius
r = h / sqrt(pi * DensityScale) (h: voxel size, the opacity unit distance set
on the volume) reproduce the volume's opacity on average (exactly for
g = -ln(1 - alpha) * DensityScale; using alpha itself is within 12 % for
alpha < 0.2). The macro picks DensityScale for TARGET_PARTICLES and sets the
radius accordingly. Editing the opacity function afterwards re-samples the
particles (the sampler follows the function); run the macro again to re-fit
the count and the radius.

The settings below can be edited before importing the macro.
"""
import math

import paraview.simple as pvs

TARGET_PARTICLES = 100000
METHOD = "Error Diffusion"  # or "White Noise" (hit-and-miss, for comparison)
SEED = 0
SHADER = "Plain circle"  # opaque discs; "Sphere" adds shading
JITTER = True  # move each particle uniformly within its voxel (no lattice columns)


def _sampler_constructor():
    ctor = getattr(pvs, "ErrorDiffusionSampler", None)
    if ctor is None:
        # Proxies of a plugin loaded after paraview.simple was imported.
        pvs._add_functions(vars(pvs))
        ctor = getattr(pvs, "ErrorDiffusionSampler", None)
    return ctor


def _color_array(source, view):
    rep = pvs.GetDisplayProperties(source, view) if view is not None else None
    if rep is not None and rep.ColorArrayName and rep.ColorArrayName[1]:
        return rep.ColorArrayName[1]
    info = source.GetPointDataInformation()
    for i in range(info.GetNumberOfArrays()):
        return info.GetArray(i).GetName()
    return None


def _voxel_size(source):
    info = source.GetDataInformation().DataInformation
    bounds = info.GetBounds()
    extent = info.GetExtent()
    sizes = [(bounds[2 * a + 1] - bounds[2 * a]) / (extent[2 * a + 1] - extent[2 * a])
             for a in range(3) if extent[2 * a + 1] > extent[2 * a]]
    return sum(sizes) / len(sizes) if sizes else 1.0


def setup_pbvr(source=None, view=None, target=TARGET_PARTICLES, method=METHOD, seed=SEED,
               shader=SHADER, jitter=JITTER):
    """Add the particle rendering of `source` (default: the active source) to `view`.

    Returns (sampler proxy, the representation of the particles)."""
    source = source or pvs.GetActiveSource()
    if source is None:
        raise RuntimeError("select a volume (image data) in the Pipeline Browser first")
    view = view or pvs.GetActiveViewOrCreate("RenderView")
    ctor = _sampler_constructor()
    if ctor is None:
        raise RuntimeError("the BlueNoiseSampling plugin is not loaded "
                           "(Tools > Manage Plugins > Load New)")
    if not source.GetDataInformation().DataInformation.IsDataStructured():
        raise RuntimeError("the active source is not image data")
    array = _color_array(source, view)
    if array is None:
        raise RuntimeError("the active source has no point-data array")
    lut = pvs.GetColorTransferFunction(array)
    otf = pvs.GetOpacityTransferFunction(array)
    h = _voxel_size(source)

    sampler = ctor(Input=source)
    sampler.Scalars = ["POINTS", array]
    sampler.Method = method
    sampler.Seed = seed
    sampler.DensityMapping = "Transfer Function"
    sampler.TransferFunction = otf
    sampler.UseNumberOfPoints = 0
    # Expected count at DensityScale 1 = sum of the opacities (few voxels reach 1).
    sampler.DensityScale = 1.0
    sampler.UpdatePipeline()
    n1 = sampler.GetDataInformation().GetNumberOfPoints()
    if n1 == 0:
        raise RuntimeError("the opacity function of %r is zero on the whole volume" % array)
    scale = float(target) / n1
    sampler.DensityScale = scale
    sampler.UpdatePipeline()
    radius = h / math.sqrt(math.pi * scale)

    shown = sampler
    if jitter:
        # Voxel-center particles line up in columns when the view is near a grid
        # axis (a visible lattice, too little coverage); PBVR places particles
        # anywhere in their cell: a random offset of up to half a voxel per axis.
        offsets = pvs.RandomAttributes(Input=sampler)
        offsets.DataType = "Float"
        offsets.ComponentRange = [-0.5, 0.5]
        offsets.GeneratePointVectors = 1
        pvs.RenameSource("PBVR offsets", offsets)
        shown = pvs.WarpByVector(Input=offsets)
        shown.Vectors = ["POINTS", "RandomPointVectors"]
        shown.ScaleFactor = h
        pvs.RenameSource("PBVR particles (%s, jittered)" % method, shown)
        pvs.Hide(sampler, view)

    # The representation proxy is named: the plugin's RepresentationType hint
    # makes ParaView 5.11's default Show() fail for this filter.
    rep = pvs.Show(shown, view, "GeometryRepresentation")
    rep.SetRepresentationType("Point Gaussian")
    # Not ColorBy(): it would rescale the color and opacity functions to the
    # particles' range.
    rep.ColorArrayName = ["POINTS", array]
    rep.LookupTable = lut
    rep.MapScalars = 1
    rep.ScaleByArray = 0
    rep.GaussianRadius = radius
    rep.ShaderPreset = shader
    rep.Opacity = 1.0
    rep.Ambient = 1.0
    rep.Diffuse = 0.0
    rep.Specular = 0.0
    volume_rep = pvs.GetDisplayProperties(source, view)
    if volume_rep is not None and volume_rep.GetProperty("ScalarOpacityUnitDistance") is not None:
        # The relation above takes the opacity per voxel length.
        volume_rep.ScalarOpacityUnitDistance = h
    pvs.Hide(source, view)
    pvs.RenameSource("PBVR sampler (%s)" % method, sampler)
    pvs.SetActiveSource(shown)
    pvs.Render(view)
    n = sampler.GetDataInformation().GetNumberOfPoints()
    print("PBVR: %d particles (%s), DensityScale %.4g, particle radius %.4g (voxel size %.4g)"
          % (n, method, scale, radius, h))
    if n < 0.9 * target:
        print("PBVR warning: %d particles instead of %d: the densities are clamped at one "
              "particle per voxel, so the particles are too few for their size (the image is "
              "too transparent); ask for fewer particles or use a finer volume" % (n, target))
    return sampler, rep


if __name__ in ("__main__", "__vtkconsole__") or not __name__.startswith("pbvr"):
    # Run as a macro (ParaView executes the file) or as a script.
    setup_pbvr()
