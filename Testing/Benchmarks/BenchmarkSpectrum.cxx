// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Time of the blue-noise spectrum metric for one realization: a random mask at
// g = 0.05 on L^3 grids, on 1 thread and on every core (vtkSMPTools' STDThread
// backend, whatever the default backend is).
//   Fresh      a new kernel in every run: buffers allocated, committed and
//              released (plans are cached for the process)
//   Reused     Reset + AddRealization + Compute on a kernel kept between runs
//   Transform  AddRealization alone (FFT and power), Compute the shell pass alone
//   Filter     vtkBlueNoiseSpectrum on the mask's points (sampler field data),
//              without and with the spectrum image
//   FFTW3D     FFTW's one-call 3D real-to-complex plan (FFTW_ESTIMATE) with as
//              many FFTW threads, the baseline the slab and column transform
//              replaces
// After the table, ratios measured in the same run: each stage on 1 thread
// against N threads, and the FFTW 3D plan against Transform.
#include "vtkBlueNoiseSpectrum.h"
#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <benchmark/benchmark.h>
#ifdef BLUENOISE_HAVE_FFTW3_THREADS
#include <fftw3.h>
#endif

#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace
{
const std::vector<unsigned char>& RandomMask(int n)
{
  static std::map<int, std::vector<unsigned char>> masks;
  auto& mask = masks[n];
  if (mask.empty())
  {
    std::mt19937 rng(12345);
    std::bernoulli_distribution draw(0.05);
    mask.resize(static_cast<std::size_t>(n) * n * n);
    for (auto& m : mask)
    {
      m = draw(rng) ? 1 : 0;
    }
  }
  return mask;
}

// The mask's set voxels as points at unit spacing, with the sampler's grid.
vtkPolyData* MaskPoints(int n)
{
  static std::map<int, vtkSmartPointer<vtkPolyData>> sets;
  auto& data = sets[n];
  if (!data)
  {
    const std::vector<unsigned char>& mask = RandomMask(n);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    std::size_t v = 0;
    for (int k = 0; k < n; ++k)
    {
      for (int j = 0; j < n; ++j)
      {
        for (int i = 0; i < n; ++i, ++v)
        {
          if (mask[v])
          {
            points->InsertNextPoint(i, j, k);
          }
        }
      }
    }
    data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(points);
    const auto add = [&](vtkDataArray* array, const char* name, std::vector<double> values)
    {
      array->SetName(name);
      array->SetNumberOfComponents(static_cast<int>(values.size()));
      array->SetNumberOfTuples(1);
      for (std::size_t c = 0; c < values.size(); ++c)
      {
        array->SetComponent(0, static_cast<int>(c), values[c]);
      }
      data->GetFieldData()->AddArray(array);
      array->Delete();
    };
    const double last = n - 1;
    add(vtkDoubleArray::New(), "SamplingGridOrigin", { 0, 0, 0 });
    add(vtkDoubleArray::New(), "SamplingGridSpacing", { 1, 1, 1 });
    add(vtkIntArray::New(), "SamplingGridExtent", { 0, last, 0, last, 0, last });
  }
  return data;
}

// Runs `body` with vtkSMPTools on the STDThread backend and `threads` threads.
template <typename Body>
void WithThreads(int threads, Body body)
{
  vtkSMPTools::LocalScope(vtkSMPTools::Config(threads, "STDThread", false), body);
}

void SetVoxelCounters(benchmark::State& state, int n)
{
  state.counters["voxels/s"] = benchmark::Counter(
    static_cast<double>(n) * n * n, benchmark::Counter::kIsIterationInvariantRate);
}

enum class Stage
{
  Fresh,
  Reused,
  Transform,
  Compute
};

// One kernel stage; the kernel is set up (plans made, buffers committed)
// before timing, and Fresh replaces it by a new one in every run.
void RunKernel(benchmark::State& state, Stage stage)
{
  const int n = static_cast<int>(state.range(0));
  const std::vector<unsigned char>& mask = RandomMask(n);
  WithThreads(static_cast<int>(state.range(1)),
    [&]()
    {
      auto kernel = std::make_unique<vtkBlueNoiseSpectrumKernel>();
      kernel->SetDimensions(n, n, n);
      kernel->AddRealization(mask.data());
      vtkBlueNoiseSpectrumKernel::Result result;
      for (auto _ : state)
      {
        if (stage == Stage::Fresh)
        {
          kernel = std::make_unique<vtkBlueNoiseSpectrumKernel>();
          kernel->SetDimensions(n, n, n);
        }
        if (stage != Stage::Compute)
        {
          kernel->Reset();
          kernel->AddRealization(mask.data());
        }
        if (stage != Stage::Transform)
        {
          kernel->Compute(result);
          benchmark::DoNotOptimize(result.TargetValue);
        }
      }
    });
  SetVoxelCounters(state, n);
}

void BM_Fresh(benchmark::State& state)
{
  RunKernel(state, Stage::Fresh);
}

void BM_Reused(benchmark::State& state)
{
  RunKernel(state, Stage::Reused);
}

void BM_Transform(benchmark::State& state)
{
  RunKernel(state, Stage::Transform);
}

void BM_Compute(benchmark::State& state)
{
  RunKernel(state, Stage::Compute);
}

void RunFilter(benchmark::State& state, bool image)
{
  const int n = static_cast<int>(state.range(0));
  vtkPolyData* points = MaskPoints(n);
  WithThreads(static_cast<int>(state.range(1)),
    [&]()
    {
      vtkNew<vtkBlueNoiseSpectrum> filter;
      filter->SetInputData(points);
      filter->SetGenerateSpectrumImage(image);
      for (auto _ : state)
      {
        filter->Modified();
        filter->Update();
      }
    });
  SetVoxelCounters(state, n);
}

void BM_Filter(benchmark::State& state)
{
  RunFilter(state, false);
}

void BM_FilterImage(benchmark::State& state)
{
  RunFilter(state, true);
}

#ifdef BLUENOISE_HAVE_FFTW3_THREADS
void BM_FFTW3D(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const int threads = static_cast<int>(state.range(1));
  const std::vector<unsigned char>& mask = RandomMask(n);
  const std::size_t padX = 2 * (static_cast<std::size_t>(n) / 2 + 1);
  double* data = fftw_alloc_real(padX * n * n);
  static const int initialized = fftw_init_threads();
  (void)initialized;
  fftw_plan_with_nthreads(threads);
  fftw_plan plan =
    fftw_plan_dft_r2c_3d(n, n, n, data, reinterpret_cast<fftw_complex*>(data), FFTW_ESTIMATE);
  fftw_plan_with_nthreads(1); // the kernel's plans stay single-threaded
  for (auto _ : state)
  {
    state.PauseTiming();
    for (std::size_t row = 0; row < static_cast<std::size_t>(n) * n; ++row)
    {
      for (int x = 0; x < n; ++x)
      {
        data[row * padX + x] = mask[row * n + x];
      }
    }
    state.ResumeTiming();
    fftw_execute(plan);
  }
  fftw_destroy_plan(plan);
  fftw_free(data);
  SetVoxelCounters(state, n);
}
#endif

// Whether a run ended in an error: Google Benchmark 1.8 replaced the bool
// Run::error_occurred with Run::skipped (an enum, zero for a run that ran).
// The overload that compiles for the installed version is the one chosen.
template <typename R>
auto RunFailed(const R& run, int) -> decltype(static_cast<bool>(run.error_occurred))
{
  return static_cast<bool>(run.error_occurred);
}
template <typename R>
auto RunFailed(const R& run, long) -> decltype(static_cast<bool>(run.skipped))
{
  return static_cast<bool>(run.skipped);
}

// The console table, and the real times kept by name for the ratios.
class RatioReporter : public benchmark::ConsoleReporter
{
public:
  void ReportRuns(const std::vector<Run>& runs) override
  {
    for (const Run& run : runs)
    {
      if (!RunFailed(run, 0) && run.run_type == Run::RT_Iteration)
      {
        // "BM_Stage/L/threads", without the "/real_time" the name ends with.
        std::string name = run.benchmark_name();
        name = name.substr(0, name.find("/real_time"));
        this->Times[name] = run.GetAdjustedRealTime();
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }

  void PrintRatios(int threads) const
  {
    const std::string many = std::to_string(threads);
    std::printf("\nSpeed-up, time on 1 thread / time on %d threads:\n", threads);
    for (const auto& entry : this->Times)
    {
      const std::string& name = entry.first;
      if (name.size() > 2 && name.compare(name.size() - 2, 2, "/1") == 0)
      {
        const std::string stem = name.substr(0, name.size() - 1);
        this->PrintRatio(stem + "1", stem + many);
      }
    }
    std::printf("\nFFTW's 3D plan / slab and column Transform (same thread count):\n");
    for (const auto& entry : this->Times)
    {
      if (entry.first.rfind("BM_FFTW3D/", 0) == 0)
      {
        this->PrintRatio(entry.first, "BM_Transform/" + entry.first.substr(10));
      }
    }
  }

private:
  void PrintRatio(const std::string& slow, const std::string& fast) const
  {
    const auto a = this->Times.find(slow);
    const auto b = this->Times.find(fast);
    if (a != this->Times.end() && b != this->Times.end() && b->second > 0.0)
    {
      std::printf("  %-28s / %-28s %6.2f\n", slow.c_str(), fast.c_str(), a->second / b->second);
    }
  }

  std::map<std::string, double> Times;
};

int Cores()
{
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void Register(const char* name, void (*fn)(benchmark::State&), std::vector<int> sizes)
{
  for (int n : sizes)
  {
    for (int threads : { 1, Cores() })
    {
      benchmark::RegisterBenchmark(name, fn)
        ->Args({ n, threads })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
      if (Cores() == 1)
      {
        break;
      }
    }
  }
}
}

int main(int argc, char** argv)
{
  Register("BM_Fresh", BM_Fresh, { 64, 128, 256, 512 });
  Register("BM_Reused", BM_Reused, { 64, 128, 256, 512 });
  Register("BM_Transform", BM_Transform, { 64, 128, 256, 512 });
  Register("BM_Compute", BM_Compute, { 64, 128, 256, 512 });
  Register("BM_Filter", BM_Filter, { 128, 256, 512 });
  Register("BM_FilterImage", BM_FilterImage, { 128, 256, 512 });
#ifdef BLUENOISE_HAVE_FFTW3_THREADS
  Register("BM_FFTW3D", BM_FFTW3D, { 128, 256, 512 });
#endif
  benchmark::Initialize(&argc, argv);
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.PrintRatios(Cores());
  benchmark::Shutdown();
  return 0;
}
