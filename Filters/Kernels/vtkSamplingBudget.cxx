// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSamplingBudget.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>

namespace
{
constexpr int SerialSize = 7; // doubles per bucket in Serialize()

// Integral of clamp(u, 0, 1) from 0 to u.
double ClampIntegral(double u)
{
  if (u <= 0.0)
  {
    return 0.0;
  }
  return u < 1.0 ? 0.5 * u * u : u - 0.5;
}
}

//------------------------------------------------------------------------------
void vtkSamplingBudget::ExactSum::Add(std::int64_t v, std::uint64_t n)
{
  // |v| n as 128 bits from 32-bit halves, then negated for v < 0.
  const std::uint64_t m = v < 0 ? 0u - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  const std::uint64_t m0 = m & 0xFFFFFFFFu, m1 = m >> 32, n0 = n & 0xFFFFFFFFu, n1 = n >> 32;
  const std::uint64_t p00 = m0 * n0, p01 = m0 * n1, p10 = m1 * n0, p11 = m1 * n1;
  const std::uint64_t middle = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
  ExactSum product;
  product.Low = (p00 & 0xFFFFFFFFu) | (middle << 32);
  product.High = p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32);
  if (v < 0)
  {
    product.Low = ~product.Low + 1u;
    product.High = ~product.High + (product.Low == 0 ? 1u : 0u);
  }
  this->Add(product);
}

//------------------------------------------------------------------------------
double vtkSamplingBudget::ExactSum::Value() const
{
  const bool negative = (this->High >> 63) != 0;
  std::uint64_t low = this->Low, high = this->High;
  if (negative)
  {
    low = ~low + 1u;
    high = ~high + (low == 0 ? 1u : 0u);
  }
  const double magnitude = static_cast<double>(high) * 18446744073709551616.0 + static_cast<double>(low);
  return negative ? -magnitude : magnitude;
}

//------------------------------------------------------------------------------
vtkSamplingBudget::vtkSamplingBudget()
{
  this->Reset();
}

//------------------------------------------------------------------------------
void vtkSamplingBudget::Reset()
{
  // Pages stay allocated for the next pass over a volume.
  this->Pages.resize(NumberOfPages);
  for (auto& page : this->Pages)
  {
    std::fill(page.begin(), page.end(), Bucket());
  }
  this->PositiveInfinities = 0.0;
  this->NegativeInfinities = 0.0;
}

//------------------------------------------------------------------------------
void vtkSamplingBudget::Merge(const vtkSamplingBudget& other)
{
  other.ForEachUsed([this](int i, const Bucket& o) {
    Bucket& b = this->BucketAt(i);
    b.Min = b.Count == 0.0 ? o.Min : std::min(b.Min, o.Min);
    b.Max = b.Count == 0.0 ? o.Max : std::max(b.Max, o.Max);
    b.Count += o.Count;
    b.Sum.Add(o.Sum);
  });
  this->PositiveInfinities += other.PositiveInfinities;
  this->NegativeInfinities += other.NegativeInfinities;
}

//------------------------------------------------------------------------------
// Each bucket's values as Add counts them: a float of exponent field e >= 1
// and mantissa m is v = (2^23 + m) 2^31 in the bucket's 2^-54 units (m 2^31
// for e = 0), where m = (the key's 7 bits) 2^16 + (its low 16 bits).
void vtkSamplingBudget::Merge(const FloatTally& tally)
{
  const auto value = [](std::uint32_t ordered) {
    const std::uint32_t bits = (ordered & 0x80000000u) ? (ordered & 0x7FFFFFFFu) : ~ordered;
    float x = 0.0f;
    std::memcpy(&x, &bits, sizeof(x));
    return static_cast<double>(x);
  };
  for (int i = 0; i < NumberOfBuckets; ++i)
  {
    const FloatTally::Entry& e = tally.Entries[i];
    if (e.Count == 0)
    {
      continue;
    }
    const auto key = static_cast<std::uint32_t>(i) << 16;
    const double lo = value(key | e.MinLow);
    const double hi = value(key | e.MaxLow);
    Bucket& b = this->BucketAt(i);
    b.Min = b.Count == 0.0 ? lo : std::min(b.Min, lo);
    b.Max = b.Count == 0.0 ? hi : std::max(b.Max, hi);
    b.Count += static_cast<double>(e.Count);
    // The bits of a negative value are the order-preserving ones flipped.
    const bool negative = (key & 0x80000000u) == 0;
    const std::uint32_t bits = negative ? ~key : (key & 0x7FFFFFFFu);
    const std::uint32_t field = (bits >> 23) & 0xFFu;
    const std::int64_t base =
      static_cast<std::int64_t>((field ? 0x800000u : 0u) | (bits & 0x7F0000u)) << 31;
    const std::uint64_t lows = negative ? 0xFFFFu * e.Count - e.SumOfLow : e.SumOfLow;
    b.Sum.Add(negative ? -base : base, e.Count);
    b.Sum.Add(negative ? -(std::int64_t(1) << 31) : (std::int64_t(1) << 31), lows);
  }
  this->PositiveInfinities += static_cast<double>(tally.Infinities[0]);
  this->NegativeInfinities += static_cast<double>(tally.Infinities[1]);
}

//------------------------------------------------------------------------------
bool vtkSamplingBudget::GetRange(double range[2]) const
{
  bool any = false;
  this->ForEachUsed([&](int, const Bucket& b) {
    range[0] = any ? range[0] : b.Min;
    range[1] = b.Max;
    any = true;
  });
  return any;
}

//------------------------------------------------------------------------------
double vtkSamplingBudget::BucketExpected(const Summary& b, double scale, const Mapping& map)
{
  const double low = map.A * b.Min + map.B;
  const double high = map.A * b.Max + map.B;
  if (!(high > 0.0))
  {
    return 0.0;
  }
  if (std::isinf(scale))
  {
    // Every value of positive density is drawn; one straddling 0 counts as
    // if its values were spread evenly.
    return low > 0.0 ? b.Count : b.Count * high / (high - low);
  }
  const double sLow = scale * low;
  const double sHigh = scale * high;
  if (sLow >= 1.0)
  {
    return b.Count;
  }
  if (sLow >= 0.0 && sHigh <= 1.0)
  {
    return scale * b.Count * (map.A * b.Mean + map.B);
  }
  return b.Count * (ClampIntegral(sHigh) - ClampIntegral(sLow)) / (sHigh - sLow);
}

//------------------------------------------------------------------------------
double vtkSamplingBudget::Expected(double scale, const Mapping& map) const
{
  return this->ExpectedOver(this->Summarize(), scale, map);
}

//------------------------------------------------------------------------------
// The used buckets with their means (the sum over the count, back in the
// values' units: no overflow; kept in [Min, Max] against rounding).
std::vector<vtkSamplingBudget::Summary> vtkSamplingBudget::Summarize() const
{
  std::vector<Summary> used;
  this->ForEachUsed([&used](int i, const Bucket& b) {
    const double mean = b.Sum.Value() / b.Count * PowerOfTwo(UnitExponent(i) - FixedPoint);
    used.push_back({ b.Count, std::min(std::max(mean, b.Min), b.Max), b.Min, b.Max });
  });
  return used;
}

//------------------------------------------------------------------------------
double vtkSamplingBudget::ExpectedOver(
  const std::vector<Summary>& used, double scale, const Mapping& map) const
{
  if (!(scale > 0.0))
  {
    return 0.0;
  }
  double sum = this->PositiveInfinities;
  for (const Summary& b : used)
  {
    sum += BucketExpected(b, scale, map);
  }
  return sum;
}

//------------------------------------------------------------------------------
vtkSamplingBudget::Solution vtkSamplingBudget::Solve(double target, const Mapping& map) const
{
  Solution solution;
  const std::vector<Summary> used = this->Summarize(); // the bisection sums many times
  const auto expected = [&](double scale) { return this->ExpectedOver(used, scale, map); };
  const double infinity = std::numeric_limits<double>::infinity();
  solution.Reachable = expected(infinity);
  if (!(target > 0.0) || !(solution.Reachable > 0.0))
  {
    return solution; // scale 0, nothing expected
  }
  if (target >= solution.Reachable)
  {
    solution.Scale = infinity;
    solution.Expected = solution.Reachable;
    solution.OutOfReach = target > solution.Reachable;
    return solution;
  }
  // Bracket the solution between powers of two, then bisect.
  double low = 1.0;
  double high = 1.0;
  while (expected(low) > target && low > 1e-300)
  {
    low *= 0.5;
  }
  while (expected(high) < target && high < 1e300)
  {
    high *= 2.0;
  }
  low = std::min(low, high * 0.5);
  for (int i = 0; i < 200 && high - low > 1e-15 * high; ++i)
  {
    const double middle = 0.5 * (low + high);
    (expected(middle) < target ? low : high) = middle;
  }
  solution.Scale = 0.5 * (low + high);
  solution.Expected = expected(solution.Scale);
  return solution;
}

//------------------------------------------------------------------------------
std::vector<double> vtkSamplingBudget::Serialize() const
{
  std::vector<double> values(SerialSize * static_cast<size_t>(NumberOfBuckets), 0.0);
  this->ForEachUsed([&values](int i, const Bucket& b) {
    double* v = values.data() + SerialSize * static_cast<size_t>(i);
    v[0] = b.Count;
    v[1] = static_cast<double>(b.Sum.Low & 0xFFFFFFFFu);
    v[2] = static_cast<double>(b.Sum.Low >> 32);
    v[3] = static_cast<double>(b.Sum.High & 0xFFFFFFFFu);
    v[4] = static_cast<double>(static_cast<std::int32_t>(b.Sum.High >> 32));
    v[5] = b.Min;
    v[6] = b.Max;
  });
  values.push_back(this->PositiveInfinities);
  values.push_back(this->NegativeInfinities);
  return values;
}

//------------------------------------------------------------------------------
bool vtkSamplingBudget::Deserialize(const std::vector<double>& values)
{
  if (values.size() != SerialSize * static_cast<size_t>(NumberOfBuckets) + 2)
  {
    return false;
  }
  this->Reset();
  for (int i = 0; i < NumberOfBuckets; ++i)
  {
    const double* v = values.data() + SerialSize * static_cast<size_t>(i);
    if (v[0] != 0.0) // an unused bucket allocates no page
    {
      ExactSum sum;
      sum.Low = static_cast<std::uint64_t>(v[1]) | (static_cast<std::uint64_t>(v[2]) << 32);
      sum.High = static_cast<std::uint64_t>(v[3]) |
        (static_cast<std::uint64_t>(static_cast<std::int64_t>(v[4])) << 32);
      this->BucketAt(i) = Bucket{ v[0], sum, v[5], v[6] };
    }
  }
  this->PositiveInfinities = values[values.size() - 2];
  this->NegativeInfinities = values.back();
  return true;
}
