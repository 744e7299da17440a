// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkVoxelBall.h"

#include <algorithm>
#include <cmath>

namespace
{
// The largest e >= 0 with e^2 < r2, at most limit; -1 when r2 <= 0.
int Extent(double r2, int limit)
{
  if (r2 <= 0.0)
  {
    return -1;
  }
  const double root = std::sqrt(r2);
  if (root >= limit)
  {
    return limit;
  }
  auto e = static_cast<int>(root);
  if (static_cast<double>(e) * e >= r2)
  {
    --e;
  }
  return e;
}
}

//------------------------------------------------------------------------------
void vtkVoxelBall::SetDimensions(int nx, int ny, int nz)
{
  this->N[0] = std::max(nx, 0);
  this->N[1] = std::max(ny, 0);
  this->N[2] = std::max(nz, 0);
}

//------------------------------------------------------------------------------
const std::vector<vtkVoxelBall::Run>& vtkVoxelBall::Compute(
  int cx, int cy, int cz, double radius2, const float* rowReach2)
{
  this->Runs.clear();
  const int nx = this->N[0], ny = this->N[1], nz = this->N[2];
  const int ez = Extent(radius2, std::max(cz, nz - 1 - cz));
  for (int z = std::max(cz - ez, 0); z <= std::min(cz + ez, nz - 1); ++z)
  {
    const std::int64_t dz2 = static_cast<std::int64_t>(z - cz) * (z - cz);
    const int ey = Extent(radius2 - static_cast<double>(dz2), std::max(cy, ny - 1 - cy));
    for (int y = std::max(cy - ey, 0); y <= std::min(cy + ey, ny - 1); ++y)
    {
      const int row = y + ny * z;
      const std::int64_t dyz2 = dz2 + static_cast<std::int64_t>(y - cy) * (y - cy);
      if (rowReach2 && static_cast<double>(dyz2) >= rowReach2[row])
      {
        continue;
      }
      const int ex = Extent(radius2 - static_cast<double>(dyz2), std::max(cx, nx - 1 - cx));
      const int lo = std::max(cx - ex, 0);
      const int hi = std::min(cx + ex, nx - 1);
      if (hi >= lo)
      {
        Run run;
        run.Start = static_cast<vtkIdType>(row) * nx + lo;
        run.Length = hi - lo + 1;
        run.DX = lo - cx;
        run.DYZ2 = dyz2;
        this->Runs.push_back(run);
      }
    }
  }
  return this->Runs;
}
