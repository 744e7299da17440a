// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionOptimizer
 * @brief   The paper's parameter search: minimize T(g) per key density level.
 *
 * For one density level g the objective is the blue-noise target
 * T(g) = w L(g) + (1 - w) S(g) (paper Eq. 5) of what the sampler produces on
 * a constant-density cube: the sampler kernel (vtkErrorDiffusionKernel, the
 * boundary handling users get included) samples a GridSize^3 cube once per
 * seed, the periodograms of the realizations are averaged, and the metric is
 * vtkBlueNoiseSpectrumKernel's (one implementation, shared with the
 * vtkBlueNoiseSpectrum filter). The seeds are the same for every candidate
 * (common random numbers), so the objective is a deterministic function of the
 * parameters and the simplex compares like with like.
 *
 * The search variables are the six coefficients (their absolute values; only
 * their ratios matter, the start point is normalized to sum 1) and m(g) (its
 * absolute value), minimized with vtkNelderMeadMinimizer from a start key
 * (typically the Table 1 parameters at that level).
 *
 * Relaxed: the samples are measured after vtkBlueNoiseRelaxation's pass,
 * as the default method (relaxed error diffusion) gives them, so that a
 * table can be searched for that method.
 *
 * KeepSymmetry: the objective is L(g) alone, among the parameters whose S(g)
 * and mean anisotropy are at most the start point's (a point of more ranks
 * behind the start, so the result never has more than the start; T then
 * falls with L).
 *
 * Evaluate() measures any parameter table at any level with the same recipe;
 * it also reports the interior figures (faces cropped by CropFaces voxels).
 */
#ifndef vtkErrorDiffusionOptimizer_h
#define vtkErrorDiffusionOptimizer_h

#include "vtkErrorDiffusionParameterTable.h"
#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <functional>

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionOptimizer
{
public:
  struct Settings
  {
    int GridSize = 64;        ///< the cube's edge, voxels
    int Seeds = 4;            ///< realizations averaged per evaluation
    int FirstSeed = 0;        ///< seeds FirstSeed .. FirstSeed + Seeds - 1
    double Weight = 0.02;     ///< w of Eq. 5
    int MaximumEvaluations = 400;
    double Tolerance = 1e-6;  ///< relative spread of T over the simplex
    double ModulationScale = 0.5;
    int WarmUpLayers = 8;
    int CropFaces = 8;        ///< for the interior figures of Evaluate()
    bool Relaxed = false;     ///< measure after the default method's relaxation
    bool KeepSymmetry = false; ///< minimize L(g), S(g) and anisotropy at most the start's
  };

  struct Metrics
  {
    double Target = 0.0;            ///< T(g)
    double LowFrequencyRatio = 0.0; ///< L(g)
    double Symmetry = 0.0;          ///< S(g)
    double AnisotropyDB = 0.0;      ///< mean over shells 1 .. GridSize / 2
    double Points = 0.0;            ///< mean number of samples
  };

  struct Evaluation
  {
    Metrics Whole;
    Metrics Interior; ///< only when Evaluate() is asked for it
  };

  struct LevelResult
  {
    double Level = 0.0; ///< 1/255 units
    vtkErrorDiffusionParameterTable::Key Start;
    vtkErrorDiffusionParameterTable::Key Optimized;
    Metrics StartMetrics;
    Metrics OptimizedMetrics;
    int Evaluations = 0;
  };

  /// Called during OptimizeLevel with (evaluations, best T so far).
  using Progress = std::function<void(int, double)>;

  /**
   * The metrics of `table` at density level/255 (level in 1/255 units, in
   * (0, 255)). Returns false with a reason for bad settings.
   */
  static bool Evaluate(const vtkErrorDiffusionParameterTable& table, double level,
    const Settings& settings, Evaluation& result, bool interior = false,
    std::string* error = nullptr);

  /// Minimize T at one level from `start` (its Level field is ignored).
  static LevelResult OptimizeLevel(double level, const vtkErrorDiffusionParameterTable::Key& start,
    const Settings& settings, const Progress& progress = nullptr);

  /// A table with one key: `key` at `level` (so every density uses it).
  static vtkErrorDiffusionParameterTable SingleKeyTable(
    const vtkErrorDiffusionParameterTable::Key& key, double level);

  /// The key a table gives at `level` (interpolated), as raw coefficients summing to 1.
  static vtkErrorDiffusionParameterTable::Key KeyAt(
    const vtkErrorDiffusionParameterTable& table, double level);
};

#endif
