// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBlueNoiseThreads
 * @brief   Where the module decides on threads beyond vtkSMPTools, and why.
 *
 * The module's parallel loops use vtkSMPTools. Debian's VTK and ParaView
 * default to its Sequential backend, which runs every loop on the calling
 * thread: a stock ParaView would sample on one core however many it has.
 * Where that backend is in use, two jobs get threads of their own, both
 * decided here:
 * - Split(): independent parts of one pass (the budget statistics of the
 *   densities) on up to Available() threads, the caller's included;
 * - ForEach(): independent tasks (the z-parts of a sampler's scan) spread
 *   over as many threads;
 * - the scan's worker thread (vtkErrorDiffusionLayerRunner): the scan of the
 *   layers runs beside the thread that reads their densities, when
 *   Available() is more than one. It is a pipeline of two stages, which
 *   vtkSMPTools does not express, so it has its own std::thread whatever the
 *   backend.
 * With any other backend vtkSMPTools decides (VTK_SMP_MAX_THREADS, or its
 * own estimate); with the Sequential backend, VTK_SMP_MAX_THREADS, or else the
 * hardware. Every result is the same whatever the number of threads.
 */
#ifndef vtkBlueNoiseThreads_h
#define vtkBlueNoiseThreads_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <functional>

class VTKFILTERSBLUENOISE_EXPORT vtkBlueNoiseThreads
{
public:
  /// Whether vtkSMPTools runs its loops on the calling thread alone.
  static bool SequentialBackend();

  /// The threads the module may use (see the class comment); at least 1.
  static int Available();

  /**
   * Threads of its own for a pass split into parts: Available() with the
   * Sequential backend, else 1 (vtkSMPTools spreads the pass itself).
   */
  static int OwnThreads();

  /**
   * task(part) for part in [0, parts): part 0 on the calling thread, the
   * others on threads of their own, all joined before it returns. The parts
   * must be independent.
   */
  static void Split(int parts, const std::function<void(int)>& task);

  /**
   * task(i) for i in [0, count), each once, on up to Available() threads: the
   * Sequential backend's on threads of its own (the caller's included, each
   * taking the next i when done), any other backend's through vtkSMPTools.
   * The tasks must be independent; all are done when it returns.
   */
  static void ForEach(int count, const std::function<void(int)>& task);
};

#endif
