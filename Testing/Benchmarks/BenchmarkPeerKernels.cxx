// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Sampling speed of the point-set peers (vtkPoissonDiskKernel,
// vtkWeightedSampleEliminationKernel) next to the error-diffusion kernel, on
// constant cubes of 64^3 and 128^3 at g = 8/255 and 32/255. Prints voxels/s
// and samples/s (counters), and for the peers "vs_ED", how many times longer
// they take than the error-diffusion kernel on the same cube in the same run.
// Wall-clock times; no thresholds.
#include "vtkErrorDiffusionKernel.h"
#include "vtkPoissonDiskKernel.h"
#include "vtkWeightedSampleEliminationKernel.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <utility>
#include <vector>

namespace
{
// With --benchmark_repetitions, the fastest run: on a shared virtual machine
// the other aggregates mostly measure the neighbors.
double Fastest(const std::vector<double>& v)
{
  return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}

// Seconds per run of the error-diffusion kernel for each (size, level), as
// measured by BM_ErrorDiffusion earlier in the same run (it is registered first).
std::map<std::pair<int, int>, double>& BaselineSeconds()
{
  static std::map<std::pair<int, int>, double> seconds;
  return seconds;
}

void SetCounters(benchmark::State& state, double voxels, double samples, double seconds)
{
  state.counters["voxels/s"] =
    benchmark::Counter(voxels, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["samples/s"] =
    benchmark::Counter(samples, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["samples"] = samples;
  const auto key =
    std::make_pair(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const auto found = BaselineSeconds().find(key);
  if (seconds > 0.0 && found != BaselineSeconds().end() && found->second > 0.0 &&
    state.iterations() > 0)
  {
    state.counters["vs_ED"] = seconds / static_cast<double>(state.iterations()) / found->second;
  }
}

template <typename Run>
void Measure(benchmark::State& state, Run&& run, bool baseline)
{
  const int L = static_cast<int>(state.range(0));
  const float g = static_cast<float>(state.range(1)) / 255.0f;
  const std::vector<float> density(static_cast<size_t>(L) * L * L, g);
  std::vector<unsigned char> mask(density.size());
  vtkIdType samples = 0;
  double seconds = 0.0;
  for (auto _ : state)
  {
    const auto start = std::chrono::steady_clock::now();
    samples = run(L, density, mask);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    benchmark::DoNotOptimize(samples);
  }
  if (baseline && state.iterations() > 0)
  {
    const auto key = std::make_pair(L, static_cast<int>(state.range(1)));
    const double perRun = seconds / static_cast<double>(state.iterations());
    auto& best = BaselineSeconds()[key];
    best = best > 0.0 ? std::min(best, perRun) : perRun;
  }
  SetCounters(state, static_cast<double>(density.size()), static_cast<double>(samples),
    baseline ? 0.0 : seconds);
}

void BM_ErrorDiffusion(benchmark::State& state)
{
  Measure(
    state,
    [](int L, const std::vector<float>& density, std::vector<unsigned char>& mask) {
      vtkErrorDiffusionKernel kernel;
      kernel.Begin(L, L, L);
      const size_t layer = static_cast<size_t>(L) * L;
      vtkIdType samples = 0;
      for (int z = 0; z < L; ++z)
      {
        const size_t next = static_cast<size_t>(std::min(z + 1, L - 1)) * layer;
        samples += kernel.ProcessLayer(
          density.data() + z * layer, density.data() + next, mask.data() + z * layer);
      }
      return samples;
    },
    true);
}

// The cubes and levels, the same for every kernel.
void Cases(benchmark::internal::Benchmark* b)
{
  b->ArgNames({ "L", "g255" })
    ->ArgsProduct({ { 64, 128 }, { 8, 32 } })
    ->UseRealTime()
    ->ComputeStatistics("min", Fastest)
    ->Unit(benchmark::kMillisecond);
}

template <typename Kernel>
void BM_Peer(benchmark::State& state)
{
  Measure(
    state,
    [](int L, const std::vector<float>& density, std::vector<unsigned char>& mask) {
      Kernel kernel;
      return kernel.Sample(L, L, L, density.data(), mask.data());
    },
    false);
}
}

BENCHMARK(BM_ErrorDiffusion)->Apply(Cases);
BENCHMARK_TEMPLATE(BM_Peer, vtkPoissonDiskKernel)->Apply(Cases);
BENCHMARK_TEMPLATE(BM_Peer, vtkWeightedSampleEliminationKernel)->Apply(Cases);
BENCHMARK_MAIN();
