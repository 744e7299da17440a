// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSamplingBudget
 * @brief   The density scale that gives a volume a chosen expected number of
 *          points, from one pass over its values.
 *
 * A sampler draws each voxel with density g = clamp(s * (a x + b), 0, 1),
 * where x is the voxel's value (an array component, its magnitude, or a
 * transfer function's output), a x + b a linear mapping (a > 0; a = 1, b = 0
 * for values that already are densities) and s the density scale; the
 * expected number of points is the sum of g over the voxels. The budget
 * collects a histogram of x in one pass (Add, AddCount, Merge) and then solves
 * for the s that makes that sum a target (Solve), through the clamp at 1,
 * exactly where the histogram is exact.
 *
 * Histogram. 65536 buckets keyed by the top 16 bits of x as a float (sign,
 * exponent and 7 bits of mantissa, ordered like the values), each with the
 * count, mean, minimum and maximum of its values: a bucket whose values are all
 * equal (every value of 8- and 16-bit data, and any value of fewer than 2^7
 * distinct values per power of two) is exact. NaN is not counted (its density
 * is 0); +inf and -inf are counted apart (density 1 and 0 for any s > 0).
 * Memory: the buckets live in 256 pages of 256 (8 KiB each), a page allocated
 * when a value first falls in it and kept, zeroed, by Reset() for the next
 * pass: up to 2 MiB, a few pages for most data (the values of one sign and a
 * few binary orders of magnitude share a page), so that a histogram per
 * thread per update costs what its values touch. Merging, the range and
 * Solve pass over the allocated pages only, in bucket order as before.
 *
 * Solve. Sum(s) = sum over buckets of: 0 where a Max + b <= 0, the count
 * where s (a Min + b) >= 1, and s Count (a Mean + b) where the whole bucket
 * lies between; a bucket straddling 0 or 1 / s counts as if its values were
 * spread evenly between its Min and Max (the only approximation, bounded by
 * that bucket's count). Sum(s) is continuous and non-decreasing; the solution
 * is bracketed between powers of two and bisected to a relative 1e-15, or
 * reported as unreachable when the target is at least the number of voxels
 * of positive density (the Reachable count, every one of them drawn with
 * density 1: then Scale is +inf).
 */
#ifndef vtkSamplingBudget_h
#define vtkSamplingBudget_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <cstdint>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkSamplingBudget
{
public:
  static constexpr int NumberOfBuckets = 65536;

  struct Bucket
  {
    double Count = 0.0;
    double Mean = 0.0; // kept as a mean: a sum of values near 1e308 would overflow
    double Min = 0.0;
    double Max = 0.0;
  };

  /// The linear map x -> a x + b (a > 0) from histogram values to densities.
  struct Mapping
  {
    double A = 1.0;
    double B = 0.0;
  };

  struct Solution
  {
    double Scale = 0.0;     ///< s; +inf when the target is out of reach
    double Expected = 0.0;  ///< sum of the densities at that scale
    double Reachable = 0.0; ///< voxels of positive density: the most points possible
    bool OutOfReach = false;
  };

  vtkSamplingBudget();

  /// Forget every value.
  void Reset();

  /// The bucket of a value (NaN and infinities are not bucketed).
  static int BucketOf(double x);

  /// Count one value (n times).
  void Add(double x, double n = 1.0);

  /// Add another histogram (another piece or thread of the same volume).
  void Merge(const vtkSamplingBudget& other);

  /// Finite range of the values counted; false when there is none.
  bool GetRange(double range[2]) const;

  /// Sum of the densities at scale s (s >= 0, +inf allowed).
  double Expected(double scale, const Mapping& map) const;

  /// The scale whose expected count is `target` (> 0).
  Solution Solve(double target, const Mapping& map) const;

  /// For reductions across processes: the buckets' counts, means, minima and
  /// maxima, then +inf and -inf counts, as one flat array (and back).
  std::vector<double> Serialize() const;
  bool Deserialize(const std::vector<double>& values);

private:
  static constexpr int PageSize = 256;
  static constexpr int NumberOfPages = NumberOfBuckets / PageSize;

  Bucket& BucketAt(int i);                 // allocates its page
  void MergeBucket(int i, const Bucket& o); // o: bucket i of another histogram
  std::vector<Bucket> UsedBuckets() const; // those with a count, in bucket order
  double BucketExpected(const Bucket& b, double scale, const Mapping& map) const;
  double ExpectedOver(const std::vector<Bucket>& buckets, double scale, const Mapping& map) const;

  // NumberOfPages pages of PageSize buckets, each empty until used (copyable:
  // vtkSMPThreadLocal copies its exemplar).
  std::vector<std::vector<Bucket>> Pages;
  double PositiveInfinities = 0.0;
  double NegativeInfinities = 0.0;
};

#endif
