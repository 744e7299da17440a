// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Sampling speed: the kernel alone and the whole VTK filter, on constant
// cubes of 128^3 and 256^3 at g = 8/255 and 127/255, and the filter on a
// real volume (the MRI brain ch2bet of Debian's mricron-data, 181 x 217 x
// 181, density from the scalar range, about 1e5 and 1e6 points). Prints
// voxels/s and samples/s (counters), no thresholds.
#include "vtkErrorDiffusionKernel.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include "vtksys/SystemTools.hxx"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

namespace
{
// With --benchmark_repetitions, the fastest run: on a shared virtual machine
// the other aggregates mostly measure the neighbours.
double Fastest(const std::vector<double>& v)
{
  return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}

void SetCounters(benchmark::State& state, double voxels, double samples)
{
  state.counters["voxels/s"] =
    benchmark::Counter(voxels, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["samples/s"] =
    benchmark::Counter(samples, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["samples"] = samples;
}

void BM_Kernel(benchmark::State& state)
{
  const int L = static_cast<int>(state.range(0));
  const float g = static_cast<float>(state.range(1)) / 255.0f;
  const size_t layer = static_cast<size_t>(L) * L;
  std::vector<float> density(layer, g);
  std::vector<unsigned char> mask(layer);
  vtkIdType samples = 0;
  for (auto _ : state)
  {
    vtkErrorDiffusionKernel kernel;
    kernel.Begin(L, L);
    samples = 0;
    for (int z = 0; z < L; ++z)
    {
      samples += kernel.ProcessLayer(density.data(), z + 1 < L ? density.data() : nullptr, mask.data());
    }
    benchmark::DoNotOptimize(samples);
  }
  SetCounters(state, static_cast<double>(layer) * L, static_cast<double>(samples));
}

// The whole filter; range(2) = 1 runs the scan on a worker thread.
void BM_Filter(benchmark::State& state)
{
  const int L = static_cast<int>(state.range(0));
  const float g = static_cast<float>(state.range(1)) / 255.0f;
  vtkNew<vtkImageData> image;
  image->SetDimensions(L, L, L);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfValues(static_cast<vtkIdType>(L) * L * L);
  values->Fill(g);
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToIdentity();
  sampler->UseNumberOfPointsOff();
  sampler->SetUseWorkerThread(state.range(2) != 0);
  vtkIdType samples = 0;
  for (auto _ : state)
  {
    sampler->Modified();
    sampler->Update();
    samples = sampler->GetOutput()->GetNumberOfPoints();
  }
  SetCounters(state, static_cast<double>(L) * L * L, static_cast<double>(samples));
}

// range(0): DensityScale in 1/1000 (50: about 1e5 points, 500: about 1e6).
void BM_FilterBrain(benchmark::State& state)
{
  const char* path = "/usr/share/mricron/templates/ch2bet.nii.gz";
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    state.SkipWithError("ch2bet.nii.gz not found (install Debian's mricron-data)");
    return;
  }
  vtkNew<vtkNIFTIImageReader> reader;
  reader->SetFileName(path);
  reader->Update();
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(reader->GetOutput());
  sampler->SetDensityMappingToScalarRange();
  sampler->UseNumberOfPointsOff();
  sampler->SetDensityScale(static_cast<double>(state.range(0)) / 1000.0);
  vtkIdType samples = 0;
  for (auto _ : state)
  {
    sampler->Modified();
    sampler->Update();
    samples = sampler->GetOutput()->GetNumberOfPoints();
  }
  const int* d = reader->GetOutput()->GetDimensions();
  SetCounters(state, static_cast<double>(d[0]) * d[1] * d[2], static_cast<double>(samples));
}
}

BENCHMARK(BM_Kernel)
  ->Args({ 128, 8 })
  ->Args({ 128, 127 })
  ->Args({ 256, 8 })
  ->Args({ 256, 127 })
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Filter)
  ->ArgNames({ "L", "g255", "thread" })
  ->ArgsProduct({ { 128, 256 }, { 8, 127 }, { 0, 1 } })
  ->UseRealTime() // two threads: CPU time of the caller alone would flatter
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FilterBrain)
  ->ArgName("scale_milli")
  ->Arg(50)
  ->Arg(500)
  ->UseRealTime()
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
