// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Checks shared by the tests of the point-set peers (vtkPoissonDiskKernel,
// vtkWeightedSampleEliminationKernel): both take nx, ny, nz, a density and a
// mask and return the sample count, so the checks are templates on the kernel.
#ifndef PeerKernelTestUtilities_h
#define PeerKernelTestUtilities_h

#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseRandom.h"
#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace bluenoise_test
{
struct Volume
{
  int Dims[3] = { 0, 0, 0 };
  std::vector<float> Density;
  vtkIdType Size() const { return static_cast<vtkIdType>(this->Density.size()); }
  double Sum() const
  {
    double sum = 0.0;
    for (float g : this->Density)
    {
      sum += g > 0.0f ? std::min(g, 1.0f) : 0.0;
    }
    return sum;
  }
};

inline Volume MakeDensity(int nx, int ny, int nz, const std::function<float(int, int, int)>& f)
{
  Volume v;
  v.Dims[0] = nx;
  v.Dims[1] = ny;
  v.Dims[2] = nz;
  v.Density.reserve(static_cast<size_t>(nx) * ny * nz);
  for (int z = 0; z < nz; ++z)
  {
    for (int y = 0; y < ny; ++y)
    {
      for (int x = 0; x < nx; ++x)
      {
        v.Density.push_back(f(x, y, z));
      }
    }
  }
  return v;
}

inline Volume MakeConstantDensity(int n, float g)
{
  return MakeDensity(n, n, n, [g](int, int, int) { return g; });
}

/// g(z) rising linearly from 0.01 to 0.25 along z.
inline Volume MakeRamp(int n)
{
  return MakeDensity(
    n, n, n, [n](int, int, int z) { return 0.01f + 0.24f * static_cast<float>(z) / (n - 1); });
}

inline vtkIdType CountOf(const std::vector<unsigned char>& mask)
{
  return static_cast<vtkIdType>(std::count(mask.begin(), mask.end(), 1));
}

/// Independent Bernoulli(p) voxels (hit and miss), for white-noise baselines.
inline std::vector<unsigned char> WhiteNoiseMask(vtkIdType voxels, double p, std::uint64_t seed)
{
  vtkBlueNoiseRandom random;
  random.Seed(seed, 11);
  std::vector<unsigned char> mask(static_cast<size_t>(voxels));
  for (auto& m : mask)
  {
    m = random.Uniform() < p ? 1 : 0;
  }
  return mask;
}

template <typename Kernel>
vtkIdType Run(Kernel& kernel, const Volume& v, std::vector<unsigned char>& mask)
{
  mask.assign(v.Density.size(), 255);
  return kernel.Sample(v.Dims[0], v.Dims[1], v.Dims[2], v.Density.data(), mask.data());
}

/// Bad input gives -1, a message and an untouched mask; the next good call works.
template <typename Kernel>
void CheckBadInput(const char* name)
{
  Kernel kernel;
  std::vector<float> density(8, 0.5f);
  std::vector<unsigned char> mask(8, 7);
  std::string error;
  Check(kernel.Sample(0, 2, 2, density.data(), mask.data(), &error) == -1 && !error.empty(),
    std::string(name) + ": a zero dimension is an error");
  error.clear();
  Check(kernel.Sample(2, 2, 2, nullptr, mask.data(), &error) == -1 && !error.empty(),
    std::string(name) + ": a null density is an error");
  Check(kernel.Sample(2, 2, 2, density.data(), nullptr, &error) == -1,
    std::string(name) + ": a null mask is an error");
  Check(std::all_of(mask.begin(), mask.end(), [](unsigned char m) { return m == 7; }),
    std::string(name) + ": bad input leaves the mask untouched");
  const vtkIdType n = kernel.Sample(2, 2, 2, density.data(), mask.data(), &error);
  Check(n >= 1 && n == CountOf(mask), std::string(name) + ": a good call after bad input works");
}

/// The progress callback: several reports, strictly increasing in (0, 1), and
/// the same mask as without it; false from it stops Sample() (-1, "aborted",
/// GetAborted(), the mask untouched); the next call without an abort works.
template <typename Kernel>
void CheckProgress(const char* name)
{
  const std::string who = name;
  const Volume volume = MakeRamp(64);
  const vtkIdType voxels = volume.Size();
  std::vector<unsigned char> reference(static_cast<size_t>(voxels));
  Kernel plain;
  const vtkIdType count = plain.Sample(
    volume.Dims[0], volume.Dims[1], volume.Dims[2], volume.Density.data(), reference.data());

  Kernel kernel;
  std::vector<double> reports;
  int abortAt = -1; // the report that asks to stop, none when negative
  kernel.SetProgressCallback([&](double p) {
    reports.push_back(p);
    return static_cast<int>(reports.size()) - 1 != abortAt;
  });
  std::vector<unsigned char> mask(static_cast<size_t>(voxels), 7);
  std::string error;
  const vtkIdType n = kernel.Sample(
    volume.Dims[0], volume.Dims[1], volume.Dims[2], volume.Density.data(), mask.data(), &error);
  bool increasing = true;
  for (size_t i = 0; i < reports.size(); ++i)
  {
    increasing = increasing && reports[i] > (i ? reports[i - 1] : 0.0) && reports[i] < 1.0;
  }
  Check(reports.size() >= 3 && increasing,
    who + ": " + Str(reports.size()) + " progress reports, strictly increasing in (0, 1)");
  Check(n == count && mask == reference && !kernel.GetAborted(),
    who + ": the callback does not change the samples");

  const size_t all = reports.size();
  reports.clear();
  abortAt = static_cast<int>(all / 2);
  std::fill(mask.begin(), mask.end(), 7);
  error.clear();
  Check(kernel.Sample(volume.Dims[0], volume.Dims[1], volume.Dims[2], volume.Density.data(),
          mask.data(), &error) == -1 &&
      kernel.GetAborted() && error == "aborted",
    who + ": false from the callback stops the run (error '" + error + "')");
  Check(static_cast<int>(reports.size()) == abortAt + 1,
    who + ": it stops at the report that asked (" + Str(reports.size()) + " reports)");
  Check(std::all_of(mask.begin(), mask.end(), [](unsigned char m) { return m == 7; }),
    who + ": an aborted run leaves the mask untouched");

  abortAt = -1;
  Check(kernel.Sample(volume.Dims[0], volume.Dims[1], volume.Dims[2], volume.Density.data(),
          mask.data()) == count &&
      mask == reference && !kernel.GetAborted(),
    who + ": the next run after an abort gives the same samples");
}

/// g <= 0 and NaN are never sampled, g >= 1 always, whatever surrounds them.
template <typename Kernel>
void CheckEmptyAndSaturated(const char* name, std::vector<unsigned char>& mask)
{
  const std::string who = name;
  Kernel kernel;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  Volume empty = MakeDensity(16, 12, 10, [nan](int x, int, int) {
    return x % 3 == 0 ? 0.0f : (x % 3 == 1 ? -0.5f : nan);
  });
  Check(Run(kernel, empty, mask) == 0 && CountOf(mask) == 0,
    who + ": an empty volume has no sample");
  Volume full = MakeDensity(16, 12, 10, [](int x, int, int) { return x % 2 ? 1.0f : 3.0f; });
  Check(Run(kernel, full, mask) == full.Size() && CountOf(mask) == full.Size(),
    who + ": a saturated volume is sampled everywhere");
  // A saturated block in a sparse region next to an empty half.
  Volume mixed = MakeDensity(32, 32, 32, [](int x, int y, int z) {
    if (z < 16)
    {
      return 0.0f;
    }
    return (x >= 8 && x < 16 && y >= 8 && y < 16 && z >= 20 && z < 28) ? 1.0f : 0.05f;
  });
  Run(kernel, mixed, mask);
  bool emptyOk = true, fullOk = true;
  for (vtkIdType v = 0; v < mixed.Size(); ++v)
  {
    const float g = mixed.Density[v];
    emptyOk = emptyOk && (g > 0.0f || mask[v] == 0);
    fullOk = fullOk && (g < 1.0f || mask[v] == 1);
  }
  Check(emptyOk, who + ": no sample where g = 0 next to sampled voxels");
  Check(fullOk, who + ": every voxel of a saturated block is a sample");
}

/// Same seed, same mask; another seed, another mask.
template <typename Kernel>
void CheckDeterminism(const char* name, const Volume& volume)
{
  std::vector<unsigned char> a, b, c;
  Kernel first, second, other;
  first.SetSeed(77);
  second.SetSeed(77);
  other.SetSeed(78);
  Run(first, volume, a);
  Run(second, volume, b);
  Run(other, volume, c);
  Check(a == b, std::string(name) + ": the same seed gives the same samples");
  Check(a != c, std::string(name) + ": another seed gives other samples");
}

/**
 * A ball of g = 16/255 (radius 0.4 n) in an empty n^3 cube: the count within
 * 1.5 voxels of the empty region against its sum of g (1.35 when the support
 * is not continued), which must be within `tolerance`.
 */
template <typename Kernel>
void CheckRim(const char* name, int n, double tolerance)
{
  const double center = (n - 1) / 2.0, radius = 0.4 * n;
  auto depth = [=](int x, int y, int z) {
    return radius -
      std::sqrt((x - center) * (x - center) + (y - center) * (y - center) +
        (z - center) * (z - center));
  };
  const Volume ball = MakeDensity(
    n, n, n, [&](int x, int y, int z) { return depth(x, y, z) > 0.0 ? 16.0f / 255.0f : 0.0f; });
  Kernel kernel;
  std::vector<unsigned char> mask;
  Run(kernel, ball, mask);
  double expected = 0.0, count = 0.0;
  vtkIdType v = 0;
  for (int z = 0; z < n; ++z)
  {
    for (int y = 0; y < n; ++y)
    {
      for (int x = 0; x < n; ++x, ++v)
      {
        const bool rim = depth(x, y, z) > 0.0 && depth(x, y, z) < 1.5;
        expected += rim ? ball.Density[v] : 0.0;
        count += rim ? mask[v] : 0;
      }
    }
  }
  std::cout << name << ": the rim of the support gets " << count / expected
            << " of its expected count" << std::endl;
  Check(std::abs(count / expected - 1.0) < tolerance,
    std::string(name) + ": rim count ratio " + Str(count / expected));
}

/**
 * On MakeRamp(64), the count of each slab of 8 layers against its sum of g:
 * the largest relative deviation must stay below `tolerance`.
 */
template <typename Kernel>
void CheckRamp(const char* name, double tolerance)
{
  const Volume ramp = MakeRamp(64);
  Kernel kernel;
  std::vector<unsigned char> mask;
  Run(kernel, ramp, mask);
  const vtkIdType layer = static_cast<vtkIdType>(ramp.Dims[0]) * ramp.Dims[1];
  double worst = 0.0;
  for (int z0 = 0; z0 < ramp.Dims[2]; z0 += 8)
  {
    double expected = 0.0, count = 0.0;
    for (vtkIdType v = z0 * layer; v < (z0 + 8) * layer; ++v)
    {
      expected += ramp.Density[v];
      count += mask[v];
    }
    worst = std::max(worst, std::abs(count - expected) / expected);
  }
  std::cout << name << ": on a ramp, the largest deviation of an 8-layer slab is "
            << 100.0 * worst << " %" << std::endl;
  Check(worst < tolerance, std::string(name) + ": ramp slabs within " + Str(tolerance));
}
}

#endif
