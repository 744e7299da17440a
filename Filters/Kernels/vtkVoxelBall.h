// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkVoxelBall
 * @brief   The voxels within a radius of a voxel center, as runs along x.
 *
 * For a center voxel (cx, cy, cz) of an nx x ny x nz grid (index x + nx * (y +
 * ny * z)) and a squared radius R2, Compute() lists the voxels whose centers
 * lie at squared distance d2 < R2, as runs of consecutive x: the k-th voxel of
 * a run has index Start + k and d2 = DYZ2 + (DX + k)^2. The center
 * itself is included (d2 = 0).
 *
 * Positions outside the grid are left out.
 *
 * Row skipping: with rowReach2 (one value per row y + ny * z), a row whose
 * squared distance to the center dy^2 + dz^2 is at least rowReach2[row] is
 * left out. The kernels pass the squared largest interaction radius of the
 * row's voxels, so rows that cannot interact with the center cost nothing: a
 * large radius in a sparse region then scans only the rows it can reach.
 *
 * Cost: O(rows within R) to build the runs, plus the caller's loop over them.
 * Memory: the run list, reused across calls.
 */
#ifndef vtkVoxelBall_h
#define vtkVoxelBall_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <cstdint>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkVoxelBall
{
public:
  struct Run
  {
    vtkIdType Start = 0;    ///< index of the run's first voxel
    int Length = 0;         ///< voxels in the run
    int DX = 0;             ///< x offset of the run's first position from the center
    std::int64_t DYZ2 = 0;  ///< dy^2 + dz^2 of the run's row
  };

  void SetDimensions(int nx, int ny, int nz);

  /**
   * The runs of the ball d2 < radius2 around voxel (cx, cy, cz), valid until
   * the next call. rowReach2: optional, see the class documentation.
   */
  const std::vector<Run>& Compute(
    int cx, int cy, int cz, double radius2, const float* rowReach2 = nullptr);

private:

  int N[3] = { 0, 0, 0 };
  std::vector<Run> Runs;
};

#endif
