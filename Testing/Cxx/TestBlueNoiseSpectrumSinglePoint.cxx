// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// A single point has |B(f)| = 1 everywhere: P = 1 on every shell and segment,
// anisotropy 0, flat SRAPS (C = 0 by the constant-curve rule, S = 1), and L is
// the fraction of non-DC frequencies below f_g.
#include "TestBlueNoiseSpectrumUtilities.h"

#include <cmath>

using namespace spectrum_test;

namespace
{
void CheckSinglePoint(const int dims[3], const int point[3])
{
  const std::string what =
    "single point on " + Str(dims[0]) + "x" + Str(dims[1]) + "x" + Str(dims[2]);
  const std::size_t voxels = Voxels(dims);
  std::vector<unsigned char> mask(voxels, 0);
  mask[(static_cast<std::size_t>(point[2]) * dims[1] + point[1]) * dims[0] + point[0]] = 1;

  vtkBlueNoiseSpectrumKernel kernel;
  std::string error;
  if (!Check(kernel.SetDimensions(dims[0], dims[1], dims[2], &error), what + ": " + error) ||
    !Check(kernel.AddRealization(mask.data(), &error), what + ": " + error))
  {
    return;
  }
  Result r;
  if (!Check(kernel.Compute(r, &error), what + ": " + error))
  {
    return;
  }
  CheckFinite(r, what);
  const int lmin = std::min(dims[0], std::min(dims[1], dims[2]));
  for (std::size_t i = 0; i < r.RadialPower.size(); ++i)
  {
    const std::string shell = what + " shell " + Str(i + 1);
    Check(r.ShellCount[i] > 0, shell + " is empty");
    Check(std::abs(r.RadialPower[i] - 1.0) <= 1e-9, shell + " power " + Str(r.RadialPower[i]));
    Check(std::abs(r.Anisotropy[i]) <= 1e-9, shell + " anisotropy " + Str(r.Anisotropy[i]));
    Check(r.AnisotropyDB[i] <= -90.0 && r.AnisotropyDB[i] >= -300.0,
      shell + " anisotropy dB " + Str(r.AnisotropyDB[i]));
    Check(std::abs(r.Frequency[i] - static_cast<double>(i + 1) / lmin) <= 1e-15,
      shell + " frequency " + Str(r.Frequency[i]));
    for (double s : { r.SrapsXY[i], r.SrapsXZ[i], r.SrapsYZ[i] })
    {
      Check(s == 0.0 || std::abs(s - 1.0) <= 1e-9, shell + " segment power " + Str(s));
    }
  }
  Check(TotalCount(r) == static_cast<long long>(voxels) - 1,
    what + ": shell counts add up to " + Str(TotalCount(r)) + ", not V - 1");
  CheckClose(r.NumberOfPoints, 1.0, 1e-15, what + " N");
  CheckClose(r.Density, 1.0 / voxels, 1e-15, what + " g");
  CheckClose(r.PrincipalFrequency, std::cbrt(1.0 / voxels), 1e-15, what + " f_g");
  Check(r.SymmetryCorrelation == 0.0, what + ": C of flat curves is " + Str(r.SymmetryCorrelation));
  Check(r.Symmetry == 1.0, what + ": S is " + Str(r.Symmetry));

  // With flat power, L is the share of non-DC frequencies with |f| < f_g,
  // decided as |f|^6 < g^2 (see the kernel's definition).
  long long below = 0;
  for (int z = 0; z < dims[2]; ++z)
  {
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x)
      {
        const int k[3] = { x, y, z };
        double f[3];
        for (int a = 0; a < 3; ++a)
        {
          const int folded = 2 * k[a] < dims[a] ? k[a] : k[a] - dims[a];
          f[a] = static_cast<double>(folded) / dims[a];
        }
        const double f2 = (f[2] * f[2] + f[1] * f[1]) + f[0] * f[0];
        below += (f2 > 0.0 && f2 * f2 * f2 < r.Density * r.Density) ? 1 : 0;
      }
    }
  }
  CheckClose(r.LowFrequencyRatio, static_cast<double>(below) / (voxels - 1), 1e-12, what + " L");
  CheckClose(r.TargetValue, 0.02 * r.LowFrequencyRatio + 0.98 * r.Symmetry, 1e-15, what + " T");

  std::vector<double> spectrum;
  if (Check(kernel.GetCenteredPowerSpectrum(spectrum), what + ": no centered spectrum"))
  {
    const std::size_t center =
      (static_cast<std::size_t>(dims[2] / 2) * dims[1] + dims[1] / 2) * dims[0] + dims[0] / 2;
    double worst = 0.0;
    for (std::size_t i = 0; i < spectrum.size(); ++i)
    {
      worst = std::max(worst, std::abs(spectrum[i] - (i == center ? 0.0 : 1.0)));
    }
    Check(worst <= 1e-9, what + ": centered spectrum deviates from 1 by " + Str(worst));
  }

  // The one-call path gives the same numbers.
  Result once;
  if (Check(vtkBlueNoiseSpectrumKernel::Evaluate(mask.data(), dims, 0.02, once, &error),
        what + " Evaluate: " + error))
  {
    CheckSameResult(once, r, 1e-15, what + " Evaluate");
  }
}
}

int main()
{
  // g = 1/512, f_g = 1/8: the six frequencies with |f| = 1/8 lie on f_g, not
  // below it, so nothing is below (cbrt(2^-9) alone would round under 1/8).
  const int small[3] = { 8, 8, 8 };
  const int p0[3] = { 2, 7, 5 };
  CheckSinglePoint(small, p0);
  {
    std::vector<unsigned char> mask(512, 0);
    mask[100] = 1;
    Result r;
    vtkBlueNoiseSpectrumKernel::Evaluate(mask.data(), small, 0.02, r);
    Check(r.LowFrequencyRatio == 0.0, "one point in 8^3: L = " + Str(r.LowFrequencyRatio));
  }

  const int cube[3] = { 16, 16, 16 };
  const int p1[3] = { 3, 5, 7 };
  CheckSinglePoint(cube, p1);
  const int odd[3] = { 9, 12, 10 };
  const int p2[3] = { 8, 0, 4 };
  CheckSinglePoint(odd, p2);
  return bluenoise_test::Summary("TestBlueNoiseSpectrumSinglePoint");
}
