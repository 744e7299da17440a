// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The kernel on 1, 2 and 3 vtkSMPTools threads (STDThread backend): every
// reported value and the centered spectrum must be the same to the last bit,
// for one realization (power kept in the transform buffer) and for two (the
// averaged sum), for masks and for samples. Grids are large enough to be
// split into several tasks in every pass, with odd and even lengths. Samples
// given as voxel indices must also give exactly what the float count volume
// filled in the same order gives.
#include "TestBlueNoiseSpectrumUtilities.h"

#include "vtkSMPTools.h"

using namespace spectrum_test;

namespace
{
struct Run
{
  Result Metrics;
  std::vector<double> Spectrum;
  bool Ok = false;
};

// Voxel indices of the set voxels of `mask` and of some repeated ones, with
// fractional weights: several samples land on one voxel.
void MakeSamples(const std::vector<unsigned char>& mask, std::mt19937& rng,
  std::vector<long long>& voxels, std::vector<float>& weights)
{
  std::uniform_real_distribution<float> weight(0.1f, 2.0f);
  for (std::size_t v = 0; v < mask.size(); ++v)
  {
    if (mask[v])
    {
      voxels.push_back(static_cast<long long>(v));
      weights.push_back(weight(rng));
    }
  }
  const std::size_t n = voxels.size();
  std::uniform_int_distribution<std::size_t> pick(0, n - 1);
  for (std::size_t i = 0; i < n / 3; ++i)
  {
    voxels.push_back(voxels[pick(rng)]);
    weights.push_back(weight(rng));
  }
}

template <typename AddAll>
Run Evaluate(const int dims[3], int threads, AddAll addAll)
{
  Run run;
  vtkSMPTools::LocalScope(vtkSMPTools::Config(threads, "STDThread", false),
    [&]()
    {
      vtkBlueNoiseSpectrumKernel kernel;
      run.Ok = kernel.SetDimensions(dims[0], dims[1], dims[2]) && addAll(kernel) &&
        kernel.Compute(run.Metrics) && kernel.GetCenteredPowerSpectrum(run.Spectrum);
    });
  return run;
}

void CheckSameRun(const Run& a, const Run& b, const std::string& what)
{
  if (!Check(a.Ok && b.Ok, what + ": a kernel call failed"))
  {
    return;
  }
  CheckSameResult(a.Metrics, b.Metrics, 0.0, what);
  Check(a.Metrics.AnisotropyDB == b.Metrics.AnisotropyDB, what + ": AnisotropyDB differs");
  Check(a.Spectrum == b.Spectrum, what + ": the centered power spectrum differs");
}
}

int main()
{
  if (!vtkSMPTools::SetBackend("STDThread"))
  {
    std::cout << "TestBlueNoiseSpectrumThreadCount: no STDThread backend, nothing to compare\n";
    return EXIT_SUCCESS;
  }
  std::mt19937 rng(77);
  const int shapes[2][3] = { { 96, 72, 80 }, { 129, 96, 70 } };
  for (const auto& dims : shapes)
  {
    const std::string shape = Str(dims[0]) + "x" + Str(dims[1]) + "x" + Str(dims[2]);
    const std::vector<unsigned char> first = RandomMask(dims, 0.07, rng);
    const std::vector<unsigned char> second = RandomMask(dims, 0.3, rng);
    std::vector<long long> voxels;
    std::vector<float> weights;
    MakeSamples(first, rng, voxels, weights);
    std::vector<float> volume(Voxels(dims), 0.0f);
    for (std::size_t i = 0; i < voxels.size(); ++i)
    {
      volume[voxels[i]] += weights[i];
    }

    const auto oneMask = [&](vtkBlueNoiseSpectrumKernel& k)
    { return k.AddRealization(first.data()); };
    const auto twoMasks = [&](vtkBlueNoiseSpectrumKernel& k)
    { return k.AddRealization(first.data()) && k.AddRealization(second.data()); };
    const auto samples = [&](vtkBlueNoiseSpectrumKernel& k)
    {
      return k.AddSamples(voxels.data(), weights.data(), voxels.size()) &&
        k.AddRealization(second.data());
    };
    const auto floats = [&](vtkBlueNoiseSpectrumKernel& k)
    { return k.AddRealization(volume.data()) && k.AddRealization(second.data()); };
    const Run one = Evaluate(dims, 1, oneMask);
    const Run two = Evaluate(dims, 1, twoMasks);
    const Run sampled = Evaluate(dims, 1, samples);
    for (int threads = 2; threads <= 3; ++threads)
    {
      const std::string what = shape + ", " + Str(threads) + " threads";
      CheckSameRun(Evaluate(dims, threads, oneMask), one, what + ", one mask");
      CheckSameRun(Evaluate(dims, threads, twoMasks), two, what + ", two masks");
      CheckSameRun(Evaluate(dims, threads, samples), sampled, what + ", samples");
    }
    CheckSameRun(Evaluate(dims, 2, floats), sampled, shape + ": samples against their volume");
    Check(one.Metrics.RadialPower != two.Metrics.RadialPower,
      shape + ": one and two realizations agree, the comparison would not see a difference");
  }
  return bluenoise_test::Summary("TestBlueNoiseSpectrumThreadCount");
}
