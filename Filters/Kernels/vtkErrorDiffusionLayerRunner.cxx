// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionLayerRunner.h"

#include "vtkErrorDiffusionKernel.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

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

// A counter one thread advances and the other waits on. The waiter spins for
// a few microseconds (a layer hand-over usually comes that soon), then sleeps;
// the advancing side makes the wake-up call only when it sleeps.
//
// Value and Sleeping are sequentially consistent on purpose: the advancing
// side stores Value then reads Sleeping, the waiter stores Sleeping then reads
// Value. With a release store and an acquire load each side may read the
// other's old value (a store can wait in the core's store buffer past a later
// load, even on x86): the waiter then sleeps on a value that has changed and
// the advancing side skips the wake-up, which hung a run whose last layer was
// handed over that way.
class LayerCounter
{
public:
  int Get() const { return this->Value.load(); }

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
    const auto ready = [&] { return stop.load() || this->Get() >= target; };
    for (int spin = 0; spin < 256 && !ready(); ++spin)
    {
      CpuRelax();
    }
    if (!ready())
    {
      std::unique_lock<std::mutex> lock(this->Mutex);
      this->Sleeping.store(true);
      this->Changed.wait(lock, ready);
      this->Sleeping.store(false);
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

// The first exception of either thread, and the flag that stops both.
struct Failure
{
  std::mutex Mutex;
  std::exception_ptr Error;
  std::atomic<bool> Stop{ false };

  void Set(std::exception_ptr e)
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      if (!this->Error)
      {
        this->Error = e;
      }
    }
    this->Stop.store(true);
  }
};
}

//------------------------------------------------------------------------------
// What the two threads of a threaded run share: how far filling, scanning and
// consuming have come, the counts of the layers scanned and not yet consumed
// (written before `Scanned` advances past a layer, read after: the atomic
// orders them), and the first failure.
struct vtkErrorDiffusionLayerRunner::ThreadState
{
  ThreadState(int slots, int toFill)
    : Counts(slots, 0)
    , ToFill(toFill)
  {
  }
  void Fail(std::exception_ptr e)
  {
    this->Failed.Set(e);
    this->WakeAll();
  }
  void Stop()
  {
    this->Failed.Stop.store(true);
    this->WakeAll();
  }
  void WakeAll()
  {
    this->Filled.Wake();
    this->Scanned.Wake();
    this->Consumed.Wake();
  }

  LayerCounter Filled;   // layers whose densities are ready
  LayerCounter Scanned;  // layers whose mask is ready
  LayerCounter Consumed; // layers whose buffers are free again
  Failure Failed;
  std::vector<vtkIdType> Counts;
  const int ToFill;      // layers to fill: the run's, and its last one's successor if any
  std::mutex Filling;    // held by the thread that fills; guards Next
  int Next = 0;          // the next layer to fill
};

//------------------------------------------------------------------------------
float* vtkErrorDiffusionLayerRunner::DensitySlot(int k)
{
  return this->Densities.data() + static_cast<size_t>(k % this->Slots) * this->LayerSize;
}

//------------------------------------------------------------------------------
vtkErrorDiffusionLayerRunner::Layer vtkErrorDiffusionLayerRunner::LayerOf(int k, vtkIdType count)
{
  Layer layer;
  layer.Index = k;
  layer.Count = count;
  layer.Density = this->DensitySlot(k);
  layer.Mask = this->LayerMasks[k % this->Slots];
  return layer;
}

//------------------------------------------------------------------------------
// Scans layer k, whose densities (and its successor's) are filled.
vtkIdType vtkErrorDiffusionLayerRunner::ScanLayer(vtkErrorDiffusionKernel& kernel, int k)
{
  const bool hasNext = k + 1 < this->Layers || this->LastHasNext;
  unsigned char* mask = this->Work->MaskStorage(k);
  if (!mask)
  {
    mask = this->Masks.data() + static_cast<size_t>(k % this->Slots) * this->LayerSize;
  }
  this->LayerMasks[k % this->Slots] = mask; // published to the consumer with the count
  this->Work->BeforeScan(k, this->DensitySlot(k));
  return kernel.ProcessLayer(
    this->DensitySlot(k), hasNext ? this->DensitySlot(k + 1) : nullptr, mask);
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionLayerRunner::Run(
  vtkErrorDiffusionKernel& kernel, Stages& stages, int nx, int ny, int nz, bool lastHasNext)
{
  this->Error.clear();
  this->Work = &stages;
  if (nx <= 0 || ny <= 0 || nz <= 0)
  {
    stages.Finish(0);
    return true;
  }
  this->Layers = nz;
  this->LastHasNext = lastHasNext;
  // Two buffers suffice in turn; eight let the filling, the scan and the
  // consumer each run a few layers apart.
  this->Slots = this->Threaded ? 8 : 2;
  this->LayerSize = static_cast<size_t>(nx) * static_cast<size_t>(ny);
  try
  {
    this->Densities.resize(this->Slots * this->LayerSize);
    this->Masks.resize(this->Slots * this->LayerSize);
  }
  catch (const std::exception& e)
  {
    this->Error = std::string("cannot allocate the layer buffers: ") + e.what();
    return false;
  }
  this->LayerMasks.assign(this->Slots, nullptr);
  const bool done = this->Threaded ? this->RunThreaded(kernel) : this->RunSequential(kernel);
  this->Work = nullptr;
  return done;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionLayerRunner::ReleaseBuffers()
{
  this->Densities = std::vector<float>();
  this->Masks = std::vector<unsigned char>();
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionLayerRunner::SwapBuffers(vtkErrorDiffusionLayerRunner& other)
{
  this->Densities.swap(other.Densities);
  this->Masks.swap(other.Masks);
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionLayerRunner::RunSequential(vtkErrorDiffusionKernel& kernel)
{
  try
  {
    vtkIdType total = 0;
    this->Work->Fill(0, this->DensitySlot(0));
    for (int k = 0; k < this->Layers; ++k)
    {
      if (k + 1 < this->Layers || this->LastHasNext)
      {
        this->Work->Fill(k + 1, this->DensitySlot(k + 1));
      }
      const vtkIdType count = this->ScanLayer(kernel, k);
      total += count;
      if (!this->Work->Consume(this->LayerOf(k, count)))
      {
        return false;
      }
    }
    this->Work->Finish(total);
    return true;
  }
  catch (...)
  {
    this->Error = Describe(std::current_exception());
    return false;
  }
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionLayerRunner::RunThreaded(vtkErrorDiffusionKernel& kernel)
{
  ThreadState state(this->Slots, this->Layers + (this->LastHasNext ? 1 : 0));
  std::thread scanner([&]() { this->ScanAll(kernel, state); });
  const bool complete = this->ConsumeAll(state);
  if (!complete)
  {
    state.Stop();
  }
  scanner.join();
  if (state.Failed.Error)
  {
    this->Error = Describe(state.Failed.Error);
    return false;
  }
  return complete;
}

//------------------------------------------------------------------------------
// The layers below `target` filled (at most all of them), each into a slot
// whose layer was consumed; false when the run stopped. The caller holds
// state.Filling.
bool vtkErrorDiffusionLayerRunner::FillUpTo(ThreadState& state, int target)
{
  for (target = std::min(target, state.ToFill); state.Next < target;)
  {
    if (!this->WaitForSlot(state, state.Next))
    {
      return false;
    }
    this->FillNext(state);
  }
  return true;
}

//------------------------------------------------------------------------------
// The scan thread: waits until the slot of layer k is free (its previous layer
// consumed), doing the idle work it is given meanwhile; false when the run
// stopped.
bool vtkErrorDiffusionLayerRunner::WaitForSlot(ThreadState& state, int k)
{
  const int consumed = k - this->Slots + 1;
  while (state.Consumed.Get() < consumed && !state.Failed.Stop.load() && this->Work->Idle())
  {
  }
  return state.Consumed.WaitFor(consumed, state.Failed.Stop);
}

//------------------------------------------------------------------------------
// Fills layer state.Next, whose slot is free, and says so. The caller holds
// state.Filling.
void vtkErrorDiffusionLayerRunner::FillNext(ThreadState& state)
{
  this->Work->Fill(state.Next, this->DensitySlot(state.Next));
  ++state.Next;
  state.Filled.Advance(state.Next);
}

//------------------------------------------------------------------------------
// The calling thread, idle: fills the next layer if no one is filling and
// its slot is free (without waiting); false when there was nothing to do.
bool vtkErrorDiffusionLayerRunner::FillOneAhead(ThreadState& state)
{
  std::unique_lock<std::mutex> lock(state.Filling, std::try_to_lock);
  if (!lock.owns_lock() || state.Next >= state.ToFill ||
    state.Consumed.Get() < state.Next - this->Slots + 1)
  {
    return false;
  }
  this->FillNext(state);
  return true;
}

//------------------------------------------------------------------------------
// The scan thread: every layer once its densities and its successor's are
// filled (by itself when the calling thread has not), then Finish.
void vtkErrorDiffusionLayerRunner::ScanAll(vtkErrorDiffusionKernel& kernel, ThreadState& state)
{
  try
  {
    vtkIdType total = 0;
    for (int k = 0; k < this->Layers; ++k)
    {
      // Layers k and k + 1 filled: by the other thread, or now by this one.
      const int need = std::min(k + 2, state.ToFill);
      if (state.Filled.Get() < need)
      {
        std::lock_guard<std::mutex> lock(state.Filling);
        if (!this->FillUpTo(state, need))
        {
          return;
        }
      }
      const vtkIdType count = this->ScanLayer(kernel, k);
      total += count;
      state.Counts[k % this->Slots] = count;
      state.Scanned.Advance(k + 1);
    }
    this->Work->Finish(total);
  }
  catch (...)
  {
    state.Fail(std::current_exception());
  }
}

//------------------------------------------------------------------------------
// The calling thread: consumes the layers in order, filling ahead while it
// waits for the next; false when the consumer stopped or anything threw.
bool vtkErrorDiffusionLayerRunner::ConsumeAll(ThreadState& state)
{
  try
  {
    for (int k = 0; k < this->Layers; ++k)
    {
      while (state.Scanned.Get() < k + 1 && !state.Failed.Stop.load() && this->FillOneAhead(state))
      {
      }
      const bool consumed = state.Scanned.WaitFor(k + 1, state.Failed.Stop) &&
        this->Work->Consume(this->LayerOf(k, state.Counts[k % this->Slots]));
      state.Consumed.Advance(k + 1);
      if (!consumed)
      {
        return false;
      }
    }
    return true;
  }
  catch (...)
  {
    state.Fail(std::current_exception());
    return false;
  }
}
