// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// bluenoise-boundary-study: how the sampler's boundary handling shows in the
// spectrum. For each density level it samples a constant L^3 cube and prints
// the mean anisotropy (dB, shells 1 .. L/2) and L(g) of the whole volume and
// of the interior (faces cropped by `crop` voxels), averaged over seeds.
//
//   bluenoise-boundary-study [--size L] [--crop C] [--seeds K]
//                            [--mode renormalize|steady] [--warmup W] [--scale S]
//                            [--levels 8,16,...]   (1/255 units)
#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkErrorDiffusionKernel.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Figures
{
  double AnisotropyDB = 0.0;
  double LowFrequencyRatio = 0.0;
};

Figures Measure(const std::vector<unsigned char>& mask, const int dims[3])
{
  vtkBlueNoiseSpectrumKernel::Result r;
  std::string error;
  if (!vtkBlueNoiseSpectrumKernel::Evaluate(mask.data(), dims, 0.02, r, &error))
  {
    std::fprintf(stderr, "spectrum: %s\n", error.c_str());
    std::exit(1);
  }
  Figures f;
  const int shells = std::min<int>(static_cast<int>(r.AnisotropyDB.size()), dims[0] / 2);
  for (int s = 0; s < shells; ++s)
  {
    f.AnisotropyDB += r.AnisotropyDB[s] / shells;
  }
  f.LowFrequencyRatio = r.LowFrequencyRatio;
  return f;
}
}

int main(int argc, char* argv[])
{
  int L = 64, crop = 8, seeds = 4, warmUp = 8;
  double scale = 1.0;
  int mode = vtkErrorDiffusionKernel::BOUNDARY_STEADY_STATE;
  std::vector<int> levels = { 8, 16, 24, 32, 40, 48, 56, 64, 72, 80, 88, 96, 104, 112, 120, 127 };
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i], v = argv[i + 1];
    if (a == "--size") L = std::atoi(v.c_str());
    else if (a == "--crop") crop = std::atoi(v.c_str());
    else if (a == "--seeds") seeds = std::atoi(v.c_str());
    else if (a == "--warmup") warmUp = std::atoi(v.c_str());
    else if (a == "--scale") scale = std::atof(v.c_str());
    else if (a == "--mode")
      mode = v == "renormalize" ? vtkErrorDiffusionKernel::BOUNDARY_RENORMALIZE
                                : vtkErrorDiffusionKernel::BOUNDARY_STEADY_STATE;
    else if (a == "--levels")
    {
      levels.clear();
      std::stringstream list(v);
      std::string item;
      while (std::getline(list, item, ','))
        levels.push_back(std::atoi(item.c_str()));
    }
    else
    {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      return 2;
    }
  }
  const int inner = L - 2 * crop;
  const int whole[3] = { L, L, L };
  const int cropped[3] = { inner, inner, inner };
  std::printf("# size %d, crop %d, seeds %d, mode %s, warm-up %d, modulation scale %g\n", L, crop,
    seeds, mode == vtkErrorDiffusionKernel::BOUNDARY_RENORMALIZE ? "renormalize" : "steady", warmUp,
    scale);
  std::printf("%6s %12s %12s %10s %10s %10s\n", "level", "anisWhole", "anisInner", "diff_dB",
    "L_whole", "L_inner");
  double worst = 0.0;
  for (int level : levels)
  {
    Figures w, c;
    for (int seed = 0; seed < seeds; ++seed)
    {
      vtkErrorDiffusionKernel kernel;
      kernel.SetBoundaryMode(mode);
      kernel.SetWarmUpLayers(warmUp);
      kernel.SetModulationScale(scale);
      kernel.SetSeed(seed);
      kernel.Begin(L, L, L);
      const size_t layer = static_cast<size_t>(L) * L;
      std::vector<float> density(layer, level / 255.0f);
      std::vector<unsigned char> mask(layer * L), inside(static_cast<size_t>(inner) * inner * inner);
      for (int z = 0; z < L; ++z)
      {
        kernel.ProcessLayer(density.data(), density.data(), mask.data() + z * layer); // constant density
      }
      size_t o = 0;
      for (int z = crop; z < L - crop; ++z)
        for (int y = crop; y < L - crop; ++y)
          for (int x = crop; x < L - crop; ++x)
            inside[o++] = mask[x + L * (y + static_cast<size_t>(L) * z)];
      const Figures fw = Measure(mask, whole), fc = Measure(inside, cropped);
      w.AnisotropyDB += fw.AnisotropyDB / seeds;
      w.LowFrequencyRatio += fw.LowFrequencyRatio / seeds;
      c.AnisotropyDB += fc.AnisotropyDB / seeds;
      c.LowFrequencyRatio += fc.LowFrequencyRatio / seeds;
    }
    const double diff = w.AnisotropyDB - c.AnisotropyDB;
    worst = std::max(worst, std::abs(diff));
    std::printf("%6d %12.3f %12.3f %10.3f %10.5f %10.5f\n", level, w.AnisotropyDB, c.AnisotropyDB,
      diff, w.LowFrequencyRatio, c.LowFrequencyRatio);
  }
  std::printf("# largest |whole - interior| anisotropy: %.3f dB\n", worst);
  return 0;
}
