#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Tetrahedral meshing of importance samples: the "vectorised volume" (paper Fig. 13).

A volume is sampled with vtkErrorDiffusionSampler (Method ErrorDiffusion, blue
noise, or WhiteNoise, hit-and-miss), the samples are tetrahedralised with
vtkDelaunay3D, the tetrahedra that bridge empty space are removed, and the mesh
(samples carrying their voxel values, linear interpolation inside each
tetrahedron) is resampled back onto the original grid to measure how well it
represents the volume:

- RMSE / PSNR of the reconstruction against the original voxels;
- the storage ratio: mesh bytes over voxel bytes;
- the tetrahedron quality (vtkMeshQuality radius ratio).

Run with a Python that has VTK (Debian's /usr/bin/python3 with ParaView's
vtkmodules) and the bluenoise package on PYTHONPATH:

    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 \\
        Examples/tetrahedral_mesh.py [--volume ch2bet.nii.gz] [--counts 1e4 3e4 1e5]

The functions are used by Testing/Applications/TestTetrahedralMesh.py.

Choices (measured on ch2bet; see Examples/README.md for the numbers)
----------------------------------------------------------------------
Density. The density is the voxel value mapped by the sampler's ScalarRange
mapping (minimum -> 0, maximum -> 1) times a DensityScale found by bisection
so that the expected count sum(min(1, s g)) is the requested vertex count. The
sampler's actual count then differs a little (error diffusion ends about 2 %
low on ch2bet at 3e4 points, hit-and-miss is a binomial draw), so
DensityScale is corrected from the actual count (two or three runs) for each
method: both methods are compared at the same number of vertices.

Mesher. vtkDelaunay3D on the sample points. The points are inserted in a
random order (a fixed permutation): in the sampler's scan order (layer after
layer) vtkDelaunay3D took 43 s for 3e4 points and 368 s for 1e5; in random
order 10 to 15 s for 3e4 and 110 to 150 s for 1e5 (on a busy 2-core
machine). The mesh vertices are the sample points themselves (same
coordinates, same arrays), only reordered. `--mesher qhull` uses
scipy.spatial.Delaunay (Qhull) instead: 6 s instead of 110 to 150 s at 1e5 on
ch2bet, with the same measures within 1 %; the same kind of mesh (another
valid Delaunay tetrahedralisation: samples on the voxel lattice are often
co-spherical, so the Delaunay mesh is not unique). TetGen
(Debian's tetgen 1.5) is not used: what it adds over these is quality meshing
with Steiner points (-q), which would break "every vertex is a sample", and a
constrained mode that needs a boundary surface the samples do not have; for
the plain Delaunay tetrahedralisation it would only be one more dependency.

Restriction to the volume. A Delaunay mesh fills the convex hull of the points:
it bridges concavities and empty space (between the hemispheres, outside the
cortex) and has flat slivers on the hull. Four rules are available
(`--restrict`, several may be joined with '+'):
- `alpha`: vtkDelaunay3D's global Alpha = k * d, with d the mean sample
  spacing (foreground voxel volume / vertices)^(1/3) and k = --alpha-factor.
  One radius for the whole volume, while the spacing of importance samples
  varies with the density as g^(-1/3): it either keeps bridges in dense
  regions or eats holes into sparse ones.
- `adaptive`: the same test made local: a tetrahedron is kept when its
  circumradius is at most k times the expected sample spacing at its vertices,
  h * mean(g_i^(-1/3)) (h the voxel size, g_i the Density the vertex was drawn
  with). Default, with k = 3: it removes the flat slivers of the convex hull
  (radius ratio up to 10^4) and the long bridges; k = 2 cuts into the
  foreground (cover 0.922 instead of 0.930 for ED at 3e4 on ch2bet), k = 4
  keeps a little more (0.935) at the same quality.
- `centroid`: a tetrahedron is dropped when its centroid lies in a voxel of
  density 0 (empty space). Default, together with `adaptive`. Alone it keeps
  the most foreground (cover 0.946 for ED at 3e4) but also the hull slivers
  (0.26 % of the tetrahedra with radius ratio > 100).
- `vertices`: a tetrahedron is dropped when all four vertices have a value
  at or below --threshold. With the default threshold (the minimum, density 0)
  this never fires: the sampler only emits samples where the density is > 0,
  so a rule on the vertices alone cannot see a tetrahedron that spans empty
  space between two dense regions. Kept for measuring that.
Vertices that no kept tetrahedron uses are dropped from the mesh.

Reconstruction. vtkResampleWithDataSet of the mesh onto the volume's grid
(cropped to the mesh's bounds for speed), linear (barycentric) interpolation
of a float copy of the voxel value. Voxels outside the mesh (vtkValidPointMask
0) are reconstructed as the volume's minimum (0 for the brain, its background
value): the mesh says "nothing here". Reported:
- cover: fraction of the foreground voxels (density > 0) inside the mesh;
- spill: fraction of the background voxels (density 0) inside the mesh;
- RMSEc / PSNRc: over the voxels inside the meshes of all compared methods
  (same count, same seed): the fair "inside the valid region" comparison;
- RMSEin: over the voxels inside this mesh only (a mesh that covers less
  skips the hardest voxels, so this favours it);
- RMSE and PSNR: over the region of interest = foreground voxels plus every
  voxel inside the mesh, with the outside rule above (this charges a mesh for
  the foreground it does not cover).
PSNR = 20 log10(peak / RMSE), peak = value range of the volume (max - min).

Storage. Mesh bytes = vertices * (3 * 4 bytes of float32 coordinates + the
bytes of the carried voxel value in its own type) + tetrahedra * 4 * 4 bytes
(int32 vertex ids); the derived Density array is not counted (it is a function
of the value). Voxel bytes = voxels * bytes of the value type. A Delaunay mesh
has about 6.5 tetrahedra per vertex, so a vertex costs about 120 bytes: for an
8-bit volume the mesh is smaller than the voxels only below about one vertex
per 120 voxels.

Quality. vtkMeshQuality's tetrahedron radius ratio R / (3 r) (1 for the
regular tetrahedron, unbounded for flat ones): mean, median, 5th and 95th
percentiles, the fraction above 3 (outside Verdict's acceptable range 1..3) and
above 100 (degenerate: nearly flat). The degenerate tetrahedra are kept in the
mesh by default (--drop-degenerate removes them; they hold almost no volume).
"""
import argparse
import math
import os
import sys
import time

import numpy as np

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdTypeArray, vtkPoints, vtkVersion
from vtkmodules.vtkCommonDataModel import (
    VTK_TETRA,
    vtkCellArray,
    vtkDataObject,
    vtkImageData,
    vtkPolyData,
    vtkStaticCellLocator,
    vtkUnstructuredGrid,
)
from vtkmodules.vtkFiltersCore import vtkDelaunay3D, vtkResampleWithDataSet
from vtkmodules.vtkFiltersVerdict import vtkMeshQuality

try:
    from bluenoise import vtkErrorDiffusionSampler
except ImportError:  # pragma: no cover - explained to the user
    sys.stderr.write("tetrahedral_mesh.py: cannot import the bluenoise package; put the build's "
                     "lib/python3/dist-packages on PYTHONPATH\n")
    raise

DEFAULT_VOLUME = "/usr/share/mricron/templates/ch2bet.nii.gz"
METHODS = {"ED": vtkErrorDiffusionSampler.METHOD_ERROR_DIFFUSION,
           "WN": vtkErrorDiffusionSampler.METHOD_WHITE_NOISE}
DEFAULT_RESTRICT = "adaptive+centroid"
DEFAULT_ALPHA_FACTOR = 3.0
DEGENERATE_RADIUS_RATIO = 100.0
POOR_RADIUS_RATIO = 3.0


# ---------------------------------------------------------------------------
# Volumes
def read_volume(path, array=None):
    """Read a .nii/.nii.gz, .vti, .mhd/.mha or .nrrd volume; return (image, array name)."""
    lower = path.lower()
    if lower.endswith((".nii", ".nii.gz")):
        from vtkmodules.vtkIOImage import vtkNIFTIImageReader
        reader = vtkNIFTIImageReader()
    elif lower.endswith(".vti"):
        from vtkmodules.vtkIOXML import vtkXMLImageDataReader
        reader = vtkXMLImageDataReader()
    elif lower.endswith((".mhd", ".mha")):
        from vtkmodules.vtkIOImage import vtkMetaImageReader
        reader = vtkMetaImageReader()
    elif lower.endswith((".nrrd", ".nhdr")):
        from vtkmodules.vtkIOImage import vtkNrrdReader
        reader = vtkNrrdReader()
    else:
        raise ValueError("unknown volume format: %s" % path)
    if not os.path.exists(path):
        raise FileNotFoundError(path)
    reader.SetFileName(path)
    reader.Update()
    image = vtkImageData()
    image.ShallowCopy(reader.GetOutput())
    pd = image.GetPointData()
    if array is None:
        scalars = pd.GetScalars() or pd.GetArray(0)
        if scalars is None:
            raise ValueError("%s has no point-data array" % path)
        array = scalars.GetName()
    if pd.GetArray(array) is None:
        raise ValueError("%s has no point-data array %r" % (path, array))
    pd.SetActiveScalars(array)
    return image, array


def analytic_volume(n=32, kind="blob", name="value"):
    """A small smooth volume on [0, n-1]^3 with unit spacing, float32 array `name`.

    blob: two Gaussian blobs (values 0..1, exactly 0 far from them so that
    the volume has empty space and a concavity between the blobs); sines: a
    sum of sines in [0, 1]."""
    ax = np.arange(n, dtype=np.float64)
    z, y, x = np.meshgrid(ax, ax, ax, indexing="ij")  # x fastest in the flattened order
    if kind == "blob":
        c1 = np.array([0.35, 0.5, 0.5]) * (n - 1)
        c2 = np.array([0.68, 0.5, 0.5]) * (n - 1)
        sigma = 0.13 * (n - 1)
        v = (np.exp(-((x - c1[0]) ** 2 + (y - c1[1]) ** 2 + (z - c1[2]) ** 2) / (2 * sigma ** 2))
             + np.exp(-((x - c2[0]) ** 2 + (y - c2[1]) ** 2 + (z - c2[2]) ** 2) / (2 * sigma ** 2)))
        v = np.clip(v / v.max() - 0.08, 0.0, None) / 0.92
    elif kind == "sines":
        w = 2 * math.pi / (n - 1)
        v = 0.5 + (np.sin(1.5 * w * x) + np.sin(w * y + 0.5) + np.sin(1.2 * w * z + 1.0)) / 6.0
    else:
        raise ValueError(kind)
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(1.0, 1.0, 1.0)
    image.SetOrigin(0.0, 0.0, 0.0)
    arr = numpy_to_vtk(np.ascontiguousarray(v.ravel().astype(np.float32)), deep=1)
    arr.SetName(name)
    image.GetPointData().SetScalars(arr)
    return image


def volume_values(image, array):
    """The array's first component as float64, in VTK point order (x fastest)."""
    a = vtk_to_numpy(image.GetPointData().GetArray(array))
    if a.ndim > 1:
        a = a[:, 0]
    return a.astype(np.float64)


def base_density(values):
    """The sampler's ScalarRange mapping (array range -> [0, 1]) before DensityScale."""
    lo, hi = float(values.min()), float(values.max())
    if hi <= lo:
        return np.ones_like(values)
    return (values - lo) / (hi - lo)


def density_scale_for_count(g0, target):
    """DensityScale s with sum(min(1, s g0)) == target (bisection)."""
    total = float(np.count_nonzero(g0 > 0))
    if target >= total:
        return float("inf")
    lo, hi = 0.0, 1.0
    while np.minimum(1.0, hi * g0).sum() < target:
        hi *= 2.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if np.minimum(1.0, mid * g0).sum() < target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


# ---------------------------------------------------------------------------
# Sampling
def run_sampler(image, array, method, scale, seed):
    sampler = vtkErrorDiffusionSampler()
    sampler.SetInputData(image)
    sampler.SetInputArrayToProcess(0, 0, 0, vtkDataObject.FIELD_ASSOCIATION_POINTS, array)
    sampler.SetDensityMappingToScalarRange()
    sampler.UseNumberOfPointsOff()
    sampler.SetDensityScale(scale)
    sampler.SetMethod(METHODS[method] if isinstance(method, str) else method)
    sampler.SetSeed(seed)
    sampler.Update()
    out = vtkPolyData()
    out.ShallowCopy(sampler.GetOutput())
    return out


def sample_volume(image, array, method, target, seed=0, match_count=True, g0=None):
    """Sample `image` with about `target` points; return (points polydata, DensityScale).

    The DensityScale starts from the expected count and, with match_count, is
    corrected from the actual count until it is within 0.2 % (or 3 runs)."""
    if g0 is None:
        g0 = base_density(volume_values(image, array))
    scale = density_scale_for_count(g0, target)
    points = run_sampler(image, array, method, scale, seed)
    if match_count:
        for _ in range(3):
            n = points.GetNumberOfPoints()
            if n == 0 or abs(n - target) <= 0.002 * target:
                break
            # The expected count is nearly proportional to the scale (few clamped voxels).
            expected = np.minimum(1.0, scale * g0).sum()
            scale = density_scale_for_count(g0, expected * target / n)
            points = run_sampler(image, array, method, scale, seed)
    return points, scale


# ---------------------------------------------------------------------------
# Meshes as numpy arrays
def points_of(data):
    return vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)


# vtkUnstructuredGrid.GetCellTypesArray() is deprecated in VTK 9.6 and returns None there; its
# successor GetCellTypes() (an array of one type per cell only from 9.6 on) may be an implicit
# array that numpy cannot view.
VTK_9_6 = (vtkVersion.GetVTKMajorVersion(), vtkVersion.GetVTKMinorVersion()) >= (9, 6)


def cell_types(grid):
    """The VTK cell type of each cell of an unstructured grid, as a numpy array."""
    n = grid.GetNumberOfCells()
    if n == 0:
        return np.zeros(0, dtype=np.uint8)
    array = grid.GetCellTypes() if VTK_9_6 else grid.GetCellTypesArray()
    try:
        types = vtk_to_numpy(array)
        if len(types) == n:
            return types
    except (TypeError, ValueError, AttributeError):
        pass
    return np.array([grid.GetCellType(i) for i in range(n)], dtype=np.uint8)


def tets_of(grid):
    """The (m, 4) vertex ids of a grid made of tetrahedra only."""
    if grid.GetNumberOfCells() == 0:
        return np.zeros((0, 4), dtype=np.int64)
    types = cell_types(grid)
    if not np.all(types == VTK_TETRA):
        raise ValueError("the grid has cells other than tetrahedra")
    return vtk_to_numpy(grid.GetCells().GetConnectivityArray()).astype(np.int64).reshape(-1, 4)


def make_grid(points, tets, point_data=None, keep=None):
    """A vtkUnstructuredGrid of tetrahedra from numpy arrays.

    point_data: a vtkPointData to carry (tuples taken by `keep`, the old id of
    each new vertex, or all when None)."""
    grid = vtkUnstructuredGrid()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points.astype(np.float32)), deep=1))
    grid.SetPoints(pts)
    m = len(tets)
    offsets = vtkIdTypeArray()
    offsets.DeepCopy(numpy_to_vtk(np.arange(0, 4 * m + 1, 4, dtype=np.int64), deep=1))
    conn = vtkIdTypeArray()
    conn.DeepCopy(numpy_to_vtk(np.ascontiguousarray(tets.astype(np.int64).ravel()), deep=1))
    cells = vtkCellArray()
    cells.SetData(offsets, conn)
    grid.SetCells(VTK_TETRA, cells)
    if point_data is not None:
        for i in range(point_data.GetNumberOfArrays()):
            src = point_data.GetArray(i)
            if src is None:
                continue
            a = vtk_to_numpy(src)
            if keep is not None:
                a = a[keep]
            dst = numpy_to_vtk(np.ascontiguousarray(a), deep=1, array_type=src.GetDataType())
            dst.SetName(src.GetName())
            grid.GetPointData().AddArray(dst)
        if point_data.GetScalars() is not None:
            grid.GetPointData().SetActiveScalars(point_data.GetScalars().GetName())
    return grid


def permuted_points(points_pd, seed=0):
    """The samples (points and arrays) in a random order, as a vtkPolyData."""
    n = points_pd.GetNumberOfPoints()
    order = np.random.default_rng(seed).permutation(n)
    pd = vtkPolyData()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points_of(points_pd)[order].astype(np.float32)),
                             deep=1))
    pd.SetPoints(pts)
    src = points_pd.GetPointData()
    for i in range(src.GetNumberOfArrays()):
        arr = src.GetArray(i)
        if arr is None:
            continue
        dst = numpy_to_vtk(np.ascontiguousarray(vtk_to_numpy(arr)[order]), deep=1,
                           array_type=arr.GetDataType())
        dst.SetName(arr.GetName())
        pd.GetPointData().AddArray(dst)
    return pd


def circumradii(P, T):
    """Circumradius of every tetrahedron (inf for flat ones)."""
    A = P[T]
    B = A[:, 1:] - A[:, :1]
    rhs = 0.5 * (B ** 2).sum(axis=2)
    det = np.linalg.det(B)
    ok = np.abs(det) > 1e-12 * np.maximum(1.0, (B ** 2).sum(axis=(1, 2))) ** 1.5
    R = np.full(len(T), np.inf)
    if np.any(ok):
        c = np.linalg.solve(B[ok], rhs[ok][..., None])[..., 0]
        R[ok] = np.linalg.norm(c, axis=1)
    return R


def tet_volumes(P, T):
    A = P[T]
    return np.einsum("ij,ij->i", np.cross(A[:, 1] - A[:, 0], A[:, 2] - A[:, 0]), A[:, 3] - A[:, 0]) / 6.0


def voxel_index(image, xyz):
    """Flat index of the voxel nearest to each world point (axis-aligned images)."""
    origin = np.array(image.GetOrigin())
    spacing = np.array(image.GetSpacing())
    ext = image.GetExtent()
    dims = np.array(image.GetDimensions())
    ijk = np.rint((xyz - origin) / spacing).astype(np.int64) - np.array(ext[0::2])
    ijk = np.clip(ijk, 0, dims - 1)
    return ijk[:, 0] + dims[0] * (ijk[:, 1] + dims[1] * ijk[:, 2])


def mean_spacing(image, g, n):
    """Mean sample spacing: (foreground volume / vertices)^(1/3)."""
    vox = float(np.prod(image.GetSpacing()))
    return (np.count_nonzero(g > 0) * vox / max(n, 1)) ** (1.0 / 3.0)


# ---------------------------------------------------------------------------
# Meshing
def tetrahedralize(points_pd, image, array, g, restrict=DEFAULT_RESTRICT,
                   alpha_factor=DEFAULT_ALPHA_FACTOR, threshold=None, mesher="vtk",
                   drop_degenerate=False, order_seed=0):
    """Tetrahedral mesh of the samples restricted to the volume.

    g: the density of every voxel (0 = empty space) used by `centroid`.
    Returns (vtkUnstructuredGrid, info dict). The grid's points are sample
    points (in another order) carrying all the samples' arrays."""
    rules = set(r for r in restrict.split("+") if r and r != "none")
    unknown = rules - {"alpha", "adaptive", "centroid", "vertices"}
    if unknown:
        raise ValueError("unknown restriction rule(s): %s" % ", ".join(sorted(unknown)))
    info = {}
    n = points_pd.GetNumberOfPoints()
    spacing = mean_spacing(image, g, n)
    info["spacing"] = spacing
    shuffled = permuted_points(points_pd, order_seed)
    P = points_of(shuffled)
    t0 = time.time()
    if mesher == "vtk":
        dl = vtkDelaunay3D()
        dl.SetInputData(shuffled)
        # Merge only coincident points (the default 0.001 of the diagonal
        # could merge neighboring voxels of a large volume).
        dl.SetTolerance(1e-7)
        if "alpha" in rules:
            dl.SetAlpha(alpha_factor * spacing)
            dl.AlphaTetsOn()
            dl.AlphaTrisOff()
            dl.AlphaLinesOff()
            dl.AlphaVertsOff()
        dl.Update()
        raw = dl.GetOutput()
        if raw.GetNumberOfPoints() != n:
            raise RuntimeError("vtkDelaunay3D changed the points")
        types = cell_types(raw)
        conn = raw.GetCells()
        offs = vtk_to_numpy(conn.GetOffsetsArray()).astype(np.int64)
        ids = vtk_to_numpy(conn.GetConnectivityArray()).astype(np.int64)
        tet_cells = np.nonzero(types == VTK_TETRA)[0]
        T = np.stack([ids[offs[tet_cells] + k] for k in range(4)], axis=1) if len(tet_cells) else \
            np.zeros((0, 4), dtype=np.int64)
    elif mesher == "qhull":
        from scipy.spatial import Delaunay
        T = Delaunay(P).simplices.astype(np.int64)
        if "alpha" in rules:
            T = T[circumradii(P, T) <= alpha_factor * spacing]
    else:
        raise ValueError("unknown mesher %r" % mesher)
    info["mesh_seconds"] = time.time() - t0
    info["delaunay_tets"] = len(T)

    keep = np.ones(len(T), dtype=bool)
    if "adaptive" in rules and len(T):
        dens = vtk_to_numpy(shuffled.GetPointData().GetArray("Density")).astype(np.float64)
        h = float(np.mean(image.GetSpacing()))
        local = h * np.mean(np.maximum(dens[T], 1e-12) ** (-1.0 / 3.0), axis=1)
        drop = circumradii(P, T) > alpha_factor * local
        info["dropped_adaptive"] = int(np.count_nonzero(drop & keep))
        keep &= ~drop
    if "centroid" in rules and len(T):
        centroid = P[T].mean(axis=1)
        drop = g[voxel_index(image, centroid)] <= 0
        info["dropped_centroid"] = int(np.count_nonzero(drop & keep))
        keep &= ~drop
    if "vertices" in rules and len(T):
        vals = vtk_to_numpy(shuffled.GetPointData().GetArray(array))
        vals = (vals[:, 0] if vals.ndim > 1 else vals).astype(np.float64)
        thr = float(volume_values(image, array).min()) if threshold is None else threshold
        drop = np.all(vals[T] <= thr, axis=1)
        info["dropped_vertices"] = int(np.count_nonzero(drop & keep))
        keep &= ~drop
    # Orientation and degeneracy.
    vol = tet_volumes(P, T)
    neg = vol < 0
    T = T.copy()
    T[neg, 2], T[neg, 3] = T[neg, 3].copy(), T[neg, 2].copy()
    if drop_degenerate and len(T):
        rr = radius_ratio_numpy(P, T)
        drop = ~(rr <= DEGENERATE_RADIUS_RATIO)
        info["dropped_degenerate"] = int(np.count_nonzero(drop & keep))
        keep &= ~drop
    T = T[keep]
    # Compact: only the vertices the kept tetrahedra use.
    used = np.zeros(n, dtype=bool)
    used[T.ravel()] = True
    old_ids = np.nonzero(used)[0]
    new_id = np.full(n, -1, dtype=np.int64)
    new_id[old_ids] = np.arange(len(old_ids))
    grid = make_grid(P[old_ids], new_id[T], shuffled.GetPointData(), keep=old_ids)
    info["vertices"] = len(old_ids)
    info["unused_samples"] = n - len(old_ids)
    info["tets"] = len(T)
    return grid, info


def radius_ratio_numpy(P, T):
    """R / (3 r) of every tetrahedron (inf for flat ones), as Verdict defines it."""
    A = P[T]
    vol = np.abs(tet_volumes(P, T))
    faces = [(1, 2, 3), (0, 2, 3), (0, 1, 3), (0, 1, 2)]
    area = sum(0.5 * np.linalg.norm(np.cross(A[:, b] - A[:, a], A[:, c] - A[:, a]), axis=1)
               for a, b, c in faces)
    with np.errstate(divide="ignore", invalid="ignore"):
        r = 3.0 * vol / area
        return circumradii(P, T) / (3.0 * r)


# ---------------------------------------------------------------------------
# Measures
def radius_ratios(grid):
    """vtkMeshQuality's tetrahedron radius ratio of every cell."""
    if grid.GetNumberOfCells() == 0:
        return np.zeros(0)
    mq = vtkMeshQuality()
    mq.SetInputData(grid)
    mq.SetTetQualityMeasureToRadiusRatio()
    mq.Update()
    return vtk_to_numpy(mq.GetOutput().GetCellData().GetArray("Quality")).astype(np.float64)


def quality_summary(rr):
    if len(rr) == 0:
        return dict(rr_mean=float("nan"), rr_median=float("nan"), rr_p5=float("nan"),
                    rr_p95=float("nan"), frac_poor=float("nan"), frac_degenerate=float("nan"))
    finite = np.where(np.isfinite(rr), rr, 1e30)
    return dict(rr_mean=float(np.mean(np.minimum(finite, 1e6))),
                rr_median=float(np.median(finite)),
                rr_p5=float(np.percentile(finite, 5)),
                rr_p95=float(np.percentile(finite, 95)),
                frac_poor=float(np.mean(finite > POOR_RADIUS_RATIO)),
                frac_degenerate=float(np.mean(finite > DEGENERATE_RADIUS_RATIO)))


def reconstruct(grid, image, array):
    """Resample the mesh's `array` onto the image grid (vtkResampleWithDataSet).

    Returns (values, valid): float64 values per voxel (VTK order) and a bool
    mask of the voxels inside the mesh; outside voxels hold the volume's
    minimum."""
    nvox = image.GetNumberOfPoints()
    values = np.full(nvox, volume_values(image, array).min())
    valid = np.zeros(nvox, dtype=bool)
    if grid.GetNumberOfCells() == 0:
        return values, valid
    # The value as float: an integer array would be rounded by the interpolation.
    src = vtkUnstructuredGrid()
    src.CopyStructure(grid)
    a = vtk_to_numpy(grid.GetPointData().GetArray(array))
    a = (a[:, 0] if a.ndim > 1 else a).astype(np.float64)
    fa = numpy_to_vtk(np.ascontiguousarray(a), deep=1)
    fa.SetName("value")
    src.GetPointData().AddArray(fa)
    # Crop the grid to the mesh's bounds: voxels outside them are outside the mesh.
    origin = np.array(image.GetOrigin())
    spacing = np.array(image.GetSpacing())
    ext = np.array(image.GetExtent())
    b = np.array(src.GetBounds())
    lo = np.maximum(np.floor((b[0::2] - origin) / spacing).astype(int) - 1, ext[0::2])
    hi = np.minimum(np.ceil((b[1::2] - origin) / spacing).astype(int) + 1, ext[1::2])
    geometry = vtkImageData()
    geometry.SetOrigin(image.GetOrigin())
    geometry.SetSpacing(image.GetSpacing())
    geometry.SetExtent(lo[0], hi[0], lo[1], hi[1], lo[2], hi[2])
    rs = vtkResampleWithDataSet()
    rs.SetInputData(geometry)
    rs.SetSourceData(src)
    rs.SetCellLocatorPrototype(vtkStaticCellLocator())
    rs.MarkBlankPointsAndCellsOff()
    rs.Update()
    out = rs.GetOutput()
    sub_vals = vtk_to_numpy(out.GetPointData().GetArray("value")).astype(np.float64)
    sub_valid = vtk_to_numpy(out.GetPointData().GetArray("vtkValidPointMask")) > 0
    # Scatter the sub-box back into the full grid.
    dims = np.array(image.GetDimensions())
    i = np.arange(lo[0], hi[0] + 1) - ext[0]
    j = np.arange(lo[1], hi[1] + 1) - ext[2]
    k = np.arange(lo[2], hi[2] + 1) - ext[4]
    kk, jj, ii = np.meshgrid(k, j, i, indexing="ij")
    flat = (ii + dims[0] * (jj + dims[1] * kk)).ravel()
    values[flat[sub_valid]] = sub_vals[sub_valid]
    valid[flat] = sub_valid
    return values, valid


def error_summary(original, reconstruction, valid, g):
    fg = g > 0
    roi = fg | valid
    peak = float(original.max() - original.min()) or 1.0
    diff = reconstruction - original
    rmse = float(np.sqrt(np.mean(diff[roi] ** 2))) if np.any(roi) else float("nan")
    rmse_in = float(np.sqrt(np.mean(diff[valid] ** 2))) if np.any(valid) else float("nan")
    psnr = 20.0 * math.log10(peak / rmse) if rmse > 0 else float("inf")
    return dict(rmse=rmse, psnr=psnr, rmse_in=rmse_in,
                cover=float(np.mean(valid[fg])) if np.any(fg) else float("nan"),
                spill=float(np.mean(valid[~fg])) if np.any(~fg) else 0.0)


def storage_ratio(grid, image, array):
    """Mesh bytes (float32 xyz + carried value + 4 int32 ids per tet) / voxel bytes."""
    value_bytes = image.GetPointData().GetArray(array).GetDataTypeSize() * \
        image.GetPointData().GetArray(array).GetNumberOfComponents()
    mesh = grid.GetNumberOfPoints() * (3 * 4 + value_bytes) + grid.GetNumberOfCells() * 4 * 4
    voxels = image.GetNumberOfPoints() * value_bytes
    return mesh / voxels, mesh, voxels


# ---------------------------------------------------------------------------
def run_case(image, array, method, target, seed=0, restrict=DEFAULT_RESTRICT,
             alpha_factor=DEFAULT_ALPHA_FACTOR, mesher="vtk", drop_degenerate=False,
             values=None, g=None, match_count=True):
    """Sample, mesh, reconstruct and measure one (method, count, seed).

    Returns (result dict, points polydata, grid)."""
    if values is None:
        values = volume_values(image, array)
    g0 = base_density(values)
    t0 = time.time()
    points, scale = sample_volume(image, array, method, target, seed, match_count, g0=g0)
    t_sample = time.time() - t0
    if g is None:
        g = np.minimum(1.0, scale * g0)
    grid, info = tetrahedralize(points, image, array, g, restrict=restrict, alpha_factor=alpha_factor,
                                mesher=mesher, drop_degenerate=drop_degenerate, order_seed=seed)
    t0 = time.time()
    rec, valid = reconstruct(grid, image, array)
    t_res = time.time() - t0
    result = dict(method=method, target=target, seed=seed, samples=points.GetNumberOfPoints(),
                  scale=scale, sample_seconds=t_sample, resample_seconds=t_res)
    result.update(info)
    result.update(error_summary(values, rec, valid, g))
    ratio, mesh_bytes, voxel_bytes = storage_ratio(grid, image, array)
    result.update(storage=ratio, mesh_bytes=mesh_bytes, voxel_bytes=voxel_bytes)
    result.update(quality_summary(radius_ratios(grid)))
    result["_reconstruction"] = rec
    result["_valid"] = valid
    return result, points, grid


def add_common_region(results, values):
    """RMSE/PSNR of each result over the voxels inside every result's mesh.

    Comparing RMSE_in of two meshes compares different regions (a mesh that
    covers less skips the hard voxels at the boundary); the common region is
    the fair comparison. Adds rmse_common, psnr_common and common (the
    fraction of voxels in it) to each result and drops the per-voxel arrays."""
    common = np.logical_and.reduce([r["_valid"] for r in results])
    peak = float(values.max() - values.min()) or 1.0
    for r in results:
        if np.any(common):
            e = float(np.sqrt(np.mean((r["_reconstruction"][common] - values[common]) ** 2)))
        else:
            e = float("nan")
        r["rmse_common"] = e
        r["psnr_common"] = 20.0 * math.log10(peak / e) if e > 0 else float("inf")
        r["common"] = float(np.mean(common))
    for r in results:
        r.pop("_reconstruction", None)
        r.pop("_valid", None)
    return results


COLUMNS = [
    ("method", "%-6s", "method"), ("target", "%8.0f", "target"), ("vertices", "%8d", "verts"),
    ("tets", "%8d", "tets"), ("cover", "%6.3f", "cover"), ("spill", "%6.3f", "spill"),
    ("rmse_common", "%7.4g", "RMSEc"), ("psnr_common", "%6.2f", "PSNRc"),
    ("rmse_in", "%7.4g", "RMSEin"), ("rmse", "%7.4g", "RMSE"), ("psnr", "%6.2f", "PSNR"),
    ("storage", "%7.3f", "store"), ("rr_mean", "%7.2f", "RRmean"), ("rr_median", "%6.2f", "RRmed"),
    ("rr_p5", "%5.2f", "RRp5"), ("rr_p95", "%6.2f", "RRp95"), ("frac_poor", "%6.3f", "RR>3"),
    ("frac_degenerate", "%7.4f", "RR>100"), ("mesh_seconds", "%6.1f", "mesh_s"),
    ("resample_seconds", "%5.1f", "res_s"),
]


def format_row(r):
    return " ".join(fmt % r[key] for key, fmt, _ in COLUMNS)


def header():
    widths = []
    for key, fmt, title in COLUMNS:
        width = int("".join(ch for ch in fmt.split(".")[0] if ch.isdigit()) or len(title))
        widths.append(("%" + ("-" if "-" in fmt else "") + str(width) + "s") % title)
    return " ".join(widths)


def mean_result(results):
    """Average of the numeric fields over seeds (method/target from the first)."""
    out = dict(results[0])
    for key in out:
        if isinstance(out[key], (int, float)) and key not in ("target",):
            out[key] = type(out[key])(np.mean([r[key] for r in results])) \
                if isinstance(out[key], float) else int(round(np.mean([r[key] for r in results])))
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--volume", default=DEFAULT_VOLUME,
                        help="volume file (.nii/.nii.gz/.vti/.mhd/.nrrd), default ch2bet "
                             "of mricron-data; 'blob' or 'sines' for an analytic 32^3 volume")
    parser.add_argument("--array", default=None, help="point-data array (default: the scalars)")
    parser.add_argument("--counts", type=float, nargs="+", default=[1e4, 3e4, 1e5],
                        help="vertex counts (default 1e4 3e4 1e5)")
    parser.add_argument("--methods", nargs="+", default=["ED", "WN"], choices=sorted(METHODS))
    parser.add_argument("--seeds", type=int, nargs="+", default=[0])
    parser.add_argument("--restrict", default=DEFAULT_RESTRICT,
                        help="none or rules joined by '+': alpha, adaptive, centroid, vertices "
                             "(default %s)" % DEFAULT_RESTRICT)
    parser.add_argument("--alpha-factor", type=float, default=DEFAULT_ALPHA_FACTOR,
                        help="k of the alpha rules (default %g)" % DEFAULT_ALPHA_FACTOR)
    parser.add_argument("--mesher", choices=["vtk", "qhull"], default="vtk",
                        help="vtkDelaunay3D (default) or scipy.spatial.Delaunay")
    parser.add_argument("--drop-degenerate", action="store_true",
                        help="also remove tetrahedra with radius ratio > %g" % DEGENERATE_RADIUS_RATIO)
    parser.add_argument("--save", default="", help="folder to write the meshes (.vtu) to")
    args = parser.parse_args(argv)

    if args.volume in ("blob", "sines"):
        image, array = analytic_volume(32, args.volume), "value"
    else:
        image, array = read_volume(args.volume, args.array)
    values = volume_values(image, array)
    print("volume: %s, array %s, %s voxels, values %g..%g, %d voxels of density > 0"
          % (args.volume, array, "x".join(str(d) for d in image.GetDimensions()), values.min(),
             values.max(), np.count_nonzero(base_density(values) > 0)))
    print("restriction: %s (k = %g), mesher: %s, seeds: %s"
          % (args.restrict, args.alpha_factor, args.mesher, " ".join(map(str, args.seeds))))
    print("columns: cover/spill = fraction of foreground/background voxels inside the mesh; "
          "RMSEc/PSNRc over the voxels inside the meshes of all methods (same seed); RMSEin over "
          "the voxels inside this mesh; RMSE/PSNR over foreground + mesh voxels (outside the "
          "mesh = minimum value); store = mesh bytes / voxel bytes; RR = tetrahedron radius ratio; "
          "PSNR peak = value range")
    print(header(), flush=True)
    if args.save:
        os.makedirs(args.save, exist_ok=True)
    for target in args.counts:
        per_method = {m: [] for m in args.methods}
        for seed in args.seeds:
            batch = []
            for method in args.methods:
                r, _, grid = run_case(image, array, method, target, seed, restrict=args.restrict,
                                      alpha_factor=args.alpha_factor, mesher=args.mesher,
                                      drop_degenerate=args.drop_degenerate, values=values)
                batch.append(r)
                per_method[method].append(r)
                if args.save:
                    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
                    w = vtkXMLUnstructuredGridWriter()
                    w.SetFileName(os.path.join(args.save, "mesh_%s_%d_seed%d.vtu"
                                               % (method, int(target), seed)))
                    w.SetInputData(grid)
                    # Inline binary: VTK 9.2's readers fail on large appended
                    # sections with Debian's expat (reparse deferral).
                    w.SetDataModeToBinary()
                    w.Write()
            add_common_region(batch, values)
        for method in args.methods:
            print(format_row(mean_result(per_method[method])), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
