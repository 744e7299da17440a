// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkPoissonDiskKernel: counts within 1 % of the sum of g on constant and
// varying densities, the conflict rule (no two samples in conflict, every
// other active voxel in conflict with a sample), the density followed on a
// ramp, empty and saturated voxels, determinism, bad input.
#include "PeerKernelTestUtilities.h"
#include "vtkPoissonDiskKernel.h"

#include <cmath>
#include <iostream>

namespace
{
using namespace bluenoise_test;

// The documented accuracy: within 1 % of sum g (the search stops at 0.5 %).
const double CountTolerance = 0.01;

void CheckCounts(std::vector<unsigned char>& mask)
{
  struct Case
  {
    const char* What;
    Volume Density;
  };
  const Case cases[] = {
    { "constant 64^3, 8/255", MakeConstantDensity(64, 8.0f / 255.0f) },
    { "constant 64^3, 32/255", MakeConstantDensity(64, 32.0f / 255.0f) },
    { "constant 48^3, 180/255", MakeConstantDensity(48, 180.0f / 255.0f) },
    { "ramp 64^3", MakeRamp(64) },
    { "waves 48 x 40 x 56", MakeDensity(48, 40, 56, [](int x, int y, int z) {
        return 0.1f + 0.08f * std::sin(x / 5.0f) * std::sin(y / 7.0f) * std::cos(z / 6.0f);
      }) },
    { "half empty, saturated block", MakeDensity(40, 40, 40, [](int x, int y, int z) {
        return z < 10 ? 0.0f : (x < 8 && y < 8 ? 1.0f : 0.04f);
      }) },
  };
  for (const auto& c : cases)
  {
    vtkPoissonDiskKernel kernel;
    kernel.SetSeed(5);
    const vtkIdType n = Run(kernel, c.Density, mask);
    const double sum = c.Density.Sum();
    std::cout << c.What << ": " << n << " samples for sum g = " << sum << " ("
              << 100.0 * (n - sum) / sum << " %), " << kernel.GetNumberOfLevels() << " levels, "
              << kernel.GetNumberOfPasses() << " runs, margin " << kernel.GetMargin() << std::endl;
    Check(n == CountOf(mask), std::string(c.What) + ": the count is the mask's");
    Check(std::abs(n - sum) <= CountTolerance * sum,
      std::string(c.What) + ": count " + Str(n) + " within 1 % of " + Str(sum));
    Check(std::abs(kernel.GetExpectedCount() - sum) < 1e-6 * sum,
      std::string(c.What) + ": GetExpectedCount is the sum of g");
  }
}

// The rule of the class documentation, recomputed here: a and b conflict iff
// |a - b|^2 + h(a, b) < min(r_a, r_b)^2 with r = c g^(-1/3). No two samples
// conflict; with extendFaces off (the whole grid is sampled) every active voxel
// that is not a sample conflicts with one (maximality).
void CheckConflictRule(const char* what, const Volume& volume, bool extendFaces)
{
  vtkPoissonDiskKernel kernel;
  kernel.SetSeed(9);
  kernel.SetExtendSupport(extendFaces);
  std::vector<unsigned char> mask;
  Run(kernel, volume, mask);
  const int nx = volume.Dims[0], ny = volume.Dims[1], nz = volume.Dims[2];
  auto radius = [&](vtkIdType v) { return kernel.GetRadius(v); };
  std::vector<unsigned char> covered(mask.size(), 0);
  long conflicts = 0;
  for (vtkIdType a = 0; a < volume.Size(); ++a)
  {
    if (!mask[a] || radius(a) == 0.0)
    {
      continue;
    }
    const int ax = static_cast<int>(a % nx), ay = static_cast<int>((a / nx) % ny);
    const int az = static_cast<int>(a / (static_cast<vtkIdType>(nx) * ny));
    const int reach = static_cast<int>(std::ceil(radius(a)));
    for (int z = std::max(0, az - reach); z <= std::min(nz - 1, az + reach); ++z)
    {
      for (int y = std::max(0, ay - reach); y <= std::min(ny - 1, ay + reach); ++y)
      {
        for (int x = std::max(0, ax - reach); x <= std::min(nx - 1, ax + reach); ++x)
        {
          const vtkIdType b = x + static_cast<vtkIdType>(nx) * (y + static_cast<vtkIdType>(ny) * z);
          if (b == a || radius(b) == 0.0)
          {
            continue;
          }
          const double smaller = std::min(radius(a), radius(b));
          const double r2 = smaller * smaller;
          const double d2 = (x - ax) * (x - ax) + (y - ay) * (y - ay) + (z - az) * (z - az);
          if (d2 + kernel.GetPairDither(a, b) < r2)
          {
            conflicts += mask[b] ? 1 : 0;
            covered[b] = 1;
          }
        }
      }
    }
  }
  Check(conflicts == 0, std::string(what) + ": " + Str(conflicts) + " pairs of samples conflict");
  if (!extendFaces)
  {
    long uncovered = 0;
    for (vtkIdType v = 0; v < volume.Size(); ++v)
    {
      uncovered += (radius(v) > 0.0 && !mask[v] && !covered[v]) ? 1 : 0;
    }
    Check(uncovered == 0,
      std::string(what) + ": " + Str(uncovered) + " active voxels conflict with no sample");
  }
}
}

int main()
{
  std::vector<unsigned char> mask;
  CheckCounts(mask);

  const Volume constant = MakeConstantDensity(40, 16.0f / 255.0f);
  const Volume graded =
    MakeDensity(40, 36, 32, [](int x, int, int) { return 0.02f + 0.3f * x / 39.0f; });
  CheckConflictRule("constant 16/255, whole grid", constant, false);
  CheckConflictRule("constant 16/255, with margin", constant, true);
  CheckConflictRule("graded, whole grid", graded, false);
  CheckConflictRule("graded, with margin", graded, true);

  CheckRamp<vtkPoissonDiskKernel>("vtkPoissonDiskKernel", 0.04);
  CheckRim<vtkPoissonDiskKernel>("vtkPoissonDiskKernel", 64, 0.07);
  CheckEmptyAndSaturated<vtkPoissonDiskKernel>("vtkPoissonDiskKernel", mask);
  CheckDeterminism<vtkPoissonDiskKernel>("vtkPoissonDiskKernel", MakeRamp(32));
  CheckBadInput<vtkPoissonDiskKernel>("vtkPoissonDiskKernel");
  CheckProgress<vtkPoissonDiskKernel>("vtkPoissonDiskKernel");
  return Summary("TestPoissonDiskKernel");
}
