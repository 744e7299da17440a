// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Progress is reported layer by layer, from 0 to 1, and an abort requested from
// a progress observer stops the sampling with an empty output; with the scan
// on a worker thread (the default) and without it. The whole-volume methods
// (Poisson disk, sample elimination) report from inside their kernels: many
// distinct values on the way, an abort stops them at the report that asked
// for it, and the next Update samples again.
#include "SamplerTestUtilities.h"
#include "vtkCommand.h"

#include <algorithm>
#include <iostream>
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
      bluenoise_test::Abort(static_cast<vtkAlgorithm*>(caller));
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
  for (const int method : { static_cast<int>(vtkErrorDiffusionSampler::METHOD_POISSON_DISK),
         static_cast<int>(vtkErrorDiffusionSampler::METHOD_SAMPLE_ELIMINATION) })
  {
    const std::string name = method == vtkErrorDiffusionSampler::METHOD_POISSON_DISK
      ? " (Poisson disk)"
      : " (sample elimination)";
    vtkNew<vtkErrorDiffusionSampler> sampler;
    vtkNew<ProgressObserver> progress;
    sampler->AddObserver(vtkCommand::ProgressEvent, progress);
    sampler->SetInputData(image);
    sampler->SetDensityMappingToIdentity();
    sampler->UseNumberOfPointsOff();
    sampler->SetMethod(method);
    sampler->Update();
    const auto& v = progress->Values;
    bool increasing = true;
    std::vector<double> inside; // the values strictly between 0 and 1
    for (size_t i = 0; i < v.size(); ++i)
    {
      // The executive reports 0 and 1 too, around the filter's own reports.
      increasing = increasing &&
        (i == 0 || v[i] > v[i - 1] || (v[i] == v[i - 1] && (v[i] == 0.0 || v[i] == 1.0)));
      if (v[i] > 0.0 && v[i] < 1.0)
      {
        inside.push_back(v[i]);
      }
    }
    std::cout << "progress" << name << ": " << v.size() << " reports, " << inside.size()
              << " in (0, 1)\n";
    Check(increasing && !v.empty() && v.front() == 0.0 && v.back() == 1.0,
      "progress strictly increasing from 0 to 1" + name);
    Check(inside.size() >= 6,
      "the kernel reports on the way: " + Str(inside.size()) + " values in (0, 1)" + name);
    const vtkIdType points = sampler->GetOutput()->GetNumberOfPoints();
    Check(points > 0, "samples without abort" + name);

    // Abort at the first report past 0.3: nothing is reported after it (the
    // executive's closing 1.0 aside), and the output is empty.
    progress->Values.clear();
    progress->AbortAt = 0.3;
    sampler->Modified();
    sampler->Update();
    auto first = std::find_if(v.begin(), v.end(), [](double p) { return p >= 0.3; });
    Check(first != v.end() && *first < 1.0, "a report between 0.3 and 1" + name);
    Check(first == v.end() ||
        std::all_of(first + 1, v.end(), [](double p) { return p == 1.0; }),
      "sampling stops at the report that asked for the abort" + name);
    Check(sampler->GetOutput()->GetNumberOfPoints() == 0, "aborted run has an empty output" + name);

    // The next update, without the abort, samples the same points again.
    progress->AbortAt = -1.0;
    sampler->SetAbortExecute(0);
    sampler->Modified();
    sampler->Update();
    Check(sampler->GetOutput()->GetNumberOfPoints() == points,
      "the update after the abort samples again (" +
        Str(sampler->GetOutput()->GetNumberOfPoints()) + " points for " + Str(points) + ")" + name);
  }
  return Summary("TestErrorDiffusionSamplerProgress");
}
