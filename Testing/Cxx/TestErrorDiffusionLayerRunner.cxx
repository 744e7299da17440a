// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkErrorDiffusionLayerRunner: on one thread or two, the layers reach the
// consumer in order with the masks a plain ProcessLayer loop gives; a consumer
// that says stop, or a callback that throws, ends the run cleanly; Finish gets
// the total; MaskStorage receives the masks. Threaded, the densities are
// filled one layer at a time, in order, by whichever thread has time: the scan
// thread when the consumer is slow, the calling thread when the scan is.
// Idle runs on the scan thread while it waits for a slow consumer, and is
// called again as long as it had work.
// A kernel and a runner that take over the buffers of others that ran
// before them give the same masks.
// Many short threaded runs end without a lost wake-up (a watchdog fails the
// test when one stops making progress: a hang, not a timeout of CTest).
#include "BlueNoiseTestUtilities.h"
#include "vtkErrorDiffusionKernel.h"
#include "vtkErrorDiffusionLayerRunner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace bluenoise_test;

namespace
{
const int NX = 37, NY = 23, NZ = 41;
const size_t LayerSize = static_cast<size_t>(NX) * NY;

// Densities with empty and full voxels, different in every layer.
float Density(int x, int y, int z)
{
  const int v = (x * 7 + y * 11 + z * 5) % 29;
  return v < 3 ? 0.0f : (v > 26 ? 1.0f : 0.03f * static_cast<float>(v));
}

void FillLayer(int z, float* out)
{
  for (int y = 0; y < NY; ++y)
  {
    for (int x = 0; x < NX; ++x)
    {
      out[x + NX * y] = Density(x, y, z);
    }
  }
}

vtkErrorDiffusionKernel MakeKernel(vtkErrorDiffusionKernel* ended = nullptr)
{
  vtkErrorDiffusionKernel kernel;
  kernel.SetSeed(5);
  if (ended)
  {
    kernel.SwapLayerBuffers(*ended);
  }
  kernel.Begin(NX, NY);
  return kernel;
}

// The reference: ProcessLayer called directly, layer after layer.
std::vector<unsigned char> Reference()
{
  auto kernel = MakeKernel();
  std::vector<unsigned char> mask(LayerSize * NZ);
  std::vector<float> current(LayerSize), next(LayerSize);
  FillLayer(0, current.data());
  for (int z = 0; z < NZ; ++z)
  {
    if (z + 1 < NZ)
    {
      FillLayer(z + 1, next.data());
    }
    kernel.ProcessLayer(current.data(), z + 1 < NZ ? next.data() : nullptr, mask.data() + z * LayerSize);
    current.swap(next);
  }
  return mask;
}

struct Outcome
{
  bool Done = false;
  std::string Error;
  std::vector<unsigned char> Mask;
  std::vector<int> Order;
  vtkIdType Counted = 0;
  vtkIdType Finished = -1;
  bool DensitiesRight = true;
  bool FillsInOrder = true;  // one at a time, layer after layer
  int FilledByCaller = 0;    // layers filled on the calling thread
  int FilledElsewhere = 0;   // on the scan thread
  int IdleCalls = 0;         // Idle, called on the scan thread while it waits
  bool IdleOnScanThread = true;
};

// The stages of RunWith: they record what the runner asked of them.
// mode 0: one thread; 1: two threads; 2: two, the consumer slow; 3: two, the
// scan slow.
class Recorder : public vtkErrorDiffusionLayerRunner::Stages
{
public:
  Recorder(Outcome& o, int mode, int stopAt, int throwInFill, int throwInConsume, bool external)
    : O(o)
    , Mode(mode)
    , StopAt(stopAt)
    , ThrowInFill(throwInFill)
    , ThrowInConsume(throwInConsume)
    , External(external)
  {
  }

  void Fill(int z, float* out) override
  {
    O.FillsInOrder = O.FillsInOrder && this->Filling.fetch_add(1) == 0 && z == this->NextFill++;
    (std::this_thread::get_id() == this->Caller ? O.FilledByCaller : O.FilledElsewhere)++;
    if (z == this->ThrowInFill)
    {
      this->Filling.fetch_sub(1);
      throw std::runtime_error("fill failed");
    }
    FillLayer(z, out);
    this->Filling.fetch_sub(1);
  }

  unsigned char* MaskStorage(int z) override
  {
    return this->External ? O.Mask.data() + z * LayerSize : nullptr;
  }

  void BeforeScan(int, const float*) override
  {
    if (this->Mode == 3)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }

  bool Consume(const vtkErrorDiffusionLayerRunner::Layer& layer) override
  {
    if (layer.Index == this->ThrowInConsume)
    {
      throw std::runtime_error("consume failed");
    }
    if (this->Mode == 2)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    O.Order.push_back(layer.Index);
    vtkIdType ones = 0;
    for (size_t i = 0; i < LayerSize; ++i)
    {
      ones += layer.Mask[i];
      O.DensitiesRight = O.DensitiesRight &&
        layer.Density[i] == Density(static_cast<int>(i % NX), static_cast<int>(i / NX), layer.Index);
    }
    O.Counted += ones;
    O.DensitiesRight = O.DensitiesRight && ones == layer.Count;
    if (!this->External)
    {
      std::copy(layer.Mask, layer.Mask + LayerSize, O.Mask.data() + layer.Index * LayerSize);
    }
    return layer.Index != this->StopAt;
  }

  void Finish(vtkIdType total) override { O.Finished = total; }

  bool Idle() override
  {
    O.IdleOnScanThread = O.IdleOnScanThread && std::this_thread::get_id() != this->Caller;
    return ++O.IdleCalls % 2 == 1; // work, then none: called again, then no more
  }

private:
  Outcome& O;
  const int Mode, StopAt, ThrowInFill, ThrowInConsume;
  const bool External;
  const std::thread::id Caller = std::this_thread::get_id();
  std::atomic<int> Filling{ 0 };
  int NextFill = 0;
};

// takeOver: the kernel and the runner start with the buffers of a kernel and
// a runner that ran before them (another seed, and stopped halfway: errors
// left in them).
Outcome RunWith(int mode, int stopAt = -1, int throwInFill = -1, int throwInConsume = -1,
  bool external = false, bool takeOver = false)
{
  Outcome o;
  o.Mask.assign(LayerSize * NZ, 0);
  vtkErrorDiffusionKernel ended;
  vtkErrorDiffusionLayerRunner endedRunner;
  if (takeOver)
  {
    Outcome before;
    before.Mask.assign(LayerSize * NZ, 0);
    ended.SetSeed(11);
    ended.Begin(NX, NY);
    endedRunner.SetThreaded(mode > 0);
    Recorder stages(before, mode, -1, -1, -1, false);
    endedRunner.Run(ended, stages, NX, NY, NZ / 2, true); // errors carried on left in it
  }
  auto kernel = MakeKernel(takeOver ? &ended : nullptr);
  vtkErrorDiffusionLayerRunner runner;
  if (takeOver)
  {
    runner.SwapBuffers(endedRunner);
  }
  runner.SetThreaded(mode > 0);
  Recorder stages(o, mode, stopAt, throwInFill, throwInConsume, external);
  o.Done = runner.Run(kernel, stages, NX, NY, NZ);
  o.Error = runner.GetError();
  return o;
}

// The least a run needs: densities and a consumer that counts the layers.
class Counter : public vtkErrorDiffusionLayerRunner::Stages
{
public:
  Counter(std::atomic<long>& consumed, int n)
    : Consumed(consumed)
    , N(n)
  {
  }
  void Fill(int, float* out) override { std::fill(out, out + this->N * this->N, 0.3f); }
  bool Consume(const vtkErrorDiffusionLayerRunner::Layer&) override
  {
    this->Consumed.fetch_add(1);
    return true;
  }

private:
  std::atomic<long>& Consumed;
  int N;
};

// Short threaded runs hand a layer over every few microseconds, and the end of
// each run is a hand-over nothing follows: a wake-up lost there hangs the run
// (it did, about once in 10^4 runs on a loaded machine, with the counters'
// release/acquire ordering). The watchdog ends the process when no layer is
// consumed for 30 s.
void CheckShortRuns(int runs)
{
  std::atomic<long> consumed{ 0 };
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::thread watchdog([&] {
    std::unique_lock<std::mutex> lock(mutex);
    long last = -1;
    while (!finished.wait_for(lock, std::chrono::seconds(30), [&] { return done; }))
    {
      if (consumed.load() == last)
      {
        std::printf("FAIL: a threaded run hung after %ld layers\n", last);
        std::fflush(stdout);
        std::_Exit(1);
      }
      last = consumed.load();
    }
  });
  const int n = 16, layers = 6;
  int completed = 0;
  for (int r = 0; r < runs; ++r)
  {
    vtkErrorDiffusionKernel kernel;
    kernel.SetSeed(r);
    kernel.Begin(n, n);
    vtkErrorDiffusionLayerRunner runner;
    runner.SetThreaded(true);
    Counter stages(consumed, n);
    completed += runner.Run(kernel, stages, n, n, layers) ? 1 : 0;
  }
  {
    std::lock_guard<std::mutex> lock(mutex);
    done = true;
  }
  finished.notify_all();
  watchdog.join();
  Check(completed == runs, Str(completed) + " of " + Str(runs) + " short threaded runs complete");
}
}

int main()
{
  const auto reference = Reference();
  vtkIdType ones = 0;
  for (unsigned char b : reference)
  {
    ones += b;
  }
  Check(ones > 1000, "the reference has samples: " + Str(ones));

  const char* const modes[] = { "one thread", "two threads", "two threads, slow consumer",
    "two threads, slow scan" };
  for (const int threads : { 0, 1, 2, 3 })
  {
    const std::string mode = std::string(" (") + modes[threads] + ")";
    for (const bool external : { false, true })
    {
      const Outcome o = RunWith(threads, -1, -1, -1, external);
      bool inOrder = static_cast<int>(o.Order.size()) == NZ;
      for (int z = 0; inOrder && z < NZ; ++z)
      {
        inOrder = o.Order[z] == z;
      }
      Check(o.Done && o.Error.empty(), "complete run" + mode);
      Check(inOrder, "every layer once, in order" + mode);
      Check(o.Mask == reference,
        std::string(external ? "masks in MaskStorage" : "masks") + " equal the plain loop's" + mode);
      Check(o.DensitiesRight, "each layer comes with its densities and count" + mode);
      Check(o.Finished == ones && o.Counted == ones,
        "Finish gets the total: " + Str(o.Finished) + " of " + Str(ones) + mode);
      Check(o.FillsInOrder && o.FilledByCaller + o.FilledElsewhere == NZ,
        "every layer filled once, one at a time, in order" + mode);
      // Where the time is spare: mostly on the scan thread with a slow
      // consumer, mostly on the calling thread with a slow scan.
      Check(threads < 2 || (threads == 2 ? o.FilledElsewhere > NZ / 2 : o.FilledByCaller > NZ / 2),
        "the layers filled by the thread with time to spare: " + Str(o.FilledByCaller) +
          " by the calling thread, " + Str(o.FilledElsewhere) + " by the scan thread" + mode);
      // Idle: on the scan thread, while it waits for the (slow) consumer.
      Check(o.IdleOnScanThread && (threads > 0 || o.IdleCalls == 0) &&
          (threads != 2 || o.IdleCalls >= 2),
        "Idle called " + Str(o.IdleCalls) + " times, on the scan thread" + mode);
    }
    {
      const Outcome o = RunWith(threads, -1, -1, -1, false, true);
      Check(o.Done && o.Mask == reference,
        "with the buffers of a kernel and a runner that ran before: the plain loop's masks" + mode);
    }
    {
      const Outcome o = RunWith(threads, 6);
      Check(!o.Done && o.Error.empty() && o.Order.size() == 7 && o.Finished < 0,
        "a consumer that says stop at layer 6 ends the run after 7 layers, without Finish" + mode);
    }
    {
      const Outcome o = RunWith(threads, -1, 9);
      Check(!o.Done && o.Error == "fill failed" && o.Order.size() <= 9,
        "an exception in Fill ends the run and is reported ('" + o.Error + "', " +
          Str(o.Order.size()) + " layers consumed)" + mode);
    }
    {
      const Outcome o = RunWith(threads, -1, -1, 4);
      Check(!o.Done && o.Error == "consume failed" && o.Order.size() == 4,
        "an exception in Consume ends the run and is reported ('" + o.Error + "')" + mode);
    }
  }
  CheckShortRuns(20000);
  return Summary("TestErrorDiffusionLayerRunner");
}
