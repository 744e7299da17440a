// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionLayerBacklog
 * @brief   The final layers of a vtkBlueNoiseRelaxation on their way to the
 *          output, emitted in order by whichever thread has time.
 *
 * The relaxation is the slowest step of a threaded run at low densities: the
 * thread that relaxes is busy while the scan thread waits for it. Turning a
 * final layer into points (Emit) need not wait on the relaxation, so the
 * relaxing thread queues the layers Push returns (AfterPush) and the scan
 * thread emits them to the Sink while it waits (EmitOne, from the layer
 * runner's Idle).
 *
 * A layer the relaxation returns keeps its buffers through the next Push only
 * (vtkBlueNoiseRelaxation's promise): BeforePush, called before each Push,
 * emits on the calling thread whatever the Push could overwrite and the other
 * thread has not emitted yet. A borrowed layer (the caller's buffers, valid
 * only until the caller goes on) is emitted at once, after the layers queued
 * before it. EmitAll empties the queue (after Flush, at the end of a slab:
 * Emit may read the input). Layers are emitted one at a time, in the order
 * they came, whatever the threads: the output does not depend on them.
 *
 * Threads: AfterPush, BeforePush, EmitAll and Clear on the thread that
 * relaxes; EmitOne on any. Emit runs under a lock, so what it writes is seen
 * by the next thread that emits.
 */
#ifndef vtkErrorDiffusionLayerBacklog_h
#define vtkErrorDiffusionLayerBacklog_h

#include "vtkBlueNoiseRelaxation.h"    // for vtkBlueNoiseRelaxation::Layer
#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <deque>      // for std::deque
#include <mutex>      // for std::mutex
#include <vector>     // for std::vector

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionLayerBacklog
{
public:
  using Layer = vtkBlueNoiseRelaxation::Layer;

  /// Where the final layers go.
  class Sink
  {
  public:
    virtual ~Sink() = default;
    virtual void Emit(const Layer& layer) = 0;
  };

  /// Where each final layer goes (not owned); set before the first one (empties the queue).
  void SetSink(Sink* sink);

  /// Before each Push: emits the layers it could overwrite.
  void BeforePush();

  /// The layers one Push (or Flush) returned: queued, a borrowed one emitted now.
  void AfterPush(const std::vector<Layer>& layers);

  /// Emits the oldest layer queued unless another thread is emitting; false when it did not.
  bool EmitOne();

  /// Emits every layer queued.
  void EmitAll();

  /// Drops the queue (a run that failed or was aborted).
  void Clear();

private:
  struct Entry
  {
    Layer Final;
    long Push = 0; // the number of the Push that returned it
  };
  void EmitThrough(long push);
  bool Take(long push, Layer& layer);

  Sink* Output = nullptr;
  std::mutex Queue;    // guards Entries
  std::mutex Emitting; // held while a layer is taken and emitted
  std::deque<Entry> Entries;
  long Pushes = 0; // AfterPush calls
};

#endif
