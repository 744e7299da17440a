// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBlueNoiseRelaxation keeps the number of samples at any density, down to
// 0 and tiny densities, whose blue-noise spacing is huge: the search radius
// clamps to MaximumRadius. (The square of that spacing was converted to int,
// undefined behavior for g below about 1e-14; found by fuzzing.)
#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseRelaxation.h"

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
  return Summary("TestBlueNoiseRelaxation");
}
