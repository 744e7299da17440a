// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionChargeCurve.h"

#include "vtkErrorDiffusionScan.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <list>
#include <utility>

namespace
{
// The level whose calibration starts from a fixed guess; the others start
// from their neighbor's charge, in a chain from this one.
constexpr double AnchorLevel = 8.0;

// Calibration levels (1/255 units), whatever the table's keys: C varies with
// g even where the parameters do not.
const double FixedLevels[] = { 0.0255, 0.05, 0.1, 0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0,
  48.0, 64.0, 80.0, 96.0, 112.0, 127.5 };

// What a curve is calibrated from: every value of the table's keys, in order,
// then the scale, compared bit for bit (the key once was the table's text with
// the scale to 6 digits, so nearby scales shared one curve).
std::vector<double> CurveKey(const vtkErrorDiffusionParameterTable& table, double scale)
{
  std::vector<double> key;
  for (const auto& k : table.GetKeys())
  {
    key.push_back(k.Level);
    key.insert(key.end(), k.Coefficients.begin(), k.Coefficients.end());
    key.push_back(k.Modulation);
  }
  key.push_back(scale);
  return key;
}

bool SameKey(const std::vector<double>& a, const std::vector<double>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// The charges of the built-in tables at the sampler's default modulation
// scale, one per calibration level, as their calibration gives them: a first
// update with default settings then calibrates nothing (a whole curve costs
// as much as a small sampling run). TestErrorDiffusionChargeCurve calibrates
// them afresh and prints new values when the kernel or the tables changed.
constexpr double KnownScale = 0.5;
struct KnownCurve
{
  vtkErrorDiffusionParameterTable (*Table)();
  std::vector<float> Charges;
};

const std::vector<KnownCurve>& KnownCurves()
{
  static const std::vector<KnownCurve> curves = {
    { &vtkErrorDiffusionParameterTable::Optimized,
      { 0.493763596f, 0.491163105f, 0.487891048f, 0.482026845f, 0.475639492f, 0.467557788f,
        0.457772911f, 0.44648695f, 0.440527409f, 0.416206151f, 0.378671646f, 0.356863618f,
        0.259639084f, 0.215688929f, 0.207357123f, 0.187627792f, 0.123140156f, 0.10137482f,
        0.0706655234f, 0.0590118244f, 0.0373818465f, 0.0231010448f, 0.00244743936f,
        0.261204064f, 0.264808983f } },
    { &vtkErrorDiffusionParameterTable::Paper,
      { 0.492875487f, 0.490819633f, 0.487670958f, 0.481839418f, 0.474581659f, 0.466197103f,
        0.455924392f, 0.443948328f, 0.435185075f, 0.416320056f, 0.405488253f, 0.388781875f,
        0.374894142f, 0.353934407f, 0.354792625f, 0.324842274f, 0.336846858f, 0.330414236f,
        0.312790573f, 0.303028136f, 0.269461751f, 0.292794287f, 0.264378428f, 0.30753085f,
        0.307082117f } },
    { &vtkErrorDiffusionParameterTable::Fixed,
      { 0.493571192f, 0.491241544f, 0.488743842f, 0.483402669f, 0.477722526f, 0.47054106f,
        0.46088174f, 0.448293924f, 0.432585746f, 0.412896156f, 0.390971392f, 0.371094912f,
        0.349428564f, 0.324907362f, 0.299722761f, 0.275221586f, 0.250230908f } },
  };
  return curves;
}

// The curves that kernels hold now. An entry owns no curve: the release of a
// curve's last owner takes its entry out, so the registry is empty once no
// kernel holds a curve.
struct Entry
{
  std::vector<double> Key;
  const vtkErrorDiffusionChargeCurve* Curve;
  std::weak_ptr<vtkErrorDiffusionChargeCurve> Owned;
};
struct Registry
{
  std::mutex Mutex;
  std::list<Entry> Entries;
};

// Never destroyed: a curve may be released by a static object of another
// library after this one's statics are gone.
Registry& Curves()
{
  static Registry* registry = new Registry;
  return *registry;
}

void Release(vtkErrorDiffusionChargeCurve* curve)
{
  {
    std::lock_guard<std::mutex> lock(Curves().Mutex);
    Curves().Entries.remove_if([curve](const Entry& entry) { return entry.Curve == curve; });
  }
  delete curve;
}
}

//------------------------------------------------------------------------------
std::shared_ptr<vtkErrorDiffusionChargeCurve> vtkErrorDiffusionChargeCurve::Get(
  const vtkErrorDiffusionParameterTable& table, double modulationScale)
{
  std::vector<double> key = CurveKey(table, modulationScale);
  Registry& registry = Curves();
  std::lock_guard<std::mutex> lock(registry.Mutex);
  for (const Entry& entry : registry.Entries)
  {
    // An expired entry's release is waiting for the lock: it is passed over.
    std::shared_ptr<vtkErrorDiffusionChargeCurve> curve;
    if (SameKey(entry.Key, key) && (curve = entry.Owned.lock()))
    {
      return curve;
    }
  }
  std::shared_ptr<vtkErrorDiffusionChargeCurve> curve(
    new vtkErrorDiffusionChargeCurve(table, modulationScale), Release);
  registry.Entries.push_front({ std::move(key), curve.get(), curve });
  return curve;
}

//------------------------------------------------------------------------------
vtkErrorDiffusionChargeCurve::vtkErrorDiffusionChargeCurve(
  const vtkErrorDiffusionParameterTable& table, double modulationScale, bool useKnownCharges)
  : Table(table)
  , ModulationScale(modulationScale)
{
  this->Levels.assign(std::begin(FixedLevels), std::end(FixedLevels));
  for (const auto& key : table.GetKeys())
  {
    if (key.Level > FixedLevels[0] && key.Level < 127.5)
    {
      this->Levels.push_back(key.Level);
    }
  }
  std::sort(this->Levels.begin(), this->Levels.end());
  this->Levels.erase(std::unique(this->Levels.begin(), this->Levels.end()), this->Levels.end());
  for (double level : this->Levels)
  {
    this->RootLevels.push_back(std::cbrt(level));
  }
  this->Charges.assign(this->Levels.size(), std::numeric_limits<float>::quiet_NaN());
  if (useKnownCharges && modulationScale == KnownScale)
  {
    const std::vector<double> key = CurveKey(table, modulationScale);
    for (const KnownCurve& known : KnownCurves())
    {
      if (known.Charges.size() == this->Charges.size() &&
        SameKey(CurveKey(known.Table(), KnownScale), key))
      {
        this->Charges = known.Charges;
      }
    }
  }
}

//------------------------------------------------------------------------------
float vtkErrorDiffusionChargeCurve::ChargeOfLevel(size_t i)
{
  if (!std::isnan(this->Charges[i]))
  {
    return this->Charges[i];
  }
  // Start from the neighbor towards the anchor level (calibrated first): the
  // refinement then only has to settle a small difference, and a level's
  // charge does not depend on the levels the process happened to calibrate
  // before it (it did when the guess was the nearest level known).
  const size_t anchor = static_cast<size_t>(
    std::lower_bound(this->Levels.begin(), this->Levels.end(), AnchorLevel) - this->Levels.begin());
  float guess = i == anchor ? 0.45f : this->ChargeOfLevel(i > anchor ? i - 1 : i + 1);
  const double g = this->Levels[i] / 255.0;
  for (int seed : { 12345, 12346 })
  {
    guess += static_cast<float>(vtkErrorDiffusionScan::MeasureReceivedError(
      this->Table, this->ModulationScale, g, guess, seed));
  }
  this->Charges[i] = guess;
  return guess;
}

//------------------------------------------------------------------------------
float vtkErrorDiffusionChargeCurve::At(double g)
{
  if (!(g > 0.0) || g >= 1.0)
  {
    g = 0.0; // the charge of saturated voxels is never used; keep it finite
  }
  const double level = 255.0 * (g > 0.5 ? 1.0 - g : g);
  std::lock_guard<std::mutex> lock(this->Mutex);
  if (level <= this->Levels.front())
  {
    return this->ChargeOfLevel(0);
  }
  if (level >= this->Levels.back())
  {
    return this->ChargeOfLevel(this->Levels.size() - 1);
  }
  const size_t i =
    std::upper_bound(this->Levels.begin(), this->Levels.end(), level) - this->Levels.begin();
  const double r = std::cbrt(level);
  const double t = (r - this->RootLevels[i - 1]) / (this->RootLevels[i] - this->RootLevels[i - 1]);
  const float c0 = this->ChargeOfLevel(i - 1);
  const float c1 = this->ChargeOfLevel(i);
  return static_cast<float>(c0 + t * (c1 - c0));
}

//------------------------------------------------------------------------------
std::vector<float> vtkErrorDiffusionChargeCurve::GetCharges()
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  for (size_t i = 0; i < this->Levels.size(); ++i)
  {
    this->ChargeOfLevel(i);
  }
  return this->Charges;
}
