// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionParameterTable
 * @brief   Density-dependent 3D error-diffusion parameters (the paper's Table 1).
 *
 * A table of key density levels; each key holds the six diffusion coefficients
 * A100, A-110, A010, A0-11, A-101, A001 (offsets in x, y, z for the first layer
 * of a scanning cycle) and the threshold modulation strength m(g).
 *
 * Evaluate() returns the parameters for any density g in [0, 1]:
 * - g > 0.5 uses the parameters of 1 - g (the minority voxels of g and 1 - g
 *   share one distribution, paper section 4.2);
 * - between two keys the normalized coefficients A/M and m are interpolated
 *   linearly; below the first key and above the last one the nearest key holds.
 *
 * Built-in tables: Paper() is Table 1 verbatim; Fixed() is the un-optimized
 * baseline of the paper's Fig. 8 (4, 2, 4, 2, 2, 2 and m = 1); Optimized() is
 * the result of this project's own search.
 *
 * Text format (read by Parse/ReadFile, written by Write): one key per line,
 * eight numbers separated by white space or commas,
 * @code
 *   level A100 A-110 A010 A0-11 A-101 A001 m
 * @endcode
 * with level in 1/255 units (the paper's g_k * 255, in (0, 127.5]) and the
 * coefficients in any common unit (only their ratios matter). '#' starts a
 * comment; blank lines are ignored. Levels must increase strictly; coefficients
 * must be finite and non-negative with a positive sum; m must be finite and
 * non-negative.
 *
 * This is a plain C++ value type, not a vtkObject: it is cheap to copy and is
 * shared by the sampler, its kernel and the parameter optimizer.
 */
#ifndef vtkErrorDiffusionParameterTable_h
#define vtkErrorDiffusionParameterTable_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionParameterTable
{
public:
  static constexpr int NumberOfCoefficients = 6;
  /// Index of each coefficient, in the paper's order.
  enum Coefficient
  {
    A100 = 0,
    Am110 = 1,
    A010 = 2,
    A0m11 = 3,
    Am101 = 4,
    A001 = 5
  };

  struct Key
  {
    double Level = 0.0; ///< key density level in 1/255 units (Table 1's first column)
    std::array<double, NumberOfCoefficients> Coefficients{}; ///< raw A values
    double Modulation = 0.0;                                 ///< m(g)
  };

  /// Parameters at one density: normalized weights (sum 1) and m(g).
  struct Parameters
  {
    std::array<float, NumberOfCoefficients> Weights{};
    float Modulation = 0.0f;
  };

  vtkErrorDiffusionParameterTable() = default;

  static vtkErrorDiffusionParameterTable Paper();
  static vtkErrorDiffusionParameterTable Fixed();
  /**
   * The table this project's parameter search produced (bluenoise-optimize,
   * minimum of T(g) per key level; the search settings and the figures of
   * every level are in Filters/vtkErrorDiffusionOptimizedParameters.txt).
   */
  static vtkErrorDiffusionParameterTable Optimized();

  /**
   * Replace the keys. Returns false (and leaves the table unchanged) when the
   * keys break the rules above; the reason goes to `error` if given.
   */
  bool SetKeys(const std::vector<Key>& keys, std::string* error = nullptr);
  const std::vector<Key>& GetKeys() const { return this->Keys; }
  bool IsEmpty() const { return this->Keys.empty(); }

  /**
   * Parse the text format. On failure returns false and `error` names the
   * offending line ("line 3: expected 8 numbers, found 7").
   */
  static bool Parse(std::istream& in, vtkErrorDiffusionParameterTable& table, std::string& error);
  static bool ReadFile(
    const std::string& fileName, vtkErrorDiffusionParameterTable& table, std::string& error);

  /// Write the text format; `comment`, if not empty, goes first as '#' lines.
  void Write(std::ostream& out, const std::string& comment = std::string()) const;
  bool WriteFile(const std::string& fileName, const std::string& comment = std::string()) const;

  /// Parameters for density g (clamped to [0, 1]); see the class comment.
  Parameters Evaluate(double g) const;

private:
  void BuildSegments();

  std::vector<Key> Keys;
  // Per key: normalized weights and m, so Evaluate only interpolates.
  std::vector<Parameters> Normalized;
};

#endif
