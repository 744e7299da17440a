// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionOptimizer.h"

#include "vtkBlueNoiseRelaxation.h"
#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkErrorDiffusionKernel.h"
#include "vtkNelderMeadMinimizer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace
{
using Key = vtkErrorDiffusionParameterTable::Key;

vtkErrorDiffusionOptimizer::Metrics ToMetrics(
  const vtkBlueNoiseSpectrumKernel::Result& r, int gridSize)
{
  vtkErrorDiffusionOptimizer::Metrics m;
  m.Target = r.TargetValue;
  m.LowFrequencyRatio = r.LowFrequencyRatio;
  m.Symmetry = r.Symmetry;
  m.Points = r.NumberOfPoints;
  const size_t shells = std::min<size_t>(r.AnisotropyDB.size(), gridSize / 2);
  for (size_t s = 0; s < shells; ++s)
  {
    m.AnisotropyDB += r.AnisotropyDB[s] / static_cast<double>(shells);
  }
  return m;
}

// The default method's relaxation of a sampled cube, in place.
void Relax(const std::vector<float>& density, int n, std::uint64_t seed, std::vector<unsigned char>& mask)
{
  const size_t layer = static_cast<size_t>(n) * n;
  std::vector<unsigned char> relaxed(mask.size());
  const auto keep = [&](const std::vector<vtkBlueNoiseRelaxation::Layer>& done) {
    for (const auto& l : done)
    {
      std::copy(l.Mask, l.Mask + layer, relaxed.begin() + l.Z * layer);
    }
  };
  vtkBlueNoiseRelaxation relaxation;
  relaxation.Begin(n, n, 0, seed);
  for (int z = 0; z < n; ++z)
  {
    keep(relaxation.Push(z, density.data(), mask.data() + z * layer));
  }
  keep(relaxation.Flush());
  mask.swap(relaxed);
}

// Samples the cube once per seed and feeds the spectra (whole, and cropped
// when `interior` is given).
bool Measure(const vtkErrorDiffusionParameterTable& table, double level,
  const vtkErrorDiffusionOptimizer::Settings& settings, vtkBlueNoiseSpectrumKernel& whole,
  vtkBlueNoiseSpectrumKernel* interior, std::string* error)
{
  const int n = settings.GridSize;
  const size_t layer = static_cast<size_t>(n) * n;
  std::vector<float> density(layer, static_cast<float>(level / 255.0));
  std::vector<unsigned char> mask(layer * n);
  const int crop = settings.CropFaces;
  const int inner = n - 2 * crop;
  std::vector<unsigned char> inside;
  if (interior)
  {
    inside.resize(static_cast<size_t>(inner) * inner * inner);
  }
  vtkErrorDiffusionKernel kernel; // one for the seeds: one charge curve
  for (int s = 0; s < settings.Seeds; ++s)
  {
    kernel.SetParameters(table);
    kernel.SetModulationScale(settings.ModulationScale);
    kernel.SetWarmUpLayers(settings.WarmUpLayers);
    kernel.SetSeed(static_cast<std::uint64_t>(settings.FirstSeed + s));
    kernel.Begin(n, n);
    for (int z = 0; z < n; ++z)
    {
      kernel.ProcessLayer(density.data(), z + 1 < n ? density.data() : nullptr, mask.data() + z * layer);
    }
    if (settings.Relaxed)
    {
      Relax(density, n, static_cast<std::uint64_t>(settings.FirstSeed + s), mask);
    }
    if (!whole.AddRealization(mask.data(), error))
    {
      return false;
    }
    if (interior)
    {
      size_t o = 0;
      for (int z = crop; z < n - crop; ++z)
      {
        for (int y = crop; y < n - crop; ++y)
        {
          const unsigned char* row = mask.data() + (static_cast<size_t>(z) * n + y) * n;
          for (int x = crop; x < n - crop; ++x)
          {
            inside[o++] = row[x];
          }
        }
      }
      if (!interior->AddRealization(inside.data(), error))
      {
        return false;
      }
    }
  }
  return true;
}

bool CheckSettings(
  const vtkErrorDiffusionOptimizer::Settings& settings, double level, std::string* error)
{
  auto fail = [error](const char* why) {
    if (error)
    {
      *error = why;
    }
    return false;
  };
  if (settings.GridSize < 4)
  {
    return fail("the grid size must be at least 4");
  }
  if (settings.Seeds < 1)
  {
    return fail("at least one seed is needed");
  }
  if (!(level > 0.0 && level < 255.0))
  {
    return fail("the level must be in (0, 255) (1/255 units)");
  }
  return true;
}

double CoefficientSum(const Key& key)
{
  double sum = 0.0;
  for (double a : key.Coefficients)
  {
    sum += std::abs(a);
  }
  return sum;
}

// The key of a point of the simplex (six coefficients, the modulation), at
// `level`: a point may wander below zero, a coefficient may not.
Key KeyOf(double level, const std::vector<double>& x)
{
  Key k;
  k.Level = level;
  for (int c = 0; c < 6; ++c)
  {
    k.Coefficients[c] = std::abs(x[c]);
  }
  k.Modulation = std::abs(x[6]);
  return k;
}

// The objective with KeepSymmetry: L relative to the start's. A point of
// more S or more anisotropy than the start's ranks behind the start (so the
// best point never has more), and the more so the more it has, which leads
// the simplex back.
double KeepingSymmetry(
  const vtkErrorDiffusionOptimizer::Metrics& m, const vtkErrorDiffusionOptimizer::Metrics& from)
{
  const double low = from.LowFrequencyRatio > 0.0 ? from.LowFrequencyRatio : 1.0;
  const double relative = m.LowFrequencyRatio / low;
  const double symmetry = from.Symmetry > 0.0 ? m.Symmetry / from.Symmetry - 1.0 : m.Symmetry;
  const double anisotropy = m.AnisotropyDB - from.AnisotropyDB;
  if (symmetry <= 0.0 && anisotropy <= 0.0)
  {
    return relative;
  }
  return 1.0 + relative + 10.0 * std::max(symmetry, 0.0) + std::max(anisotropy, 0.0);
}

// The metrics of one key at one level, on a spectrum kernel kept from one
// key to the next (its buffers and plan stay).
class LevelMeasure
{
public:
  LevelMeasure(double level, const vtkErrorDiffusionOptimizer::Settings& settings)
    : Level(level)
    , Settings(settings)
  {
    const int n = settings.GridSize;
    this->Valid = this->Spectrum.SetDimensions(n, n, n);
    this->Spectrum.SetWeight(settings.Weight);
  }
  bool Ready() const { return this->Valid; }
  bool operator()(const Key& key, vtkErrorDiffusionOptimizer::Metrics& metrics)
  {
    const double total = CoefficientSum(key);
    if (!(total > 0.0) || !std::isfinite(total) || !std::isfinite(key.Modulation))
    {
      return false;
    }
    this->Spectrum.Reset();
    vtkBlueNoiseSpectrumKernel::Result r;
    if (!Measure(vtkErrorDiffusionOptimizer::SingleKeyTable(key, this->Level), this->Level,
          this->Settings, this->Spectrum, nullptr, nullptr) ||
      !this->Spectrum.Compute(r))
    {
      return false;
    }
    metrics = ToMetrics(r, this->Settings.GridSize);
    return true;
  }

private:
  double Level;
  const vtkErrorDiffusionOptimizer::Settings& Settings;
  vtkBlueNoiseSpectrumKernel Spectrum;
  bool Valid = false;
};
}

//------------------------------------------------------------------------------
vtkErrorDiffusionParameterTable vtkErrorDiffusionOptimizer::SingleKeyTable(
  const Key& key, double level)
{
  Key k = key;
  k.Level = std::min(std::max(level > 127.5 ? 255.0 - level : level, 1e-6), 127.5);
  vtkErrorDiffusionParameterTable table;
  table.SetKeys({ k });
  return table;
}

//------------------------------------------------------------------------------
Key vtkErrorDiffusionOptimizer::KeyAt(const vtkErrorDiffusionParameterTable& table, double level)
{
  const auto p = table.Evaluate(level / 255.0);
  Key k;
  k.Level = level;
  for (int c = 0; c < vtkErrorDiffusionParameterTable::NumberOfCoefficients; ++c)
  {
    k.Coefficients[c] = p.Weights[c];
  }
  k.Modulation = p.Modulation;
  return k;
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionOptimizer::Evaluate(const vtkErrorDiffusionParameterTable& table,
  double level, const Settings& settings, Evaluation& result, bool interior, std::string* error)
{
  if (!CheckSettings(settings, level, error))
  {
    return false;
  }
  if (interior && settings.GridSize - 2 * settings.CropFaces < 4)
  {
    if (error)
    {
      *error = "a cube of " + std::to_string(settings.GridSize) + " voxels less " +
        std::to_string(settings.CropFaces) + " at each face leaves less than 4";
    }
    return false;
  }
  const int n = settings.GridSize;
  vtkBlueNoiseSpectrumKernel whole;
  vtkBlueNoiseSpectrumKernel inner;
  const int m = n - 2 * settings.CropFaces;
  if (!whole.SetDimensions(n, n, n, error) || (interior && !inner.SetDimensions(m, m, m, error)))
  {
    return false;
  }
  whole.SetWeight(settings.Weight);
  inner.SetWeight(settings.Weight);
  if (!Measure(table, level, settings, whole, interior ? &inner : nullptr, error))
  {
    return false;
  }
  vtkBlueNoiseSpectrumKernel::Result r;
  if (!whole.Compute(r, error))
  {
    return false;
  }
  result.Whole = ToMetrics(r, n);
  if (interior)
  {
    if (!inner.Compute(r, error))
    {
      return false;
    }
    result.Interior = ToMetrics(r, m);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkErrorDiffusionOptimizer::LevelResult vtkErrorDiffusionOptimizer::OptimizeLevel(
  double level, const Key& start, const Settings& settings, const Progress& progress)
{
  LevelResult result;
  result.Level = level;
  result.Start = start;
  result.Start.Level = level;
  const double sum = CoefficientSum(start);
  if (!CheckSettings(settings, level, nullptr) || !(sum > 0.0))
  {
    return result;
  }
  LevelMeasure measure(level, settings);
  if (!measure.Ready())
  {
    return result;
  }
  // The simplex's point: the six coefficients, then the modulation.
  std::vector<double> x0(7), steps(7);
  for (int c = 0; c < 6; ++c)
  {
    x0[c] = std::abs(start.Coefficients[c]) / sum;
    steps[c] = 0.05; // a quarter or so of a typical weight
  }
  x0[6] = std::abs(start.Modulation);
  steps[6] = 0.15;
  result.Start = KeyOf(level, x0);
  measure(result.Start, result.StartMetrics);
  const Metrics& from = result.StartMetrics;
  auto objective = [&](const std::vector<double>& x) {
    Metrics m;
    if (!measure(KeyOf(level, x), m))
    {
      return std::numeric_limits<double>::infinity();
    }
    return settings.KeepSymmetry ? KeepingSymmetry(m, from) : m.Target;
  };
  vtkNelderMeadMinimizer minimizer;
  minimizer.SetMaximumEvaluations(settings.MaximumEvaluations);
  minimizer.SetTolerance(settings.Tolerance);
  if (progress)
  {
    minimizer.SetObserver(progress);
  }
  const auto best = minimizer.Minimize(objective, x0, steps);
  result.Evaluations = best.Evaluations;
  result.Optimized = KeyOf(level, best.Point);
  const double total = CoefficientSum(result.Optimized);
  for (double& a : result.Optimized.Coefficients)
  {
    a /= total;
  }
  measure(result.Optimized, result.OptimizedMetrics);
  return result;
}
