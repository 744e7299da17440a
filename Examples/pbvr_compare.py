# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Particle-based volume rendering with blue-noise particles (paper Fig. 12).

Renders a volume three ways with the same color and opacity transfer
functions and the same camera, and measures the particle images against the
ray-cast one:

1. particles drawn by vtkErrorDiffusionSampler with its default method,
   relaxed error diffusion (RED), and with the paper's error diffusion (ED);
2. particles drawn by the same filter, Method WhiteNoise (WN: hit-and-miss, the
   sampling of Sakamoto's particle-based volume rendering, PBVR);
3. the reference: ParaView's ray-cast volume representation.

With --curve it also plots the error against the number of particles for each
method (the image error curve of the README).

Run with pvbatch (or pvpython) under a display:

    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" pvbatch Examples/pbvr_compare.py \\
        --plugin build/lib/paraview-5.11/plugins/BlueNoiseSampling/BlueNoiseSampling.so \\
        [--volume ch2bet.nii.gz] [--counts 3e4 1e5 3e5] [--size 480] [--out pbvr_compare.png]
        [--curve pbvr_error_curve.png]

It writes one PNG (a row per particle count: RED | ED | WN | reference) and
prints a line per count and method:

    RESULT count=<N> method=<RED|ED|WN> particles=<n> radius=<r> scale=<s> clamped=<voxels>
           jitter=<0|1> ensembles=<K> rmse=<..> rmse_covered=<..> rmse_lowpass=<..> bias=<..>

Particle density, opacity and particle size (Sakamoto's PBVR)
--------------------------------------------------------------
The volume renderer treats the opacity transfer function alpha(x) as the
opacity of a slab of thickness u (ScalarOpacityUnitDistance, set here to the
voxel size h), i.e. an extinction coefficient tau(x) = -ln(1 - alpha(x)) / u.
PBVR replaces the absorbing medium by opaque particles of radius r with number
density rho: a ray crosses a particle within ds with probability
rho * pi r^2 * ds, so the expected image of opaque particles is the volume
rendering integral when rho(x) = tau(x) / (pi r^2), each particle showing the
color of its voxel. With at most one particle per voxel (the sampler's
points are voxel centers), the probability that a voxel holds a particle is
g = rho h^3 = -ln(1 - alpha) * h^2 / (pi r^2).
So the sampler runs with DensityMapping = "Transfer Function", its transfer
function the "density" function g0(x) = -ln(1 - alpha(x)) (--density extinction,
default; --density opacity uses alpha(x) itself, which is what the GUI macro
does and is within 12 % for alpha < 0.2), and DensityScale s; then
    expected particle count N = s * sum over voxels of g0,
    particle radius         r = h / sqrt(pi * s).
A particle count therefore fixes the particle size: 4 / pi particles per unit
of g0 give particles one voxel across, more particles are smaller. Both
methods use the same s (same expected count, same radius). Voxels where s * g0
would exceed 1 are clamped by the sampler (the script prints how many).

The particles are drawn with the Point Gaussian representation, preset
"Plain circle" (opaque discs of radius r facing the camera, depth tested, no
sorting), unlit (Ambient 1, Diffuse 0) like the unshaded volume rendering,
colored by their carried value through the same color transfer function.
With --jitter 1 (default) each particle is moved by a uniform random offset of
up to half a voxel per axis (the sampler's Jitter), as PBVR places particles
anywhere in a cell: particles at voxel centers line up in columns when the
view is close to a grid axis (a lattice pattern and too little coverage). One set of particles is one PBVR "ensemble"; --ensembles K averages the
images of K independent particle sets (seeds seed .. seed + K - 1), Sakamoto's
repetition level.

Measures (printed)
------------------
Luma Y = 0.2126 R + 0.7152 G + 0.0722 B of the 8-bit sRGB pixels, in 8-bit
units (0..255), of each particle image against the reference:
- rmse: over the whole image;
- rmse_covered: over the pixels the reference covers (its alpha, rendered on
  a transparent background, above 0.02);
- rmse_lowpass: over the whole image after a Gaussian blur of both images with
  sigma = --lowpass pixels (default 1.5): the error a viewer sees at a slight
  distance; blue noise puts its error at high frequencies, white noise
  everywhere;
- bias: the mean luma difference over the covered pixels.
Every image is taken after checking that the transfer functions are still the
ones set here (ColorBy() would rescale them to the particles' value range).
"""
import argparse
import ctypes
import math
import os
import shutil
import sys
import tempfile

import numpy as np

from paraview.simple import (
    CreatePiecewiseFunction,
    CreateRenderView,
    Delete,
    GetColorTransferFunction,
    GetOpacityTransferFunction,
    Hide,
    LoadPlugin,
    OpenDataFile,
    Render,
    SaveScreenshot,
    Show,
)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData

from png_arrays import read_png, write_png

DEFAULT_VOLUME = "/usr/share/mricron/templates/ch2bet.nii.gz"
# The sampler's methods compared: (Method, short name); the paper's error
# diffusion with the paper's parameters, the others with the default ones.
METHODS = (("Relaxed Error Diffusion", "RED"), ("Error Diffusion", "ED"), ("White Noise", "WN"))
PARAMETER_SETS = {"ED": "Paper"}
LONG_NAMES = {"RED": "relaxed error diffusion (default)", "ED": "error diffusion (paper)",
              "WN": "white noise (hit and miss)"}
HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_PLUGIN = os.path.join(HERE, os.pardir, "build-apps", "lib", "paraview-5.11", "plugins",
                              "BlueNoiseSampling", "BlueNoiseSampling.so")
COVERED_ALPHA = 0.02


# ---------------------------------------------------------------------------
# Transfer functions for an MRI brain (T1, brain extracted), relative to the
# value range [lo, hi]: background and CSF transparent, gray matter faint,
# white matter denser. Fractions of the range of ch2bet (0..133): CSF < 0.35,
# gray matter about 0.55..0.7, white matter about 0.75..0.9.
def brain_transfer_functions(lo, hi):
    def v(f):
        return lo + f * (hi - lo)
    rgb = [v(0.00), 0.00, 0.00, 0.00,
           v(0.30), 0.30, 0.08, 0.05,
           v(0.55), 0.85, 0.35, 0.20,
           v(0.70), 1.00, 0.70, 0.40,
           v(0.85), 1.00, 0.95, 0.80,
           v(1.00), 1.00, 1.00, 1.00]
    # (value, opacity per voxel length, midpoint, sharpness)
    opacity = [v(0.00), 0.000, 0.5, 0.0,
               v(0.35), 0.000, 0.5, 0.0,
               v(0.55), 0.010, 0.5, 0.0,
               v(0.70), 0.015, 0.5, 0.0,
               v(0.82), 0.050, 0.5, 0.0,
               v(1.00), 0.080, 0.5, 0.0]
    return rgb, opacity


def piecewise_linear(points, x):
    """Evaluate ParaView Points (x, y, midpoint 0.5, sharpness 0) at x (linear)."""
    px = np.array(points[0::4], dtype=np.float64)
    py = np.array(points[1::4], dtype=np.float64)
    return np.interp(x, px, py)


def density_points(opacity_points, lo, hi, mode, samples=257):
    """Points of the piecewise function g0(x) the sampler maps values with."""
    xs = np.linspace(lo, hi, samples)
    xs = np.union1d(xs, np.array(opacity_points[0::4], dtype=np.float64))
    alpha = np.clip(piecewise_linear(opacity_points, xs), 0.0, 0.999999)
    g0 = -np.log1p(-alpha) if mode == "extinction" else alpha
    pts = []
    for x, g in zip(xs, g0):
        pts += [float(x), float(g), 0.5, 0.0]
    return pts, (lambda values: (-np.log1p(-np.clip(piecewise_linear(opacity_points, values), 0,
                                                     0.999999)) if mode == "extinction"
                                 else piecewise_linear(opacity_points, values)))


# ---------------------------------------------------------------------------
def read_volume(path, workdir):
    """(path ParaView can open, numpy values, array name, vtkImageData geometry)."""
    lower = path.lower()
    if lower.endswith((".nii", ".nii.gz")):
        from vtkmodules.vtkIOImage import vtkNIFTIImageReader
        from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
        reader = vtkNIFTIImageReader()
        reader.SetFileName(path)
        reader.Update()
        image = vtkImageData()
        image.ShallowCopy(reader.GetOutput())
        scalars = image.GetPointData().GetScalars()
        scalars.SetName("intensity")
        out = os.path.join(workdir, "volume.vti")
        writer = vtkXMLImageDataWriter()
        writer.SetFileName(out)
        writer.SetInputData(image)
        # Inline binary, not appended: VTK 9.1-9.2's XML readers cannot read
        # large appended sections with Debian's patched expat (reparse deferral).
        writer.SetDataModeToBinary()
        writer.Write()
        path = out
    elif lower.endswith(".vti"):
        from vtkmodules.vtkIOXML import vtkXMLImageDataReader
        reader = vtkXMLImageDataReader()
        reader.SetFileName(path)
        reader.Update()
        image = reader.GetOutput()
    else:
        raise ValueError("give a .nii, .nii.gz or .vti volume")
    pd = image.GetPointData()
    scalars = pd.GetScalars() or pd.GetArray(0)
    values = vtk_to_numpy(scalars).astype(np.float64)
    if values.ndim > 1:
        values = values[:, 0]
    geometry = vtkImageData()
    geometry.CopyStructure(image)
    return path, values, scalars.GetName(), geometry


def support_bounds(geometry, mask):
    """World bounds of the voxels where mask (VTK point order) is true."""
    if not np.any(mask):
        return geometry.GetBounds()
    dims = geometry.GetDimensions()
    k, j, i = np.nonzero(mask.reshape(dims[2], dims[1], dims[0]))
    ext = geometry.GetExtent()
    lo = np.array([i.min(), j.min(), k.min()]) + np.array(ext[0::2])
    hi = np.array([i.max(), j.max(), k.max()]) + np.array(ext[0::2])
    corners = []
    for c in range(8):
        ijk = [hi[a] if (c >> a) & 1 else lo[a] for a in range(3)]
        xyz = [0.0, 0.0, 0.0]
        geometry.TransformContinuousIndexToPhysicalPoint(float(ijk[0]), float(ijk[1]),
                                                         float(ijk[2]), xyz)
        corners.append(xyz)
    corners = np.array(corners)
    b = np.empty(6)
    b[0::2] = corners.min(axis=0)
    b[1::2] = corners.max(axis=0)
    return list(b)


def luma(rgb):
    return 255.0 * (0.2126 * rgb[..., 0] + 0.7152 * rgb[..., 1] + 0.0722 * rgb[..., 2])


def gaussian_blur(img, sigma):
    if sigma <= 0:
        return img
    radius = int(math.ceil(3 * sigma))
    x = np.arange(-radius, radius + 1)
    k = np.exp(-0.5 * (x / sigma) ** 2)
    k /= k.sum()
    pad = np.pad(img, radius, mode="edge")
    tmp = np.apply_along_axis(lambda r: np.convolve(r, k, mode="valid"), 1, pad)
    return np.apply_along_axis(lambda c: np.convolve(c, k, mode="valid"), 0, tmp)


def rmse(a, b, mask=None):
    d = (a - b) ** 2
    if mask is not None:
        if not np.any(mask):
            return float("nan")
        d = d[mask]
    return float(np.sqrt(d.mean()))


def text_strip(text, width, height=28):
    """A black strip with white text (vtkTextRenderer), (h, w, 3) floats."""
    strip = np.zeros((height, width, 3))
    try:
        from vtkmodules.vtkRenderingCore import vtkTextProperty, vtkTextRenderer
        import vtkmodules.vtkRenderingFreeType  # noqa: F401  (the text renderer's factory)
        tr = vtkTextRenderer.GetInstance()
        prop = vtkTextProperty()
        prop.SetFontSize(max(8, min(15, width // 34)))
        prop.SetColor(1, 1, 1)
        prop.SetBackgroundOpacity(0.0)
        img = vtkImageData()
        if tr is None or not tr.RenderString(prop, text, img, [0, 0], 96):
            return strip
        ext = img.GetExtent()
        w, h = ext[1] - ext[0] + 1, ext[3] - ext[2] + 1
        a = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)[::-1] / 255.0
        alpha = a[..., 3:4] if a.shape[2] == 4 else np.ones((h, w, 1))
        h2, w2 = min(h, height), min(w, width - 6)
        y0 = (height - h2) // 2
        strip[y0:y0 + h2, 6:6 + w2] = (a[:h2, :w2, :3] * alpha[:h2, :w2])
    except Exception as error:  # labels are cosmetic
        print("note: no text labels (%s)" % error)
    return strip


# ---------------------------------------------------------------------------
class Scene:
    """One render view and camera shared by every image."""

    def __init__(self, width, height, bounds):
        self.view = CreateRenderView()
        self.view.ViewSize = [width, height]
        self.view.OrientationAxesVisibility = 0
        if self.view.GetProperty("UseColorPaletteForBackground") is not None:
            self.view.UseColorPaletteForBackground = 0
        self.view.Background = [0.0, 0.0, 0.0]
        self.view.UseFXAA = 0
        self.width, self.height = width, height
        b = bounds
        self.center = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
        radius = 0.5 * math.sqrt((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2)
        # A three-quarter view from the left, front and above (RAS volume: +y anterior, +z superior).
        direction = np.array([-0.75, 0.55, 0.37])
        direction /= np.linalg.norm(direction)
        self.view_angle = 30.0
        distance = 0.8 * radius / math.sin(math.radians(self.view_angle / 2))
        self.position = list(np.array(self.center) + distance * direction)
        self.up = [0.0, 0.0, 1.0]

    def set_camera(self):
        cam = self.view.GetActiveCamera()
        cam.SetFocalPoint(*self.center)
        cam.SetPosition(*self.position)
        cam.SetViewUp(*self.up)
        cam.SetViewAngle(self.view_angle)
        self.view.CameraParallelProjection = 0
        # Clipping range from the scene, never a camera reset.
        self.view.GetRenderer().ResetCameraClippingRange()

    def shoot(self, path, transparent=False, check=None):
        if check is not None:
            check()
        self.set_camera()
        Render(self.view)
        self.set_camera()
        SaveScreenshot(path, self.view, ImageResolution=[self.width, self.height],
                       TransparentBackground=1 if transparent else 0)
        return read_png(path)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--plugin", default=DEFAULT_PLUGIN, help="BlueNoiseSampling.so")
    parser.add_argument("--volume", default=DEFAULT_VOLUME, help=".nii, .nii.gz or .vti")
    parser.add_argument("--counts", type=float, nargs="+", default=[3e4, 1e5, 3e5],
                        help="expected particle counts (default 3e4 1e5 3e5)")
    parser.add_argument("--size", type=int, default=480, help="panel width and height in pixels")
    parser.add_argument("--out", default="pbvr_compare.png", help="the PNG to write")
    parser.add_argument("--ensembles", type=int, default=1,
                        help="particle sets averaged per image (PBVR repetition level)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--density", choices=["extinction", "opacity"], default="extinction",
                        help="g0 = -ln(1 - opacity) (default) or the opacity itself")
    parser.add_argument("--lowpass", type=float, default=1.5,
                        help="sigma in pixels of the blur of rmse_lowpass (default 1.5)")
    parser.add_argument("--shader", default="Plain circle",
                        help="Point Gaussian ShaderPreset (default 'Plain circle')")
    parser.add_argument("--jitter", type=int, choices=[0, 1], default=1,
                        help="1 (default): move each particle uniformly within its voxel; "
                             "0: particles at voxel centers")
    parser.add_argument("--reference-mode", default="GPU Based",
                        choices=["GPU Based", "Ray Cast Only", "Smart"],
                        help="VolumeRenderingMode of the reference (default 'GPU Based')")
    parser.add_argument("--curve", default="",
                        help="also plot the error against the particle count into this PNG")
    parser.add_argument("--keep-panels", default="",
                        help="folder to keep the single images in (default: a temporary one)")
    args = parser.parse_args(argv)

    if not os.path.exists(args.plugin):
        print("error: plugin %s not found (give --plugin)" % args.plugin)
        return 2
    LoadPlugin(args.plugin, remote=False, ns=globals())
    sampler_ctor = globals().get("ErrorDiffusionSampler")
    if sampler_ctor is None:
        print("error: the plugin did not define ErrorDiffusionSampler")
        return 2

    workdir = tempfile.mkdtemp(prefix="pbvr_")
    paneldir = args.keep_panels or workdir
    os.makedirs(paneldir, exist_ok=True)
    try:
        path, values, array, geometry = read_volume(args.volume, workdir)
        h = float(np.mean(geometry.GetSpacing()))
        lo, hi = float(values.min()), float(values.max())
        reader = OpenDataFile(path)
        reader.UpdatePipeline()

        # Transfer functions of the array (the ones a ParaView user edits).
        rgb_points, opacity_points = brain_transfer_functions(lo, hi)
        lut = GetColorTransferFunction(array)
        lut.ColorSpace = "RGB"
        lut.RGBPoints = rgb_points
        lut.AutomaticRescaleRangeMode = "Never"
        otf = GetOpacityTransferFunction(array)
        otf.Points = opacity_points
        otf.AllowDuplicateScalars = 1
        lut.ScalarOpacityFunction = otf

        def check_tfs():
            """Every image must use these transfer functions, unrescaled."""
            if (len(lut.RGBPoints) != len(rgb_points)
                    or not np.allclose(list(lut.RGBPoints), rgb_points)
                    or len(otf.Points) != len(opacity_points)
                    or not np.allclose(list(otf.Points), opacity_points)):
                raise RuntimeError("the transfer functions were changed (rescaled?)")

        dpoints, g0_of = density_points(opacity_points, lo, hi, args.density)
        density_tf = otf if args.density == "opacity" else CreatePiecewiseFunction(Points=dpoints)
        g0_sum = float(g0_of(values).sum())
        print("volume %s: %d voxels, %s in [%g, %g], voxel size %g; sum of g0 = %.1f (%s)"
              % (args.volume, values.size, array, lo, hi, h, g0_sum, args.density))

        # Frame the voxels that have some opacity, not the whole box.
        scene = Scene(args.size, args.size, support_bounds(geometry, g0_of(values) > 0))

        # Reference: ray-cast volume rendering of the same transfer functions.
        vol = Show(reader, scene.view)
        vol.SetRepresentationType("Volume")
        # Not ColorBy(): it rescales the transfer functions to the data range.
        vol.ColorArrayName = ["POINTS", array]
        vol.LookupTable = lut
        vol.ScalarOpacityFunction = otf
        vol.ScalarOpacityUnitDistance = h
        vol.Shade = 0
        vol.VolumeRenderingMode = args.reference_mode
        # The image on black, and the accumulated opacity from a second shot on a
        # transparent background (whose colors are not premultiplied).
        ref = scene.shoot(os.path.join(paneldir, "reference.png"), check=check_tfs)[..., :3]
        ref_rgba = scene.shoot(os.path.join(paneldir, "reference_alpha.png"), transparent=True,
                               check=check_tfs)
        covered = ref_rgba[..., 3] > COVERED_ALPHA if ref_rgba.shape[2] == 4 else luma(ref) > 1.0
        Hide(reader, scene.view)
        ref_y = luma(ref)
        ref_y_low = gaussian_blur(ref_y, args.lowpass)
        print("reference: %.1f %% of the pixels covered (alpha > %g), mean luma %.2f"
              % (100.0 * covered.mean(), COVERED_ALPHA, ref_y.mean()))

        rows = []
        results = []
        for count in args.counts:
            scale = count / g0_sum
            radius = h / math.sqrt(math.pi * scale)
            clamped = int(np.count_nonzero(scale * g0_of(values) > 1.0))
            panels = {}
            for method, name in METHODS:
                acc = None
                n_total = 0
                for e in range(args.ensembles):
                    s = sampler_ctor(Input=reader)
                    s.Scalars = ["POINTS", array]
                    s.Method = method
                    if name in PARAMETER_SETS:
                        s.ParameterSet = PARAMETER_SETS[name]
                    s.DensityMapping = "Transfer Function"
                    s.TransferFunction = density_tf
                    s.UseNumberOfPoints = 0
                    s.DensityScale = scale
                    s.Seed = args.seed + e
                    # Each particle anywhere in its voxel (PBVR places particles
                    # anywhere in a cell): voxel-center particles line up in
                    # columns when the view is near an axis of the grid.
                    s.Jitter = args.jitter
                    s.UpdatePipeline()
                    n_total += s.GetDataInformation().GetNumberOfPoints()
                    chain = [s]
                    shown = chain[-1]
                    # The representation proxy named explicitly: the plugin's
                    # <RepresentationType type="Points"/> hint makes ParaView 5.11's
                    # default Show() look for a representation proxy called "Points".
                    d = Show(shown, scene.view, "GeometryRepresentation")
                    d.SetRepresentationType("Point Gaussian")
                    # Not ColorBy(): it would rescale the shared color and opacity
                    # functions to the particles' value range (only values with
                    # opacity > 0), shifting every particle color.
                    d.ColorArrayName = ["POINTS", array]
                    d.LookupTable = lut
                    d.MapScalars = 1
                    d.ScaleByArray = 0
                    d.GaussianRadius = radius
                    d.ShaderPreset = args.shader
                    d.Opacity = 1.0
                    d.Ambient = 1.0
                    d.Diffuse = 0.0
                    d.Specular = 0.0
                    img = scene.shoot(os.path.join(paneldir, "%s_%d_%d.png" % (name, int(count), e)),
                                      check=check_tfs)
                    Hide(shown, scene.view)
                    for proxy in reversed(chain):
                        Delete(proxy)
                    acc = img[..., :3] if acc is None else acc + img[..., :3]
                img = acc / args.ensembles
                y = luma(img)
                res = dict(count=count, method=name, particles=n_total / args.ensembles,
                           radius=radius, rmse=rmse(y, ref_y), rmse_covered=rmse(y, ref_y, covered),
                           rmse_lowpass=rmse(gaussian_blur(y, args.lowpass), ref_y_low),
                           bias=float(np.mean(y[covered] - ref_y[covered])) if np.any(covered)
                           else float("nan"))
                results.append(res)
                panels[name] = img
                print("RESULT count=%d method=%s particles=%.0f radius=%.4g scale=%.4g clamped=%d "
                      "jitter=%d ensembles=%d rmse=%.3f rmse_covered=%.3f rmse_lowpass=%.3f bias=%.3f"
                      % (count, name, res["particles"], radius, scale, clamped, args.jitter,
                         args.ensembles,
                         res["rmse"], res["rmse_covered"], res["rmse_lowpass"], res["bias"]),
                      flush=True)
            def label(name):
                r = [r for r in results if r["count"] == count and r["method"] == name][0]
                return text_strip("%s  N=%.0f  r=%.2g  RMSE %.1f  low-pass %.1f"
                                  % (name, count, radius, r["rmse"], r["rmse_lowpass"]), args.size)

            row = np.concatenate(
                [np.concatenate([label(name), panels[name]], axis=0) for _, name in METHODS]
                + [np.concatenate([text_strip("reference (ray cast)", args.size), ref], axis=0)],
                axis=1)
            rows.append(row)
        mosaic = np.concatenate(rows, axis=0)
        out_dir = os.path.dirname(os.path.abspath(args.out))
        os.makedirs(out_dir, exist_ok=True)
        write_png(args.out, mosaic)
        print("wrote %s (%dx%d)" % (args.out, mosaic.shape[1], mosaic.shape[0]))
        print("summary (luma RMSE against the reference, 8-bit units):")
        print("%10s %6s %10s %8s %10s %10s %10s %10s" % ("count", "method", "particles", "radius",
                                                        "rmse", "covered", "lowpass", "bias"))
        for r in results:
            print("%10.0f %6s %10.0f %8.3g %10.3f %10.3f %10.3f %10.3f"
                  % (r["count"], r["method"], r["particles"], r["radius"], r["rmse"],
                     r["rmse_covered"], r["rmse_lowpass"], r["bias"]))
        if args.curve:
            write_curve(args.curve, results, args)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    return 0


def write_curve(path, results, args):
    """The image error against the number of particles, one line per method."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for (_, name), style in zip(METHODS, ("o-", "s--", "^:")):
        mine = sorted((r for r in results if r["method"] == name), key=lambda r: r["particles"])
        x = [r["particles"] for r in mine]
        axes[0].plot(x, [r["rmse_lowpass"] for r in mine], style, label=LONG_NAMES[name])
        axes[1].plot(x, [r["rmse_covered"] for r in mine], style, label=LONG_NAMES[name])
    for ax, title in zip(axes, ("after a blur of sigma %g px" % args.lowpass,
                                "per pixel, where the reference is covered")):
        ax.set_xscale("log")
        ax.set_xlabel("particles")
        ax.set_ylabel("luma RMSE against ray casting (8-bit)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle("Particle-based volume rendering of %s (%d ensemble%s)"
                 % (os.path.basename(args.volume), args.ensembles,
                    "" if args.ensembles == 1 else "s"))
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    print("wrote %s" % path)


if __name__ == "__main__":
    status = main()
    sys.stdout.flush()
    sys.stderr.flush()
    # From ParaView 5.13, pvbatch prints through C stdio once paraview.simple is
    # loaded, which os._exit does not flush: without this the output is lost
    # when it is not a terminal.
    ctypes.CDLL(None).fflush(None)
    # Leave without ParaView's teardown: under xvfb-run, pvbatch 5.11 with Mesa
    # sometimes dies in it (GLXBadContext, SIGABRT) after all the work is done,
    # which would turn a finished run into a failure.
    os._exit(status)
