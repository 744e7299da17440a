// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The parameter optimizer on a tiny grid with a tiny budget lowers T(g) from
// its start point, returns normalized coefficients, and its figures agree with
// Evaluate() on the same settings (one metric implementation). Relaxed
// measures the relaxed samples; KeepSymmetry lowers L without raising S or
// the anisotropy.
#include "BlueNoiseTestUtilities.h"
#include "vtkErrorDiffusionOptimizer.h"

#include <cmath>

using namespace bluenoise_test;

int main()
{
  vtkErrorDiffusionOptimizer::Settings settings;
  settings.GridSize = 24;
  settings.Seeds = 2;
  settings.MaximumEvaluations = 60;
  // A deliberately poor start: the Fixed baseline at 16/255.
  const auto start = vtkErrorDiffusionOptimizer::KeyAt(vtkErrorDiffusionParameterTable::Fixed(), 16);
  int calls = 0;
  const auto r = vtkErrorDiffusionOptimizer::OptimizeLevel(
    16, start, settings, [&calls](int, double) { ++calls; });
  std::cout << "T(16/255): start " << r.StartMetrics.Target << ", optimized "
            << r.OptimizedMetrics.Target << " after " << r.Evaluations << " evaluations"
            << std::endl;
  Check(r.Evaluations > 0 && r.Evaluations <= settings.MaximumEvaluations + 8, "budget honored");
  Check(calls > 0, "progress reported");
  Check(r.OptimizedMetrics.Target < r.StartMetrics.Target, "T lowered from the start point");
  double sum = 0.0;
  for (double a : r.Optimized.Coefficients)
  {
    sum += a;
    Check(a >= 0.0, "coefficients non-negative");
  }
  Check(std::abs(sum - 1.0) < 1e-9, "coefficients normalized");
  Check(r.OptimizedMetrics.Points > 0.9 * 16.0 / 255.0 * 24 * 24 * 24, "sample count sane");

  // Evaluate() with the optimized key gives the same T.
  vtkErrorDiffusionOptimizer::Evaluation e;
  std::string error;
  Check(vtkErrorDiffusionOptimizer::Evaluate(
          vtkErrorDiffusionOptimizer::SingleKeyTable(r.Optimized, 16), 16, settings, e, true, &error),
    "Evaluate: " + error);
  Check(std::abs(e.Whole.Target - r.OptimizedMetrics.Target) < 1e-12,
    "Evaluate agrees with the optimizer");
  Check(e.Interior.Points > 0 && e.Interior.Points < e.Whole.Points, "interior figures computed");

  // Relaxed: the default method's samples, as many as the scan's, and with
  // less low-frequency energy.
  vtkErrorDiffusionOptimizer::Settings relaxed = settings;
  relaxed.GridSize = 32;
  const auto optimized = vtkErrorDiffusionParameterTable::Optimized();
  vtkErrorDiffusionOptimizer::Evaluation scan, moved;
  Check(vtkErrorDiffusionOptimizer::Evaluate(optimized, 8, relaxed, scan, false, &error),
    "Evaluate, scan: " + error);
  relaxed.Relaxed = true;
  Check(vtkErrorDiffusionOptimizer::Evaluate(optimized, 8, relaxed, moved, false, &error),
    "Evaluate, relaxed: " + error);
  std::cout << "L(8/255), 32^3: scan " << scan.Whole.LowFrequencyRatio << ", relaxed "
            << moved.Whole.LowFrequencyRatio << std::endl;
  Check(moved.Whole.Points == scan.Whole.Points, "the relaxation keeps the count");
  Check(moved.Whole.LowFrequencyRatio < 0.9 * scan.Whole.LowFrequencyRatio,
    "the relaxation lowers L");

  // KeepSymmetry: L lowered, S and anisotropy not raised above the start's.
  relaxed.KeepSymmetry = true;
  relaxed.MaximumEvaluations = 40;
  const auto k = vtkErrorDiffusionOptimizer::OptimizeLevel(
    8, vtkErrorDiffusionOptimizer::KeyAt(optimized, 8), relaxed);
  std::cout << "KeepSymmetry at 8/255: L " << k.StartMetrics.LowFrequencyRatio << " -> "
            << k.OptimizedMetrics.LowFrequencyRatio << ", S " << k.StartMetrics.Symmetry << " -> "
            << k.OptimizedMetrics.Symmetry << std::endl;
  Check(k.OptimizedMetrics.LowFrequencyRatio < k.StartMetrics.LowFrequencyRatio, "L lowered");
  Check(k.OptimizedMetrics.Symmetry <= k.StartMetrics.Symmetry, "S not above the start's");
  Check(k.OptimizedMetrics.AnisotropyDB <= k.StartMetrics.AnisotropyDB,
    "anisotropy not above the start's");

  // Bad settings are refused.
  settings.GridSize = 2;
  Check(!vtkErrorDiffusionOptimizer::Evaluate(vtkErrorDiffusionParameterTable::Paper(), 16,
          settings, e, false, &error) &&
      !error.empty(),
    "bad grid size refused");
  return Summary("TestErrorDiffusionOptimizer");
}
