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
  const vtkIdType voxels = static_cast<vtkIdType>(nx) * ny * nz;
  double sum = 0.0;
  for (vtkIdType v = 0; v < voxels; ++v)
  {
    sum += density[v] > 0.0f ? std::min(density[v], 1.0f) : 0.0f;
  }
  this->ExpectedCount = sum; // the peers' searches use it
  int margin = 0;
  if (this->ExtendFaces)
  {
    const double reach = this->GetMarginFactor() /
      std::cbrt(vtkVoxelMargin::SmallestFaceDensity(nx, ny, nz, density));
    margin = static_cast<int>(
      std::min(std::ceil(reach), static_cast<double>(std::max(nx, std::max(ny, nz)))));
  }
  this->Margin.Extend(nx, ny, nz, density, margin);
  if (!this->Run(error))
  {
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
