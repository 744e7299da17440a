// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Method WhiteNoise (hit and miss): the expected count, determinism with the
// seed, no samples where the density is 0, and a flat (white) spectrum.
#include "SamplerTestUtilities.h"
#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkPoints.h"

#include <cmath>
#include <cstring>

using namespace bluenoise_test;

int main()
{
  const int L = 64;
  auto image = MakeVolume(L, L, L, [](int i, int, int) { return i < 8 ? 0.0f : 0.1f; });
  auto run = [&](int seed, int method) {
    vtkNew<vtkErrorDiffusionSampler> s;
    s->SetInputData(image);
    s->SetDensityMappingToIdentity();
    s->UseNumberOfPointsOff();
    s->SetMethod(method);
    s->SetSeed(seed);
    s->GenerateMaskOn();
    s->Update();
    auto out = vtkSmartPointer<vtkPolyData>::New();
    out->DeepCopy(s->GetOutput());
    auto mask = vtkSmartPointer<vtkImageData>::New();
    mask->DeepCopy(s->GetMaskOutput());
    return std::make_pair(out, mask);
  };
  const int white = vtkErrorDiffusionSampler::METHOD_WHITE_NOISE;
  auto a = run(1, white);
  auto b = run(1, white);
  auto c = run(2, white);
  const double expected = 0.1 * (L - 8) * L * L;
  const double sigma = std::sqrt(expected * 0.9);
  const vtkIdType n = a.first->GetNumberOfPoints();
  std::cout << "white noise: " << n << " points, expected " << expected << " +- " << sigma
            << std::endl;
  Check(std::abs(n - expected) < 4 * sigma, "count within 4 sigma of the expected");
  Check(n == b.first->GetNumberOfPoints() &&
      std::memcmp(a.first->GetPoints()->GetData()->GetVoidPointer(0),
        b.first->GetPoints()->GetData()->GetVoidPointer(0), n * 3 * sizeof(float)) == 0,
    "same seed, same points");
  Check(n != c.first->GetNumberOfPoints() ||
      std::memcmp(a.first->GetPoints()->GetData()->GetVoidPointer(0),
        c.first->GetPoints()->GetData()->GetVoidPointer(0), n * 3 * sizeof(float)) != 0,
    "another seed, other points");
  int inZero = 0;
  for (vtkIdType p = 0; p < n; ++p)
  {
    inZero += a.first->GetPoint(p)[0] < 7.5;
  }
  Check(inZero == 0, Str(inZero) + " samples where the density is 0");

  // White: power about 1 - g at every shell, unlike error diffusion's low band.
  const int dims[3] = { L, L, L };
  auto lowPower = [&](vtkImageData* mask) {
    vtkBlueNoiseSpectrumKernel::Result r;
    auto* bits = static_cast<unsigned char*>(mask->GetPointData()->GetScalars()->GetVoidPointer(0));
    vtkBlueNoiseSpectrumKernel::Evaluate(bits, dims, 0.02, r);
    double sum = 0.0;
    int shells = 0;
    for (size_t s = 2; s < r.Frequency.size() && r.Frequency[s] < 0.2; ++s, ++shells)
    {
      sum += r.RadialPower[s];
    }
    return sum / shells;
  };
  // On a constant density, so the spectrum shows the sampling alone.
  image = MakeConstantVolume(L, 0.1f);
  const double whiteLow = lowPower(run(1, white).second);
  const double blueLow = lowPower(run(1, vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION).second);
  std::cout << "mean power over 0.03..0.2 cycles/voxel: white noise " << whiteLow
            << ", error diffusion " << blueLow << std::endl;
  Check(std::abs(whiteLow - 0.9) < 0.1 && blueLow < 0.2 * whiteLow, "white noise has low-frequency power, blue noise not");
  return Summary("TestErrorDiffusionSamplerWhiteNoise");
}
