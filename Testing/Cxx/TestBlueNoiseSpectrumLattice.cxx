// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// A regular lattice of spacing s puts all its energy on the reciprocal lattice
// (frequencies that are multiples of 1/s on every axis), P = N there, and none
// anywhere else. Checked on the centered spectrum and on the shell sums.
#include "TestBlueNoiseSpectrumUtilities.h"

#include <cmath>
#include <map>

using namespace spectrum_test;

namespace
{
void CheckLattice(const int dims[3], int s, const int offset[3])
{
  const std::string what =
    "lattice s=" + Str(s) + " on " + Str(dims[0]) + "x" + Str(dims[1]) + "x" + Str(dims[2]);
  std::vector<unsigned char> mask(Voxels(dims), 0);
  double n = 0.0;
  for (int z = offset[2]; z < dims[2]; z += s)
  {
    for (int y = offset[1]; y < dims[1]; y += s)
    {
      for (int x = offset[0]; x < dims[0]; x += s)
      {
        mask[(static_cast<std::size_t>(z) * dims[1] + y) * dims[0] + x] = 1;
        n += 1.0;
      }
    }
  }

  vtkBlueNoiseSpectrumKernel kernel;
  std::string error;
  Result r;
  std::vector<double> spectrum;
  if (!Check(kernel.SetDimensions(dims[0], dims[1], dims[2], &error), what + ": " + error) ||
    !Check(kernel.AddRealization(mask.data(), &error), what + ": " + error) ||
    !Check(kernel.Compute(r, &error), what + ": " + error) ||
    !Check(kernel.GetCenteredPowerSpectrum(spectrum), what + ": no centered spectrum"))
  {
    return;
  }
  CheckFinite(r, what);

  // Reciprocal lattice: every folded k a multiple of L / s on every axis.
  const int lmin = std::min(dims[0], std::min(dims[1], dims[2]));
  std::map<int, double> expectedShellSum;
  double worstOff = 0.0;
  double worstOn = 0.0;
  int onCount = 0;
  std::size_t index = 0;
  for (int k = 0; k < dims[2]; ++k)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i, ++index)
      {
        const int folded[3] = { i - dims[0] / 2, j - dims[1] / 2, k - dims[2] / 2 };
        bool reciprocal = true;
        double f2 = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          reciprocal = reciprocal && (folded[a] % (dims[a] / s) == 0);
          const double f = static_cast<double>(folded[a]) / dims[a];
          f2 += f * f;
        }
        const bool dc = (folded[0] == 0 && folded[1] == 0 && folded[2] == 0);
        if (reciprocal && !dc)
        {
          worstOn = std::max(worstOn, std::abs(spectrum[index] - n));
          ++onCount;
          expectedShellSum[static_cast<int>(std::sqrt(f2) * lmin + 0.5)] += n;
        }
        else
        {
          worstOff = std::max(worstOff, std::abs(spectrum[index]));
        }
      }
    }
  }
  Check(onCount == s * s * s - 1, what + ": " + Str(onCount) + " reciprocal frequencies");
  Check(worstOn <= 1e-9 * n, what + ": power on the reciprocal lattice off N by " + Str(worstOn));
  Check(worstOff <= 1e-9 * n, what + ": power off the reciprocal lattice up to " + Str(worstOff));

  double total = 0.0;
  for (std::size_t i = 0; i < r.RadialPower.size(); ++i)
  {
    const int shell = static_cast<int>(i) + 1;
    const double sum = r.RadialPower[i] * r.ShellCount[i];
    const auto it = expectedShellSum.find(shell);
    const double expected = it == expectedShellSum.end() ? 0.0 : it->second;
    Check(std::abs(sum - expected) <= 1e-9 * n,
      what + " shell " + Str(shell) + ": power sum " + Str(sum) + ", expected " + Str(expected));
    total += sum;
  }
  CheckClose(total, n * (s * s * s - 1), 1e-12, what + " total power");
  CheckClose(r.NumberOfPoints, n, 0.0, what + " N");
}
}

int main()
{
  const int cube[3] = { 32, 32, 32 };
  const int origin[3] = { 0, 0, 0 };
  CheckLattice(cube, 4, origin);
  const int shifted[3] = { 1, 2, 3 };
  CheckLattice(cube, 4, shifted);
  const int box[3] = { 32, 16, 24 };
  CheckLattice(box, 4, shifted);
  const int coarse[3] = { 24, 24, 24 };
  CheckLattice(coarse, 8, shifted);
  return bluenoise_test::Summary("TestBlueNoiseSpectrumLattice");
}
