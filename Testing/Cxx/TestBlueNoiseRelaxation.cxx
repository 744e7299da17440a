// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBlueNoiseRelaxation keeps the number of samples at any density, down to
// 0 and tiny densities, whose blue-noise spacing is huge: the search radius
// clamps to MaximumRadius. (The square of that spacing was converted to int,
// undefined behavior for g below about 1e-14; found by fuzzing.)
// A layer with one density in (0, 1/4], wherever it lies, is relaxed; one
// without is returned at once, the caller's (Borrowed).
#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseRelaxation.h"

#include <cmath>
#include <limits>
#include <vector>

using namespace bluenoise_test;

namespace
{
vtkIdType Count(const std::vector<vtkBlueNoiseRelaxation::Layer>& layers)
{
  vtkIdType count = 0;
  for (const auto& layer : layers)
  {
    count += layer.Count;
  }
  return count;
}
}

int main()
{
  const int n = 8;
  for (float g : { 0.0f, 1e-30f, 1e-12f, 1e-4f, 0.01f, 0.25f })
  {
    vtkBlueNoiseRelaxation relaxation;
    relaxation.Begin(n, n, 0, 7);
    const std::vector<float> density(n * n, g);
    std::vector<std::vector<unsigned char>> masks(n, std::vector<unsigned char>(n * n, 0));
    vtkIdType pushed = 0;
    vtkIdType out = 0;
    for (int z = 0; z < n; ++z)
    {
      masks[z][(3 * z) % (n * n)] = 1;
      masks[z][(5 * z + 9) % (n * n)] = 1;
      pushed += 2;
      out += Count(relaxation.Push(z, density.data(), masks[z].data()));
    }
    out += Count(relaxation.Flush());
    Check(out == pushed, "g = " + Str(g) + ": " + Str(out) + " samples out of " + Str(pushed));
  }

  // 40 x 3 voxels: 7 blocks of 16 and a tail of 8.
  const int nx = 40, ny = 3;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<unsigned char> mask(nx * ny, 0);
  for (int at : { 0, 5, 15, 16, 31, 47, 111, 112, 119 })
  {
    for (float g : { 0.1f, 0.25f, std::nextafter(0.25f, 1.0f), 0.0f, -0.1f, nan })
    {
      std::vector<float> density(nx * ny, 0.5f);
      density[at] = g;
      vtkBlueNoiseRelaxation relaxation;
      relaxation.Begin(nx, ny, 0, 1);
      const auto& done = relaxation.Push(0, density.data(), mask.data());
      const bool borrowed = done.size() == 1 && done[0].Borrowed;
      const bool relaxable = g > 0.0f && g <= 0.25f;
      Check(borrowed != relaxable,
        "density " + Str(g) + " at " + Str(at) + (relaxable ? ": relaxed" : ": returned as it came"));
    }
  }
  return Summary("TestBlueNoiseRelaxation");
}
