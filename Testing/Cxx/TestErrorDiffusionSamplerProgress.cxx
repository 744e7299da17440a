// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Progress is reported layer by layer, from 0 to 1, and an abort requested from
// a progress observer stops the sampling with an empty output; with the scan
// on a worker thread (the default) and without it.
#include "SamplerTestUtilities.h"
#include "vtkCommand.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <vector>

using namespace bluenoise_test;

namespace
{
class ProgressObserver : public vtkCommand
{
public:
  static ProgressObserver* New() { return new ProgressObserver; }
  void Execute(vtkObject* caller, unsigned long, void* data) override
  {
    const double p = *static_cast<double*>(data);
    this->Values.push_back(p);
    if (this->AbortAt >= 0.0 && p >= this->AbortAt)
    {
      auto* algorithm = static_cast<vtkAlgorithm*>(caller);
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 20220831)
      algorithm->SetAbortExecuteAndUpdateTime();
#else
      algorithm->SetAbortExecute(1);
#endif
    }
  }
  std::vector<double> Values;
  double AbortAt = -1.0;
};
}

int main()
{
  auto image = MakeConstantVolume(64, 0.1f);
  for (const bool threaded : { true, false })
  {
  const std::string mode = threaded ? " (worker thread)" : " (one thread)";
  {
    vtkNew<vtkErrorDiffusionSampler> sampler;
    vtkNew<ProgressObserver> progress;
    sampler->AddObserver(vtkCommand::ProgressEvent, progress);
    sampler->SetInputData(image);
    sampler->SetDensityMappingToIdentity();
    sampler->SetUseWorkerThread(threaded);
    sampler->Update();
    const auto& v = progress->Values;
    bool increasing = true;
    for (size_t i = 1; i < v.size(); ++i)
    {
      increasing = increasing && v[i] >= v[i - 1];
    }
    Check(v.size() >= 32, "progress reported per layer: " + Str(v.size()) + " events" + mode);
    Check(increasing && !v.empty() && v.front() == 0.0 && v.back() == 1.0,
      "progress goes from 0 to 1" + mode);
    Check(sampler->GetOutput()->GetNumberOfPoints() > 0, "samples without abort" + mode);
  }
  {
    vtkNew<vtkErrorDiffusionSampler> sampler;
    vtkNew<ProgressObserver> progress;
    progress->AbortAt = 0.3;
    sampler->AddObserver(vtkCommand::ProgressEvent, progress);
    sampler->SetInputData(image);
    sampler->SetDensityMappingToIdentity();
    sampler->SetUseWorkerThread(threaded);
    sampler->Update();
    // The executive may still report 1.0 when the request ends; the filter's
    // own layer-by-layer reports must stop right after the abort.
    double lastLayer = 0.0;
    for (double p : progress->Values)
    {
      lastLayer = p < 1.0 ? std::max(lastLayer, p) : lastLayer;
    }
    Check(lastLayer >= 0.3 && lastLayer < 0.35,
      "sampling stops right after the abort (last layer progress " + Str(lastLayer) + ")" + mode);
    Check(sampler->GetOutput()->GetNumberOfPoints() == 0, "aborted run has an empty output" + mode);
  }
  }
  return Summary("TestErrorDiffusionSamplerProgress");
}
