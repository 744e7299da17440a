// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The closing correction and the mask: a scan that ends on negative error
// takes its last points back, and their voxels must leave the mask too. Those
// voxels once came back from the points' coordinates, which single-precision
// output far from the origin rounds to another voxel: one outside the sampled
// extent was written out of bounds (a fuzzer finding, then guarded), one
// inside was cleared instead of the point's own, which stayed set. The scan
// does not depend on the geometry, so each run must give the same mask and
// the same number of points at origin (1, 1, 1) 10^8 in single precision as at
// origin 0 in double precision.
#include "SamplerTestUtilities.h"

#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

using namespace bluenoise_test;

namespace
{
struct Run
{
  vtkIdType Points = 0;
  std::vector<unsigned char> Mask;
};

Run SampleWithMask(vtkImageData* image, int method, int seed, int precision)
{
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToIdentity();
  sampler->UseNumberOfPointsOff();
  sampler->SetMethod(method);
  sampler->SetSeed(seed);
  sampler->SetOutputPointsPrecision(precision);
  sampler->GenerateMaskOn();
  sampler->Update();
  Run run;
  run.Points = sampler->GetOutput()->GetNumberOfPoints();
  auto* mask = vtkUnsignedCharArray::SafeDownCast(
    sampler->GetMaskOutput()->GetPointData()->GetArray("SampleMask"));
  if (mask)
  {
    run.Mask.assign(mask->GetPointer(0), mask->GetPointer(0) + mask->GetNumberOfValues());
  }
  return run;
}
}

int main()
{
  // A float in [2^26, 2^27) holds multiples of 8 only: voxel centers at 10^8
  // + 5 to 9 round to 10^8 + 8, so the last of 8 layers to a ninth, outside
  // the sampled extent, and x and y to other voxels.
  // Low densities: several of these scans end on negative error, which takes
  // points back from the last layers with points.
  auto image = MakeVolume(10, 9, 8,
    [](int i, int j, int k) { return 0.005f + 0.001f * static_cast<float>((i + 2 * j + 3 * k) % 7); });
  int runs = 0;
  for (int method : { vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION,
         vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION })
  {
    for (int seed = 0; seed < 10; ++seed)
    {
      image->SetOrigin(0.0, 0.0, 0.0);
      const Run reference = SampleWithMask(image, method, seed, vtkAlgorithm::DOUBLE_PRECISION);
      image->SetOrigin(1.0e8, 1.0e8, 1.0e8);
      const Run far = SampleWithMask(image, method, seed, vtkAlgorithm::SINGLE_PRECISION);
      const std::string what = "method " + Str(method) + ", seed " + Str(seed);
      const auto ones = std::count(reference.Mask.begin(), reference.Mask.end(), 1);
      Check(ones == reference.Points, what + ": the reference mask has " + Str(ones) +
          " voxels set for " + Str(reference.Points) + " points");
      Check(far.Points == reference.Points, what + ": the far-off run has " + Str(far.Points) +
          " points, the reference " + Str(reference.Points));
      Check(far.Mask == reference.Mask, what + ": the far-off run's mask differs");
      ++runs;
    }
  }
  std::cout << runs << " runs\n";
  return Summary("TestErrorDiffusionSamplerMaskCorrection");
}
