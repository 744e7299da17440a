// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Sampling speed against a baseline measured in the same run: a plain
// single-threaded loop of the same scan, written straight from the paper with
// no pipeline around it (PlainScan below). Cases: constant cubes of 256^3 and
// 512^3 at g = 8/255 and 127/255 (and 256^3 at 4, 16, 32 and 64/255, where the
// default method's relaxation works), uint8 and float input, the filter with its
// default settings but for the identity mapping (a constant cube has no
// scalar range): a point budget of g * voxels, the worker thread when more
// than one thread is allowed, the default method or the paper's; the kernel
// alone; the relaxation pass alone, on the kernel's samples; and the filter
// with another process busy on every core ("busy").
// Counters: voxels/s, and x_plain = the plain loop's time / this time (the
// plain loop timed, fastest of 3, right before the case and, for the filter,
// right after it too, under the same load).
// No thresholds.
#include "vtkBlueNoiseRelaxation.h"
#include "vtkErrorDiffusionKernel.h"
#include "vtkErrorDiffusionParameterTable.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

// With --benchmark_repetitions, the fastest run: on a shared virtual machine
// the other aggregates mostly measure the neighbors.
double Fastest(const std::vector<double>& v)
{
  return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}

// PCG32, as the paper's implementations use a plain generator.
struct Pcg32
{
  std::uint64_t State = 0x853c49e6748fea9bULL;
  float Uniform()
  {
    const std::uint64_t old = this->State;
    this->State = old * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto x = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto r = static_cast<std::uint32_t>(old >> 59u);
    return static_cast<float>(((x >> r) | (x << ((32u - r) & 31u))) >> 8) * (1.0f / 16777216.0f);
  }
};

// The scan straight from the paper: layers along z, the serpentine of each
// layer turned by 90 degrees per layer, the threshold 0.5 + s r m(g), the
// error to the six neighbors of Table 1 (renormalized over those inside the
// volume), the binary volume b as output. Densities g = clamp(scale * value).
template <typename T>
vtkIdType PlainScan(const T* values, int n, double scale, unsigned char* b)
{
  const auto table = vtkErrorDiffusionParameterTable::Paper();
  const size_t layer = static_cast<size_t>(n) * n;
  std::vector<float> current(layer, 0.0f), next(layer, 0.0f);
  Pcg32 random;
  vtkIdType count = 0;
  for (int z = 0; z < n; ++z)
  {
    const auto scan = vtkErrorDiffusionKernel::GetLayerScan(n, n, z);
    float lastG = -1.0f;
    vtkErrorDiffusionParameterTable::Parameters p;
    for (int q = 0; q < scan.NV; ++q)
    {
      int offsets[6][3];
      vtkErrorDiffusionKernel::GetTargetOffsets(scan, q, offsets);
      for (int u = 0; u < scan.NU; ++u)
      {
        const vtkIdType idx = scan.Start + q * scan.VStride +
          ((q & 1) ? (scan.NU - 1 - u) : u) * scan.UStride;
        const float g = static_cast<float>(
          std::min(1.0, std::max(0.0, scale * static_cast<double>(values[z * layer + idx]))));
        if (g != lastG)
        {
          p = table.Evaluate(g);
          lastG = g;
        }
        const float r = 0.5f * random.Uniform() * p.Modulation;
        const float threshold = g <= 0.5f ? 0.5f + r : 0.5f - r;
        const float value = g + current[idx];
        const unsigned char bit = value >= threshold ? 1 : 0;
        b[z * layer + idx] = bit;
        count += bit;
        const float e = value - bit;
        const int x = static_cast<int>(idx % n), y = static_cast<int>(idx / n);
        float sum = 0.0f;
        bool inside[6];
        for (int t = 0; t < 6; ++t)
        {
          const int X = x + offsets[t][0], Y = y + offsets[t][1], Z = z + offsets[t][2];
          inside[t] = X >= 0 && X < n && Y >= 0 && Y < n && Z < n;
          sum += inside[t] ? p.Weights[t] : 0.0f;
        }
        for (int t = 0; t < 6 && sum > 0.0f; ++t)
        {
          if (inside[t])
          {
            const size_t j = (x + offsets[t][0]) + static_cast<size_t>(n) * (y + offsets[t][1]);
            (offsets[t][2] ? next : current)[j] += e * p.Weights[t] / sum;
          }
        }
      }
    }
    std::swap(current, next);
    std::fill(next.begin(), next.end(), 0.0f);
  }
  return count;
}

// A constant cube of `value` in an array of type T.
template <typename ArrayT>
vtkSmartPointer<vtkImageData> Cube(int n, double value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, n);
  auto values = vtkSmartPointer<ArrayT>::New();
  values->SetName("values");
  values->SetNumberOfValues(static_cast<vtkIdType>(n) * n * n);
  values->Fill(value);
  image->GetPointData()->SetScalars(values);
  return image;
}

// The plain loop on the same cube, fastest of 3, in seconds.
template <typename T>
double PlainSeconds(vtkImageData* image, double g)
{
  const int n = image->GetDimensions()[0];
  const auto* values = static_cast<const T*>(image->GetPointData()->GetScalars()->GetVoidPointer(0));
  const double scale = g / static_cast<double>(values[0]);
  std::vector<unsigned char> b(static_cast<size_t>(n) * n * n);
  double best = 1e30;
  for (int i = 0; i < 3; ++i)
  {
    const auto start = Clock::now();
    benchmark::DoNotOptimize(PlainScan(values, n, scale, b.data()));
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
  }
  return best;
}

// Keeps every core busy while alive (the "busy machine" case).
class Load
{
public:
  explicit Load(bool on)
  {
    for (unsigned i = 0; on && i < std::max(1u, std::thread::hardware_concurrency()); ++i)
    {
      this->Threads.emplace_back([this] {
        volatile std::uint64_t x = 1;
        while (!this->Stop.load(std::memory_order_relaxed))
        {
          x = x * 6364136223846793005ULL + 1;
        }
      });
    }
  }
  ~Load()
  {
    this->Stop.store(true);
    for (auto& t : this->Threads)
    {
      t.join();
    }
  }

private:
  std::atomic<bool> Stop{ false };
  std::vector<std::thread> Threads;
};

// range(0): edge; range(1): g in 1/255; range(2): 1 for float input;
// range(3): 1 with every core busy; range(4): 0 forbids the worker thread;
// range(5): the Method (2, relaxed error diffusion, is the default; 0 the
// paper's error diffusion, with the paper's parameters).
void BM_Filter(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const double g = static_cast<double>(state.range(1)) / 255.0;
  const bool floats = state.range(2) != 0;
  auto image = floats ? Cube<vtkFloatArray>(n, g) : Cube<vtkUnsignedCharArray>(n, state.range(1));
  // Busy: the baseline runs under the same load, before and after the
  // filter (the faster of the two: the host's other guests come and go).
  Load load(state.range(3) != 0);
  const auto plainSeconds = [&] {
    return floats ? PlainSeconds<float>(image, g) : PlainSeconds<unsigned char>(image, g);
  };
  double plain = plainSeconds();
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToIdentity(); // a constant cube has no scalar range
  sampler->SetNumberOfPoints(static_cast<vtkIdType>(g * n * n * n));
  sampler->SetUseWorkerThread(state.range(4) != 0);
  sampler->SetMethod(static_cast<int>(state.range(5)));
  if (state.range(5) == vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION)
  {
    sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_PAPER);
  }
  // Once untimed: the first run of a process calibrates the charge curve of
  // the parameter table (cached for the process) and faults the output in.
  sampler->Update();
  double best = 1e30;
  for (auto _ : state)
  {
    sampler->Modified();
    const auto start = Clock::now();
    sampler->Update();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
    benchmark::DoNotOptimize(sampler->GetOutput()->GetNumberOfPoints());
  }
  plain = std::min(plain, plainSeconds());
  state.counters["voxels/s"] = benchmark::Counter(
    static_cast<double>(n) * n * n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["x_plain"] = plain / best;
  state.counters["points"] = static_cast<double>(sampler->GetOutput()->GetNumberOfPoints());
}

// The plain loop alone: the baseline of pvpython_update_pipeline.py.
void BM_Plain(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const double g = static_cast<double>(state.range(1)) / 255.0;
  const bool floats = state.range(2) != 0;
  auto image = floats ? Cube<vtkFloatArray>(n, g) : Cube<vtkUnsignedCharArray>(n, state.range(1));
  double best = 1e30;
  for (auto _ : state)
  {
    best = std::min(best,
      floats ? PlainSeconds<float>(image, g) : PlainSeconds<unsigned char>(image, g));
  }
  state.counters["seconds"] = best;
}

// The kernel alone on the same cubes, against the plain loop.
void BM_Kernel(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const float g = static_cast<float>(state.range(1)) / 255.0f;
  auto image = Cube<vtkFloatArray>(n, g);
  const double plain = PlainSeconds<float>(image, g);
  const size_t layer = static_cast<size_t>(n) * n;
  std::vector<float> density(layer, g);
  std::vector<unsigned char> mask(layer);
  double best = 1e30;
  for (auto _ : state)
  {
    const auto start = Clock::now();
    vtkErrorDiffusionKernel kernel;
    kernel.Begin(n, n);
    vtkIdType samples = 0;
    for (int z = 0; z < n; ++z)
    {
      samples += kernel.ProcessLayer(density.data(), z + 1 < n ? density.data() : nullptr, mask.data());
    }
    benchmark::DoNotOptimize(samples);
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
  }
  state.counters["voxels/s"] = benchmark::Counter(
    static_cast<double>(layer) * n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["x_plain"] = plain / best;
}

// The default method's relaxation pass alone, on the kernel's samples of a
// constant cube; x_kernel = the kernel's time on that cube / this time.
void BM_Relaxation(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const float g = static_cast<float>(state.range(1)) / 255.0f;
  const size_t layer = static_cast<size_t>(n) * n;
  std::vector<float> density(layer, g);
  std::vector<unsigned char> masks(layer * n);
  const auto scanStart = Clock::now();
  vtkErrorDiffusionKernel kernel;
  kernel.Begin(n, n);
  for (int z = 0; z < n; ++z)
  {
    kernel.ProcessLayer(density.data(), z + 1 < n ? density.data() : nullptr, &masks[z * layer]);
  }
  const double scan = std::chrono::duration<double>(Clock::now() - scanStart).count();
  double best = 1e30;
  vtkIdType moves = 0;
  for (auto _ : state)
  {
    const auto start = Clock::now();
    vtkBlueNoiseRelaxation relaxation;
    relaxation.Begin(n, n, 0, 1);
    vtkIdType samples = 0;
    for (int z = 0; z < n; ++z)
    {
      for (const auto& l : relaxation.Push(z, density.data(), &masks[z * layer]))
      {
        samples += l.Count;
      }
    }
    for (const auto& l : relaxation.Flush())
    {
      samples += l.Count;
    }
    benchmark::DoNotOptimize(samples);
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
    moves = relaxation.GetNumberOfMoves();
  }
  state.counters["moves"] = static_cast<double>(moves);
  state.counters["x_kernel"] = scan / best;
}
}

BENCHMARK(BM_Kernel)
  ->ArgNames({ "L", "g255" })
  ->ArgsProduct({ { 256, 512 }, { 8, 127 } })
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Relaxation)
  ->ArgNames({ "L", "g255" })
  ->ArgsProduct({ { 256 }, { 8, 32, 48 } })
  ->Args({ 512, 8 })
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Plain)
  ->ArgNames({ "L", "g255", "float" })
  ->ArgsProduct({ { 256, 512 }, { 8, 127 }, { 0, 1 } })
  ->Iterations(1)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Filter)
  ->ArgNames({ "L", "g255", "float", "busy", "thread", "method" })
  ->ArgsProduct({ { 256, 512 }, { 8, 127 }, { 0, 1 }, { 0 }, { 1 }, { 2, 0 } })
  ->ArgsProduct({ { 256 }, { 8 }, { 0 }, { 1 }, { 0, 1 }, { 2, 0 } })
  ->ArgsProduct({ { 256 }, { 4, 16, 32, 64 }, { 0 }, { 0 }, { 1 }, { 2, 0 } })
  ->UseRealTime() // two threads: CPU time of the caller alone would flatter
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
