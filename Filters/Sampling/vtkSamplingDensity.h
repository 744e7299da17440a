// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSamplingDensity
 * @brief   How a sampler turns a point-data array into densities in [0, 1].
 *
 * For voxel values v (one component of the array, or the magnitude of its
 * tuples for component -1) the density is g = clamp(s * (a x + b), 0, 1),
 * with x = v for the IDENTITY (a = 1, b = 0) and SCALAR_RANGE mappings
 * (a = 1 / (hi - lo), b = -lo a, [lo, hi] a chosen range or the finite range
 * of the values) and x = f(v) for TRANSFER_FUNCTION (a piecewise function f;
 * a = 1, b = 0). NaN gives 0, as does a voxel flagged DUPLICATEPOINT or
 * HIDDENPOINT in the image's ghost array. The scale s is DensityScale, or the
 * one that makes the expected number of points (the sum of g) a budget:
 * CollectStatistics makes the one pass over the values that both the finite
 * range and the budget need (vtkSamplingBudget), in parallel with vtkSMPTools.
 *
 * Edge cases: a range of zero width (a constant array) maps every value to
 * x-density 1 (a = 0, b = 1): the volume is sampled uniformly. A range so wide
 * that hi - lo overflows is mapped through values halved first. An array
 * without finite values gives density 0 everywhere.
 *
 * The same object serves every layer of a run (and every slab of a streamed
 * one): it is configured once, then Fill is called for each layer (from one
 * thread at a time: it keeps a table of densities from layer to layer).
 */
#ifndef vtkSamplingDensity_h
#define vtkSamplingDensity_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkSamplingBudget.h"         // for vtkSamplingBudget::Mapping
#include "vtkType.h"                   // for vtkIdType

#include <cstdint>
#include <memory> // for std::shared_ptr
#include <mutex>  // for std::mutex
#include <vector> // for std::vector

class vtkDataArray;
class vtkPiecewiseFunction;

class VTKFILTERSBLUENOISE_EXPORT vtkSamplingDensity
{
public:
  enum Mappings
  {
    IDENTITY = 0,
    SCALAR_RANGE = 1,
    TRANSFER_FUNCTION = 2
  };

  /// mode: one of Mappings; component: >= 0, or -1 for the magnitude.
  void SetMapping(int mode, int component, vtkPiecewiseFunction* function = nullptr);
  int GetMapping() const { return this->Mode; }
  int GetComponent() const { return this->Component; }
  /// The component alone (>= 0, or -1 for the magnitude), the rest kept.
  void SetComponent(int component) { this->Component = component; }

  /// Whether the values must be counted before the densities are known:
  /// for the finite range (SCALAR_RANGE without a set range) or a budget.
  bool NeedsStatistics(bool budget) const;

  /// SCALAR_RANGE with a chosen range (hi > lo, both finite).
  void SetRange(double low, double high);
  bool HasRange() const { return this->RangeSet; }
  void GetRange(double range[2]) const;

  /**
   * Count the values of tuples [begin, end) of `array` into `statistics`
   * (the transfer function already applied). Voxels whose ghost flag (if
   * `ghosts`, indexed like the tuples) marks them as not owned are skipped.
   * The pass uses vtkSMPTools; with `threads` > 1 it is also split into that
   * many contiguous parts on threads of its own (vtkBlueNoiseThreads::Split,
   * for vtkSMPTools' Sequential backend), each counted apart and merged (not with a transfer function,
   * whose evaluation is not known to be thread-safe). The histogram's sums
   * are exact, so neither split changes the result.
   */
  void CollectStatistics(vtkDataArray* array, vtkIdType begin, vtkIdType end,
    const unsigned char* ghosts, vtkSamplingBudget& statistics, int threads = 1) const;

  /// What the densities of a run add up to: a scale set by hand, or the
  /// scale that makes them a number of points.
  struct Budget
  {
    static Budget Scale(double scale)
    {
      Budget b;
      b.Value = scale;
      return b;
    }
    static Budget Points(double points)
    {
      Budget b;
      b.ByPoints = true;
      b.Value = points;
      return b;
    }
    bool ByPoints = false;
    double Value = 1.0;
  };

  /// What Finish found besides the scale.
  struct Outcome
  {
    const char* Note = nullptr; ///< a warning to give (a constant array), or nullptr
    bool OutOfReach = false;    ///< more points asked for than the volume can hold
    double Reachable = 0.0;     ///< voxels of positive density (every one drawn then)
  };

  /**
   * After the statistics (when needed): take the finite range from them
   * (when no range is set), fix the linear map, and set the scale the budget
   * asks for: the given one, or the one whose densities add up to the number
   * of points (vtkSamplingBudget::Solve over the statistics, which a budget
   * in points needs, see NeedsStatistics).
   */
  Outcome Finish(const vtkSamplingBudget* statistics, const Budget& budget);

  /// The map from x to the unscaled density a x + b.
  vtkSamplingBudget::Mapping GetLinearMap() const { return this->Map; }

  /// The scale Finish set.
  double GetScale() const { return this->Scale; }

  struct ValueTable;

  /**
   * The densities of tuples [begin, end) in order into `out`; returns their
   * sum. Ghost flags as in CollectStatistics. `table` is what Fill keeps from
   * one call to the next (see ValueTable): threads that fill side by side
   * each pass their own; Fill changes nothing else, so one density serves
   * them all.
   */
  double Fill(vtkDataArray* array, vtkIdType begin, vtkIdType end, const unsigned char* ghosts,
    float* out, ValueTable& table) const;

private:
  const char* FixLinearMap(const vtkSamplingBudget* statistics);

  int Mode = SCALAR_RANGE;
  int Component = 0;
  vtkPiecewiseFunction* Function = nullptr; // not owned: the caller keeps it alive
  bool RangeSet = false;
  double Range[2] = { 0.0, 1.0 };
  vtkSamplingBudget::Mapping Map;
  double Scale = 1.0;

public:
  /// The densities of every 8- or 16-bit value, built by the first Fill of
  /// a run and kept for the next layers while type and map stay the same
  /// (a 16-bit table costs as much as a 256^2 layer), and the counts of the
  /// values of the layer being filled. For Fill only, one per thread.
  struct ValueTable
  {
    int Type = -1; // VTK type of the values, -1 for none
    double A = 0.0, B = 0.0, Scale = 0.0;
    std::vector<float> Density;
    std::vector<std::uint64_t> Counts; // per value, in the layer being filled (in lanes)
  };

  /// Float tallies (1.5 MiB each) kept from one statistics pass to the next:
  /// fresh ones would be faulted in, a page at a time, by every part of every
  /// pass. Shared by copies; thread-safe.
  class SpareTallies
  {
  public:
    std::unique_ptr<vtkSamplingBudget::FloatTally> Take();
    void Give(std::unique_ptr<vtkSamplingBudget::FloatTally> tally);

  private:
    std::mutex Mutex;
    std::vector<std::unique_ptr<vtkSamplingBudget::FloatTally>> Tallies;
  };

private:
  std::shared_ptr<SpareTallies> Spares = std::make_shared<SpareTallies>();
};

#endif
