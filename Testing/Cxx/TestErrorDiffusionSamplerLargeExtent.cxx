// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// More than 2^31 voxels (the voxel count overflows 32-bit integers): the
// sampler works with vtkIdType throughout, and the last layers are sampled.
#include "SamplerTestUtilities.h"
#include "vtkUnsignedCharArray.h"

#include <limits>

using namespace bluenoise_test;

int main()
{
  const int nx = 2048, ny = 1024, nz = 1025; // 2^31 + 2^21 voxels
  const vtkIdType voxels = static_cast<vtkIdType>(nx) * ny * nz;
  Check(voxels > std::numeric_limits<int>::max(), "the extent overflows 32 bits");
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  auto values = vtkSmartPointer<vtkUnsignedCharArray>::New();
  values->SetName("values");
  values->SetNumberOfValues(voxels);
  // Zero except the first and last 8 layers: g = 0.01 there.
  std::fill(values->GetPointer(0), values->GetPointer(0) + voxels, 0);
  const vtkIdType layer = static_cast<vtkIdType>(nx) * ny;
  std::fill(values->GetPointer(0), values->GetPointer(0) + 8 * layer, 1);
  std::fill(values->GetPointer(voxels - 8 * layer), values->GetPointer(0) + voxels, 1);
  image->GetPointData()->SetScalars(values);

  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToIdentity();
  sampler->UseNumberOfPointsOff();
  sampler->SetDensityScale(0.01);
  sampler->Update();
  vtkPolyData* out = sampler->GetOutput();
  const double expected = 0.01 * 16 * layer;
  const vtkIdType n = out->GetNumberOfPoints();
  std::cout << n << " points, expected " << expected << std::endl;
  // No error is lost, whatever the size of the volume.
  Check(std::abs(n - expected) <= std::max(2.0, 5e-4 * expected), "count over > 2^31 voxels");
  vtkIdType last = 0;
  for (vtkIdType p = 0; p < n; ++p)
  {
    last += out->GetPoint(p)[2] >= nz - 8 ? 1 : 0;
  }
  Check(std::abs(last - expected / 2) < 0.05 * expected / 2,
    "the last layers, past 2^31 voxels, hold their share: " + Str(last));
  return Summary("TestErrorDiffusionSamplerLargeExtent");
}
