// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkVoxelMargin.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
int vtkVoxelMargin::DensityLevel(float g)
{
  const auto level = static_cast<int>(std::floor(LevelsPerOctave * std::log2(g)));
  return std::min(std::max(level + NumberOfLevels, 0), NumberOfLevels - 1);
}

//------------------------------------------------------------------------------
float vtkVoxelMargin::SmallestFaceDensity(int nx, int ny, int nz, const float* density)
{
  float smallest = 1.0f;
  for (int z = 0; z < nz; ++z)
  {
    for (int y = 0; y < ny; ++y)
    {
      // Rows inside the y and z faces touch the faces at their two ends only.
      const bool inner = z > 0 && z < nz - 1 && y > 0 && y < ny - 1;
      const int step = (inner && nx > 1) ? nx - 1 : 1;
      for (int x = 0; x < nx; x += step)
      {
        const float g =
          density[x + static_cast<vtkIdType>(nx) * (y + static_cast<vtkIdType>(ny) * z)];
        if (g > 0.0f && g < smallest)
        {
          smallest = g;
        }
      }
    }
  }
  return smallest;
}

//------------------------------------------------------------------------------
void vtkVoxelMargin::Extend(int nx, int ny, int nz, const float* density, int margin)
{
  this->Dims[0] = nx;
  this->Dims[1] = ny;
  this->Dims[2] = nz;
  this->Margin = std::max(margin, 0);
  const int m = this->Margin;
  for (int i = 0; i < 3; ++i)
  {
    this->Extent[i] = this->Dims[i] + 2 * m;
  }
  const int ex = this->Extent[0], ey = this->Extent[1], ez = this->Extent[2];
  this->Density.resize(static_cast<size_t>(ex) * ey * ez);
  float* out = this->Density.data();
  for (int z = 0; z < ez; ++z)
  {
    const vtkIdType iz = std::min(std::max(z - m, 0), nz - 1);
    for (int y = 0; y < ey; ++y)
    {
      const vtkIdType iy = std::min(std::max(y - m, 0), ny - 1);
      const float* row = density + nx * (iy + ny * iz);
      // Left margin, the row itself, right margin.
      out = std::fill_n(out, m, row[0]);
      out = std::copy(row, row + nx, out);
      out = std::fill_n(out, m, row[nx - 1]);
    }
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkVoxelMargin::ToExtended(vtkIdType inner) const
{
  const vtkIdType nx = this->Dims[0], ny = this->Dims[1], m = this->Margin;
  const vtkIdType x = inner % nx, y = (inner / nx) % ny, z = inner / (nx * ny);
  return (x + m) + this->Extent[0] * ((y + m) + this->Extent[1] * (z + m));
}

//------------------------------------------------------------------------------
bool vtkVoxelMargin::IsInside(vtkIdType v) const
{
  const vtkIdType ex = this->Extent[0], ey = this->Extent[1], m = this->Margin;
  const vtkIdType x = v % ex, y = (v / ex) % ey, z = v / (ex * ey);
  return x >= m && x < m + this->Dims[0] && y >= m && y < m + this->Dims[1] && z >= m &&
    z < m + this->Dims[2];
}
