// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// A real volume: the MRI brain ch2bet.nii.gz of Debian's mricron-data, read
// with vtkNIFTIImageReader and normalized by its range. Points fall inside the
// brain (non-zero voxels), and brighter tissue gets more points per voxel.
#include "MriTestUtilities.h"
#include "SamplerTestUtilities.h"

#include <vector>

using namespace bluenoise_test;

int main(int argc, char* argv[])
{
  const auto image = ReadMri(argc, argv);
  if (!image)
  {
    return SkipReturnCode;
  }
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToScalarRange();
  sampler->UseNumberOfPointsOff();
  sampler->SetDensityScale(0.5);
  sampler->GenerateMaskOn();
  sampler->Update();
  vtkDataArray* intensity = image->GetPointData()->GetScalars();
  vtkDataArray* mask = sampler->GetMaskOutput()->GetPointData()->GetScalars();
  const vtkIdType n = sampler->GetOutput()->GetNumberOfPoints();
  double range[2];
  intensity->GetRange(range);
  std::cout << "volume " << image->GetDimensions()[0] << "x" << image->GetDimensions()[1] << "x"
            << image->GetDimensions()[2] << ", range " << range[0] << ".." << range[1] << ", "
            << n << " points" << std::endl;
  Check(n > 10000, "enough points: " + Str(n));

  // Inside the brain mask, and the count per intensity quartile rising.
  const int bins = 4;
  std::vector<double> samples(bins, 0.0), voxels(bins, 0.0);
  vtkIdType outside = 0;
  double expected = 0.0;
  for (vtkIdType i = 0; i < intensity->GetNumberOfTuples(); ++i)
  {
    const double v = intensity->GetComponent(i, 0);
    const bool sampled = mask->GetComponent(i, 0) != 0.0;
    const double g = 0.5 * (v - range[0]) / (range[1] - range[0]);
    expected += g;
    if (v <= range[0])
    {
      outside += sampled;
      continue;
    }
    const int b = std::min(bins - 1, static_cast<int>(bins * (v - range[0]) / (range[1] - range[0])));
    samples[b] += sampled;
    voxels[b] += 1;
  }
  Check(outside == 0, Str(outside) + " points outside the brain (zero intensity)");
  Check(std::abs(n - expected) <= std::max(2.0, 5e-4 * expected),
    "count " + Str(n) + " equal to the expected " + Str(expected));
  double previous = -1.0;
  for (int b = 0; b < bins; ++b)
  {
    if (voxels[b] < 100)
    {
      continue;
    }
    const double rate = samples[b] / voxels[b];
    std::cout << "intensity quartile " << b << ": " << rate << " points per voxel" << std::endl;
    Check(rate > previous, "more points per voxel where the intensity is higher (quartile " +
        Str(b) + ")");
    previous = rate;
  }
  return Summary("TestErrorDiffusionSamplerBrain");
}
