// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The process-wide cache of charge curves (vtkErrorDiffusionChargeCurve::Get):
// one curve per table and scale, bit for bit (scales equal to 6 digits once
// shared a curve), the least recently used curve out first when the cache is
// full while a curve in use stays, and one curve for threads asking at once;
// a level's charge does not depend on the levels calibrated before it; the
// known charges of the built-in tables are those a calibration gives.
#include "BlueNoiseTestUtilities.h"
#include "vtkErrorDiffusionChargeCurve.h"
#include "vtkErrorDiffusionParameterTable.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <utility>
#include <thread>
#include <vector>

using namespace bluenoise_test;

namespace
{
using Curve = std::shared_ptr<vtkErrorDiffusionChargeCurve>;

void OneCurvePerKey()
{
  const auto paper = vtkErrorDiffusionParameterTable::Paper();
  const auto fixed = vtkErrorDiffusionParameterTable::Fixed();
  const Curve a = vtkErrorDiffusionChargeCurve::Get(paper, 0.3);
  Check(vtkErrorDiffusionChargeCurve::Get(paper, 0.3) == a, "the same table and scale: one curve");
  Check(vtkErrorDiffusionChargeCurve::Get(fixed, 0.3) != a, "another table: another curve");
  // 0.30000049 prints as 0.3 to 6 digits, and is another float.
  const Curve b = vtkErrorDiffusionChargeCurve::Get(paper, 0.30000049);
  Check(b != a, "a scale that differs in the 7th digit: another curve");
  // The curve calibrates for its own scale: as a curve made apart does.
  vtkErrorDiffusionChargeCurve apart(paper, 0.30000049);
  for (double g : { 0.01, 0.2 })
  {
    Check(b->At(g) == apart.At(g), "the cached curve's charge at g = " + Str(g));
  }
}

// Two curves of one table and scale asked for levels in different orders: the
// same charges bit for bit (the starting guess was once the nearest level
// known, so a process that had sampled at 8/255 sampled 32/255 differently).
void OrderFree()
{
  const auto table = vtkErrorDiffusionParameterTable::Optimized();
  vtkErrorDiffusionChargeCurve upward(table, 0.75); // a scale without known charges
  vtkErrorDiffusionChargeCurve direct(table, 0.75);
  const double gs[] = { 2.0 / 255.0, 8.0 / 255.0, 32.0 / 255.0, 100.0 / 255.0 };
  for (double g : gs)
  {
    upward.At(g);
  }
  for (int k = 3; k >= 0; --k)
  {
    Check(direct.At(gs[k]) == upward.At(gs[k]),
      "C(" + Str(255.0 * gs[k]) + "/255) alike whatever was calibrated before");
  }
}

// The built-in tables' charges at the default scale, which curves start
// with, are those a calibration gives (printed for the source when not).
void KnownCharges()
{
  const std::pair<const char*, vtkErrorDiffusionParameterTable> tables[] = {
    { "Optimized", vtkErrorDiffusionParameterTable::Optimized() },
    { "Paper", vtkErrorDiffusionParameterTable::Paper() },
    { "Fixed", vtkErrorDiffusionParameterTable::Fixed() } };
  for (const auto& named : tables)
  {
    const auto known = vtkErrorDiffusionChargeCurve(named.second, 0.5).GetCharges();
    const auto fresh = vtkErrorDiffusionChargeCurve(named.second, 0.5, false).GetCharges();
    float worst = known.size() == fresh.size() ? 0.0f : 1.0f;
    std::ostringstream values;
    values.precision(9);
    for (size_t i = 0; i < fresh.size(); ++i)
    {
      worst = std::max(worst, i < known.size() ? std::abs(known[i] - fresh[i]) : 1.0f);
      values << fresh[i] << "f, ";
    }
    Check(worst <= 1e-5f,
      std::string(named.first) + ": known charges within 1e-5 of a calibration (worst " +
        Str(worst) + "); calibrated: " + values.str());
  }
}

void LeastRecentlyUsedOut()
{
  const auto table = vtkErrorDiffusionParameterTable::Paper();
  const std::size_t capacity = vtkErrorDiffusionChargeCurve::CacheCapacity;
  // `kept` is asked for again and again, `old` once; both stay alive here, so
  // that a new curve cannot take an evicted one's address.
  const Curve kept = vtkErrorDiffusionChargeCurve::Get(table, 1.0 / 3.0);
  const Curve old = vtkErrorDiffusionChargeCurve::Get(table, 2.0 / 3.0);
  std::vector<Curve> others;
  for (std::size_t i = 0; i < capacity; ++i)
  {
    others.push_back(vtkErrorDiffusionChargeCurve::Get(table, 1.0 + 0.001 * static_cast<double>(i)));
    Check(vtkErrorDiffusionChargeCurve::Get(table, 1.0 / 3.0) == kept,
      "a curve asked for all along stays (after " + Str(i + 1) + " others)");
  }
  Check(vtkErrorDiffusionChargeCurve::Get(table, 2.0 / 3.0) != old,
    "the least recently used curve went after " + Str(capacity) + " others");
  Check(vtkErrorDiffusionChargeCurve::Get(table, 1.0 + 0.001 * static_cast<double>(capacity - 1)) ==
      others.back(),
    "a recent curve stays");
}

void ThreadsShareCurves()
{
  const auto table = vtkErrorDiffusionParameterTable::Optimized();
  const int threads = 4;
  const int keys = 24;
  std::vector<std::vector<Curve>> got(threads, std::vector<Curve>(keys));
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t)
  {
    workers.emplace_back(
      [&got, &table, t]
      {
        for (int k = 0; k < keys; ++k)
        {
          got[t][k] = vtkErrorDiffusionChargeCurve::Get(table, 0.05 * k);
        }
      });
  }
  for (auto& worker : workers)
  {
    worker.join();
  }
  for (int t = 1; t < threads; ++t)
  {
    Check(got[t] == got[0], "thread " + Str(t) + " got the curves thread 0 got");
  }
}
}

int main()
{
  OneCurvePerKey();
  OrderFree();
  KnownCharges();
  LeastRecentlyUsedOut();
  ThreadsShareCurves();
  return Summary("TestErrorDiffusionChargeCurve");
}
