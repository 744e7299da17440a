// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Running the sampler in tests.
#ifndef SamplerTestUtilities_h
#define SamplerTestUtilities_h

#include "BlueNoiseTestUtilities.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

namespace bluenoise_test
{
// Samples `image`, its values taken as densities (identity mapping, no point
// budget), with the settings changed by `configure`.
inline vtkSmartPointer<vtkPolyData> Sample(vtkImageData* image,
  const std::function<void(vtkErrorDiffusionSampler*)>& configure = nullptr)
{
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToIdentity();
  sampler->UseNumberOfPointsOff();
  if (configure)
  {
    configure(sampler);
  }
  sampler->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(sampler->GetOutput());
  return out;
}
}

#endif
