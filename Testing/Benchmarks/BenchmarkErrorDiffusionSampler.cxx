// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Sampling speed against a baseline measured in the same run: the tightest
// simple single-threaded loop of the same scan, with no pipeline around it
// (TightScan in BlueNoiseTightScan.h says what it does and does not do). Cases: constant cubes of 256^3 and
// 512^3 at g = 8/255 and 127/255 (and 256^3 at 4, 16, 32 and 64/255, where the
// default method's relaxation works), uint8 and float input, the filter with its
// default settings but for the identity mapping (a constant cube has no
// scalar range): a point budget of g * voxels, the worker thread when more
// than one thread is allowed, the default method or the paper's; the kernel
// alone; the relaxation pass alone, on the kernel's samples; the filter
// with another process busy on every core ("busy"); and a volume of density
// steps (BM_Steps).
// Counters: voxels/s, and x_tight = the tight loop's time / this time (the
// tight loop timed, fastest of 3, right before the case and, for the filter,
// right after it too, under the same load).
// No thresholds.
#include "BlueNoiseTightScan.h"
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
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

namespace
{
using BlueNoiseTight::Pcg32;
using Clock = std::chrono::steady_clock;

// With --benchmark_repetitions, the fastest run: on a shared virtual machine
// the other aggregates mostly measure the neighbors.
double Fastest(const std::vector<double>& v)
{
  return v.empty() ? 0.0 : *std::min_element(v.begin(), v.end());
}

// A constant cube of `value` in an array of type T.
template <typename ArrayT>
vtkSmartPointer<vtkImageData> Cube(int n, double value, int layers = 0)
{
  layers = layers > 0 ? layers : n;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, layers);
  auto values = vtkSmartPointer<ArrayT>::New();
  values->SetName("values");
  values->SetNumberOfValues(static_cast<vtkIdType>(n) * n * layers);
  values->Fill(value);
  image->GetPointData()->SetScalars(values);
  return image;
}

// 8^3 blocks of values drawn from [low, high] filling an n^3 uint8 cube
// (n a multiple of 8): a density step at every block face.
vtkSmartPointer<vtkImageData> Blocks(int n, int low, int high)
{
  auto image = Cube<vtkUnsignedCharArray>(n, 0);
  auto* v = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars())->GetPointer(0);
  Pcg32 random;
  const int blocks = n / 8;
  std::vector<unsigned char> value(static_cast<size_t>(blocks) * blocks * blocks);
  for (auto& b : value)
  {
    b = static_cast<unsigned char>(low + std::min(high - low, static_cast<int>(random.Uniform() * (high - low + 1))));
  }
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        *v++ = value[(static_cast<size_t>(z / 8) * blocks + y / 8) * blocks + x / 8];
  return image;
}

// Layers first ... first + layers - 1 of an n^3 uint8 ball graded from 255
// (times 0.75 to 1 by layer) at its center to 0 at its surface, 0 outside:
// the formula of the streaming benchmark's volume (scripts/bench-streaming.sh).
// Its z-parts differ in work: the end parts are mostly empty, the middle ones
// full.
vtkSmartPointer<vtkImageData> GradedBall(int n, int first = 0, int layers = 0)
{
  layers = layers > 0 ? layers : n;
  auto image = Cube<vtkUnsignedCharArray>(n, 0, layers);
  auto* v = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars())->GetPointer(0);
  const double c = (n - 1) / 2.0;
  for (int z = first; z < first + layers; ++z)
  {
    const double dz = (z - c) / c;
    const double scale = 255.0 * (0.75 + 0.25 * std::sin(z / 16.0));
    for (int y = 0; y < n; ++y)
    {
      for (int x = 0; x < n; ++x)
      {
        const double dx = (x - c) / c, dy = (y - c) / c;
        const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
        *v++ = static_cast<unsigned char>(scale * std::min(1.0, std::max(0.0, 1.0 - d)));
      }
    }
  }
  return image;
}

// The tight loop on the same n^3 cube, fastest of 3, in seconds; densities
// value / 255 for 8-bit values, the value itself for floats (as the cases'
// cubes hold them).
template <typename T>
double PlainSeconds(vtkImageData* image)
{
  const int n = image->GetDimensions()[0];
  const auto* values = static_cast<const T*>(image->GetPointData()->GetScalars()->GetVoidPointer(0));
  const double scale = sizeof(T) == 1 ? 1.0 / 255.0 : 1.0;
  std::vector<unsigned char> b(static_cast<size_t>(n) * n * n);
  vtkIdType count = 0;
  const double seconds = BlueNoiseTight::FastestSeconds(values, n, scale, b.data(), count);
  benchmark::DoNotOptimize(count);
  return seconds;
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

// The Method (the paper's error diffusion with the paper's parameters).
void SetMethod(vtkErrorDiffusionSampler* sampler, int method)
{
  sampler->SetMethod(method);
  if (method == vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION)
  {
    sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_PAPER);
  }
}

// The fastest re-execution of the sampler (as after a change of property),
// one per iteration, in seconds. Once untimed before: the first run faults
// the output in.
double UpdateSeconds(benchmark::State& state, vtkErrorDiffusionSampler* sampler)
{
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
  return best;
}

// The counters of a filter case on an n^3 volume: voxels/s, x_tight, points.
void FilterCounters(benchmark::State& state, int n, double tight, vtkErrorDiffusionSampler* sampler)
{
  state.counters["voxels/s"] = benchmark::Counter(
    static_cast<double>(n) * n * n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["x_tight"] = tight;
  state.counters["points"] = static_cast<double>(sampler->GetOutput()->GetNumberOfPoints());
}

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
    return floats ? PlainSeconds<float>(image) : PlainSeconds<unsigned char>(image);
  };
  double plain = plainSeconds();
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToIdentity(); // a constant cube has no scalar range
  sampler->SetNumberOfPoints(static_cast<vtkIdType>(g * n * n * n));
  sampler->SetUseWorkerThread(state.range(4) != 0);
  SetMethod(sampler, static_cast<int>(state.range(5)));
  const double best = UpdateSeconds(state, sampler);
  plain = std::min(plain, plainSeconds());
  FilterCounters(state, n, plain / best, sampler);
}

// A volume with density steps everywhere against the tight loop on it: 256^3
// uint8 of 8^3 blocks of values drawn from 2 .. 64, densities value / 255
// (all where the default method relaxes, and neighbors up to 32 times
// denser: about half the voxels are next to a dissimilar density, where the
// scan and the relaxation take their slower paths). The budget is the sum of
// the densities, the worker thread allowed. range(0): the Method.
void BM_Steps(benchmark::State& state)
{
  const int n = 256;
  auto image = Blocks(n, 2, 64);
  double plain = PlainSeconds<unsigned char>(image);
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToIdentity();
  sampler->UseNumberOfPointsOff();
  sampler->SetDensityScale(1.0 / 255.0);
  SetMethod(sampler, static_cast<int>(state.range(0)));
  const double best = UpdateSeconds(state, sampler);
  plain = std::min(plain, PlainSeconds<unsigned char>(image));
  FilterCounters(state, n, plain / best, sampler);
}

// The fastest of `runs` executions of the filter on one thread, or with its
// worker thread beside it (`worker`: two threads), in seconds, the first one
// untimed; in one part unless `parts`.
double FilterSeconds(vtkImageData* image, double g, int method, bool parts, int runs,
  vtkErrorDiffusionSampler* plan = nullptr, bool worker = false)
{
  vtkNew<vtkErrorDiffusionSampler> sampler;
  vtkErrorDiffusionSampler* s = plan ? plan : sampler.Get();
  s->SetInputData(image);
  s->SetDensityMappingToIdentity();
  s->UseNumberOfPointsOff();
  s->SetDensityScale(g);
  s->SetUseWorkerThread(worker);
  SetMethod(s, method);
  if (!parts)
  {
    s->SetPartLayers(65536);
  }
  s->Update();
  double best = 1e30;
  for (int r = 0; r < runs; ++r)
  {
    s->Modified();
    const auto start = Clock::now();
    s->Update();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
  }
  return best;
}

// The time of one part's layers: alone on a thread, and with a worker
// thread beside it (paired).
struct PartWork
{
  double Single;
  double Paired;
};

// The wall time of parts (in z order) on `threads` threads as the filter's
// schedule runs them: in epochs of half a second, each of up to `threads`
// threads taking the lowest part not done that no thread holds, and the
// next when that one is done, until the epoch ends (a thread that finds
// none leaves); threads neither holding a part nor left to the next epoch
// pair up with the lowest parts held (their scan on a worker thread),
// decided afresh at each part's end and every tenth of a second (the
// filter: at each chunk); the last part left paired, at once.
double Replay(int threads, const std::vector<PartWork>& parts)
{
  const double epoch = 0.5, chunk = 0.1;
  std::vector<double> left(parts.size(), 1.0); // of each part's work
  const auto notDone = [&] {
    std::vector<size_t> p;
    for (size_t i = 0; i < left.size(); ++i)
    {
      if (left[i] > 1e-12)
      {
        p.push_back(i);
      }
    }
    return p;
  };
  double now = 0.0;
  for (auto rest = notDone(); !rest.empty(); rest = notDone())
  {
    if (rest.size() == 1 || threads == 1)
    {
      now += left[rest[0]] * (threads > 1 ? parts[rest[0]].Paired : parts[rest[0]].Single);
      left[rest[0]] = 0.0;
      continue;
    }
    const size_t workers = std::min(static_cast<size_t>(threads), rest.size());
    const double end = now + epoch;
    while (now < end && rest.size() > 1)
    {
      const size_t held = std::min(workers, rest.size());
      const size_t pairs = std::min(held, threads - held);
      const auto seconds = [&](size_t k) {
        return k < pairs ? parts[rest[k]].Paired : parts[rest[k]].Single;
      };
      double step = std::min(end - now, chunk);
      for (size_t k = 0; k < held; ++k)
      {
        step = std::min(step, left[rest[k]] * seconds(k));
      }
      for (size_t k = 0; k < held; ++k)
      {
        left[rest[k]] = std::max(0.0, left[rest[k]] - step / seconds(k));
      }
      now += step;
      rest = notDone();
    }
  }
  return now;
}

// The speed-up of the z-parts on N threads, projected from the work of each
// part measured alone: each part's scanned layers (its overlap included)
// sampled as a volume of their own in one part, which also relaxes and
// emits the overlap (so the projection errs on the slow side), warmed up
// as the filter warms the part up (only for what its overlap is short of),
// on one thread and with the worker thread beside it. The schedule is replayed as
// the filter runs it (Replay). Speed-up = the whole volume in one part on
// one thread / the replayed wall time. Counters: parts, overlap (scanned
// layers / sampled layers), paired (the parts' time with a worker thread
// over their time alone) and x_N for N = 2, 4, 8, 16; xs_N the same for the
// volume streamed as bluenoise-sample streams it on N threads: in max(1,
// parts / N) z-slabs one after the other (the filter's even split of the
// layers), the parts' layers in each slab (their overlap's with them) side
// by side as above. Only two threads are used: the machine measuring need
// not have N cores.
// range(0): edge; range(1): g in 1/255; range(2): the Method; range(3): 0 a
// constant cube of density g, 1 the graded ball (GradedBall) of densities
// value / 255 x g (g at the center of its densest layers); range(4): the
// PartLayers (0: the default).
void BM_PartsProjection(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const bool ball = state.range(3) != 0;
  const double g = static_cast<double>(state.range(1)) / 255.0 / (ball ? 255.0 : 1.0);
  const int method = static_cast<int>(state.range(2));
  const auto volume = [n, ball](int first, int layers) {
    return ball ? GradedBall(n, first, layers) : Cube<vtkUnsignedCharArray>(n, 1.0, layers);
  };
  auto image = volume(0, n);
  for (auto _ : state)
  {
    vtkNew<vtkErrorDiffusionSampler> plan;
    if (state.range(4) > 0)
    {
      plan->SetPartLayers(static_cast<int>(state.range(4)));
    }
    FilterSeconds(image, g, method, true, 0, plan);
    const double whole = FilterSeconds(image, g, method, false, 2);
    const int parts = plan->GetNumberOfParts();
    std::vector<std::array<int, 2>> scans(static_cast<size_t>(parts)); // first and last layer
    std::vector<PartWork> perLayer(static_cast<size_t>(parts));
    double scanned = 0.0, single = 0.0, paired = 0.0;
    for (int p = 0; p < parts; ++p)
    {
      int range[3];
      plan->GetPartRange(p, range);
      scans[p] = { range[0], range[2] };
      const int layers = range[2] - range[0] + 1;
      scanned += layers;
      auto part = volume(range[0], layers);
      vtkNew<vtkErrorDiffusionSampler> alone;
      alone->SetWarmUpLayers(std::max(0, plan->GetWarmUpLayers() - (range[1] - range[0])));
      perLayer[p] = { FilterSeconds(part, g, method, false, 2, alone) / layers,
        FilterSeconds(part, g, method, false, 2, alone, true) / layers };
      single += perLayer[p].Single * layers;
      paired += perLayer[p].Paired * layers;
    }
    // The wall time of the parts' layers in [from, to] on `threads` threads.
    const auto wallOf = [&](int threads, int from, int to) {
      std::vector<PartWork> work;
      for (int p = 0; p < parts; ++p)
      {
        const int layers = std::min(to, scans[p][1]) - std::max(from, scans[p][0]) + 1;
        if (layers > 0)
        {
          work.push_back({ layers * perLayer[p].Single, layers * perLayer[p].Paired });
        }
      }
      return Replay(threads, work);
    };
    for (const int threads : { 2, 4, 8, 16 })
    {
      state.counters["x_" + std::to_string(threads)] = whole / wallOf(threads, 0, n - 1);
      const int slabs = std::max(1, parts / std::min(parts, threads));
      double streamed = 0.0;
      for (int k = 0; k < slabs; ++k)
      {
        streamed += wallOf(threads, n * k / slabs, n * (k + 1) / slabs - 1);
      }
      state.counters["xs_" + std::to_string(threads)] = whole / streamed;
    }
    state.counters["parts"] = parts;
    state.counters["overlap"] = scanned / n;
    state.counters["paired"] = paired / single;
    state.counters["one_part_s"] = whole;
  }
}

// The kernel alone on the same cubes, against the tight loop.
void BM_Kernel(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  const float g = static_cast<float>(state.range(1)) / 255.0f;
  auto image = Cube<vtkFloatArray>(n, g);
  const double plain = PlainSeconds<float>(image);
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
  state.counters["x_tight"] = plain / best;
}

// A relaxation pass alone, by the default method's rule (rule 0) or the
// energy rule (1), on the kernel's samples of a constant cube; x_kernel = the
// kernel's time on that cube / this time.
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
    relaxation.SetRule(static_cast<int>(state.range(2)));
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
  ->ArgsProduct({ { 256, 512 }, { 1, 8, 127 } })
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Relaxation)
  ->ArgNames({ "L", "g255", "rule" })
  ->ArgsProduct({ { 256 }, { 1, 4, 8, 32, 48 }, { 0 } })
  ->Args({ 512, 8, 0 })
  ->ArgsProduct({ { 256 }, { 8, 32 }, { 1 } })
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Filter)
  ->ArgNames({ "L", "g255", "float", "busy", "thread", "method" })
  ->ArgsProduct({ { 256, 512 }, { 8, 127 }, { 0, 1 }, { 0 }, { 1 }, { 2, 0 } })
  ->ArgsProduct({ { 256 }, { 8 }, { 0 }, { 1 }, { 0, 1 }, { 2, 0 } })
  ->ArgsProduct({ { 256 }, { 4, 16, 32, 64 }, { 0 }, { 0 }, { 1 }, { 2, 0 } })
  ->ArgsProduct({ { 256 }, { 4, 8, 16, 32, 64 }, { 0 }, { 0 }, { 1 }, { 5 } })
  ->UseRealTime() // two threads: CPU time of the caller alone would flatter
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Steps)
  ->ArgName("method")
  ->Arg(2)
  ->Arg(0)
  ->UseRealTime()
  ->ComputeStatistics("min", Fastest)
  ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PartsProjection)
  ->ArgNames({ "L", "g255", "method", "ball", "layers" })
  ->ArgsProduct({ { 512 }, { 8, 127 }, { 2, 0 }, { 0 }, { 0, 32 } })
  ->ArgsProduct({ { 1024 }, { 8 }, { 2, 0 }, { 0 }, { 0 } })
  ->ArgsProduct({ { 512, 1024 }, { 32 }, { 2, 0 }, { 1 }, { 0 } })
  ->ArgsProduct({ { 512 }, { 32 }, { 2, 0 }, { 1 }, { 32 } })
  ->Iterations(1)
  ->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
