// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkVoxelPointSetKernel.h"

#include <algorithm>
#include <cmath>

//------------------------------------------------------------------------------
vtkVoxelPointSetKernel::~vtkVoxelPointSetKernel() = default;

//------------------------------------------------------------------------------
vtkIdType vtkVoxelPointSetKernel::Sample(
  int nx, int ny, int nz, const float* density, unsigned char* mask, std::string* error)
{
  if (nx < 1 || ny < 1 || nz < 1 || !density || !mask)
  {
    if (error)
    {
      *error = "dimensions must be at least 1 and the density and mask must not be null";
    }
    return -1;
  }
  this->Aborted = false;
  this->LastProgress = 0.0;
  const vtkIdType voxels = static_cast<vtkIdType>(nx) * ny * nz;
  double sum = 0.0;
  for (vtkIdType v = 0; v < voxels; ++v)
  {
    sum += density[v] > 0.0f ? std::min(density[v], 1.0f) : 0.0f;
  }
  this->ExpectedCount = sum; // the peers' searches use it
  // The reach at the smallest densities of the faces and of the border of
  // the support (none where there is no active voxel).
  int margin = 0, depth = 0;
  if (this->ExtendSupport)
  {
    auto reach = [this](float g) {
      const double r = g < 1.0f ? std::ceil(this->GetMarginFactor() / std::cbrt(g)) : 0.0;
      return static_cast<int>(std::min(r, 65536.0));
    };
    margin = reach(vtkVoxelMargin::SmallestFaceDensity(nx, ny, nz, density));
    auto grown = [&](int m) {
      return static_cast<double>(nx + 2 * m) * (ny + 2 * m) * (nz + 2 * m);
    };
    while (margin > 0 && grown(margin) > MaximumGrowth * static_cast<double>(voxels))
    {
      --margin;
    }
    depth = std::min(
      reach(vtkVoxelMargin::SmallestBorderDensity(nx, ny, nz, density)), MaximumDepth);
    depth = std::max(depth, margin);
  }
  // The continuation costs a few passes over the volume: the first share of
  // the progress, the peer's run the rest.
  std::function<bool(double)> extending;
  if (this->Progress)
  {
    extending = [this](double f) { return this->Report(ExtendedShare * f); };
  }
  if (!this->Margin.Extend(nx, ny, nz, density, margin, depth, extending) ||
    !this->Report(ExtendedShare) || !this->Run(error))
  {
    if (this->Aborted && error)
    {
      *error = "aborted";
    }
    return -1;
  }
  vtkIdType count = 0;
  for (vtkIdType v = 0; v < voxels; ++v)
  {
    const float g = density[v];
    mask[v] = (g >= 1.0f || (g > 0.0f && this->IsSample(this->Margin.ToExtended(v)))) ? 1 : 0;
    count += mask[v];
  }
  return count;
}

//------------------------------------------------------------------------------
bool vtkVoxelPointSetKernel::ReportProgress(double fraction)
{
  return this->Report(ExtendedShare + (1.0 - ExtendedShare) * fraction);
}

//------------------------------------------------------------------------------
bool vtkVoxelPointSetKernel::Report(double fraction)
{
  if (!this->Progress)
  {
    return true;
  }
  // Reports only go forward, and 1 is left for the caller to say when it is done.
  fraction = std::min(fraction, std::nextafter(1.0, 0.0));
  if (fraction <= this->LastProgress)
  {
    return true;
  }
  this->LastProgress = fraction;
  if (!this->Progress(fraction))
  {
    this->Aborted = true;
  }
  return !this->Aborted;
}
