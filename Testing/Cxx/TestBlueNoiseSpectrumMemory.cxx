// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The spectrum's peak memory against the class documentation: the kernel's
// buffers (vtkBlueNoiseSpectrumKernel::BufferBytes: about 8 bytes a grid
// point), 16 bytes a binned point and, with GenerateSpectrumImage, 8 bytes a
// grid point more. The peak is the process's resident high-water mark
// (VmHWM, reset through /proc/self/clear_refs) over one Update of a filter
// on points drawn on a 256^3 grid. Linux only; skipped under sanitizers,
// whose allocators keep freed memory.
#include "TestBlueNoiseSpectrumUtilities.h"
#include "vtkBlueNoiseSpectrum.h"

#include <fstream>
#include <iostream>
#include <random>
#include <string>

namespace
{
using namespace spectrum_test;

constexpr int Skip = 125; // ctest SKIP_RETURN_CODE

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool Sanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) ||                       \
  __has_feature(memory_sanitizer)
constexpr bool Sanitized = true;
#else
constexpr bool Sanitized = false;
#endif
#else
constexpr bool Sanitized = false;
#endif

// A /proc/self/status field in bytes; -1 when absent.
double StatusBytes(const std::string& field)
{
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key)
  {
    if (key == field + ":")
    {
      double kib = 0;
      status >> kib;
      return kib * 1024.0;
    }
    std::getline(status, key);
  }
  return -1.0;
}

bool ResetPeak()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5\n";
  return static_cast<bool>(clear.flush());
}

// Peak resident growth over one Update, after an Update that made the
// filter's FFTW plans (kept across executions, not part of a grid's cost).
double PeakGrowth(vtkBlueNoiseSpectrum* filter)
{
  filter->Modified();
  const double before = StatusBytes("VmRSS");
  ResetPeak();
  filter->Update();
  return StatusBytes("VmHWM") - before;
}
}

int main()
{
  if (Sanitized)
  {
    std::cout << "skipped: a sanitizer's allocator keeps freed memory\n";
    return Skip;
  }
  if (StatusBytes("VmHWM") < 0 || !ResetPeak())
  {
    std::cout << "skipped: no VmHWM to reset in /proc/self\n";
    return Skip;
  }
  const int dims[3] = { 256, 256, 256 };
  std::mt19937 rng(7);
  const std::vector<unsigned char> mask = RandomMask(dims, 0.05, rng);
  auto points = MaskPoints(mask, dims, [](int i, int j, int k, double x[3]) {
    x[0] = i;
    x[1] = j;
    x[2] = k;
  });
  const double origin[3] = { 0, 0, 0 };
  const double spacing[3] = { 1, 1, 1 };
  const int extent[6] = { 0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1 };
  AddSamplingGrid(points, origin, spacing, extent);
  const double n = static_cast<double>(points->GetNumberOfPoints());
  const double voxels = static_cast<double>(Voxels(dims));
  const double kernel = vtkBlueNoiseSpectrumKernel::BufferBytes(dims[0], dims[1], dims[2], false);
  // The output table, the threads' column blocks and the allocators' rounding.
  const double slack = 48.0 * 1024 * 1024;

  vtkNew<vtkBlueNoiseSpectrum> filter;
  filter->SetInputData(points);
  filter->Update();
  for (const bool image : { false, true })
  {
    filter->SetGenerateSpectrumImage(image);
    filter->Update(); // plans for this output
    const double documented = kernel + 16.0 * n + (image ? 8.0 * voxels : 0.0);
    const double growth = PeakGrowth(filter);
    const std::string what = std::string(image ? "with" : "without") + " the spectrum image";
    std::cout << what << ": peak growth " << growth / 1e6 << " MB for " << voxels
              << " grid points and " << n << " points (" << growth / voxels
              << " bytes a grid point); documented " << documented / 1e6 << " MB\n";
    Check(growth <= documented + slack,
      what + ": peak growth " + Str(growth / 1e6) + " MB, documented " + Str(documented / 1e6) +
        " MB (+ " + Str(slack / 1e6) + " MB)");
    // The measure sees the transform: a peak far below it means the
    // reading is broken, not that memory was saved.
    Check(growth >= 0.75 * kernel,
      what + ": peak growth " + Str(growth / 1e6) + " MB, below the transform's " +
        Str(kernel / 1e6) + " MB");
  }
  return bluenoise_test::Summary("TestBlueNoiseSpectrumMemory");
}
