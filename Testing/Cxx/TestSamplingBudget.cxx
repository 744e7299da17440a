// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkSamplingBudget, whose buckets live in pages allocated on first use: values
// over many pages (both signs, tiny to huge, infinities, NaN) give the range
// and the expected counts a direct sum gives; a histogram reset and reused,
// a copy, and one serialized and read back are the same histogram bit for
// bit; merged pieces equal the whole; the same values in any order and split
// in any pieces give the same histogram bit for bit (exact sums); values beyond
// the float range (up to the largest double) keep their range and means.
#include "BlueNoiseTestUtilities.h"
#include "vtkSamplingBudget.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace bluenoise_test;

namespace
{
// Values whose buckets lie on many pages, each value a few times (a bucket
// of equal values is exact).
std::vector<double> Values()
{
  std::vector<double> values;
  for (double v : { 1e-30, 3e-7, 0.001, 0.25, 0.5, 1.0, 7.0, 300.0, 65536.0, 1e12, 1e30 })
  {
    for (int k = 0; k < 3; ++k)
    {
      values.push_back(v);
      values.push_back(-v);
    }
  }
  return values;
}

vtkSamplingBudget Histogram(const std::vector<double>& values)
{
  vtkSamplingBudget budget;
  for (double v : values)
  {
    budget.Add(v);
  }
  return budget;
}

bool Same(const vtkSamplingBudget& a, const vtkSamplingBudget& b)
{
  const std::vector<double> x = a.Serialize();
  const std::vector<double> y = b.Serialize();
  return x.size() == y.size() && std::equal(x.begin(), x.end(), y.begin(),
    [](double p, double q) { return p == q || (std::isnan(p) && std::isnan(q)); });
}
}

int main()
{
  const std::vector<double> values = Values();
  vtkSamplingBudget budget = Histogram(values);
  budget.Add(std::numeric_limits<double>::infinity(), 2.0);
  budget.Add(-std::numeric_limits<double>::infinity());
  budget.Add(std::numeric_limits<double>::quiet_NaN());
  double range[2];
  Check(budget.GetRange(range) && range[0] == -1e30 && range[1] == 1e30,
    "the range spans the pages: " + Str(range[0]) + " " + Str(range[1]));

  // Densities x (identity): a small scale keeps every density below 1, so the
  // expected count is the scale times the sum of the positive values, plus the
  // two +inf; an infinite scale draws every positive value.
  double positive = 0.0;
  int count = 0;
  for (double v : values)
  {
    positive += v > 0.0 ? v : 0.0;
    count += v > 0.0 ? 1 : 0;
  }
  const vtkSamplingBudget::Mapping identity;
  const double s = 1e-31;
  const double expected = budget.Expected(s, identity);
  Check(std::abs(expected - (2.0 + s * positive)) < 1e-12,
    "expected count at s = 1e-31: " + Str(expected) + ", direct sum " + Str(2.0 + s * positive));
  const double all = budget.Expected(std::numeric_limits<double>::infinity(), identity);
  Check(all == count + 2.0, "every positive value drawn: " + Str(all));
  const auto solution = budget.Solve(10.0, identity);
  Check(std::abs(solution.Expected - 10.0) < 1e-9 && !solution.OutOfReach,
    "Solve reaches 10 points: " + Str(solution.Expected));

  // A copy (vtkSMPThreadLocal copies), a read-back and a reused histogram.
  const vtkSamplingBudget copy = budget;
  Check(Same(copy, budget), "a copy is the same histogram");
  vtkSamplingBudget back;
  Check(back.Deserialize(budget.Serialize()) && Same(back, budget), "serialized and read back");
  vtkSamplingBudget reused = budget;
  reused.Reset();
  Check(!reused.GetRange(range) && reused.Expected(1.0, identity) == 0.0, "a reset histogram is empty");
  for (double v : { 2.0, 3.0, -5.0 })
  {
    reused.Add(v);
  }
  Check(Same(reused, Histogram({ 2.0, 3.0, -5.0 })), "a reset histogram reused is a fresh one");

  // Pieces on different pages merged: the whole.
  const std::vector<double> first(values.begin(), values.begin() + values.size() / 2);
  const std::vector<double> second(values.begin() + values.size() / 2, values.end());
  vtkSamplingBudget merged = Histogram(first);
  merged.Merge(Histogram(second));
  const vtkSamplingBudget whole = Histogram(values);
  Check(merged.GetRange(range) && range[0] == -1e30 && range[1] == 1e30, "the merged range");
  Check(merged.Expected(s, identity) == whole.Expected(s, identity) &&
      merged.Expected(0.5, identity) == whole.Expected(0.5, identity),
    "merged pieces expect what the whole does");

  // Order: random doubles of many magnitudes, whose plain sums round
  // differently in another order, added forwards and shuffled in three pieces.
  std::mt19937_64 random(7);
  std::vector<double> many;
  for (int i = 0; i < 100000; ++i)
  {
    const double m = std::uniform_real_distribution<double>(-1.0, 1.0)(random);
    many.push_back(std::ldexp(m, std::uniform_int_distribution<int>(-30, 30)(random)));
  }
  const vtkSamplingBudget forwards = Histogram(many);
  std::shuffle(many.begin(), many.end(), random);
  vtkSamplingBudget shuffled = Histogram(std::vector<double>(many.begin(), many.begin() + 777));
  shuffled.Merge(Histogram(std::vector<double>(many.begin() + 777, many.begin() + 50001)));
  shuffled.Merge(Histogram(std::vector<double>(many.begin() + 50001, many.end())));
  Check(Same(forwards, shuffled), "shuffled values in three pieces: the same histogram");
  Check(forwards.Solve(1234.5, identity).Scale == shuffled.Solve(1234.5, identity).Scale,
    "and the same scale for a budget");

  // Floats tallied by their bits: the histogram of Add, bit for bit (both
  // signs, zeros, subnormals, the largest floats, infinities, NaN).
  std::vector<float> floats;
  for (double v : many)
  {
    floats.push_back(static_cast<float>(v));
  }
  for (float v : { 0.0f, -0.0f, 1e-45f, -3e-42f, 1e-38f, 3.4e38f, -3.4e38f, 1.0f, 1.0f })
  {
    floats.push_back(v);
  }
  floats.push_back(std::numeric_limits<float>::infinity());
  floats.push_back(-std::numeric_limits<float>::infinity());
  floats.push_back(std::numeric_limits<float>::quiet_NaN());
  vtkSamplingBudget added;
  vtkSamplingBudget::FloatTally tally;
  for (float v : floats)
  {
    added.Add(v);
    tally.Add(v);
  }
  added.Add(-0.3f, 1000.0); // a run of equal values
  tally.Add(-0.3f, 1000);
  vtkSamplingBudget tallied;
  tallied.Merge(tally);
  Check(Same(added, tallied), "floats tallied by their bits: the histogram of Add");

  // Beyond the float range: the range, and the expected count at a scale that
  // keeps every density below 1 (each value in a bucket of its own).
  const std::vector<double> huge = { 1e39, 5e100, 3e300, std::numeric_limits<double>::max(),
    -1e39, -std::numeric_limits<double>::max() };
  const vtkSamplingBudget far = Histogram(huge);
  Check(far.GetRange(range) && range[0] == -std::numeric_limits<double>::max() &&
      range[1] == std::numeric_limits<double>::max(),
    "the range up to the largest double: " + Str(range[0]) + " " + Str(range[1]));
  const double tiny = 1e-309 / 4.0;
  const double direct = tiny * 1e39 + tiny * 5e100 + tiny * 3e300 + tiny * huge[3];
  const double farExpected = far.Expected(tiny, identity);
  Check(std::abs(farExpected - direct) <= 1e-12 * direct,
    "expected count beyond the float range: " + Str(farExpected) + ", direct sum " + Str(direct));
  return Summary("TestSamplingBudget");
}
