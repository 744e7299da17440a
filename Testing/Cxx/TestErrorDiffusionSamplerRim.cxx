// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The rim of the support: voxels next to empty space get their share of the
// samples. On the MRI brain ch2bet (Debian's mricron-data), density from the
// scalar range, the samples in each shell of voxels around the empty region
// (shell 1: an empty voxel within 1.5 voxels; shell s: next to shell s - 1)
// are compared with the sum of the densities there. When empty voxels
// absorbed the error diffused into them, shell 1 held about half of its
// expected samples and the shells behind it too many.
#include "MriTestUtilities.h"
#include "SamplerTestUtilities.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"

#include <array>
#include <cmath>
#include <vector>

using namespace bluenoise_test;

namespace
{
constexpr int Shells = 4; // 1, 2, 3 and everything deeper

struct Tally
{
  std::array<double, Shells> Expected{};
  std::array<double, Shells> Samples{};
  double Points = 0.0;
  double Total = 0.0;
};

// Shell index (0-based) of every voxel with g > 0; -1 for empty voxels. The
// neighborhood is the 18 voxels within 1.5 voxels.
std::vector<int> ShellsOf(const std::vector<float>& g, const int dims[3])
{
  const vtkIdType nx = dims[0], ny = dims[1], nz = dims[2];
  std::vector<int> shell(g.size(), Shells - 1);
  std::vector<vtkIdType> front;
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(g.size()); ++i)
  {
    if (!(g[i] > 0.0f))
    {
      shell[i] = -1;
      front.push_back(i);
    }
  }
  for (int s = 0; s + 1 < Shells; ++s)
  {
    std::vector<vtkIdType> next;
    for (const vtkIdType i : front)
    {
      const vtkIdType x = i % nx, y = (i / nx) % ny, z = i / (nx * ny);
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
          {
            if (dx * dx + dy * dy + dz * dz > 2 || (dx == 0 && dy == 0 && dz == 0))
            {
              continue;
            }
            const vtkIdType X = x + dx, Y = y + dy, Z = z + dz;
            if (X < 0 || Y < 0 || Z < 0 || X >= nx || Y >= ny || Z >= nz)
            {
              continue;
            }
            const vtkIdType j = X + nx * (Y + ny * Z);
            if (shell[j] > s)
            {
              shell[j] = s;
              next.push_back(j);
            }
          }
    }
    front.swap(next);
  }
  return shell;
}

Tally Measure(vtkImageData* image, const std::vector<int>& shell, const std::vector<float>& g,
  double scale, int seed, int method)
{
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  sampler->SetDensityMappingToScalarRange();
  sampler->UseNumberOfPointsOff();
  sampler->SetDensityScale(scale);
  sampler->SetSeed(seed);
  sampler->SetMethod(method);
  sampler->GenerateMaskOn();
  sampler->Update();
  vtkDataArray* mask = sampler->GetMaskOutput()->GetPointData()->GetScalars();
  Tally t;
  t.Points = static_cast<double>(sampler->GetOutput()->GetNumberOfPoints());
  for (size_t i = 0; i < g.size(); ++i)
  {
    const double gi = std::min(1.0, scale * g[i]);
    t.Total += gi;
    if (shell[i] < 0)
    {
      continue;
    }
    t.Expected[shell[i]] += gi;
    t.Samples[shell[i]] += mask->GetComponent(static_cast<vtkIdType>(i), 0);
  }
  return t;
}
}

int main(int argc, char* argv[])
{
  const auto image = ReadMri(argc, argv);
  if (!image)
  {
    return SkipReturnCode;
  }
  vtkDataArray* intensity = image->GetPointData()->GetScalars();
  double range[2];
  intensity->GetRange(range);
  std::vector<float> g(static_cast<size_t>(intensity->GetNumberOfTuples()));
  double sum = 0.0;
  for (size_t i = 0; i < g.size(); ++i)
  {
    g[i] = static_cast<float>(
      (intensity->GetComponent(static_cast<vtkIdType>(i), 0) - range[0]) / (range[1] - range[0]));
    sum += g[i];
  }
  const std::vector<int> shell = ShellsOf(g, image->GetDimensions());

  for (const double target : { 3e4, 3e5 })
  {
    const double scale = target / sum;
    for (const int method :
      { vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION, vtkErrorDiffusionSampler::METHOD_WHITE_NOISE })
    {
      // Two seeds pooled.
      Tally pooled;
      for (const int seed : { 0, 1 })
      {
        const Tally t = Measure(image, shell, g, scale, seed, method);
        for (int s = 0; s < Shells; ++s)
        {
          pooled.Expected[s] += t.Expected[s];
          pooled.Samples[s] += t.Samples[s];
        }
        pooled.Points += t.Points;
        pooled.Total += t.Total;
      }
      const char* name = method == vtkErrorDiffusionSampler::METHOD_WHITE_NOISE ? "WN" : "ED";
      std::cout << name << " at " << target << " points: count/expected "
                << pooled.Points / pooled.Total << ", samples/expected by shell:";
      for (int s = 0; s < Shells; ++s)
      {
        std::cout << " " << pooled.Samples[s] / pooled.Expected[s] << " (of "
                  << pooled.Expected[s] / 2 << ")";
      }
      std::cout << std::endl;
      // Shell 1 holds about 2.4e3 expected samples per run at 3e4 points: a
      // 10% band is over 6 standard deviations of white noise.
      for (int s = 0; s < Shells; ++s)
      {
        const double ratio = pooled.Samples[s] / pooled.Expected[s];
        Check(std::abs(ratio - 1.0) < 0.1,
          std::string(name) + " at " + Str(target) + " points, shell " + Str(s + 1) + ": " +
            Str(ratio) + " of the expected samples");
      }
      Check(std::abs(pooled.Points / pooled.Total - 1.0) < 0.02,
        std::string(name) + " at " + Str(target) + " points: count " + Str(pooled.Points / 2) +
          " against " + Str(pooled.Total / 2) + " expected");
    }
  }
  return Summary("TestErrorDiffusionSamplerRim");
}
