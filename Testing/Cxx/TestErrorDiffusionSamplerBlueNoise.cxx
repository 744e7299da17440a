// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The sampler's points are blue noise: with the paper's parameters, the
// low-frequency ratio L(g) is below that of white noise (independent
// Bernoulli voxels) of the same density, and the power well below f_g / 2
// is a small fraction of white noise's 1 - g; the anisotropy stays near 0 dB.
#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkErrorDiffusionKernel.h"

#include <cmath>
#include <random>
#include <vector>

using namespace bluenoise_test;

namespace
{
const int L = 64;

std::vector<unsigned char> ErrorDiffusion(float g, int seed)
{
  vtkErrorDiffusionKernel kernel;
  kernel.SetSeed(seed);
  kernel.Begin(L, L);
  const size_t layer = static_cast<size_t>(L) * L;
  std::vector<float> density(layer, g);
  std::vector<unsigned char> mask(layer * L);
  for (int z = 0; z < L; ++z)
  {
    kernel.ProcessLayer(density.data(), z + 1 < L ? density.data() : nullptr, mask.data() + z * layer);
  }
  return mask;
}

std::vector<unsigned char> WhiteNoise(float g, int seed)
{
  std::mt19937 random(seed);
  std::bernoulli_distribution draw(g);
  std::vector<unsigned char> mask(static_cast<size_t>(L) * L * L);
  for (auto& m : mask)
  {
    m = draw(random) ? 1 : 0;
  }
  return mask;
}

struct Figures
{
  double LowFrequencyRatio = 0.0;
  double LowPower = 0.0; // mean radial power over shells below f_g / 2
  double AnisotropyDB = 0.0;
};

Figures Measure(const std::vector<unsigned char>& mask)
{
  const int dims[3] = { L, L, L };
  vtkBlueNoiseSpectrumKernel::Result r;
  std::string error;
  Check(vtkBlueNoiseSpectrumKernel::Evaluate(mask.data(), dims, 0.02, r, &error), error);
  Figures f;
  f.LowFrequencyRatio = r.LowFrequencyRatio;
  int low = 0, shells = 0;
  for (size_t s = 0; s < r.Frequency.size(); ++s)
  {
    if (r.Frequency[s] < 0.5 * r.PrincipalFrequency)
    {
      f.LowPower += r.RadialPower[s];
      ++low;
    }
    if (r.Frequency[s] <= 0.5)
    {
      f.AnisotropyDB += r.AnisotropyDB[s];
      ++shells;
    }
  }
  f.LowPower /= std::max(low, 1);
  f.AnisotropyDB /= std::max(shells, 1);
  return f;
}
}

int main()
{
  for (int level : { 8, 16, 32 })
  {
    const float g = level / 255.0f;
    Figures ed, wn;
    const int seeds = 2;
    for (int seed = 0; seed < seeds; ++seed)
    {
      const Figures a = Measure(ErrorDiffusion(g, seed));
      const Figures b = Measure(WhiteNoise(g, seed));
      ed.LowFrequencyRatio += a.LowFrequencyRatio / seeds;
      ed.LowPower += a.LowPower / seeds;
      ed.AnisotropyDB += a.AnisotropyDB / seeds;
      wn.LowFrequencyRatio += b.LowFrequencyRatio / seeds;
      wn.LowPower += b.LowPower / seeds;
    }
    std::cout << "g=" << level << "/255: L(g) error diffusion " << ed.LowFrequencyRatio
              << ", white noise " << wn.LowFrequencyRatio << "; power below f_g/2 "
              << ed.LowPower << " vs " << wn.LowPower << "; anisotropy " << ed.AnisotropyDB
              << " dB" << std::endl;
    Check(ed.LowFrequencyRatio < 0.8 * wn.LowFrequencyRatio,
      "L(g) below white noise at " + Str(level) + "/255");
    Check(ed.LowPower < 0.25 * wn.LowPower,
      "power below f_g/2 a small fraction of white noise at " + Str(level) + "/255");
    Check(std::abs(ed.AnisotropyDB) < 1.0, "anisotropy near 0 dB at " + Str(level) + "/255");
  }
  return Summary("TestErrorDiffusionSamplerBlueNoise");
}
