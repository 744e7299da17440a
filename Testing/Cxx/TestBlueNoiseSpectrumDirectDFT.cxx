// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The kernel against a direct O(V^2) DFT over the full spectrum with two-pass
// statistics, written from the definitions in vtkBlueNoiseSpectrumKernel.h:
// every shell value, anisotropy, segmented curve, L, C, S, T and the centered
// spectrum to 1e-9, on cubic, non-cubic and odd grids, with and without
// averaging.
#include "TestBlueNoiseSpectrumUtilities.h"

#include <cmath>

using namespace spectrum_test;

namespace
{
const double Pi = 3.141592653589793;

double Pearson(const std::vector<double>& a, const std::vector<double>& b)
{
  const std::size_t n = a.size();
  if (n < 2)
  {
    return 0.0;
  }
  double ma = 0.0, mb = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    ma += a[i] / n;
    mb += b[i] / n;
  }
  double saa = 0.0, sbb = 0.0, sab = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
    sab += (a[i] - ma) * (b[i] - mb);
  }
  return (saa == 0.0 || sbb == 0.0) ? 0.0 : sab / std::sqrt(saa * sbb);
}

// The metric of `volumes` (each x fastest on `dims`), straight from the
// definitions. `centered` receives the zero-centered averaged spectrum.
Result Reference(const std::vector<std::vector<double>>& volumes, const int dims[3], double w,
  std::vector<double>& centered)
{
  const int lx = dims[0], ly = dims[1], lz = dims[2];
  const std::size_t voxels = Voxels(dims);
  std::vector<double> power(voxels, 0.0); // indexed by (kx, ky, kz), x fastest
  double pointSum = 0.0;
  for (const auto& b : volumes)
  {
    double n = 0.0;
    for (double v : b)
    {
      n += v;
    }
    pointSum += n;
    std::size_t k = 0;
    for (int kz = 0; kz < lz; ++kz)
    {
      for (int ky = 0; ky < ly; ++ky)
      {
        for (int kx = 0; kx < lx; ++kx, ++k)
        {
          double re = 0.0, im = 0.0;
          std::size_t v = 0;
          for (int z = 0; z < lz; ++z)
          {
            for (int y = 0; y < ly; ++y)
            {
              for (int x = 0; x < lx; ++x, ++v)
              {
                if (b[v] == 0.0)
                {
                  continue;
                }
                const double phase = 2.0 * Pi *
                  (static_cast<double>(kx * x % lx) / lx + static_cast<double>(ky * y % ly) / ly +
                    static_cast<double>(kz * z % lz) / lz);
                re += b[v] * std::cos(phase);
                im -= b[v] * std::sin(phase);
              }
            }
          }
          power[k] += (re * re + im * im) / n / volumes.size();
        }
      }
    }
  }

  Result r;
  r.Realizations = static_cast<int>(volumes.size());
  r.NumberOfPoints = pointSum / volumes.size();
  r.Density = r.NumberOfPoints / voxels;
  const double g = r.Density;
  const double h = g <= 0.5 ? g : std::max(0.0, 1.0 - g);
  r.PrincipalFrequency = std::cbrt(h);
  const int lmin = std::min(lx, std::min(ly, lz));

  // Shell samples: all values, and per segment.
  std::vector<std::vector<double>> shells, segments[3]; // segments: XY, XZ, YZ
  double total = 0.0, low = 0.0;
  std::size_t k = 0;
  for (int kz = 0; kz < lz; ++kz)
  {
    for (int ky = 0; ky < ly; ++ky)
    {
      for (int kx = 0; kx < lx; ++kx, ++k)
      {
        if (k == 0)
        {
          continue;
        }
        const int fold[3] = { 2 * kx < lx ? kx : kx - lx, 2 * ky < ly ? ky : ky - ly,
          2 * kz < lz ? kz : kz - lz };
        const double fx = static_cast<double>(fold[0]) / lx;
        const double fy = static_cast<double>(fold[1]) / ly;
        const double fz = static_cast<double>(fold[2]) / lz;
        const double f2 = fz * fz + fy * fy + fx * fx;
        const double f = std::sqrt(f2);
        const std::size_t shell = static_cast<std::size_t>(f * lmin + 0.5);
        if (shells.size() <= shell)
        {
          shells.resize(shell + 1);
          for (auto& s : segments)
          {
            s.resize(shell + 1);
          }
        }
        const double p = power[k];
        shells[shell].push_back(p);
        const double ax = std::abs(fx), ay = std::abs(fy), az = std::abs(fz);
        const int segment = (ax >= ay && ax >= az) ? 2 : (ay >= az ? 1 : 0);
        segments[segment][shell].push_back(p);
        total += p;
        if (f2 * f2 * f2 < h * h)
        {
          low += p;
        }
      }
    }
  }
  const auto mean = [](const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v)
    {
      m += x;
    }
    return v.empty() ? 0.0 : m / v.size();
  };
  for (std::size_t n = 1; n < shells.size(); ++n)
  {
    const double m = mean(shells[n]);
    double var = 0.0;
    for (double x : shells[n])
    {
      var += (x - m) * (x - m);
    }
    const double anisotropy =
      (shells[n].size() >= 2 && m > 0.0) ? var / (shells[n].size() - 1) / (m * m) : 0.0;
    r.Frequency.push_back(static_cast<double>(n) / lmin);
    r.RadialPower.push_back(m);
    r.Anisotropy.push_back(anisotropy);
    r.AnisotropyDB.push_back(anisotropy > 0.0 ? 10.0 * std::log10(anisotropy) : -300.0);
    r.SrapsXY.push_back(mean(segments[0][n]));
    r.SrapsXZ.push_back(mean(segments[1][n]));
    r.SrapsYZ.push_back(mean(segments[2][n]));
    r.ShellCount.push_back(static_cast<long long>(shells[n].size()));
  }
  std::vector<double> xy, xz, yz;
  for (std::size_t n = 1; n < shells.size() && static_cast<int>(n) <= lmin / 2; ++n)
  {
    if (!segments[0][n].empty() && !segments[1][n].empty() && !segments[2][n].empty())
    {
      xy.push_back(r.SrapsXY[n - 1]);
      xz.push_back(r.SrapsXZ[n - 1]);
      yz.push_back(r.SrapsYZ[n - 1]);
    }
  }
  r.LowFrequencyRatio = total > 0.0 ? low / total : 0.0;
  r.SymmetryCorrelation = (Pearson(xy, xz) + Pearson(xy, yz) + Pearson(xz, yz)) / 3.0;
  r.Symmetry = 1.0 - r.SymmetryCorrelation;
  r.TargetValue = w * r.LowFrequencyRatio + (1.0 - w) * r.Symmetry;

  centered.assign(voxels, 0.0);
  std::size_t c = 0;
  for (int k3 = 0; k3 < lz; ++k3)
  {
    for (int k2 = 0; k2 < ly; ++k2)
    {
      for (int k1 = 0; k1 < lx; ++k1, ++c)
      {
        const int kx = (k1 - lx / 2 + lx) % lx;
        const int ky = (k2 - ly / 2 + ly) % ly;
        const int kz = (k3 - lz / 2 + lz) % lz;
        const std::size_t source = (static_cast<std::size_t>(kz) * ly + ky) * lx + kx;
        centered[c] = source == 0 ? 0.0 : power[source];
      }
    }
  }
  return r;
}

void Compare(const int dims[3], int realizations, bool masks, double w, std::mt19937& rng)
{
  const std::string what = std::string(masks ? "masks" : "counts") + " on " + Str(dims[0]) + "x" +
    Str(dims[1]) + "x" + Str(dims[2]) + " R=" + Str(realizations);
  vtkBlueNoiseSpectrumKernel kernel;
  std::string error;
  if (!Check(kernel.SetDimensions(dims[0], dims[1], dims[2], &error), what + ": " + error))
  {
    return;
  }
  kernel.SetWeight(w);
  std::vector<std::vector<double>> volumes;
  for (int i = 0; i < realizations; ++i)
  {
    bool added = false;
    if (masks)
    {
      const std::vector<unsigned char> m = RandomMask(dims, 0.3, rng);
      volumes.emplace_back(m.begin(), m.end());
      added = kernel.AddRealization(m.data(), &error);
    }
    else
    {
      const std::vector<double> counts = RandomCounts(dims, rng);
      const std::vector<float> single(counts.begin(), counts.end());
      volumes.emplace_back(single.begin(), single.end());
      added = kernel.AddRealization(single.data(), &error);
    }
    if (!Check(added, what + ": " + error))
    {
      return;
    }
  }
  Result r;
  std::vector<double> spectrum;
  if (!Check(kernel.Compute(r, &error), what + ": " + error) ||
    !Check(kernel.GetCenteredPowerSpectrum(spectrum), what + ": no centered spectrum"))
  {
    return;
  }
  std::vector<double> expectedSpectrum;
  const Result expected = Reference(volumes, dims, w, expectedSpectrum);
  CheckSameResult(r, expected, 1e-9, what);
  for (std::size_t i = 0; i < r.AnisotropyDB.size() && i < expected.AnisotropyDB.size(); ++i)
  {
    CheckClose(r.AnisotropyDB[i], expected.AnisotropyDB[i], 1e-9,
      what + " shell " + Str(i + 1) + " AnisotropyDB");
  }
  Check(r.Dimensions[0] == dims[0] && r.Dimensions[1] == dims[1] && r.Dimensions[2] == dims[2],
    what + ": Result::Dimensions");
  // The correlation must be informative here, not the constant-curve fallback.
  Check(r.SymmetryCorrelation != 0.0, what + ": C is exactly 0");
  double worst = 0.0;
  for (std::size_t i = 0; i < spectrum.size(); ++i)
  {
    worst = std::max(worst,
      std::abs(spectrum[i] - expectedSpectrum[i]) / std::max(1.0, std::abs(expectedSpectrum[i])));
  }
  Check(worst <= 1e-9, what + ": centered spectrum differs by " + Str(worst));
}
}

int main()
{
  std::mt19937 rng(99);
  const int cube[3] = { 8, 8, 8 };
  const int box[3] = { 6, 8, 10 };
  const int odd[3] = { 7, 5, 9 };
  const int flat[3] = { 12, 4, 6 };
  Compare(cube, 1, true, 0.02, rng);
  Compare(cube, 2, true, 0.3, rng);
  Compare(box, 1, false, 0.02, rng);
  Compare(box, 2, true, 0.5, rng);
  Compare(odd, 2, false, 0.02, rng);
  Compare(flat, 1, true, 1.0, rng);
  return bluenoise_test::Summary("TestBlueNoiseSpectrumDirectDFT");
}
