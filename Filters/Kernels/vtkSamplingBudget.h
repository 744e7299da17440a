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
 * collects a histogram of x in one pass (Add, Merge) and then solves
 * for the s that makes that sum a target (Solve), through the clamp at 1,
 * exactly where the histogram is exact.
 *
 * Histogram. 65536 buckets keyed by the top 16 bits of x as a float (sign,
 * exponent and 7 bits of mantissa, ordered like the values), each with the
 * count, sum, minimum and maximum of its values; values beyond the float range
 * (|x| > 3.4e38) take the keys float's NaNs would have, one per 8 powers of
 * two. A bucket whose values are all equal (every value of 8- and 16-bit data,
 * and any value of fewer than 2^7 distinct values per power of two) is exact.
 * NaN is not counted (its density is 0); +inf and -inf are counted apart
 * (density 1 and 0 for any s > 0). Memory: up to 3 MiB, in pages of 256
 * buckets allocated when first used (a small volume touches a few) and kept by
 * Reset; merging two histograms costs a pass over the used pages.
 *
 * Exact sums. A bucket sums its values as integers: x in units of 2^-54 of
 * the bucket's power of two (2^k for values in [2^k, 2^(k+1)); every double
 * of the float range is such an integer but for those below 2^-180, which are
 * truncated), added in 128 bits. The histogram is therefore the same, bit for
 * bit, whatever the order the values come in: with any number of threads or
 * vtkSMPTools backend, slab by slab, or merged from the pieces of several
 * processes.
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

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkSamplingBudget
{
public:
  static constexpr int NumberOfBuckets = 65536;

  /// A sum of 64-bit integers, exact: 128-bit two's complement.
  struct ExactSum
  {
    std::uint64_t Low = 0;
    std::uint64_t High = 0;

    void Add(std::int64_t v)
    {
      const std::uint64_t low = this->Low + static_cast<std::uint64_t>(v);
      this->High += (v < 0 ? ~std::uint64_t(0) : 0u) + (low < this->Low ? 1u : 0u);
      this->Low = low;
    }
    /// Add n times v.
    void Add(std::int64_t v, std::uint64_t n);
    void Add(const ExactSum& other)
    {
      const std::uint64_t low = this->Low + other.Low;
      this->High += other.High + (low < this->Low ? 1u : 0u);
      this->Low = low;
    }
    /// The sum, rounded to a double.
    double Value() const;
  };

  struct Bucket
  {
    double Count = 0.0;
    ExactSum Sum; // the values in units of 2^-54 UnitOf(the bucket)
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

  /// The bucket of a finite value (NaN and infinities are not bucketed).
  static int BucketOf(double x)
  {
    const std::uint32_t bits = FloatBits(x);
    return ((bits >> 23) & 0xFFu) == 0xFFu ? BeyondFloatBucket(x) : Key(bits);
  }

  /// The power of two of a bucket's values: 2^k for values in [2^k, 2^(k+1))
  /// (2^-126 for zero and the float subnormals; beyond the float range, the
  /// lowest of the bucket's 8 powers of two).
  static double UnitOf(int bucket) { return PowerOfTwo(UnitExponent(bucket)); }

  /// Count one value (n times, n a whole count); inline, as a pass calls it
  /// for every voxel.
  void Add(double x, double n = 1.0)
  {
    if (!std::isfinite(x))
    {
      if (std::isinf(x))
      {
        (x > 0.0 ? this->PositiveInfinities : this->NegativeInfinities) += n;
      }
      return;
    }
    const std::uint32_t bits = FloatBits(x);
    const int field = static_cast<int>((bits >> 23) & 0xFFu); // float's exponent field
    const int i = field == 0xFF ? BeyondFloatBucket(x) : Key(bits);
    const int unit = field == 0xFF ? UnitExponent(i) : std::max(field, 1) - 127;
    Bucket& b = this->BucketAt(i);
    b.Min = b.Count == 0.0 ? x : std::min(b.Min, x);
    b.Max = b.Count == 0.0 ? x : std::max(b.Max, x);
    b.Count += n;
    // |x| < 2 units (2^8 beyond the float range): below 2^62 in 2^-54 units;
    // scaling by a power of two is exact.
    const auto v = static_cast<std::int64_t>(x * PowerOfTwo(FixedPoint - unit));
    if (n == 1.0)
    {
      b.Sum.Add(v);
    }
    else
    {
      b.Sum.Add(v, static_cast<std::uint64_t>(n));
    }
  }

  /// Add another histogram (another piece or thread of the same volume).
  void Merge(const vtkSamplingBudget& other);

  /**
   * Float values counted by their bits, to be merged into a budget at once:
   * the histogram Add gives the same values, bit for bit, for a fraction of
   * the cost (integer work: the bucket is the top 16 bits, the sum and
   * extremes those of the low 16). Memory: 1.5 MiB.
   */
  class FloatTally
  {
  public:
    FloatTally() : Entries(NumberOfBuckets) {}
    /// Nothing counted, the memory kept.
    void Reset()
    {
      std::fill(this->Entries.begin(), this->Entries.end(), Entry());
      this->Infinities[0] = this->Infinities[1] = 0;
    }
    /// Count x n times (callers count runs of equal values: volumes have them).
    void Add(float x, std::uint64_t n = 1)
    {
      std::uint32_t bits = 0;
      std::memcpy(&bits, &x, sizeof(bits));
      if ((bits & 0x7F800000u) == 0x7F800000u) // infinities (NaN is not counted)
      {
        this->Infinities[bits >> 31] += (bits & 0x007FFFFFu) == 0 ? n : 0u;
        return;
      }
      const std::uint32_t ordered = (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
      Entry& e = this->Entries[ordered >> 16];
      const auto low = static_cast<std::uint16_t>(ordered);
      e.Count += n;
      e.SumOfLow += low * n;
      e.MinLow = std::min(e.MinLow, low);
      e.MaxLow = std::max(e.MaxLow, low);
    }

  private:
    friend class vtkSamplingBudget;
    struct Entry
    {
      std::uint64_t Count = 0;
      std::uint64_t SumOfLow = 0; // of the order-preserving bits' low 16
      std::uint16_t MinLow = 0xFFFF;
      std::uint16_t MaxLow = 0;
    };
    std::vector<Entry> Entries; // by bucket
    std::uint64_t Infinities[2] = { 0, 0 }; // +inf, -inf
  };
  void Merge(const FloatTally& tally);

  /// Finite range of the values counted; false when there is none.
  bool GetRange(double range[2]) const;

  /// Sum of the densities at scale s (s >= 0, +inf allowed).
  double Expected(double scale, const Mapping& map) const;

  /// The scale whose expected count is `target` (> 0).
  Solution Solve(double target, const Mapping& map) const;

  /// For reductions across processes: per bucket the count, the sum (in four
  /// 32-bit parts, low first, the last signed), the minimum and the maximum,
  /// then the +inf and -inf counts, as one flat array of exact doubles (and
  /// back).
  std::vector<double> Serialize() const;
  bool Deserialize(const std::vector<double>& values);

private:
  static constexpr int PageSize = 256;
  static constexpr int NumberOfPages = NumberOfBuckets / PageSize;

  Bucket& BucketAt(int i) // allocates its page
  {
    std::vector<Bucket>& page = this->Pages[i / PageSize];
    if (page.empty())
    {
      page.resize(PageSize);
    }
    return page[i % PageSize];
  }
  // Calls f(i, bucket) for the used buckets, in bucket order.
  template <typename F>
  void ForEachUsed(F&& f) const
  {
    for (int p = 0; p < NumberOfPages; ++p)
    {
      const std::vector<Bucket>& page = this->Pages[p];
      for (int k = 0; k < static_cast<int>(page.size()); ++k)
      {
        if (page[k].Count > 0.0)
        {
          f(p * PageSize + k, page[k]);
        }
      }
    }
  }

  // A used bucket as Solve needs it.
  struct Summary
  {
    double Count, Mean, Min, Max;
  };
  static std::uint32_t FloatBits(double x)
  {
    const float f = static_cast<float>(x);
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, sizeof(bits));
    return bits;
  }
  // Order-preserving: negative values have their bits flipped, positive ones
  // their sign set, so unsigned order is value order.
  static int Key(std::uint32_t bits)
  {
    bits = (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
    return static_cast<int>(bits >> 16);
  }
  // Beyond the float range: a key of float's NaNs, 0x7F80 + 1 + (k - 128) / 8
  // for |x| in [2^k, 2^(k+1)).
  static int BeyondFloatBucket(double x)
  {
    const auto k = static_cast<std::uint32_t>(std::max(std::ilogb(x), 128) - 128);
    return Key((std::signbit(x) ? 0x80000000u : 0u) | ((0x7F81u + k / 8) << 16));
  }
  // A bucket's sum counts its values in units of 2^(UnitExponent - FixedPoint).
  static constexpr int FixedPoint = 54;
  // k of a bucket's values' 2^k (see UnitOf).
  static int UnitExponent(int bucket)
  {
    const int bits = bucket >= 0x8000 ? bucket : ~bucket;
    const int field = (bits >> 7) & 0xFF; // the float exponent field
    return field == 0xFF ? 128 + 8 * ((bits & 0x7F) - 1) : std::max(field, 1) - 127;
  }
  // 2^e for -1022 <= e <= 1023, built from its bits.
  static double PowerOfTwo(int e)
  {
    const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
    double value = 0.0;
    std::memcpy(&value, &bits, sizeof(value));
    return value;
  }
  std::vector<Summary> Summarize() const;
  static double BucketExpected(const Summary& b, double scale, const Mapping& map);
  double ExpectedOver(const std::vector<Summary>& used, double scale, const Mapping& map) const;

  // NumberOfPages pages of PageSize buckets, each empty until used (copyable:
  // vtkSMPThreadLocal copies its exemplar).
  std::vector<std::vector<Bucket>> Pages;
  double PositiveInfinities = 0.0;
  double NegativeInfinities = 0.0;
};

#endif
