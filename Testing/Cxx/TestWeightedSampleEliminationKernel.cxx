// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkWeightedSampleEliminationKernel: exactly round(sum of g) samples on
// constant, varying, noisy and partly saturated densities with every option,
// the density followed on a ramp, empty and saturated voxels, determinism,
// bad input.
#include "PeerKernelTestUtilities.h"
#include "vtkWeightedSampleEliminationKernel.h"

#include <cmath>
#include <iostream>

namespace
{
using namespace bluenoise_test;

// round(sum of g) as the class defines it: saturated voxels plus the rounded
// sum of the active ones.
vtkIdType Target(const Volume& v)
{
  double active = 0.0;
  vtkIdType saturated = 0;
  for (float g : v.Density)
  {
    saturated += g >= 1.0f ? 1 : 0;
    active += (g > 0.0f && g < 1.0f) ? g : 0.0;
  }
  return saturated + static_cast<vtkIdType>(std::llround(active));
}

void CheckExactCounts(std::vector<unsigned char>& mask)
{
  struct Case
  {
    const char* What;
    Volume Density;
  };
  vtkBlueNoiseRandom random;
  random.Seed(3, 3);
  const Case cases[] = {
    { "constant 64^3, 8/255", MakeConstantDensity(64, 8.0f / 255.0f) },
    { "constant 48^3, 32/255", MakeConstantDensity(48, 32.0f / 255.0f) },
    { "constant 32^3, 200/255 (every voxel a candidate)",
      MakeConstantDensity(32, 200.0f / 255.0f) },
    { "ramp 48^3", MakeRamp(48) },
    { "noise 30 x 20 x 25", MakeDensity(30, 20, 25, [&random](int, int, int) {
        const float u = random.Uniform();
        return u < 0.2f ? 0.0f : (u > 0.95f ? 1.0f : 0.3f * u);
      }) },
    { "three voxels of 0.4 (fewer candidates than samples are drawn)",
      MakeDensity(3, 1, 1, [](int, int, int) { return 0.4f; }) },
    { "a single voxel of 0.7", MakeDensity(1, 1, 1, [](int, int, int) { return 0.7f; }) },
  };
  for (const auto& c : cases)
  {
    for (int options = 0; options < 8; ++options)
    {
      vtkWeightedSampleEliminationKernel kernel;
      kernel.SetSeed(static_cast<std::uint64_t>(options));
      kernel.SetWeightLimiting((options & 1) == 0);
      kernel.SetExtendSupport((options & 2) == 0);
      kernel.SetCandidateRatio((options & 4) ? 2.0 : 5.0);
      const vtkIdType n = Run(kernel, c.Density, mask);
      const std::string what = std::string(c.What) + ", options " + Str(options);
      Check(n == Target(c.Density) && CountOf(mask) == n,
        what + ": " + Str(CountOf(mask)) + " samples, round(sum g) = " + Str(Target(c.Density)));
      if (options == 0)
      {
        std::cout << c.What << ": " << n << " samples from " << kernel.GetNumberOfCandidates()
                  << " candidates (margin " << kernel.GetMargin() << ")" << std::endl;
      }
    }
  }
}
}

int main()
{
  std::vector<unsigned char> mask;
  CheckExactCounts(mask);

  // About 5 candidates per sample inside the volume, more with the margin.
  vtkWeightedSampleEliminationKernel kernel;
  const Volume constant = MakeConstantDensity(40, 8.0f / 255.0f);
  kernel.SetExtendSupport(false);
  Run(kernel, constant, mask);
  const double ratio = static_cast<double>(kernel.GetNumberOfCandidates()) / Target(constant);
  Check(std::abs(ratio - 5.0) < 0.15, "5 candidates per sample, got " + Str(ratio));

  CheckRamp<vtkWeightedSampleEliminationKernel>("vtkWeightedSampleEliminationKernel", 0.04);
  CheckRim<vtkWeightedSampleEliminationKernel>("vtkWeightedSampleEliminationKernel", 64, 0.07);
  CheckEmptyAndSaturated<vtkWeightedSampleEliminationKernel>(
    "vtkWeightedSampleEliminationKernel", mask);
  CheckDeterminism<vtkWeightedSampleEliminationKernel>(
    "vtkWeightedSampleEliminationKernel", MakeRamp(32));
  CheckBadInput<vtkWeightedSampleEliminationKernel>("vtkWeightedSampleEliminationKernel");
  CheckProgress<vtkWeightedSampleEliminationKernel>("vtkWeightedSampleEliminationKernel");
  return Summary("TestWeightedSampleEliminationKernel");
}
