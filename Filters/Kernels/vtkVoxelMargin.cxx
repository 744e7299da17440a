// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkVoxelMargin.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace
{
// The 26 neighbor offsets, nearest first: the 6 faces, the 12 edges, the 8
// corners, each group in index order.
struct Offsets
{
  int D[26][3];
  Offsets()
  {
    int k = 0;
    for (int steps = 1; steps <= 3; ++steps)
    {
      for (int dz = -1; dz <= 1; ++dz)
      {
        for (int dy = -1; dy <= 1; ++dy)
        {
          for (int dx = -1; dx <= 1; ++dx)
          {
            if ((dx != 0) + (dy != 0) + (dz != 0) == steps)
            {
              this->D[k][0] = dx;
              this->D[k][1] = dy;
              this->D[k][2] = dz;
              ++k;
            }
          }
        }
      }
    }
  }
};
const Offsets Neighbors;

// Calls visit(w) for the neighbors w of voxel (x, y, z) of an n[0] x n[1] x
// n[2] grid, nearest first (the 6 face neighbors only with faceOnly) until
// visit returns true.
template <typename Visit>
void ForEachNeighbor(const int n[3], int x, int y, int z, bool faceOnly, Visit&& visit)
{
  for (int k = 0; k < (faceOnly ? 6 : 26); ++k)
  {
    const int px = x + Neighbors.D[k][0], py = y + Neighbors.D[k][1], pz = z + Neighbors.D[k][2];
    if (px >= 0 && py >= 0 && pz >= 0 && px < n[0] && py < n[1] && pz < n[2] &&
      visit(px + static_cast<vtkIdType>(n[0]) * (py + static_cast<vtkIdType>(n[1]) * pz)))
    {
      return;
    }
  }
}
}

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
        smallest = IsActive(g) ? std::min(smallest, g) : smallest;
      }
    }
  }
  return smallest;
}

//------------------------------------------------------------------------------
float vtkVoxelMargin::SmallestBorderDensity(int nx, int ny, int nz, const float* density)
{
  const int n[3] = { nx, ny, nz };
  float smallest = 1.0f;
  vtkIdType v = 0;
  for (int z = 0; z < nz; ++z)
  {
    for (int y = 0; y < ny; ++y)
    {
      for (int x = 0; x < nx; ++x, ++v)
      {
        const float g = density[v];
        if (!IsActive(g) || g >= smallest)
        {
          continue;
        }
        bool border = x == 0 || y == 0 || z == 0 || x == nx - 1 || y == ny - 1 || z == nz - 1;
        ForEachNeighbor(n, x, y, z, true, [&](vtkIdType w) {
          border = !IsActive(density[w]);
          return border;
        });
        smallest = border ? g : smallest;
      }
    }
  }
  return smallest;
}

//------------------------------------------------------------------------------
bool vtkVoxelMargin::Extend(int nx, int ny, int nz, const float* density, int margin, int depth,
  const std::function<bool(double)>& progress)
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
  const vtkIdType ex = this->Extent[0], ey = this->Extent[1], ez = this->Extent[2];
  this->Density.assign(static_cast<size_t>(ex * ey * ez), 0.0f);
  this->Virtual.assign(this->Density.size(), 0);
  for (vtkIdType z = 0; z < nz; ++z)
  {
    for (vtkIdType y = 0; y < ny; ++y)
    {
      const float* row = density + nx * (y + ny * z);
      std::copy(row, row + nx, this->Density.begin() + (m + ex * ((y + m) + ey * (z + m))));
    }
  }
  if (progress && !progress(0.2))
  {
    return false;
  }
  // Steps are kept in a byte.
  return depth <= 0 || this->Grow(std::min(depth, 255), progress);
}

//------------------------------------------------------------------------------
bool vtkVoxelMargin::Pull(vtkIdType v, int step)
{
  // The nearest neighbor that is active or became virtual in an earlier step
  // (at a flat face: the face neighbor, so the margin continues the face).
  const int* n = this->Extent;
  const int x = static_cast<int>(v % n[0]);
  const int y = static_cast<int>((v / n[0]) % n[1]);
  const int z = static_cast<int>(v / (static_cast<vtkIdType>(n[0]) * n[1]));
  bool found = false;
  ForEachNeighbor(n, x, y, z, false, [&](vtkIdType w) {
    const int from = this->Virtual[w];
    found = from == 0 ? IsActive(this->Density[w]) : from < step;
    if (found)
    {
      this->Density[v] = this->Density[w];
      this->Virtual[v] = static_cast<unsigned char>(step);
    }
    return found;
  });
  return found;
}

//------------------------------------------------------------------------------
// False when `progress` stopped it (reported from 0.2, the copy, to 1).
bool vtkVoxelMargin::Grow(int depth, const std::function<bool(double)>& progress)
{
  std::vector<vtkIdType> front, next;
  const vtkIdType voxels = this->GetNumberOfVoxels();
  const vtkIdType interval = vtkIdType(1) << 18;
  for (vtkIdType v = 0; v < voxels; ++v)
  {
    // The first step visits every voxel; the later ones only the front.
    if (progress && v % interval == interval - 1 &&
      !progress(0.2 + 0.6 * static_cast<double>(v) / static_cast<double>(voxels)))
    {
      return false;
    }
    if (!IsActive(this->Density[v]) && this->Pull(v, 1))
    {
      front.push_back(v);
    }
  }
  const int* n = this->Extent;
  for (int step = 2; step <= depth && !front.empty(); ++step)
  {
    next.clear();
    for (const vtkIdType u : front)
    {
      const int x = static_cast<int>(u % n[0]);
      const int y = static_cast<int>((u / n[0]) % n[1]);
      const int z = static_cast<int>(u / (static_cast<vtkIdType>(n[0]) * n[1]));
      ForEachNeighbor(n, x, y, z, false, [&](vtkIdType w) {
        if (this->Virtual[w] == 0 && !IsActive(this->Density[w]) && this->Pull(w, step))
        {
          next.push_back(w);
        }
        return false;
      });
    }
    std::swap(front, next);
    if (progress && !progress(0.8 + 0.2 * step / depth))
    {
      return false;
    }
  }
  return true;
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
