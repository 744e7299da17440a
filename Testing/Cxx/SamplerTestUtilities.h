// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Running the sampler in tests.
#ifndef SamplerTestUtilities_h
#define SamplerTestUtilities_h

#include "BlueNoiseTestUtilities.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkVersionMacros.h"

#include <cstring>

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

// Asks a running algorithm to stop, as ParaView's abort button does.
inline void Abort(vtkAlgorithm* algorithm)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 20220831)
  algorithm->SetAbortExecuteAndUpdateTime();
#else
  algorithm->SetAbortExecute(1);
#endif
}

// The same points, bit for bit, in the same order.
inline bool SamePoints(vtkPolyData* a, vtkPolyData* b)
{
  const vtkIdType n = a->GetNumberOfPoints();
  if (n != b->GetNumberOfPoints())
  {
    return false;
  }
  auto* pa = a->GetPoints()->GetData();
  auto* pb = b->GetPoints()->GetData();
  return n == 0 ||
    std::memcmp(pa->GetVoidPointer(0), pb->GetVoidPointer(0),
      static_cast<size_t>(n) * 3 * pa->GetDataTypeSize()) == 0;
}
}

#endif
