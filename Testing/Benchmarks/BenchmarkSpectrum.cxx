// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Time of the blue-noise spectrum metric for one realisation: a random mask at
// g = 0.05 on L^3 grids. "Kernel" is the reusable path (buffers and plan kept,
// as the optimiser uses it); "Transform" and "Compute" split it into the FFT
// with the power accumulation, and the one pass of shell statistics.
#include "vtkBlueNoiseSpectrumKernel.h"

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

namespace
{
std::vector<unsigned char> RandomMask(int n)
{
  std::mt19937 rng(12345);
  std::bernoulli_distribution draw(0.05);
  std::vector<unsigned char> mask(static_cast<std::size_t>(n) * n * n);
  for (auto& m : mask)
  {
    m = draw(rng) ? 1 : 0;
  }
  return mask;
}

void SetVoxelCounters(benchmark::State& state, int n)
{
  state.counters["voxels/s"] = benchmark::Counter(
    static_cast<double>(n) * n * n, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_SpectrumKernel(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const std::vector<unsigned char> mask = RandomMask(n);
  vtkBlueNoiseSpectrumKernel kernel;
  kernel.SetDimensions(n, n, n);
  vtkBlueNoiseSpectrumKernel::Result result;
  for (auto _ : state)
  {
    kernel.Reset();
    kernel.AddRealisation(mask.data());
    kernel.Compute(result);
    benchmark::DoNotOptimize(result.TargetValue);
  }
  SetVoxelCounters(state, n);
}

void BM_SpectrumTransform(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const std::vector<unsigned char> mask = RandomMask(n);
  vtkBlueNoiseSpectrumKernel kernel;
  kernel.SetDimensions(n, n, n);
  for (auto _ : state)
  {
    kernel.Reset();
    kernel.AddRealisation(mask.data());
  }
  SetVoxelCounters(state, n);
}

void BM_SpectrumCompute(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const std::vector<unsigned char> mask = RandomMask(n);
  vtkBlueNoiseSpectrumKernel kernel;
  kernel.SetDimensions(n, n, n);
  kernel.AddRealisation(mask.data());
  vtkBlueNoiseSpectrumKernel::Result result;
  for (auto _ : state)
  {
    kernel.Compute(result);
    benchmark::DoNotOptimize(result.TargetValue);
  }
  SetVoxelCounters(state, n);
}

void BM_SpectrumEvaluate(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const std::vector<unsigned char> mask = RandomMask(n);
  const int dims[3] = { n, n, n };
  vtkBlueNoiseSpectrumKernel::Result result;
  for (auto _ : state)
  {
    vtkBlueNoiseSpectrumKernel::Evaluate(mask.data(), dims, 0.02, result);
    benchmark::DoNotOptimize(result.TargetValue);
  }
  SetVoxelCounters(state, n);
}
}

BENCHMARK(BM_SpectrumKernel)
  ->Arg(64)
  ->Arg(128)
  ->Arg(256)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_SpectrumTransform)
  ->Arg(64)
  ->Arg(128)
  ->Arg(256)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_SpectrumCompute)
  ->Arg(64)
  ->Arg(128)
  ->Arg(256)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
BENCHMARK(BM_SpectrumEvaluate)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
