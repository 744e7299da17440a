# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Tetrahedral meshing of samples (Examples/tetrahedral_mesh.py) on an analytic volume.

    PYTHONPATH=<build>/lib/python3/dist-packages python3 TestTetrahedralMesh.py \
        --examples <source>/Examples

A 32^3 volume of two overlapping Gaussian blobs (exactly 0 far from them),
density from the value (ScalarRange mapping), about 1500 vertices, seeds 0, 1,
2, both methods. Checks:
- every mesh vertex is a sample: same coordinates (bit for bit) and the same
  carried value, no vertex twice;
- the mesh is valid: only tetrahedra, positively oriented, none degenerate
  (volume at least the lattice minimum 1/6 voxel^3 that any non-flat
  tetrahedron with voxel-center vertices has, radius ratio finite and below
  1000), none bridging empty space (no centroid in a voxel of density 0);
- the vertex counts of both methods agree within 3 %;
- the mean over seeds of the reconstruction RMSE (common region of both
  meshes) from error-diffusion samples is below the white-noise one, and so
  is the RMSE over foreground + mesh voxels.
Exits 1 when a check fails.
"""
import argparse
import math
import os
import sys

import numpy as np

from bluenoise_testing import check, summary


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--examples", required=True, help="the Examples folder")
    parser.add_argument("--target", type=float, default=1500)
    parser.add_argument("--seeds", type=int, nargs="+", default=[0, 1, 2])
    args = parser.parse_args()
    sys.path.insert(0, os.path.abspath(args.examples))
    import tetrahedral_mesh as tm
    from vtkmodules.util.numpy_support import vtk_to_numpy

    image = tm.analytic_volume(32, "blob")
    values = tm.volume_values(image, "value")
    g0 = tm.base_density(values)
    check(np.count_nonzero(g0 == 0) > 1000, "the volume has empty space (%d voxels of density 0)"
          % np.count_nonzero(g0 == 0))

    per_method = {"ED": [], "WN": []}
    for seed in args.seeds:
        batch = []
        for method in ("ED", "WN"):
            result, points, grid = tm.run_case(image, "value", method, args.target, seed,
                                               values=values)
            what = "%s seed %d" % (method, seed)
            batch.append(result)
            per_method[method].append(result)

            # Every vertex is a sample.
            sp = vtk_to_numpy(points.GetPoints().GetData())
            mp = vtk_to_numpy(grid.GetPoints().GetData())
            check(sp.dtype == mp.dtype == np.float32, "%s: float32 points" % what)
            sample_rows = {row.tobytes(): i for i, row in enumerate(sp)}
            idx = np.array([sample_rows.get(row.tobytes(), -1) for row in mp])
            check(len(mp) > 0 and np.all(idx >= 0),
                  "%s: all %d mesh vertices are sample points (%d samples)"
                  % (what, len(mp), len(sp)))
            check(len(np.unique(idx)) == len(idx), "%s: no sample used twice" % what)
            if np.all(idx >= 0):
                sv = vtk_to_numpy(points.GetPointData().GetArray("value"))
                mv = vtk_to_numpy(grid.GetPointData().GetArray("value"))
                check(np.array_equal(sv[idx], mv), "%s: vertices carry their samples' values" % what)
                # ... which are the voxel values at those points.
                vox = tm.voxel_index(image, mp.astype(np.float64))
                check(np.allclose(values[vox], mv), "%s: the values are the voxels' values" % what)
            check(result["unused_samples"] <= 0.2 * len(sp),
                  "%s: %d samples outside the restricted mesh" % (what, result["unused_samples"]))

            # A valid mesh.
            types = tm.cell_types(grid)
            check(grid.GetNumberOfCells() > 3 * len(mp) and np.all(types == tm.VTK_TETRA),
                  "%s: %d cells, all tetrahedra" % (what, grid.GetNumberOfCells()))
            P = mp.astype(np.float64)
            T = tm.tets_of(grid)
            vol = tm.tet_volumes(P, T)
            check(vol.min() >= 1.0 / 6.0 - 1e-6,
                  "%s: every tetrahedron positive with volume >= 1/6 (min %.4f)" % (what, vol.min()))
            rr = tm.radius_ratios(grid)
            check(np.all(np.isfinite(rr)) and rr.max() < 1000.0 and rr.min() >= 1.0 - 1e-6,
                  "%s: radius ratio in [1, 1000) (max %.1f, median %.2f)"
                  % (what, rr.max(), np.median(rr)))
            centroid_g = g0[tm.voxel_index(image, P[T].mean(axis=1))]
            check(np.all(centroid_g > 0), "%s: no tetrahedron centroid in empty space" % what)
            check(result["spill"] < 0.01, "%s: %.4f of the empty voxels inside the mesh"
                  % (what, result["spill"]))
            check(all(math.isfinite(result[k]) for k in ("rmse", "rmse_in", "psnr", "storage")),
                  "%s: finite RMSE %.4g, PSNR %.2f, storage %.3f"
                  % (what, result["rmse"], result["psnr"], result["storage"]))
        tm.add_common_region(batch, values)
        ed, wn = batch
        check(abs(ed["vertices"] - wn["vertices"]) <= 0.03 * args.target,
              "seed %d: vertex counts ED %d, WN %d within 3 %%" % (seed, ed["vertices"], wn["vertices"]))
        check(ed["common"] > 0.05, "seed %d: common region %.3f of the voxels" % (seed, ed["common"]))
        print("      seed %d: RMSE common ED %.5f WN %.5f; RMSE ED %.5f WN %.5f; RR>3 ED %.3f WN %.3f"
              % (seed, ed["rmse_common"], wn["rmse_common"], ed["rmse"], wn["rmse"],
                 ed["frac_poor"], wn["frac_poor"]))

    mean = {m: {k: float(np.mean([r[k] for r in rs])) for k in ("rmse_common", "rmse", "frac_poor")}
            for m, rs in per_method.items()}
    check(mean["ED"]["rmse_common"] < mean["WN"]["rmse_common"],
          "mean RMSE over the common region: ED %.5f < WN %.5f"
          % (mean["ED"]["rmse_common"], mean["WN"]["rmse_common"]))
    check(mean["ED"]["rmse"] < mean["WN"]["rmse"],
          "mean RMSE over foreground + mesh: ED %.5f < WN %.5f"
          % (mean["ED"]["rmse"], mean["WN"]["rmse"]))
    check(mean["ED"]["frac_poor"] < mean["WN"]["frac_poor"],
          "fewer poor tetrahedra (radius ratio > 3) from ED: %.3f < %.3f"
          % (mean["ED"]["frac_poor"], mean["WN"]["frac_poor"]))

    return summary()


if __name__ == "__main__":
    sys.exit(main())
