// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkSamplingDensity::Fill against its class comment written the plain way:
// g = clamp(s * (a x + b), 0, 1) with NaN to 0 and ghosts to 0, bit for bit
// (a zero is +0), on float, double and integer arrays of one component (the
// path that maps two values at a time), two components, and with ghosts;
// values at the edges (NaN, infinities, signed zeros, just below and above
// the clamps), any start and length (the tails of the pairs and fours), and
// an infinite scale. The sum Fill returns is the sum of the densities. 8-bit
// values (a table of densities, the sum from counts per value, sixteen equal
// values filled and counted at once, their count held across blocks of
// sixteen) in runs and not, and their statistics against the
// same values in a 16-bit array; float statistics with runs counted four at a
// time against those counted one by one.
#include "BlueNoiseTestUtilities.h"
#include "vtkSamplingDensity.h"

#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkSamplingBudget.h"
#include "vtkShortArray.h"
#include "vtkSignedCharArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

using namespace bluenoise_test;

namespace
{
float Expected(double v, double a, double b, double scale)
{
  if (std::isnan(v))
  {
    return 0.0f;
  }
  const double g = scale * (a * v + b);
  if (std::isnan(g) || g <= 0.0)
  {
    return 0.0f;
  }
  return g >= 1.0 ? 1.0f : static_cast<float>(g);
}

std::vector<double> EdgeValues()
{
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> values = { std::nan(""), -inf, inf, -0.0, 0.0, 1e-300, -1e-300, 0.25,
    0.5, 0.999999999, 1.0, 1.000000001, 2.0, -3.0, 1e30, std::nextafter(1.0, 0.0), 3e-8 };
  for (int k = 0; k < 40; ++k)
  {
    values.push_back(std::sin(0.7 * k) * 1.5); // both signs, inside and beyond [0, 1]
  }
  return values;
}

// Fill over every start and length up to 9 values from there, against
// Expected; the array holds `values` in component `component` of `nc`.
bool CheckFills(vtkDataArray* array, int component, const std::vector<double>& values,
  const unsigned char* ghosts, double scale, const char* what, vtkIdType maxLength = 9,
  vtkIdType minLength = 0)
{
  vtkSamplingDensity density;
  density.SetMapping(vtkSamplingDensity::IDENTITY, component);
  density.Finish(nullptr, vtkSamplingDensity::Budget::Scale(scale));
  const auto map = density.GetLinearMap();
  bool ok = true;
  const vtkIdType n = static_cast<vtkIdType>(values.size());
  vtkSamplingDensity::ValueTable table; // kept from call to call, as the sampler does
  for (vtkIdType begin = 0; begin < n && ok; ++begin)
  {
    for (vtkIdType length = minLength; length <= maxLength && begin + length <= n && ok; ++length)
    {
      std::vector<float> out(static_cast<size_t>(length) + 1, -7.0f);
      const double sum = density.Fill(array, begin, begin + length, ghosts, out.data(), table);
      double expectedSum = 0.0;
      for (vtkIdType i = 0; i < length; ++i)
      {
        const bool ghost = ghosts && (ghosts[begin + i] & vtkDataSetAttributes::HIDDENPOINT);
        const float e = ghost ? 0.0f : Expected(values[begin + i], map.A, map.B, scale);
        ok = ok && std::memcmp(&e, &out[i], sizeof(float)) == 0;
        expectedSum += e;
      }
      ok = ok && out[length] == -7.0f && std::abs(sum - expectedSum) <= 1e-12 * (1.0 + length);
    }
  }
  return Check(ok, what);
}

template <typename ArrayT>
vtkSmartPointer<ArrayT> Array(const std::vector<double>& values, int nc, int component)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetNumberOfComponents(nc);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (size_t t = 0; t < values.size(); ++t)
  {
    for (int c = 0; c < nc; ++c)
    {
      array->SetComponent(static_cast<vtkIdType>(t), c, c == component ? values[t] : 0.9);
    }
  }
  return array;
}

// 8-bit values from `low` in runs of equal ones (sixteen at a time where
// they cover a block, one run over several blocks, equal runs apart) and
// not, `repeats` times.
std::vector<double> ByteRuns(int low, int repeats = 1)
{
  std::vector<double> values;
  const int runs[][2] = { { 9, 5 }, { 3, 200 }, { 40, 0 }, { 1, 7 }, { 8, 7 }, { 35, 7 },
    { 11, 255 }, { 20, 5 } };
  for (int r = 0; r < repeats; ++r)
  {
    for (const auto& run : runs)
    {
      values.insert(values.end(), static_cast<size_t>(run[0]), static_cast<double>(run[1] + low));
    }
    for (int k = 0; k < 20; ++k)
    {
      values.push_back(static_cast<double>((k * 37 + r) % 256 + low));
    }
  }
  return values;
}

// The statistics of 8-bit values (counted sixteen at a time where equal) are
// those of the same values in a 16-bit array (counted one by one).
template <typename ByteArrayT>
bool CheckByteStatistics(const std::vector<double>& values, const char* what)
{
  vtkSamplingDensity density;
  density.SetMapping(vtkSamplingDensity::IDENTITY, 0);
  vtkSamplingBudget bytes, shorts;
  const auto n = static_cast<vtkIdType>(values.size());
  for (vtkIdType begin = 0; begin < n; begin += 5)
  {
    density.CollectStatistics(Array<ByteArrayT>(values, 1, 0), begin, n, nullptr, bytes);
    density.CollectStatistics(Array<vtkShortArray>(values, 1, 0), begin, n, nullptr, shorts);
  }
  return Check(bytes.Serialize() == shorts.Serialize(), what);
}

// The statistics of floats in runs of equal bits (the rest of a run counted
// four at a time) are those counted one by one (with a ghost array that
// flags nothing), from every start.
bool CheckFloatStatistics()
{
  std::vector<double> values;
  const double runs[] = { 0.25, -0.0, 0.0, std::nan(""), 0.7, 0.25, 3.0 };
  for (int k = 0; k < 40; ++k)
  {
    values.insert(values.end(), static_cast<size_t>(1 + (k * 5) % 13), runs[k % 7]);
  }
  const auto array = Array<vtkFloatArray>(values, 1, 0);
  const std::vector<unsigned char> none(values.size(), 0);
  vtkSamplingDensity density;
  density.SetMapping(vtkSamplingDensity::IDENTITY, 0);
  bool same = true;
  const auto n = static_cast<vtkIdType>(values.size());
  for (vtkIdType begin = 0; begin < n && same; ++begin)
  {
    vtkSamplingBudget runs4, ones;
    density.CollectStatistics(array, begin, n, nullptr, runs4);
    density.CollectStatistics(array, begin, n, none.data(), ones);
    same = runs4.Serialize() == ones.Serialize();
  }
  return Check(same, "float statistics, runs counted four at a time");
}

// A budget in points: the scale that makes the densities of the scalar
// range's map add up to it, found in one call; more points than voxels of
// positive density: every one of them, and said so.
bool CheckPointBudget()
{
  std::vector<double> values;
  for (int k = 0; k < 500; ++k)
  {
    values.push_back(static_cast<double>((k * 37) % 101));
  }
  const auto array = Array<vtkFloatArray>(values, 1, 0);
  vtkSamplingDensity density;
  density.SetMapping(vtkSamplingDensity::SCALAR_RANGE, 0);
  vtkSamplingBudget statistics;
  const auto n = static_cast<vtkIdType>(values.size());
  density.CollectStatistics(array, 0, n, nullptr, statistics);
  auto outcome = density.Finish(&statistics, vtkSamplingDensity::Budget::Points(40.0));
  std::vector<float> out(values.size());
  vtkSamplingDensity::ValueTable table;
  const double sum = density.Fill(array, 0, n, nullptr, out.data(), table);
  bool ok = Check(std::abs(sum - 40.0) < 1e-3 && !outcome.OutOfReach && !outcome.Note,
    "a budget of 40 points: densities adding up to " + Str(sum));
  ok = Check(density.GetScale() == statistics.Solve(40.0, density.GetLinearMap()).Scale,
         "the scale is the statistics' solution") &&
    ok;
  outcome = density.Finish(&statistics, vtkSamplingDensity::Budget::Points(1e6));
  const double positive = static_cast<double>(
    std::count_if(values.begin(), values.end(), [](double v) { return v > 0.0; }));
  return Check(outcome.OutOfReach && outcome.Reachable == positive,
           "a budget beyond reach: " + Str(outcome.Reachable) + " voxels of positive density") &&
    ok;
}
}

int main()
{
  const std::vector<double> values = EdgeValues();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> asFloats; // the values as a float array holds them
  for (double v : values)
  {
    asFloats.push_back(static_cast<float>(v));
  }
  CheckFills(Array<vtkFloatArray>(values, 1, 0), 0, asFloats, nullptr, 1.0, "float values");
  CheckFills(Array<vtkFloatArray>(values, 1, 0), 0, asFloats, nullptr, 0.37, "float values, scaled");
  CheckFills(Array<vtkFloatArray>(values, 1, 0), 0, asFloats, nullptr, inf, "an infinite scale");
  CheckFills(Array<vtkDoubleArray>(values, 1, 0), 0, values, nullptr, 3.0, "double values");
  CheckFills(Array<vtkDoubleArray>(values, 2, 1), 1, values, nullptr, 1.0, "two components");

  std::vector<unsigned char> ghosts(values.size(), 0);
  for (size_t i = 0; i < ghosts.size(); i += 3)
  {
    ghosts[i] = vtkDataSetAttributes::HIDDENPOINT;
  }
  CheckFills(Array<vtkFloatArray>(values, 1, 0), 0, asFloats, ghosts.data(), 1.0, "ghosts");

  std::vector<double> ints; // 32-bit values: mapped one by one, as floats are
  for (int k = 0; k < 30; ++k)
  {
    ints.push_back(static_cast<double>((k * 7919) % 601 - 300));
  }
  CheckFills(Array<vtkIntArray>(ints, 1, 0), 0, ints, nullptr, 1.0 / 250.0, "int values");

  // 16-bit values in layers this small are mapped directly (no table).
  CheckFills(Array<vtkShortArray>(ints, 1, 0), 0, ints, nullptr, 1.0 / 250.0, "short values");
  // 8-bit values: mapped through a table of densities from 1024 values on,
  // their sum from the counts per value, sixteen equal values at once.
  const std::vector<double> bytes = ByteRuns(0, 16); // 2352 values
  const vtkIdType longest = static_cast<vtkIdType>(bytes.size());
  CheckFills(Array<vtkUnsignedCharArray>(bytes, 1, 0), 0, bytes, nullptr, 1.0 / 255.0,
    "unsigned char values", longest, longest - 80);
  const std::vector<double> signedBytes = ByteRuns(-128, 16);
  CheckFills(Array<vtkSignedCharArray>(signedBytes, 1, 0), 0, signedBytes, nullptr, 1.0 / 100.0,
    "signed char values", longest, longest - 80);
  std::vector<unsigned char> byteGhosts(bytes.size(), 0);
  for (size_t i = 0; i < byteGhosts.size(); i += 3)
  {
    byteGhosts[i] = vtkDataSetAttributes::HIDDENPOINT;
  }
  CheckFills(Array<vtkUnsignedCharArray>(bytes, 1, 0), 0, bytes, byteGhosts.data(), 1.0 / 255.0,
    "unsigned char values with ghosts", longest, longest - 80);
  CheckByteStatistics<vtkUnsignedCharArray>(ByteRuns(0), "unsigned char statistics");
  CheckByteStatistics<vtkSignedCharArray>(ByteRuns(-128), "signed char statistics");
  CheckFloatStatistics();
  CheckPointBudget();
  return Summary("TestSamplingDensity");
}
