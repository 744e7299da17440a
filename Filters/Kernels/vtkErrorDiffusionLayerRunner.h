// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionLayerRunner
 * @brief   Runs a vtkErrorDiffusionKernel over the layers of a volume and hands
 *          each finished layer to a consumer, optionally on two threads.
 *
 * The error-diffusion scan is sequential, but preparing its input (mapping
 * the values of a layer to densities) and using its result (turning the
 * samples of a layer into points and attributes) are not: with
 * SetThreaded(true) the scan runs on a worker thread while the calling thread
 * consumes, in order, the layers behind it. Whichever thread would otherwise
 * wait fills the densities of the layers ahead: the calling thread while the
 * next layer is not scanned yet, the scan thread when the layer it needs is
 * not filled yet, so the filling goes to the side with time to spare (the
 * scan's, where consuming costs more, as the relaxation does; the calling
 * thread's otherwise). Work the consumer leaves behind can go the same way:
 * while the scan thread waits for the consumer to free a buffer, it calls
 * Idle() until that returns false. The calling thread is the one
 * that consumes, so a consumer may report progress and check for abort the
 * way a VTK filter must (from the thread that called it). The worker is a
 * std::thread of the runner's own (a two-stage pipeline, which vtkSMPTools
 * does not express); the caller decides whether to use it
 * (vtkBlueNoiseThreads::Available() says whether there is a second core).
 *
 * What the run does around the scan comes from a Stages object, as the work
 * of a vtkSMPTools loop comes from its functor: the runner knows nothing of
 * who implements it. Per layer k (0-based in the run) the runner asks
 * Fill(k, density) for the densities (the kernel also needs the next
 * layer's, so Fill runs at least one layer ahead of the scan), calls
 * BeforeScan(k, density), lets the kernel sample layer k into the layer's
 * mask (the buffer MaskStorage(k) returns, or one of the runner's own when it
 * returns nullptr), then calls Consume with the layer's densities, mask and
 * count. The buffers of a layer stay valid until Consume returns. After the
 * last layer Finish(total) runs on the scan thread (it may start before the
 * consumer has caught up): a place for work that needs only the number of
 * samples.
 *
 * Waiting: a thread that waits for the other spins for a few microseconds and
 * then sleeps, and is woken only when it sleeps, so a machine whose other
 * cores are busy loses no time to spinning (a longer spin halved the speed
 * when another process held the second core).
 *
 * The result does not depend on threading: the kernel sees the same layers in
 * the same order either way. Memory: a ring of 8 layers of densities and
 * masks when threaded, 2 when not, kept until ReleaseBuffers() or the
 * runner's end.
 *
 * Consume runs on the calling thread; Fill on either thread, one call at a
 * time, in layer order; MaskStorage, BeforeScan, Finish and Idle on the scan
 * thread, and must not touch what the others touch (Idle, which runs while
 * Consume does, synchronizes with it itself). An exception thrown by any
 * stage stops the run; Run then returns false and GetError() says what was
 * thrown.
 */
#ifndef vtkErrorDiffusionLayerRunner_h
#define vtkErrorDiffusionLayerRunner_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <string>
#include <vector>

class vtkErrorDiffusionKernel;

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionLayerRunner
{
public:
  /// One sampled layer, as the consumer sees it.
  struct Layer
  {
    int Index = 0;                       ///< 0-based layer of the run
    const float* Density = nullptr;      ///< nx * ny densities, x fastest
    const unsigned char* Mask = nullptr; ///< nx * ny flags, 1 for a sample
    vtkIdType Count = 0;                 ///< samples in the layer
  };

  /// The work around the scan (see the class comment for the threads).
  class Stages
  {
  public:
    virtual ~Stages() = default;
    /// The densities of layer k into `density` (nx * ny values).
    virtual void Fill(int layer, float* density) = 0;
    /// A finished layer, on the calling thread; false stops the run.
    virtual bool Consume(const Layer& layer) = 0;
    /// Where the kernel writes layer k's mask; nullptr: a buffer of the runner's.
    virtual unsigned char* MaskStorage(int) { return nullptr; }
    /// Just before layer k is scanned.
    virtual void BeforeScan(int, const float*) {}
    /// Work for the scan thread while the consumer is behind (threaded runs
    /// only); false when there is none.
    virtual bool Idle() { return false; }
    /// After the last layer is scanned, with the number of samples.
    virtual void Finish(vtkIdType) {}
  };

  void SetThreaded(bool threaded) { this->Threaded = threaded; }
  bool GetThreaded() const { return this->Threaded; }

  /**
   * Samples nz layers of nx * ny voxels with a kernel on which Begin() was
   * called for that shape (it may have sampled layers before: a run can be
   * one slab of a volume), with `stages` around the scan. The last layer's
   * successor is layer nz (filled with Fill) when lastHasNext, none
   * otherwise. Returns true when every layer was consumed and Finish ran;
   * false when Consume stopped the run or a stage threw (see GetError()).
   */
  bool Run(vtkErrorDiffusionKernel& kernel, Stages& stages, int nx, int ny, int nz,
    bool lastHasNext = false);

  /**
   * Frees the ring of layer buffers, which a runner keeps from one Run to the
   * next (a run in chunks of a few layers) until this or its destruction.
   */
  void ReleaseBuffers();

  /// Trades the ring with `other`'s (see vtkErrorDiffusionScan::SwapLayerBuffers).
  void SwapBuffers(vtkErrorDiffusionLayerRunner& other);

  /// Why the last Run failed; empty when it did not, or when Consume stopped it.
  const std::string& GetError() const { return this->Error; }

private:
  bool RunSequential(vtkErrorDiffusionKernel& kernel);
  bool RunThreaded(vtkErrorDiffusionKernel& kernel);
  struct ThreadState;
  bool FillUpTo(ThreadState& state, int target);
  bool WaitForSlot(ThreadState& state, int k);
  bool FillOneAhead(ThreadState& state);
  void FillNext(ThreadState& state);
  void ScanAll(vtkErrorDiffusionKernel& kernel, ThreadState& state);
  bool ConsumeAll(ThreadState& state);
  vtkIdType ScanLayer(vtkErrorDiffusionKernel& kernel, int k);
  Layer LayerOf(int k, vtkIdType count);
  float* DensitySlot(int k);

  Stages* Work = nullptr; // during Run
  bool Threaded = false;
  std::string Error;

  // The layers of one Run and their ring of buffers.
  int Layers = 0;
  bool LastHasNext = false;
  int Slots = 2;
  size_t LayerSize = 0;
  std::vector<float> Densities;
  std::vector<unsigned char> Masks;
  std::vector<unsigned char*> LayerMasks; // the mask of the layer in each slot
};

#endif
