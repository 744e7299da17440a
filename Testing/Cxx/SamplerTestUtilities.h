// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Running the sampler in tests.
#ifndef SamplerTestUtilities_h
#define SamplerTestUtilities_h

#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseThreads.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkVersionMacros.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>

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

// Runs `job` on at most `threads` threads, the way a user limits them:
// VTK_SMP_MAX_THREADS, which the module reads at each execution for the
// threads it starts itself (Sequential backend). The other backends read the
// variable once, at their first use, so a scope sets their count too. With
// more than one thread asked for where the backend can still give more than
// one, the job must get more than one, or a comparison of thread counts
// compares nothing. (Some cannot: VTK 9.6's TBB backend stays on one thread
// in a process once a scope of one ended, so tests run their one-thread cases
// last; where a process still asks for more after that, it is said, not
// failed. The backend is asked at each call for that reason.)
inline void WithThreads(int threads, const std::function<void()>& job)
{
  const auto scope = [](int n, const std::function<void()>& inside) {
    vtkSMPTools::LocalScope(
      vtkSMPTools::Config(n, vtkSMPTools::GetBackend(), vtkSMPTools::GetNestedParallelism()),
      inside);
  };
  int most = 1;
  scope(static_cast<int>(std::thread::hardware_concurrency()),
    [&] { most = vtkSMPTools::GetEstimatedNumberOfThreads(); });
  setenv("VTK_SMP_MAX_THREADS", std::to_string(threads).c_str(), 1);
  scope(threads, [&] {
    const int available = vtkBlueNoiseThreads::Available();
    const std::string what = std::string("WithThreads(") + std::to_string(threads) +
      "): the module may use " + std::to_string(available) + " thread(s) with the " +
      vtkSMPTools::GetBackend() + " backend";
    if (threads > 1 && !vtkBlueNoiseThreads::SequentialBackend() && most < 2)
    {
      std::cout << what << ", which gives no more in this process\n";
    }
    else
    {
      const bool several = threads > 1 && std::thread::hardware_concurrency() > 1;
      Check(several ? available > 1 : threads > 1 || available == 1, what);
    }
    job();
  });
  unsetenv("VTK_SMP_MAX_THREADS");
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
