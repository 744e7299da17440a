// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The tight loop (BlueNoiseTightScan.h) for a process that is not a benchmark
// program: pvpython_update_pipeline.py loads this library with ctypes and times
// the loop in its own process, on the very array the sampler reads, so that
// the baseline neither runs under other conditions nor disturbs the sampler
// (a process of its own touched and freed the memory of a whole cube right
// before each timed update).
#include "BlueNoiseTightScan.h"

extern "C"
{
  /**
   * The fastest of three tight loops over the n^3 values (8-bit when
   * `floats` is 0, else float), densities scale * value, into the caller's
   * n^3 bytes `b`, in seconds; the samples of the last in `points`.
   */
  __attribute__((visibility("default"))) double bluenoise_tight_scan_seconds(
    const void* values, int n, int floats, double scale, unsigned char* b, long long* points)
  {
    vtkIdType count = 0;
    const double seconds = floats
      ? BlueNoiseTight::FastestSeconds(static_cast<const float*>(values), n, scale, b, count)
      : BlueNoiseTight::FastestSeconds(static_cast<const unsigned char*>(values), n, scale, b, count);
    *points = static_cast<long long>(count);
    return seconds;
  }
}
