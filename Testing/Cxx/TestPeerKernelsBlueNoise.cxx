// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Blue-noise quality of the point-set peers on a constant 64^3 cube at
// g = 8/255 and 32/255, with vtkBlueNoiseSpectrumKernel (whole volume, single
// realizations, mean of two seeds): the low-frequency ratio L well below that
// of white noise with the same count, and a mean anisotropy (shells 1 .. 32)
// near 0 dB, where a set denser along the faces has 1.5 to 3.6 dB.
#include "PeerKernelTestUtilities.h"
#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkPoissonDiskKernel.h"
#include "vtkWeightedSampleEliminationKernel.h"

#include <iostream>

namespace
{
using namespace bluenoise_test;

const int Size = 64;
const int Seeds = 2;

struct Quality
{
  double L = 0.0;
  double AnisotropyDB = 0.0;
  double Count = 0.0;
};

Quality Measure(const std::function<std::vector<unsigned char>(int seed)>& sample)
{
  vtkBlueNoiseSpectrumKernel spectrum;
  spectrum.SetDimensions(Size, Size, Size);
  Quality q;
  for (int seed = 0; seed < Seeds; ++seed)
  {
    const std::vector<unsigned char> mask = sample(seed);
    spectrum.Reset();
    std::string error;
    Check(spectrum.AddRealization(mask.data(), &error), "AddRealization: " + error);
    vtkBlueNoiseSpectrumKernel::Result result;
    spectrum.Compute(result);
    q.L += result.LowFrequencyRatio / Seeds;
    q.Count += result.NumberOfPoints / Seeds;
    for (int shell = 0; shell < Size / 2; ++shell)
    {
      q.AnisotropyDB += result.AnisotropyDB[shell] / (Size / 2) / Seeds;
    }
  }
  return q;
}

template <typename Kernel>
Quality MeasurePeer(const Volume& volume)
{
  return Measure([&volume](int seed) {
    Kernel kernel;
    kernel.SetSeed(static_cast<std::uint64_t>(seed));
    std::vector<unsigned char> mask;
    Run(kernel, volume, mask);
    return mask;
  });
}

void CheckLevel(int level, double largestRatio)
{
  const Volume volume = MakeConstantDensity(Size, level / 255.0f);
  const Quality pd = MeasurePeer<vtkPoissonDiskKernel>(volume);
  const Quality wse = MeasurePeer<vtkWeightedSampleEliminationKernel>(volume);
  const auto voxels = static_cast<vtkIdType>(volume.Density.size());
  const Quality white = Measure([&](int seed) {
    return WhiteNoiseMask(voxels, pd.Count / static_cast<double>(voxels), 100 + seed);
  });
  std::cout << "g = " << level << "/255: L (mean anisotropy dB): Poisson disk " << pd.L << " ("
            << pd.AnisotropyDB << "), sample elimination " << wse.L << " (" << wse.AnisotropyDB
            << "), white noise " << white.L << " (" << white.AnisotropyDB << ")" << std::endl;
  const std::string at = " at " + Str(level) + "/255";
  Check(pd.L < largestRatio * white.L,
    "Poisson disk L " + Str(pd.L) + " below " + Str(largestRatio) + " x white noise's" + at);
  Check(wse.L < largestRatio * white.L,
    "sample elimination L " + Str(wse.L) + " below " + Str(largestRatio) + " x white noise's" + at);
  Check(pd.AnisotropyDB < 1.0, "Poisson disk anisotropy " + Str(pd.AnisotropyDB) + " dB" + at);
  Check(wse.AnisotropyDB < 1.0,
    "sample elimination anisotropy " + Str(wse.AnisotropyDB) + " dB" + at);
}
}

int main()
{
  // White noise has L of about (4/3) pi g; a Poisson-disk set keeps power
  // just below the principal frequency, so the ratio grows with g.
  CheckLevel(8, 0.55);
  CheckLevel(32, 0.65);
  return Summary("TestPeerKernelsBlueNoise");
}
