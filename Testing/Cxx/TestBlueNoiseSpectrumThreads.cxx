// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Kernels used from several threads at once: the FFTW plans of new shapes are
// made concurrently (under the kernel's lock) and the one-call Evaluate keeps a
// kernel per thread. Every concurrent result must equal the one computed
// afterwards on a single thread.
#include "TestBlueNoiseSpectrumUtilities.h"

#include <thread>

using namespace spectrum_test;

namespace
{
struct Job
{
  int Dims[3];
  std::vector<unsigned char> Mask;
  Result Concurrent;
  bool Ok = false;
};
}

int main()
{
  // Shapes no other code in this process has planned yet, interleaved so that
  // both threads plan and switch shapes.
  const int shapes[4][3] = { { 18, 14, 10 }, { 11, 13, 17 }, { 24, 20, 22 }, { 9, 16, 12 } };
  std::mt19937 rng(5);
  std::vector<Job> jobs(24);
  for (std::size_t i = 0; i < jobs.size(); ++i)
  {
    std::copy(shapes[i % 4], shapes[i % 4] + 3, jobs[i].Dims);
    jobs[i].Mask = RandomMask(jobs[i].Dims, 0.05 + 0.02 * (i % 5), rng);
  }

  const auto work = [&jobs](std::size_t first) {
    for (std::size_t i = first; i < jobs.size(); i += 2)
    {
      if (i % 3 == 0)
      {
        // A kernel of its own, two realizations (the mask and its shift).
        vtkBlueNoiseSpectrumKernel kernel;
        std::vector<unsigned char> shifted(jobs[i].Mask.begin() + 1, jobs[i].Mask.end());
        shifted.push_back(jobs[i].Mask.front());
        jobs[i].Ok = kernel.SetDimensions(jobs[i].Dims[0], jobs[i].Dims[1], jobs[i].Dims[2]) &&
          kernel.AddRealization(jobs[i].Mask.data()) && kernel.AddRealization(shifted.data()) &&
          kernel.Compute(jobs[i].Concurrent);
      }
      else
      {
        jobs[i].Ok = vtkBlueNoiseSpectrumKernel::Evaluate(
          jobs[i].Mask.data(), jobs[i].Dims, 0.02, jobs[i].Concurrent);
      }
    }
  };
  std::thread other(work, 1);
  work(0);
  other.join();

  for (std::size_t i = 0; i < jobs.size(); ++i)
  {
    const std::string what = "job " + Str(i);
    if (!Check(jobs[i].Ok, what + " failed"))
    {
      continue;
    }
    vtkBlueNoiseSpectrumKernel kernel;
    kernel.SetDimensions(jobs[i].Dims[0], jobs[i].Dims[1], jobs[i].Dims[2]);
    kernel.AddRealization(jobs[i].Mask.data());
    if (i % 3 == 0)
    {
      std::vector<unsigned char> shifted(jobs[i].Mask.begin() + 1, jobs[i].Mask.end());
      shifted.push_back(jobs[i].Mask.front());
      kernel.AddRealization(shifted.data());
    }
    Result sequential;
    kernel.Compute(sequential);
    CheckSameResult(jobs[i].Concurrent, sequential, 1e-12, what);
  }
  return bluenoise_test::Summary("TestBlueNoiseSpectrumThreads");
}
