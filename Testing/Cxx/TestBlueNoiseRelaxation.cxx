// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBlueNoiseRelaxation keeps the number of samples at any density, down to
// 0 and tiny densities, whose blue-noise spacing is huge: the search radius
// clamps to MaximumRadius. (The square of that spacing was converted to int,
// undefined behavior for g below about 1e-14; found by fuzzing.)
// A layer with one density in (0, 1/4], wherever it lies, is relaxed; one
// without is returned at once, the caller's (Borrowed). Layers below
// firstMovable are context only. At the faces of a volume the outer layers
// keep about their samples (no skin).
#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseRelaxation.h"
#include "vtkErrorDiffusionKernel.h"

#include <algorithm>
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

// The error-diffusion masks of a constant cube of n x n x layers voxels at density g.
std::vector<std::vector<unsigned char>> Scan(int n, int layers, float g)
{
  vtkErrorDiffusionKernel kernel;
  kernel.SetSeed(3);
  kernel.Begin(n, n);
  const std::vector<float> density(static_cast<size_t>(n) * n, g);
  std::vector<std::vector<unsigned char>> masks(
    static_cast<size_t>(layers), std::vector<unsigned char>(density.size()));
  for (int z = 0; z < layers; ++z)
  {
    const float* next = z + 1 < layers ? density.data() : nullptr;
    kernel.ProcessLayer(density.data(), next, masks[static_cast<size_t>(z)].data());
  }
  return masks;
}

// Relaxes masks[first, last] of n x n layers (context below firstMovable),
// final copies by layer.
std::vector<std::vector<unsigned char>> Relax(const std::vector<std::vector<unsigned char>>& masks,
  int n, const std::vector<float>& density, int first, int firstMovable, int last)
{
  vtkBlueNoiseRelaxation relaxation;
  relaxation.Begin(n, n, first, 5, firstMovable);
  std::vector<std::vector<unsigned char>> out(masks.size());
  const auto keep = [&](const std::vector<vtkBlueNoiseRelaxation::Layer>& done) {
    for (const auto& layer : done)
    {
      out[static_cast<size_t>(layer.Z)].assign(layer.Mask, layer.Mask + density.size());
    }
  };
  for (int z = first; z <= last; ++z)
  {
    keep(relaxation.Push(z, density.data(), masks[static_cast<size_t>(z)].data()));
  }
  keep(relaxation.Flush());
  return out;
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

  // Context below firstMovable (a z-part relaxed apart from the layers below
  // it): those layers come back at once, as they came; no sample moves into or
  // out of them; the searches see their samples (the moves differ from a run
  // without them); and the first movable layer keeps about its scanned count,
  // with the context and without it (then a face of the run: no sample moves
  // towards it or away from it within the search radius, so none drifts in).
  {
    const int n = 48, layers = 40, first = 12, movable = 20;
    const float g = 0.03f;
    const auto masks = Scan(n, layers, g);
    const std::vector<float> density(static_cast<size_t>(n) * n, g);
    vtkBlueNoiseRelaxation relaxation;
    relaxation.Begin(n, n, first, 5, movable);
    bool asCame = true;
    for (int z = first; z < movable; ++z)
    {
      const auto& done = relaxation.Push(z, density.data(), masks[static_cast<size_t>(z)].data());
      asCame = asCame && done.size() == 1 && done[0].Z == z && done[0].Borrowed &&
        done[0].Mask == masks[static_cast<size_t>(z)].data();
    }
    Check(asCame, "the context layers come back at once, as they came");
    const auto count = [&](const std::vector<std::vector<unsigned char>>& m, int from, int to) {
      vtkIdType c = 0;
      for (int z = from; z <= to; ++z)
      {
        c += std::count(m[static_cast<size_t>(z)].begin(), m[static_cast<size_t>(z)].end(), 1);
      }
      return c;
    };
    const auto context = Relax(masks, n, density, first, movable, layers - 1);
    const auto none = Relax(masks, n, density, movable, movable, layers - 1);
    Check(count(context, movable, layers - 1) == count(masks, movable, layers - 1),
      "with context: the movable layers keep their samples");
    const double scanned = static_cast<double>(count(masks, movable, movable));
    const double with = static_cast<double>(count(context, movable, movable));
    const double without = static_cast<double>(count(none, movable, movable));
    Check(std::abs(with / scanned - 1.0) <= 0.05 && std::abs(without / scanned - 1.0) <= 0.05,
      "the first movable layer: " + Str(with) + " samples with context, " + Str(without) +
        " without, " + Str(scanned) + " scanned");
    bool differ = false;
    for (int z = movable; z < layers; ++z)
    {
      differ = differ || context[static_cast<size_t>(z)] != none[static_cast<size_t>(z)];
    }
    Check(differ, "the context's samples are seen");
  }

  // At the faces of a cube (24/255, where the search radius is 3) the outer
  // layers keep about the scan's counts: letting samples move towards a face
  // within the radius made a skin of 1.3 times the density in the face layer
  // and 0.7 times in the next.
  {
    const int n = 48;
    const float g = 24.0f / 255.0f;
    const auto masks = Scan(n, n, g);
    const std::vector<float> density(static_cast<size_t>(n) * n, g);
    const auto relaxed = Relax(masks, n, density, 0, 0, n - 1);
    const auto ratio = [&](bool alongZ, int at) { // relaxed / scanned, layer or slice `at`
      double before = 0.0, after = 0.0;
      for (int z = 0; z < n; ++z)
      {
        for (int i = 0; i < n * n; ++i)
        {
          if (alongZ ? z == at : i % n == at)
          {
            before += masks[static_cast<size_t>(z)][static_cast<size_t>(i)];
            after += relaxed[static_cast<size_t>(z)][static_cast<size_t>(i)];
          }
        }
      }
      return after / before;
    };
    for (const int at : { 0, 1, n - 2, n - 1 })
    {
      for (const bool alongZ : { true, false })
      {
        const double r = ratio(alongZ, at);
        Check(std::abs(r - 1.0) <= 0.08,
          std::string(alongZ ? "layer " : "x slice ") + Str(at) + " at a face: " + Str(r) +
            " of the scan's samples");
      }
    }
  }
  return Summary("TestBlueNoiseRelaxation");
}
