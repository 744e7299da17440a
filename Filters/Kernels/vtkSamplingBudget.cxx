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
vtkSamplingBudget::vtkSamplingBudget()
{
  this->Reset();
}

//------------------------------------------------------------------------------
void vtkSamplingBudget::Reset()
{
  this->Buckets.assign(NumberOfBuckets, Bucket());
  this->PositiveInfinities = 0.0;
  this->NegativeInfinities = 0.0;
}

//------------------------------------------------------------------------------
void vtkSamplingBudget::Merge(const vtkSamplingBudget& other)
{
  for (int i = 0; i < NumberOfBuckets; ++i)
  {
    const Bucket& o = other.Buckets[i];
    if (o.Count == 0.0)
    {
      continue;
    }
    Bucket& b = this->Buckets[i];
    b.Min = b.Count == 0.0 ? o.Min : std::min(b.Min, o.Min);
    b.Max = b.Count == 0.0 ? o.Max : std::max(b.Max, o.Max);
    b.Count += o.Count;
    b.Sum += o.Sum;
  }
  this->PositiveInfinities += other.PositiveInfinities;
  this->NegativeInfinities += other.NegativeInfinities;
}

//------------------------------------------------------------------------------
bool vtkSamplingBudget::GetRange(double range[2]) const
{
  int first = 0;
  while (first < NumberOfBuckets && this->Buckets[first].Count == 0.0)
  {
    ++first;
  }
  if (first == NumberOfBuckets)
  {
    return false;
  }
  int last = NumberOfBuckets - 1;
  while (this->Buckets[last].Count == 0.0)
  {
    --last;
  }
  range[0] = this->Buckets[first].Min;
  range[1] = this->Buckets[last].Max;
  return true;
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
// values' units: no overflow).
std::vector<vtkSamplingBudget::Summary> vtkSamplingBudget::Summarize() const
{
  std::vector<Summary> used;
  for (int i = 0; i < NumberOfBuckets; ++i)
  {
    const Bucket& b = this->Buckets[i];
    if (b.Count > 0.0)
    {
      used.push_back({ b.Count, b.Sum / b.Count * UnitOf(i), b.Min, b.Max });
    }
  }
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
  std::vector<double> values;
  values.reserve(4 * static_cast<size_t>(NumberOfBuckets) + 2);
  for (const Bucket& b : this->Buckets)
  {
    values.insert(values.end(), { b.Count, b.Sum, b.Min, b.Max });
  }
  values.push_back(this->PositiveInfinities);
  values.push_back(this->NegativeInfinities);
  return values;
}

//------------------------------------------------------------------------------
bool vtkSamplingBudget::Deserialize(const std::vector<double>& values)
{
  if (values.size() != 4 * static_cast<size_t>(NumberOfBuckets) + 2)
  {
    return false;
  }
  for (int i = 0; i < NumberOfBuckets; ++i)
  {
    const double* v = values.data() + 4 * static_cast<size_t>(i);
    this->Buckets[i] = Bucket{ v[0], v[1], v[2], v[3] };
  }
  this->PositiveInfinities = values[values.size() - 2];
  this->NegativeInfinities = values.back();
  return true;
}
