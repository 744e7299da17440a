// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The sharing of charge curves (vtkErrorDiffusionChargeCurve::Get): one curve
// per table and scale, bit for bit (scales equal to 6 digits once shared a
// curve), while somebody holds it and no longer; a kernel keeps the curves it
// used last, and none after it is gone; one curve for threads asking at once;
// a level's charge does not depend on the levels calibrated before it; the
// known charges of the built-in tables are those a calibration gives.
#include "BlueNoiseTestUtilities.h"
#include "vtkErrorDiffusionChargeCurve.h"
#include "vtkErrorDiffusionKernel.h"
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

// A curve nobody holds is gone (the process keeps no calibration).
void GoneWhenReleased()
{
  const auto table = vtkErrorDiffusionParameterTable::Paper();
  std::weak_ptr<vtkErrorDiffusionChargeCurve> seen = vtkErrorDiffusionChargeCurve::Get(table, 0.9);
  Check(seen.expired(), "a curve released by its only holder is gone");
}

// A kernel keeps the curves of its last RecentCurves tables and scales, the
// least recently used out first, and none once it is gone.
void KernelKeepsRecentCurves()
{
  const auto table = vtkErrorDiffusionParameterTable::Paper();
  const std::size_t keep = vtkErrorDiffusionKernel::RecentCurves;
  std::vector<std::weak_ptr<vtkErrorDiffusionChargeCurve>> seen;
  {
    vtkErrorDiffusionKernel kernel;
    kernel.SetParameters(table);
    const auto use = [&](std::size_t i) {
      kernel.SetModulationScale(1.0 + 0.001 * static_cast<double>(i));
      kernel.Begin(4, 4); // takes the curve of its table and scale
      return std::weak_ptr<vtkErrorDiffusionChargeCurve>(
        vtkErrorDiffusionChargeCurve::Get(table, 1.0 + 0.001 * static_cast<double>(i)));
    };
    for (std::size_t i = 0; i < keep; ++i)
    {
      seen.push_back(use(i));
      // The first scale, used again after each other one, stays.
      Check(use(0).lock() == seen[0].lock() && !seen[0].expired(),
        "the curve used all along stays (after " + Str(i) + " others)");
    }
    Check(!seen[keep - 1].expired(), "the curve used last but one stays");
    seen.push_back(use(keep));
    Check(seen[1].expired(), "the least recently used curve went after " + Str(keep) + " others");
    Check(!seen[0].expired() && !seen[2].expired(), "the recent curves stay");
  }
  bool any = false;
  for (const auto& curve : seen)
  {
    any = any || !curve.expired();
  }
  Check(!any, "no curve outlives the kernel that held it");
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
  GoneWhenReleased();
  KernelKeepsRecentCurves();
  ThreadsShareCurves();
  return Summary("TestErrorDiffusionChargeCurve");
}
