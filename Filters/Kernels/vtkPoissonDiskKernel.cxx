// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPoissonDiskKernel.h"

#include "vtkBlueNoiseRandom.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace
{
// State bits of a voxel while a run goes: a sample / in conflict with one.
const unsigned char SampleBit = 1;
const unsigned char CoveredBit = 2;
// Progress: the share of a run before the first pass (the radii and levels,
// then the shuffle, half each); the passes share the rest, MaximumPasses of them and the re-run
// of the best one, each by the voxels it has visited.
const double PrepareShare = 0.05;
}

//------------------------------------------------------------------------------
// One density level and the search for its radius scale c, in x = log(c)
// against f = log(count / target): the bracket found so far (Low: too many
// samples, High: too few) and the last step before there is one.
struct vtkPoissonDiskKernel::Level
{
  struct Probe
  {
    double X = 0.0;
    double F = 0.0;
    bool Valid = false;
  };
  double Target = 0.0; // sum of g of the level's real voxels
  double Scale = InitialRadiusScale;
  vtkIdType Count = 0; // the level's real samples in the last run
  Probe Low;
  Probe High;
  int LastSide = 0;
  double LastStep = 0.0;
  double LastCount = 0.0;

  // Close enough: within the relative tolerance, or within half the standard
  // deviation of a maximal set's count (about 0.3 to 0.5 sqrt(count) on the
  // voxel grid), which no c can beat.
  bool Within(double tolerance) const
  {
    const double miss = std::abs(static_cast<double>(this->Count) - this->Target);
    return miss <= std::max(tolerance * this->Target, 0.5 * std::sqrt(this->Target));
  }

  double NextScale();
};

//------------------------------------------------------------------------------
double vtkPoissonDiskKernel::Level::NextScale()
{
  const double count = std::max(static_cast<double>(this->Count), 0.5);
  const double x = std::log(this->Scale);
  const double f = std::log(count) - std::log(this->Target);
  const int side = f > 0.0 ? 1 : -1; // 1: too many samples, c must grow
  Probe& replaced = side > 0 ? this->Low : this->High;
  const bool flat = replaced.Valid && replaced.F == f;
  replaced = { x, f, true };
  if (this->Low.Valid && this->High.Valid)
  {
    // Regula falsi; bisection when the count did not change (a plateau of the
    // lattice) or the same end moved twice in a row (a knee of the count),
    // where the interpolation would creep along one end of the bracket.
    const bool bisect = flat || side == this->LastSide;
    this->LastSide = side;
    return std::exp(bisect ? 0.5 * (this->Low.X + this->High.X)
                           : (this->Low.X * this->High.F - this->High.X * this->Low.F) /
                               (this->High.F - this->Low.F));
  }
  // Not bracketed yet. A maximal set in 3D has count ~ c^-3, so the step is
  // f / 3, but at least 1 %; an unchanged count means a plateau of the lattice
  // (no squared distance between 7 and 8, say, where the dither has nothing to
  // work on), and the step grows fourfold to leave it.
  double step = f / 3.0;
  if (std::abs(step) < 0.01)
  {
    step = 0.01 * side;
  }
  if (this->LastSide == side && count == this->LastCount)
  {
    step = 4.0 * this->LastStep;
  }
  this->LastSide = side;
  this->LastStep = step;
  this->LastCount = count;
  return std::exp(x + step);
}

//------------------------------------------------------------------------------
vtkPoissonDiskKernel::vtkPoissonDiskKernel() = default;
vtkPoissonDiskKernel::~vtkPoissonDiskKernel() = default;

//------------------------------------------------------------------------------
int vtkPoissonDiskKernel::GetNumberOfLevels() const
{
  return static_cast<int>(this->Levels.size());
}

//------------------------------------------------------------------------------
double vtkPoissonDiskKernel::GetPairDither(vtkIdType a, vtkIdType b) const
{
  return vtkBlueNoiseRandom::PairUniform(this->DitherKey,
    static_cast<std::uint64_t>(this->Margin.ToExtended(a)),
    static_cast<std::uint64_t>(this->Margin.ToExtended(b)));
}

//------------------------------------------------------------------------------
double vtkPoissonDiskKernel::GetRadius(vtkIdType voxel) const
{
  const vtkIdType v = this->Margin.ToExtended(voxel);
  return this->Margin.IsReal(v) ? this->RadiusOf(v) : 0.0;
}

//------------------------------------------------------------------------------
inline double vtkPoissonDiskKernel::RadiusOf(vtkIdType v) const
{
  return this->Factor[v] > 0.0f ? this->Levels[this->LevelOf[v]].Scale * this->Factor[v] : 0.0;
}

//------------------------------------------------------------------------------
bool vtkPoissonDiskKernel::IsSample(vtkIdType v) const
{
  return (this->State[v] & SampleBit) != 0;
}

//------------------------------------------------------------------------------
bool vtkPoissonDiskKernel::Run(std::string*)
{
  this->Passes = 0;
  if (!this->Prepare() || !this->ReportProgress(0.5 * PrepareShare))
  {
    return false;
  }
  vtkBlueNoiseRandom random;
  random.Seed(this->Seed, 0x5851f42d4c957f2dULL);
  this->DitherKey = (static_cast<std::uint64_t>(random.Next()) << 32u) | random.Next();
  const double active = static_cast<double>(this->Order.size());
  for (size_t i = this->Order.size(); i > 1; --i)
  {
    if (i % (4 * ProgressInterval) == 0 &&
      !this->ReportProgress(PrepareShare * (1.0 - 0.5 * i / active)))
    {
      return false;
    }
    std::swap(this->Order[i - 1], this->Order[random.Below(i)]);
  }
  return this->ReportProgress(PrepareShare) && (this->Order.empty() || this->Search());
}

//------------------------------------------------------------------------------
// False when the progress callback stopped the run.
bool vtkPoissonDiskKernel::Prepare()
{
  const int* extent = this->Margin.GetExtent();
  this->Ball.SetDimensions(extent[0], extent[1], extent[2]);
  const vtkIdType voxels = this->Margin.GetNumberOfVoxels();
  this->Factor.assign(static_cast<size_t>(voxels), 0.0f);
  this->LevelOf.assign(static_cast<size_t>(voxels), 0);
  this->State.assign(static_cast<size_t>(voxels), 0);
  this->RowReach2.assign(static_cast<size_t>(extent[1]) * extent[2], 0.0f);
  const float* density = this->Margin.GetDensity();
  this->Order.clear();
  this->Order.reserve(static_cast<size_t>(std::count_if(
    density, density + voxels, [](float g) { return g > 0.0f && g < 1.0f; })));
  std::vector<double> subTargets(vtkVoxelMargin::NumberOfLevels, 0.0);
  for (vtkIdType v = 0; v < voxels; ++v)
  {
    if (v % (4 * ProgressInterval) == 4 * ProgressInterval - 1 &&
      !this->ReportProgress(0.5 * PrepareShare * v / voxels))
    {
      return false;
    }
    const float g = density[v];
    if (g > 0.0f && g < 1.0f)
    {
      this->Factor[v] = 1.0f / std::cbrt(g);
      this->LevelOf[v] = static_cast<std::uint16_t>(vtkVoxelMargin::DensityLevel(g));
      this->Order.push_back(v);
      subTargets[this->LevelOf[v]] += this->Margin.IsReal(v) ? g : 0.0;
    }
  }

  // Consecutive sub-levels merge until a level expects MinimumLevelCount
  // samples (its count must stand out of the noise); a short last one joins
  // the one before.
  std::vector<std::uint16_t> levelOfSub(vtkVoxelMargin::NumberOfLevels, 0);
  this->Levels.clear();
  for (int s = 0; s < vtkVoxelMargin::NumberOfLevels; ++s)
  {
    if (subTargets[s] <= 0.0)
    {
      continue;
    }
    if (this->Levels.empty() || this->Levels.back().Target >= MinimumLevelCount)
    {
      this->Levels.emplace_back();
    }
    this->Levels.back().Target += subTargets[s];
    levelOfSub[s] = static_cast<std::uint16_t>(this->Levels.size() - 1);
  }
  if (this->Levels.size() > 1 && this->Levels.back().Target < MinimumLevelCount)
  {
    const auto last = static_cast<std::uint16_t>(this->Levels.size() - 1);
    this->Levels[last - 1].Target += this->Levels.back().Target;
    this->Levels.pop_back();
    std::replace(levelOfSub.begin(), levelOfSub.end(), last, static_cast<std::uint16_t>(last - 1));
  }
  for (const vtkIdType v : this->Order)
  {
    this->LevelOf[v] = levelOfSub[this->LevelOf[v]];
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkPoissonDiskKernel::Search()
{
  const size_t n = this->Levels.size();
  std::vector<double> scales(n), best(n);
  double bestError = std::numeric_limits<double>::infinity();
  double target = 0.0;
  for (const auto& level : this->Levels)
  {
    target += level.Target;
  }
  vtkIdType count = 0;
  const double passShare = (1.0 - PrepareShare) / (this->MaximumPasses + 1);
  for (int pass = 0; pass < this->MaximumPasses; ++pass)
  {
    count = this->RunPass(PrepareShare + pass * passShare, passShare);
    if (count < 0)
    {
      return false;
    }
    // Done when the count is within CountTolerance of sum g (saturated voxels
    // included) and every level is close to its own target.
    double error = 0.0;
    bool levelsDone = true;
    for (size_t i = 0; i < n; ++i)
    {
      error += std::abs(static_cast<double>(this->Levels[i].Count) - this->Levels[i].Target);
      levelsDone = levelsDone && this->Levels[i].Within(this->CountTolerance);
      scales[i] = this->Levels[i].Scale;
    }
    if (error < bestError)
    {
      bestError = error;
      best = scales;
    }
    const double miss = std::abs(static_cast<double>(count) - target);
    if (levelsDone && miss <= this->CountTolerance * this->ExpectedCount)
    {
      break;
    }
    // The levels off their targets move; when all are close but the total is
    // not, all move.
    for (auto& level : this->Levels)
    {
      if (levelsDone || !level.Within(this->CountTolerance))
      {
        level.Scale = level.NextScale();
      }
    }
  }
  if (scales != best)
  {
    for (size_t i = 0; i < n; ++i)
    {
      this->Levels[i].Scale = best[i];
    }
    return this->RunPass(1.0 - passShare, passShare) >= 0;
  }
  return true;
}

//------------------------------------------------------------------------------
// The samples' count, or -1 when the progress callback stopped the run.
vtkIdType vtkPoissonDiskKernel::RunPass(double progressBegin, double progressWidth)
{
  ++this->Passes;
  const vtkIdType nx = this->Margin.GetExtent()[0];
  vtkIdType v = 0;
  for (float& reach2 : this->RowReach2)
  {
    reach2 = 0.0f;
    for (const vtkIdType end = v + nx; v < end; ++v)
    {
      // Rounded up, so that the skipped rows are out of reach in double precision too.
      const double r = this->RadiusOf(v);
      reach2 = std::max(reach2, std::nextafter(static_cast<float>(r * r), HUGE_VALF));
    }
  }
  std::fill(this->State.begin(), this->State.end(), 0);
  for (auto& level : this->Levels)
  {
    level.Count = 0;
  }
  vtkIdType count = 0;
  const double visits = static_cast<double>(this->Order.size());
  vtkIdType visited = 0;
  for (const vtkIdType sample : this->Order)
  {
    if (++visited % ProgressInterval == 0 &&
      !this->ReportProgress(progressBegin + progressWidth * (visited / visits)))
    {
      return -1;
    }
    if (this->State[sample] & CoveredBit)
    {
      continue;
    }
    this->State[sample] = SampleBit;
    this->MarkConflicts(sample);
    if (this->Margin.IsReal(sample))
    {
      ++this->Levels[this->LevelOf[sample]].Count;
      ++count;
    }
  }
  return count;
}

//------------------------------------------------------------------------------
void vtkPoissonDiskKernel::MarkConflicts(vtkIdType sample)
{
  const int nx = this->Margin.GetExtent()[0], ny = this->Margin.GetExtent()[1];
  const int x = static_cast<int>(sample % nx);
  const int y = static_cast<int>((sample / nx) % ny);
  const int z = static_cast<int>(sample / (static_cast<vtkIdType>(nx) * ny));
  const double own = this->RadiusOf(sample);
  const auto& runs = this->Ball.Compute(x, y, z, own * own, this->RowReach2.data());
  for (const auto& run : runs)
  {
    vtkIdType v = run.Start;
    for (int k = 0; k < run.Length; ++k, ++v)
    {
      if (this->Factor[v] == 0.0f || (this->State[v] & CoveredBit) || v == sample)
      {
        continue;
      }
      const double smaller = std::min(own, this->RadiusOf(v));
      const double r2 = smaller * smaller;
      const auto dx = static_cast<std::int64_t>(run.DX) + k;
      const auto d2 = static_cast<double>(run.DYZ2 + dx * dx);
      // h < 1: a pair closer than r2 - 1 always conflicts, one at r2 or beyond never.
      if (d2 + 1.0 <= r2 ||
        (d2 < r2 &&
          d2 + vtkBlueNoiseRandom::PairUniform(this->DitherKey, static_cast<std::uint64_t>(v),
                 static_cast<std::uint64_t>(sample)) <
            r2))
      {
        this->State[v] |= CoveredBit;
      }
    }
  }
}
