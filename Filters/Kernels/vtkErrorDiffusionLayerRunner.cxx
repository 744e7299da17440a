// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionLayerRunner.h"

#include "vtkErrorDiffusionKernel.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__) || defined(_M_X64) || defined(_M_IX86)
#include <immintrin.h> // _mm_pause
#endif

namespace
{
// A spin-wait hint: leaves the core's resources to the other thread.
inline void CpuRelax()
{
#if defined(__x86_64__) || defined(__i386__) || defined(_M_X64) || defined(_M_IX86)
  _mm_pause();
#else
  std::this_thread::yield();
#endif
}

std::string Describe(const std::exception_ptr& error)
{
  try
  {
    std::rethrow_exception(error);
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  catch (...)
  {
    return "unknown exception";
  }
}
}

//------------------------------------------------------------------------------
float* vtkErrorDiffusionLayerRunner::DensitySlot(int k)
{
  return this->Densities + static_cast<size_t>(k % this->Slots) * this->LayerSize;
}

//------------------------------------------------------------------------------
unsigned char* vtkErrorDiffusionLayerRunner::MaskSlot(int k)
{
  return this->LayerMasks[k % this->Slots];
}

//------------------------------------------------------------------------------
vtkIdType vtkErrorDiffusionLayerRunner::ScanLayer(vtkErrorDiffusionKernel& kernel, int k, int nz)
{
  // Layer k's densities were filled by the scan of layer k - 1 (the look-ahead
  // the kernel needs), except for the first one.
  if (k == 0)
  {
    this->Fill(0, this->DensitySlot(0));
  }
  const float* next = nullptr;
  if (k + 1 < nz || this->LastHasNext)
  {
    this->Fill(k + 1, this->DensitySlot(k + 1));
    next = this->DensitySlot(k + 1);
  }
  unsigned char* mask = this->MaskStorage ? this->MaskStorage(k) : nullptr;
  if (!mask)
  {
    mask = this->Masks + static_cast<size_t>(k % this->Slots) * this->LayerSize;
  }
  this->LayerMasks[k % this->Slots] = mask; // published to the consumer with the count
  if (this->BeforeScan)
  {
    this->BeforeScan(k, this->DensitySlot(k));
  }
  return kernel.ProcessLayer(this->DensitySlot(k), next, mask);
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionLayerRunner::Run(
  vtkErrorDiffusionKernel& kernel, int nx, int ny, int nz, bool lastHasNext)
{
  this->LastHasNext = lastHasNext;
  this->Error.clear();
  if (!this->Fill || !this->Consume)
  {
    this->Error = "vtkErrorDiffusionLayerRunner needs a Fill and a Consume function.";
    return false;
  }
  if (nx <= 0 || ny <= 0 || nz <= 0)
  {
    if (this->Finish)
    {
      this->Finish(0);
    }
    return true;
  }
  // A layer is filled one scan ahead of its own and freed when consumed: two
  // buffers suffice in turn; four let the scan run ahead of the consumer.
  this->Slots = this->Threaded ? 4 : 2;
  this->LayerSize = static_cast<size_t>(nx) * static_cast<size_t>(ny);
  std::vector<float> densities;
  std::vector<unsigned char> masks;
  try
  {
    densities.resize(this->Slots * this->LayerSize);
    masks.resize(this->Slots * this->LayerSize);
  }
  catch (const std::exception& e)
  {
    this->Error = std::string("cannot allocate the layer buffers: ") + e.what();
    return false;
  }
  this->Densities = densities.data();
  this->Masks = masks.data();
  this->LayerMasks.assign(this->Slots, nullptr);
  const bool done = this->Threaded ? this->RunThreaded(kernel, nz) : this->RunSequential(kernel, nz);
  this->Densities = nullptr;
  this->Masks = nullptr;
  return done;
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionLayerRunner::RunSequential(vtkErrorDiffusionKernel& kernel, int nz)
{
  try
  {
    vtkIdType total = 0;
    for (int k = 0; k < nz; ++k)
    {
      Layer layer;
      layer.Index = k;
      layer.Count = this->ScanLayer(kernel, k, nz);
      layer.Density = this->DensitySlot(k);
      layer.Mask = this->MaskSlot(k);
      total += layer.Count;
      if (!this->Consume(layer))
      {
        return false;
      }
    }
    if (this->Finish)
    {
      this->Finish(total);
    }
    return true;
  }
  catch (...)
  {
    this->Error = Describe(std::current_exception());
    return false;
  }
}

//------------------------------------------------------------------------------
namespace
{
// A counter one thread advances and the other waits on. Going to sleep and
// being woken costs tens of microseconds on a virtual machine, about the
// scan of a 128 x 128 layer, so the waiting side first spins for up to 500
// microseconds (with a pause hint that leaves the core to the other thread),
// and the advancing side makes the wake-up call only when the other sleeps.
class LayerCounter
{
public:
  void Advance(int value)
  {
    this->Value.store(value);
    if (this->Sleeping.load())
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      this->Changed.notify_all();
    }
  }

  // Waits until the value reaches `target` or `stop` is set; false if stopped.
  bool WaitFor(int target, const std::atomic<bool>& stop)
  {
    const auto ready = [&] { return stop.load() || this->Value.load() >= target; };
    const auto spinUntil = std::chrono::steady_clock::now() + std::chrono::microseconds(500);
    for (int spin = 0; !ready(); ++spin)
    {
      if ((spin & 63) == 63 && std::chrono::steady_clock::now() > spinUntil)
      {
        std::unique_lock<std::mutex> lock(this->Mutex);
        this->Sleeping.store(true);
        this->Changed.wait(lock, ready);
        this->Sleeping.store(false);
        break;
      }
      CpuRelax();
    }
    return !stop.load();
  }

  // Wakes a sleeping waiter to see `stop`.
  void Wake()
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Changed.notify_all();
  }

private:
  std::atomic<int> Value{ 0 };
  std::atomic<bool> Sleeping{ false };
  std::mutex Mutex;
  std::condition_variable Changed;
};
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionLayerRunner::RunThreaded(vtkErrorDiffusionKernel& kernel, int nz)
{
  LayerCounter scanned;  // layers whose mask is ready
  LayerCounter consumed; // layers whose buffers are free again
  std::atomic<bool> stop{ false };
  std::mutex errorMutex;
  std::exception_ptr error;
  // Written by the scan thread before it advances `scanned` past the layer,
  // read by the consumer after it saw that: the atomic orders them.
  std::vector<vtkIdType> counts(this->Slots, 0);

  auto fail = [&](std::exception_ptr e) {
    {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (!error)
      {
        error = e;
      }
    }
    stop.store(true);
    scanned.Wake();
    consumed.Wake();
  };

  std::thread scanner([&]() {
    try
    {
      vtkIdType total = 0;
      for (int k = 0; k < nz; ++k)
      {
        // Scanning layer k fills layer k + 1, whose buffer held layer
        // k + 1 - Slots: that one must have been consumed.
        if (!consumed.WaitFor(k + 2 - this->Slots, stop))
        {
          return;
        }
        const vtkIdType count = this->ScanLayer(kernel, k, nz);
        total += count;
        counts[k % this->Slots] = count;
        scanned.Advance(k + 1);
      }
      if (this->Finish)
      {
        this->Finish(total);
      }
    }
    catch (...)
    {
      fail(std::current_exception());
    }
  });

  bool complete = true;
  for (int k = 0; k < nz; ++k)
  {
    if (!scanned.WaitFor(k + 1, stop))
    {
      complete = false;
      break;
    }
    Layer layer;
    layer.Index = k;
    layer.Count = counts[k % this->Slots];
    layer.Density = this->DensitySlot(k);
    layer.Mask = this->MaskSlot(k);
    bool go = false;
    try
    {
      go = this->Consume(layer);
    }
    catch (...)
    {
      fail(std::current_exception());
    }
    if (!go)
    {
      stop.store(true);
      consumed.Wake();
      complete = false;
      break;
    }
    consumed.Advance(k + 1);
  }
  scanner.join();
  if (error)
  {
    this->Error = Describe(error);
    return false;
  }
  return complete;
}
