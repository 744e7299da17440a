// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// A cube of density 4/255 inside a margin ten times as dense, and inside one
// a tenth as dense, is sampled along its faces as the same cube alone is:
// the points per voxel of its three outer layers (the mean over four seeds)
// within 0.15 of the lone cube's, with the three error-diffusion methods, and
// its count within 2 % of its densities' sum. Inside margins of 3, 1.3 and
// 0.77 times its density (steps the scan diffuses across) the relaxed
// methods' outer layers hold what the paper's method's do, within 0.15: the
// relaxations leave no skin (the faces rule's narrow region; with the
// similar densities' factor for it, the face layer next to three times the
// density held far less than its density with both relaxed methods). Without the density-step rules
// (vtkErrorDiffusionScan, vtkBlueNoiseRelaxation) the paper's method put
// twice the density into the face layer in the dense margin (error carried
// over the step fires the sparse side at once), and the default emptied it
// to a fifth (the margin's samples crowded the cube's, which moved away from
// them) and overfilled the layers behind it.
#include "SamplerTestUtilities.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"

#include <array>
#include <cmath>
#include <string>

using namespace bluenoise_test;

namespace
{
constexpr int Cube = 64;   // edge of the cube
constexpr int Rim = 8;     // the edges of a face, left out of its counts
constexpr int Seeds = 4;
const float G = 4.0f / 255.0f;

struct Result
{
  std::array<double, 3> Profile{}; // points per voxel / g at depths 0, 1, 2, over the seeds
  double Points = 0.0;             // in the cube, per seed
};

// The cube inside a margin of `margin` voxels of density factor * G (none:
// the cube alone): the points of its outer layers over its six faces (not
// their edges), and in all.
Result SampleCube(int margin, float factor, int method)
{
  const int n = Cube + 2 * margin;
  auto image = MakeVolume(n, n, n, [&](int x, int y, int z) {
    const auto inside = [&](int c) { return c >= margin && c < margin + Cube; };
    return inside(x) && inside(y) && inside(z) ? G : factor * G;
  });
  Result result;
  const int side = Cube - 2 * Rim;
  for (int seed = 1000; seed < 1000 + Seeds; ++seed)
  {
    vtkNew<vtkErrorDiffusionSampler> sampler;
    sampler->SetInputData(image);
    sampler->SetDensityMappingToIdentity();
    sampler->UseNumberOfPointsOff();
    sampler->SetMethod(method);
    sampler->SetSeed(seed);
    sampler->GenerateMaskOn();
    sampler->Update();
    vtkDataArray* mask = sampler->GetMaskOutput()->GetPointData()->GetScalars();
    const auto sampled = [&](const int c[3]) {
      return mask->GetComponent(c[0] + n * (c[1] + static_cast<vtkIdType>(n) * c[2]), 0) != 0.0;
    };
    for (int depth = 0; depth < 3; ++depth)
    {
      for (int face = 0; face < 6; ++face)
      {
        const int axis = face / 2;
        int c[3];
        c[axis] = face % 2 == 0 ? margin + depth : margin + Cube - 1 - depth;
        for (int a = 0; a < side; ++a)
        {
          for (int b = 0; b < side; ++b)
          {
            c[(axis + 1) % 3] = margin + Rim + a;
            c[(axis + 2) % 3] = margin + Rim + b;
            result.Profile[depth] += sampled(c) ? 1.0 : 0.0;
          }
        }
      }
    }
    for (int z = margin; z < margin + Cube; ++z)
      for (int y = margin; y < margin + Cube; ++y)
        for (int x = margin; x < margin + Cube; ++x)
        {
          const int c[3] = { x, y, z };
          result.Points += sampled(c) ? 1.0 / Seeds : 0.0;
        }
  }
  for (double& p : result.Profile)
  {
    p /= Seeds * 6.0 * side * side * G;
  }
  return result;
}

std::string Format(const std::array<double, 3>& p)
{
  return Str(p[0]) + " " + Str(p[1]) + " " + Str(p[2]);
}
}

int main()
{
  const double expected = static_cast<double>(G) * Cube * Cube * Cube;
  const int paper = vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION;
  for (const int method : { static_cast<int>(vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION),
         static_cast<int>(vtkErrorDiffusionSampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION), paper })
  {
    const std::string name = method == paper ? "paper's method"
      : method == vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION ? "default"
                                                                           : "energy relaxed";
    const Result alone = SampleCube(0, 1.0f, method);
    std::cout << name << ", the cube alone: points per voxel / g at depths 0, 1, 2: "
              << Format(alone.Profile) << std::endl;
    for (const float factor : { 10.0f, 0.1f, 3.0f, 1.3f, 0.77f })
    {
      // Across a step of a factor of 4 or more the scan samples each side as
      // if alone; within it the scan lets error across, and its own profile
      // is the reference for the relaxations.
      const bool apart = factor >= 4.0f || factor <= 0.25f;
      if (!apart && method == paper)
      {
        continue;
      }
      const Result inside = SampleCube(16, factor, method);
      const Result reference = apart ? alone : SampleCube(16, factor, paper);
      const std::string where = name + ", in a margin of x" + Str(factor) + " the density";
      const std::string against = apart ? "alone" : "the paper's method";
      std::cout << where << ": " << Format(inside.Profile) << "; " << inside.Points
                << " points of " << expected << std::endl;
      for (int depth = 0; depth < 3; ++depth)
      {
        Check(std::abs(inside.Profile[depth] - reference.Profile[depth]) <= 0.15,
          where + ": depth " + Str(depth) + " holds " + Str(inside.Profile[depth]) +
            " of its density, " + against + " " + Str(reference.Profile[depth]));
      }
      Check(std::abs(inside.Points - expected) <= 0.02 * expected,
        where + ": the cube holds " + Str(inside.Points) + " points of " + Str(expected));
    }
  }
  return Summary("TestErrorDiffusionSamplerDensitySteps");
}
