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
  // Pages stay allocated for the next pass over a volume.
  for (auto& page : this->Pages)
  {
    std::fill(page.begin(), page.end(), Bucket());
  }
  this->PositiveInfinities = 0.0;
  this->NegativeInfinities = 0.0;
}

//------------------------------------------------------------------------------
vtkSamplingBudget::Bucket& vtkSamplingBudget::BucketAt(int i)
{
  if (this->Pages.empty())
  {
    this->Pages.resize(NumberOfPages);
  }
  std::vector<Bucket>& page = this->Pages[i / PageSize];
  if (page.empty())
  {
    page.resize(PageSize);
  }
  return page[i % PageSize];
}

//------------------------------------------------------------------------------
std::vector<vtkSamplingBudget::Bucket> vtkSamplingBudget::UsedBuckets() const
{
  std::vector<Bucket> used;
  for (const auto& page : this->Pages)
  {
    std::copy_if(page.begin(), page.end(), std::back_inserter(used),
      [](const Bucket& b) { return b.Count > 0.0; });
  }
  return used;
}

//------------------------------------------------------------------------------
int vtkSamplingBudget::BucketOf(double x)
{
  const float f = static_cast<float>(x);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof(bits));
  // Order-preserving: negative values have their bits flipped, positive ones
  // their sign set, so unsigned order is value order.
  bits = (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
  return static_cast<int>(bits >> 16);
}

//------------------------------------------------------------------------------
void vtkSamplingBudget::Add(double x, double n)
{
  if (std::isnan(x))
  {
    return;
  }
  if (std::isinf(x))
  {
    (x > 0.0 ? this->PositiveInfinities : this->NegativeInfinities) += n;
    return;
  }
  Bucket& b = this->BucketAt(BucketOf(x));
  if (b.Count == 0.0)
  {
    b.Min = x;
    b.Max = x;
  }
  else
  {
    b.Min = std::min(b.Min, x);
    b.Max = std::max(b.Max, x);
  }
  b.Count += n;
  b.Mean += (x - b.Mean) * (n / b.Count);
}

//------------------------------------------------------------------------------
void vtkSamplingBudget::Merge(const vtkSamplingBudget& other)
{
  for (size_t p = 0; p < other.Pages.size(); ++p)
  {
    for (size_t k = 0; k < other.Pages[p].size(); ++k)
    {
      this->MergeBucket(static_cast<int>(p * PageSize + k), other.Pages[p][k]);
    }
  }
  this->PositiveInfinities += other.PositiveInfinities;
  this->NegativeInfinities += other.NegativeInfinities;
}

//------------------------------------------------------------------------------
void vtkSamplingBudget::MergeBucket(int i, const Bucket& o)
{
  if (o.Count == 0.0)
  {
    return;
  }
  Bucket& b = this->BucketAt(i);
  b.Min = b.Count == 0.0 ? o.Min : std::min(b.Min, o.Min);
  b.Max = b.Count == 0.0 ? o.Max : std::max(b.Max, o.Max);
  b.Count += o.Count;
  b.Mean += (o.Mean - b.Mean) * (o.Count / b.Count);
}

//------------------------------------------------------------------------------
bool vtkSamplingBudget::GetRange(double range[2]) const
{
  const std::vector<Bucket> used = this->UsedBuckets();
  if (used.empty())
  {
    return false;
  }
  range[0] = used.front().Min;
  range[1] = used.back().Max;
  return true;
}

//------------------------------------------------------------------------------
double vtkSamplingBudget::BucketExpected(const Bucket& b, double scale, const Mapping& map) const
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
  return this->ExpectedOver(this->UsedBuckets(), scale, map);
}

//------------------------------------------------------------------------------
double vtkSamplingBudget::ExpectedOver(
  const std::vector<Bucket>& buckets, double scale, const Mapping& map) const
{
  if (!(scale > 0.0))
  {
    return 0.0;
  }
  double sum = this->PositiveInfinities;
  for (const Bucket& b : buckets)
  {
    if (b.Count > 0.0)
    {
      sum += this->BucketExpected(b, scale, map);
    }
  }
  return sum;
}

//------------------------------------------------------------------------------
vtkSamplingBudget::Solution vtkSamplingBudget::Solve(double target, const Mapping& map) const
{
  Solution solution;
  const std::vector<Bucket> used = this->UsedBuckets(); // the bisection sums many times
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
  for (int p = 0; p < NumberOfPages; ++p)
  {
    if (this->Pages.empty() || this->Pages[p].empty())
    {
      values.insert(values.end(), 4 * static_cast<size_t>(PageSize), 0.0);
      continue;
    }
    for (const Bucket& b : this->Pages[p])
    {
      values.insert(values.end(), { b.Count, b.Mean, b.Min, b.Max });
    }
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
  this->Reset();
  for (int i = 0; i < NumberOfBuckets; ++i)
  {
    const double* v = values.data() + 4 * static_cast<size_t>(i);
    if (v[0] != 0.0) // an empty bucket's other fields are never read
    {
      this->BucketAt(i) = Bucket{ v[0], v[1], v[2], v[3] };
    }
  }
  this->PositiveInfinities = values[values.size() - 2];
  this->NegativeInfinities = values.back();
  return true;
}
