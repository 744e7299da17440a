// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Soak: one vtkErrorDiffusionSampler in a pipeline (vtkRTAnalyticSource, 32^3
// voxels) through 150 updates of random settings from a fixed seed, so that
// each run starts from the state the one before left (the sampler's run
// state, its recycled buffers, the worker thread, the executive's requests).
// Good runs draw their budget: the error diffusion methods within max(2,
// 0.05 %), white noise within 6 sqrt(N) + 2, Poisson disk and sample
// elimination within 3 % + 2, without an error, with a Density in [0, 1] per
// point and, with GenerateMask, a mask holding one 1 per point. Among them,
// runs aborted from a ProgressEvent observer at a random progress (no error,
// both outputs empty) and runs with bad settings (an empty custom
// ScalarRange, a missing input array, a nonexistent parameter file: an error,
// both outputs empty); the run after either is a good one. Under the asan
// stage (scripts/sanitize.sh) it also runs with leak detection.
#include "SamplerTestUtilities.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkPointData.h"
#include "vtkRTAnalyticSource.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <string>

using namespace bluenoise_test;

namespace
{
/// Aborts the filter at the first progress report at or past AbortAt (below
/// 1: the last report comes when the output is already complete).
class AbortObserver : public vtkCommand
{
public:
  static AbortObserver* New() { return new AbortObserver; }
  void Execute(vtkObject* caller, unsigned long, void* data) override
  {
    const double p = *static_cast<double*>(data);
    if (this->AbortAt > 0.0 && !this->Fired && p >= this->AbortAt && p < 1.0)
    {
      this->Fired = true;
      bluenoise_test::Abort(static_cast<vtkAlgorithm*>(caller));
    }
  }
  double AbortAt = -1.0;
  bool Fired = false;
};

const char* const MethodNames[] = { "error diffusion", "white noise", "relaxed error diffusion",
  "Poisson disk", "sample elimination", "energy relaxed error diffusion" };

enum Kind
{
  GOOD,
  ABORTED,
  BAD_RANGE,
  BAD_ARRAY,
  BAD_PARAMETER_FILE
};
const char* const KindNames[] = { "good", "aborted", "bad range", "bad array",
  "bad parameter file" };

/// How far a good run's count may be from its budget.
double Tolerance(int method, vtkIdType n)
{
  switch (method)
  {
    case vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION:
    case vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION:
    case vtkErrorDiffusionSampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION:
      return std::max(2.0, 0.0005 * n);
    case vtkErrorDiffusionSampler::METHOD_WHITE_NOISE:
      return 6.0 * std::sqrt(static_cast<double>(n)) + 2.0;
    default:
      return 0.03 * n + 2.0;
  }
}

/// The number of ones in the mask output, or -1 when it has no SampleMask.
vtkIdType MaskCount(vtkImageData* mask)
{
  vtkDataArray* values = mask->GetPointData()->GetArray("SampleMask");
  if (!values)
  {
    return -1;
  }
  vtkIdType ones = 0;
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    ones += values->GetTuple1(i) != 0.0 ? 1 : 0;
  }
  return ones;
}
}

int main()
{
  constexpr int Cycles = 150;
  constexpr int Size = 32;
  const auto start = std::chrono::steady_clock::now();

  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(0, Size - 1, 0, Size - 1, 0, Size - 1);
  const vtkIdType voxels = vtkIdType(Size) * Size * Size;
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputConnection(source->GetOutputPort());
  vtkNew<MessageObserver> messages;
  messages->Watch(sampler);
  messages->Watch(sampler->GetExecutive());
  vtkNew<AbortObserver> abort;
  sampler->AddObserver(vtkCommand::ProgressEvent, abort);

  std::mt19937 random(20250611);
  const auto uniform = [&random](int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(random);
  };
  const auto chance = [&random](double p) {
    return std::uniform_real_distribution<double>(0.0, 1.0)(random) < p;
  };

  int counts[5] = { 0, 0, 0, 0, 0 };    // runs per kind
  constexpr int Methods = vtkErrorDiffusionSampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION + 1;
  int methods[Methods] = {};            // good runs per method
  int abortsFired = 0;
  double worstError[Methods] = {}; // the largest |count - budget| / tolerance
  Kind previous = GOOD;
  for (int cycle = 0; cycle < Cycles; ++cycle)
  {
    // After an aborted or a bad run, always a good one.
    Kind kind = GOOD;
    if (previous == GOOD)
    {
      const int roll = uniform(0, 99);
      kind = roll < 64 ? GOOD
        : roll < 80    ? ABORTED
        : roll < 86    ? BAD_RANGE
        : roll < 92    ? BAD_ARRAY
                       : BAD_PARAMETER_FILE;
    }
    previous = kind;
    ++counts[kind];

    // Random good settings first.
    int method = uniform(vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION,
      vtkErrorDiffusionSampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION);
    if (kind == BAD_PARAMETER_FILE) // only the error diffusion methods read it
    {
      method = chance(0.5) ? vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION
                           : vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION;
    }
    const bool slow = method == vtkErrorDiffusionSampler::METHOD_POISSON_DISK ||
      method == vtkErrorDiffusionSampler::METHOD_SAMPLE_ELIMINATION;
    sampler->SetMethod(method);
    // The whole-volume methods cost far more per point: smaller budgets.
    const vtkIdType budget = chance(0.05) ? uniform(0, 3) : uniform(50, slow ? 1500 : 8000);
    sampler->SetNumberOfPoints(budget);
    sampler->SetUseNumberOfPoints(true);
    int mapping = chance(0.5) ? vtkErrorDiffusionSampler::DENSITY_IDENTITY
                              : vtkErrorDiffusionSampler::DENSITY_SCALAR_RANGE;
    sampler->SetUseCustomScalarRange(false);
    if (mapping == vtkErrorDiffusionSampler::DENSITY_SCALAR_RANGE && chance(0.3))
    {
      // A good custom range inside RTData's [37, 277], whose positive
      // densities can hold every budget drawn (at a lower end of 90 only 6538
      // voxels have one).
      sampler->SetUseCustomScalarRange(true);
      sampler->SetScalarRange(30.0 + uniform(0, 30), 200.0 + uniform(0, 80));
    }
    if (chance(0.5))
    {
      sampler->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "RTData");
    }
    else
    {
      sampler->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
    }
    const int sets[] = { vtkErrorDiffusionSampler::PARAMETERS_PAPER,
      vtkErrorDiffusionSampler::PARAMETERS_FIXED, vtkErrorDiffusionSampler::PARAMETERS_OPTIMIZED };
    sampler->SetParameterSet(sets[uniform(0, 2)]);
    sampler->SetParameterFile("");
    sampler->SetSeed(uniform(0, 1 << 30));
    sampler->SetJitter(chance(0.5));
    sampler->SetGenerateMask(chance(0.5));
    sampler->SetNumberOfSlabs(uniform(1, 3));
    sampler->SetUseWorkerThread(chance(0.5));
    abort->AbortAt = -1.0;
    abort->Fired = false;

    // Then what makes the run bad, or aborts it.
    switch (kind)
    {
      case ABORTED:
        abort->AbortAt = 0.02 + 0.9 * std::uniform_real_distribution<double>(0.0, 1.0)(random);
        break;
      case BAD_RANGE:
      {
        mapping = vtkErrorDiffusionSampler::DENSITY_SCALAR_RANGE;
        sampler->SetUseCustomScalarRange(true);
        const double lo = uniform(0, 300);
        sampler->SetScalarRange(lo, chance(0.5) ? lo : lo - uniform(1, 100));
        break;
      }
      case BAD_ARRAY:
        sampler->SetInputArrayToProcess(
          0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "NoSuchArray");
        break;
      case BAD_PARAMETER_FILE:
        sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_CUSTOM);
        sampler->SetParameterFile("/nonexistent/bluenoise-soak-parameters.txt");
        break;
      default:
        break;
    }
    sampler->SetDensityMapping(mapping);
    // A settings change may leave nothing to re-execute (the same settings
    // as the run before): always run.
    sampler->Modified();

    messages->Clear();
    sampler->Update();
    vtkPolyData* points = sampler->GetOutput();
    vtkImageData* mask = sampler->GetMaskOutput();
    const vtkIdType n = points->GetNumberOfPoints();
    const std::string what = "cycle " + Str(cycle) + " (" + KindNames[kind] + ", " +
      MethodNames[method] + ", budget " + Str(budget) + ", mapping " + Str(mapping) + ", slabs " +
      Str(sampler->GetNumberOfSlabs()) + ", worker thread " + Str(sampler->GetUseWorkerThread()) +
      ", mask " + Str(sampler->GetGenerateMask()) + ")";

    if (kind == GOOD || (kind == ABORTED && !abort->Fired))
    {
      ++methods[method];
      Check(messages->ErrorCount == 0, what + ": no error, got: " + messages->Errors);
      const double off = std::fabs(static_cast<double>(n - budget));
      const double tolerance = Tolerance(method, budget);
      worstError[method] = std::max(worstError[method], off / tolerance);
      Check(off <= tolerance,
        what + ": " + Str(n) + " points for " + Str(budget) + " (tolerance " + Str(tolerance) + ")");
      vtkDataArray* density = points->GetPointData()->GetArray("Density");
      bool densities = density && density->GetNumberOfTuples() == n;
      for (vtkIdType i = 0; densities && i < n; ++i)
      {
        const double g = density->GetTuple1(i);
        densities = g >= 0.0 && g <= 1.0;
      }
      Check(densities, what + ": a Density in [0, 1] per point");
      Check(points->GetNumberOfVerts() == n, what + ": one vertex per point");
      if (sampler->GetGenerateMask())
      {
        Check(mask->GetNumberOfPoints() == voxels && MaskCount(mask) == n,
          what + ": the mask has one 1 per point (" + Str(MaskCount(mask)) + " ones on " +
            Str(mask->GetNumberOfPoints()) + " voxels)");
      }
      else
      {
        Check(mask->GetNumberOfPoints() == 0, what + ": no mask without GenerateMask");
      }
    }
    else if (kind == ABORTED)
    {
      ++abortsFired;
      Check(messages->ErrorCount == 0, what + ": an abort is no error, got: " + messages->Errors);
      Check(n == 0 && mask->GetNumberOfPoints() == 0,
        what + ": aborted at " + Str(abort->AbortAt) + ", empty outputs (" + Str(n) +
          " points, " + Str(mask->GetNumberOfPoints()) + " mask voxels)");
    }
    else
    {
      Check(messages->ErrorCount > 0, what + ": an error is reported");
      const char* expected = kind == BAD_RANGE ? "ScalarRange"
        : kind == BAD_ARRAY                    ? "No density array"
                                               : "parameter file";
      Check(messages->ErrorContains(expected),
        what + ": the error names the problem ('" + expected + "'), got: " + messages->Errors);
      Check(n == 0 && mask->GetNumberOfPoints() == 0,
        what + ": empty outputs (" + Str(n) + " points, " + Str(mask->GetNumberOfPoints()) +
          " mask voxels)");
    }
    // The abort flag stays set until cleared.
    sampler->SetAbortExecute(0);
  }

  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "runs:";
  for (int k = 0; k < 5; ++k)
  {
    std::cout << " " << KindNames[k] << " " << counts[k] << ";";
  }
  std::cout << " aborts that fired " << abortsFired << "\ngood runs per method:";
  for (int m = 0; m < Methods; ++m)
  {
    std::cout << " " << MethodNames[m] << " " << methods[m] << " (worst |n - N| / tolerance "
              << worstError[m] << ");";
  }
  std::cout << "\n" << Cycles << " cycles in " << seconds << " s\n";
  Check(abortsFired >= 10, "aborts fired mid-run: " + Str(abortsFired));
  for (int m = 0; m < Methods; ++m)
  {
    Check(methods[m] >= 5, std::string("good runs of ") + MethodNames[m] + ": " + Str(methods[m]));
  }
  for (int k = BAD_RANGE; k <= BAD_PARAMETER_FILE; ++k)
  {
    Check(counts[k] >= 3, std::string("runs of kind ") + KindNames[k] + ": " + Str(counts[k]));
  }
  return Summary("TestErrorDiffusionSamplerSoak");
}
