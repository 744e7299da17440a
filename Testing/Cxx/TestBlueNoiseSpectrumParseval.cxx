// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Parseval: sum over all f of |B(f)|^2 = V sum b^2, so the non-DC power is
// sum_{f != 0} P(f) = (V sum b^2 - N^2) / N. Checked on the centered spectrum
// image and on the shell sums (RadialPower * ShellCount), for masks and
// non-integer counts, even and odd dimensions, and an average of realizations.
#include "TestBlueNoiseSpectrumUtilities.h"

using namespace spectrum_test;

namespace
{
double NonDCPower(const std::vector<double>& b)
{
  double n = 0.0, squares = 0.0;
  for (double v : b)
  {
    n += v;
    squares += v * v;
  }
  return (b.size() * squares - n * n) / n;
}

void CheckParseval(const int dims[3], bool mask, int realizations, std::mt19937& rng)
{
  const std::string what = std::string(mask ? "mask" : "counts") + " on " + Str(dims[0]) + "x" +
    Str(dims[1]) + "x" + Str(dims[2]) + " R=" + Str(realizations);
  vtkBlueNoiseSpectrumKernel kernel;
  std::string error;
  if (!Check(kernel.SetDimensions(dims[0], dims[1], dims[2], &error), what + ": " + error))
  {
    return;
  }
  double expected = 0.0;
  for (int i = 0; i < realizations; ++i)
  {
    bool added = false;
    std::vector<double> b;
    if (mask)
    {
      const std::vector<unsigned char> m = RandomMask(dims, 0.2, rng);
      b.assign(m.begin(), m.end());
      added = kernel.AddRealization(m.data(), &error);
    }
    else
    {
      b = RandomCounts(dims, rng);
      added = kernel.AddRealization(b.data(), &error);
    }
    if (!Check(added, what + ": " + error))
    {
      return;
    }
    expected += NonDCPower(b) / realizations;
  }

  Result r;
  std::vector<double> spectrum;
  if (!Check(kernel.Compute(r, &error), what + ": " + error) ||
    !Check(kernel.GetCenteredPowerSpectrum(spectrum), what + ": no centered spectrum"))
  {
    return;
  }
  double imageSum = 0.0;
  for (double p : spectrum)
  {
    imageSum += p;
  }
  double shellSum = 0.0;
  for (std::size_t i = 0; i < r.RadialPower.size(); ++i)
  {
    shellSum += r.RadialPower[i] * r.ShellCount[i];
  }
  Check(std::abs(imageSum / expected - 1.0) <= 1e-9,
    what + ": image power " + Str(imageSum) + ", Parseval " + Str(expected));
  Check(std::abs(shellSum / expected - 1.0) <= 1e-9,
    what + ": shell power " + Str(shellSum) + ", Parseval " + Str(expected));
  Check(TotalCount(r) == static_cast<long long>(Voxels(dims)) - 1,
    what + ": shell counts add up to " + Str(TotalCount(r)));
}
}

int main()
{
  std::mt19937 rng(7);
  const int cube[3] = { 20, 20, 20 };
  const int box[3] = { 12, 10, 14 };
  const int odd[3] = { 11, 7, 9 };
  for (const int* dims : { cube, box, odd })
  {
    CheckParseval(dims, true, 1, rng);
    CheckParseval(dims, false, 1, rng);
    CheckParseval(dims, false, 3, rng);
  }
  return bluenoise_test::Summary("TestBlueNoiseSpectrumParseval");
}
