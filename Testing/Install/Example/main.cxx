// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Uses the installed BlueNoise::FiltersBlueNoise: samples a small volume with a
// density ramp and measures the points with the spectrum. Returns non-zero
// when a result is wrong.
#include "vtkBlueNoiseSpectrum.h"
#include "vtkErrorDiffusionSampler.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTable.h>

#include <cmath>
#include <iostream>

namespace
{
int failures = 0;

void Check(bool ok, const char* what)
{
  std::cout << (ok ? "ok:   " : "FAIL: ") << what << std::endl;
  if (!ok)
  {
    ++failures;
  }
}
}

int main()
{
  const int n = 32;
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  image->SetSpacing(0.5, 0.5, 0.5);
  vtkNew<vtkFloatArray> density;
  density->SetName("density");
  density->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  double expected = 0.0;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const float g = 0.02f + 0.2f * static_cast<float>(i) / (n - 1);
        density->SetValue(i + n * (j + n * k), g);
        expected += g;
      }
    }
  }
  image->GetPointData()->SetScalars(density);

  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToIdentity();
  sampler->UseNumberOfPointsOff();
  sampler->SetSeed(3);
  sampler->Update();
  const vtkIdType count = sampler->GetOutput()->GetNumberOfPoints();
  std::cout << count << " points, expected " << expected << std::endl;
  Check(std::abs(count - expected) <= 2.0, "point count equal to the sum of densities");
  Check(sampler->GetOutput()->GetPointData()->GetArray("Density") != nullptr, "Density array");

  vtkNew<vtkBlueNoiseSpectrum> spectrum;
  spectrum->SetInputConnection(sampler->GetOutputPort());
  spectrum->Update();
  vtkTable* table = spectrum->GetOutput();
  Check(table->GetNumberOfRows() > 0 && table->GetColumnByName("RadialPower") != nullptr,
    "spectrum table with RadialPower");
  vtkDataArray* points = vtkDataArray::SafeDownCast(table->GetFieldData()->GetAbstractArray("NumberOfPoints"));
  Check(points != nullptr && points->GetTuple1(0) == static_cast<double>(count),
    "spectrum NumberOfPoints equals the sampler's count");
  vtkDataArray* ratio = vtkDataArray::SafeDownCast(table->GetFieldData()->GetAbstractArray("LowFrequencyRatio"));
  Check(ratio != nullptr && ratio->GetTuple1(0) > 0 && ratio->GetTuple1(0) < 1, "LowFrequencyRatio in (0, 1)");

  std::cout << (failures ? "FAILED" : "passed") << std::endl;
  return failures ? 1 : 0;
}
