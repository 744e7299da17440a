// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// White noise (Bernoulli g per voxel) on 64^3: flat mean power 1 - g, an
// isotropic spectrum whose shell variance is the exponential law's (anisotropy
// 1, 0 dB, for one realization; 1/R for R averaged realizations) and a
// low-frequency ratio equal to the share of the spectrum inside |f| < f_g.
#include "TestBlueNoiseSpectrumUtilities.h"

#include <cmath>

using namespace spectrum_test;

namespace
{
// Volume of the ball |f| < radius inside the unit frequency cube [-1/2, 1/2]^3
// (the whole spectrum, volume 1), by midpoint integration over (fx, fy).
double BallInCube(double radius)
{
  const int n = 2000;
  const double h = 1.0 / n;
  double volume = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const double x = -0.5 + (i + 0.5) * h;
    for (int j = 0; j < n; ++j)
    {
      const double y = -0.5 + (j + 0.5) * h;
      const double z2 = radius * radius - x * x - y * y;
      if (z2 > 0.0)
      {
        volume += std::min(1.0, 2.0 * std::sqrt(z2)) * h * h;
      }
    }
  }
  return volume;
}

void CheckWhiteNoise(double g, int realizations, std::mt19937& rng)
{
  const int n = 64;
  const int dims[3] = { n, n, n };
  const std::string what = "white noise g=" + Str(g) + " R=" + Str(realizations);
  vtkBlueNoiseSpectrumKernel kernel;
  std::string error;
  if (!Check(kernel.SetDimensions(n, n, n, &error), what + ": " + error))
  {
    return;
  }
  for (int i = 0; i < realizations; ++i)
  {
    const std::vector<unsigned char> mask = RandomMask(dims, g, rng);
    if (!Check(kernel.AddRealization(mask.data(), &error), what + ": " + error))
    {
      return;
    }
  }
  Result r;
  if (!Check(kernel.Compute(r, &error), what + ": " + error))
  {
    return;
  }
  CheckFinite(r, what);
  Check(r.Realizations == realizations, what + ": " + Str(r.Realizations) + " realizations");
  Check(std::abs(r.Density - g) < 0.01 * g, what + ": density " + Str(r.Density));
  Check(TotalCount(r) == n * n * n - 1, what + ": shell counts add up to " + Str(TotalCount(r)));
  Check(r.RadialPower.size() == static_cast<std::size_t>(std::lround(std::sqrt(3.0) * n / 2)),
    what + ": " + Str(r.RadialPower.size()) + " shells");

  // Mean power: 1 - g on every well-populated shell. The shell mean of R
  // averaged exponential periodograms over count / 2 independent frequencies
  // has a relative standard deviation of 1 / sqrt(R count / 2).
  const double expected = 1.0 - g;
  double weighted = 0.0;
  long long samples = 0;
  for (std::size_t i = 3; i < r.RadialPower.size(); ++i)
  {
    const int shell = static_cast<int>(i) + 1;
    if (shell > n / 2 && r.ShellCount[i] < 1000)
    {
      continue;
    }
    const double sigma = 1.0 / std::sqrt(realizations * r.ShellCount[i] / 2.0);
    const double tolerance = std::max(0.05, 4.0 * sigma);
    Check(std::abs(r.RadialPower[i] / expected - 1.0) <= tolerance,
      what + " shell " + Str(shell) + ": power " + Str(r.RadialPower[i]) + ", expected " +
        Str(expected) + " within " + Str(100 * tolerance) + "%");
    weighted += r.RadialPower[i] * r.ShellCount[i];
    samples += r.ShellCount[i];
  }
  Check(std::abs(weighted / samples / expected - 1.0) <= 0.01,
    what + ": mean power over the shells " + Str(weighted / samples));

  // Anisotropy: var / mean^2 of a mean of R exponentials is 1 / R.
  double meanDB = 0.0;
  int shells = 0;
  for (int shell = 4; shell <= n / 2; ++shell)
  {
    meanDB += r.AnisotropyDB[shell - 1];
    ++shells;
  }
  meanDB /= shells;
  const double expectedDB = -10.0 * std::log10(static_cast<double>(realizations));
  Check(std::abs(meanDB - expectedDB) < 0.5,
    what + ": mean anisotropy " + Str(meanDB) + " dB, expected " + Str(expectedDB) + " dB");

  // Low-frequency ratio: flat power, so the share of the spectrum's volume
  // inside the ball of radius f_g.
  CheckClose(r.PrincipalFrequency, std::cbrt(r.Density), 1e-15, what + " f_g");
  const double ball = BallInCube(r.PrincipalFrequency);
  Check(std::abs(r.LowFrequencyRatio / ball - 1.0) <= 0.1,
    what + ": L = " + Str(r.LowFrequencyRatio) + ", ball volume " + Str(ball));
  if (g < 0.2)
  {
    // The ball is still inside the cube: its volume is 4/3 pi f_g^3 = 4/3 pi g.
    CheckClose(ball, 4.0 / 3.0 * 3.141592653589793 * r.Density, 1e-3, what + " ball volume");
  }
  CheckClose(r.TargetValue, 0.02 * r.LowFrequencyRatio + 0.98 * r.Symmetry, 1e-15, what + " T");
}
}

int main()
{
  std::mt19937 rng(20240531);
  CheckWhiteNoise(0.1, 1, rng);
  CheckWhiteNoise(0.3, 1, rng);
  CheckWhiteNoise(0.1, 16, rng);
  CheckWhiteNoise(0.3, 16, rng);
  return bluenoise_test::Summary("TestBlueNoiseSpectrumWhiteNoise");
}
