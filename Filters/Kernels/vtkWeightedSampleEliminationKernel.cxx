// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkWeightedSampleEliminationKernel.h"

#include "vtkBlueNoiseRandom.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
// (1 - x)^8 by squaring: alpha is fixed at 8.
inline double Power8(double x)
{
  const double y = 1.0 - x;
  const double y2 = y * y;
  const double y4 = y2 * y2;
  return y4 * y4;
}
static_assert(vtkWeightedSampleEliminationKernel::Alpha == 8.0, "Power8 implements alpha");

// r_max of the paper for density g: the densest sphere packing leaves
// 4 sqrt(2) r^3 of volume per sphere of radius r.
inline double PackingRadius(double g)
{
  return std::cbrt(1.0 / (4.0 * std::sqrt(2.0) * g));
}

// Progress: the shares of a run that end with the candidates drawn and with
// their weights computed (each weight and each elimination visits the
// candidate's neighborhood once); the eliminations take the rest.
const double DrawnShare = 0.1;
const double WeighedShare = 0.55;
}

//------------------------------------------------------------------------------
vtkWeightedSampleEliminationKernel::vtkWeightedSampleEliminationKernel() = default;
vtkWeightedSampleEliminationKernel::~vtkWeightedSampleEliminationKernel() = default;

//------------------------------------------------------------------------------
double vtkWeightedSampleEliminationKernel::GetMarginFactor() const
{
  return 2.0 * PackingRadius(1.0);
}

//------------------------------------------------------------------------------
bool vtkWeightedSampleEliminationKernel::IsSample(vtkIdType v) const
{
  return this->Owner[v] >= 0;
}

//------------------------------------------------------------------------------
bool vtkWeightedSampleEliminationKernel::Run(std::string* error)
{
  const float* density = this->Margin.GetDensity();
  std::vector<double> levelSums(vtkVoxelMargin::NumberOfLevels, 0.0);
  for (vtkIdType v = 0; v < this->Margin.GetNumberOfVoxels(); ++v)
  {
    if (this->Margin.IsReal(v))
    {
      levelSums[vtkVoxelMargin::DensityLevel(density[v])] += density[v];
    }
  }
  double active = 0.0;
  for (const double sum : levelSums)
  {
    active += sum;
  }
  const auto target = static_cast<vtkIdType>(std::llround(active));
  const vtkIdType real = this->DrawCandidates(target);
  if (real < 0)
  {
    if (error)
    {
      *error = "vtkWeightedSampleEliminationKernel: 2^31 candidates or more";
    }
    return false;
  }
  const double ratio = real > 0 ? static_cast<double>(target) / static_cast<double>(real) : 1.0;
  this->LimitFraction = this->WeightLimiting ? Beta * (1.0 - std::pow(ratio, Gamma)) : 0.0;
  this->SetLevelTargets(levelSums);
  return this->ReportProgress(DrawnShare) && this->ComputeWeights() && this->Eliminate();
}

//------------------------------------------------------------------------------
vtkIdType vtkWeightedSampleEliminationKernel::DrawCandidates(vtkIdType target)
{
  const float* density = this->Margin.GetDensity();
  const vtkIdType voxels = this->Margin.GetNumberOfVoxels();
  vtkBlueNoiseRandom random;
  random.Seed(this->Seed, 0xda3e39cb94b95bdbULL);
  const auto k = static_cast<float>(this->CandidateRatio);
  this->Voxel.clear();
  vtkIdType real = 0; // candidates on real voxels
  for (vtkIdType v = 0; v < voxels; ++v)
  {
    const float g = density[v];
    if (g > 0.0f && g < 1.0f && random.Uniform() < std::min(1.0f, k * g))
    {
      this->Voxel.push_back(v);
      real += this->Margin.IsReal(v) ? 1 : 0;
    }
  }
  if (real < target)
  {
    this->Voxel.clear();
    real = 0;
    for (vtkIdType v = 0; v < voxels; ++v)
    {
      if (density[v] > 0.0f && density[v] < 1.0f)
      {
        this->Voxel.push_back(v);
        real += this->Margin.IsReal(v) ? 1 : 0;
      }
    }
  }
  this->Candidates = static_cast<vtkIdType>(this->Voxel.size());
  if (this->Voxel.size() >= static_cast<size_t>(std::numeric_limits<std::int32_t>::max()))
  {
    return -1; // candidate numbers are int32
  }
  const int* extent = this->Margin.GetExtent();
  this->Ball.SetDimensions(extent[0], extent[1], extent[2]);
  this->Owner.assign(static_cast<size_t>(voxels), -1);
  this->RowReach2.assign(static_cast<size_t>(extent[1]) * extent[2], 0.0f);
  const size_t m = this->Voxel.size();
  this->Radius.resize(m);
  this->Priority.resize(m);
  this->LevelOf.resize(m);
  this->Surplus.assign(vtkVoxelMargin::NumberOfLevels, 0);
  for (size_t i = 0; i < m; ++i)
  {
    const vtkIdType v = this->Voxel[i];
    this->Owner[v] = static_cast<std::int32_t>(i);
    // Virtual candidates have no level: they are never kept for one.
    this->LevelOf[i] = -1;
    if (this->Margin.IsReal(v))
    {
      this->LevelOf[i] = static_cast<std::int16_t>(vtkVoxelMargin::DensityLevel(density[v]));
      ++this->Surplus[this->LevelOf[i]];
    }
    this->Radius[i] = static_cast<float>(PackingRadius(density[v]));
    this->Priority[i] = random.Next();
    // Rounded up, so that the skipped rows are out of reach in double precision too.
    const double reach = 2.0 * this->Radius[i];
    float& row = this->RowReach2[v / extent[0]];
    row = std::max(row, std::nextafter(static_cast<float>(reach * reach), HUGE_VALF));
  }
  return real;
}

//------------------------------------------------------------------------------
void vtkWeightedSampleEliminationKernel::SetLevelTargets(const std::vector<double>& sums)
{
  // Surplus holds the candidates of each level; the level keeps
  // round(cumulative sum) - round(previous cumulative sum) of them, so the
  // targets add up to round(S). A level with fewer candidates than its target
  // passes the difference to the next denser level, and what is left at the
  // top back down.
  const int n = vtkVoxelMargin::NumberOfLevels;
  std::vector<vtkIdType> targets(n, 0);
  double cumulative = 0.0;
  vtkIdType rounded = 0;
  for (int l = 0; l < n; ++l)
  {
    cumulative += sums[l];
    const auto next = static_cast<vtkIdType>(std::llround(cumulative));
    targets[l] = next - rounded;
    rounded = next;
  }
  vtkIdType carry = 0;
  for (int l = 0; l < n; ++l)
  {
    targets[l] += carry;
    carry = std::max<vtkIdType>(targets[l] - this->Surplus[l], 0);
    targets[l] -= carry;
  }
  for (int l = n - 1; l >= 0 && carry > 0; --l)
  {
    const vtkIdType room = std::min(carry, this->Surplus[l] - targets[l]);
    targets[l] += room;
    carry -= room;
  }
  this->Remaining = 0;
  for (int l = 0; l < n; ++l)
  {
    this->Surplus[l] -= targets[l];
    this->Remaining += this->Surplus[l];
  }
}

//------------------------------------------------------------------------------
template <typename Visit>
void vtkWeightedSampleEliminationKernel::VisitPartners(int i, Visit&& visit)
{
  const int nx = this->Margin.GetExtent()[0], ny = this->Margin.GetExtent()[1];
  const vtkIdType center = this->Voxel[i];
  const int x = static_cast<int>(center % nx);
  const int y = static_cast<int>((center / nx) % ny);
  const int z = static_cast<int>(center / (static_cast<vtkIdType>(nx) * ny));
  const double own = this->Radius[i];
  const auto& runs = this->Ball.Compute(x, y, z, 4.0 * own * own, this->RowReach2.data());
  for (const auto& run : runs)
  {
    vtkIdType v = run.Start;
    for (int k = 0; k < run.Length; ++k, ++v)
    {
      const std::int32_t j = this->Owner[v];
      const auto dx = static_cast<std::int64_t>(run.DX) + k;
      const std::int64_t d2 = run.DYZ2 + dx * dx;
      if (j < 0 || d2 == 0)
      {
        continue; // no candidate, or i itself
      }
      const double reach = 2.0 * std::min(own, static_cast<double>(this->Radius[j]));
      const auto d = std::sqrt(static_cast<double>(d2));
      if (d < reach)
      {
        visit(j, Power8(std::max(d, this->LimitFraction * reach) / reach));
      }
    }
  }
}

//------------------------------------------------------------------------------
// Heap order: the larger weight, then the larger priority, then the lower number.
inline bool vtkWeightedSampleEliminationKernel::Above(const Node& a, const Node& b)
{
  if (a.Weight != b.Weight)
  {
    return a.Weight > b.Weight;
  }
  if (a.Priority != b.Priority)
  {
    return a.Priority > b.Priority;
  }
  return a.Candidate < b.Candidate;
}

//------------------------------------------------------------------------------
// False when the progress callback stopped the run.
bool vtkWeightedSampleEliminationKernel::ComputeWeights()
{
  const auto m = static_cast<int>(this->Candidates);
  this->Heap.resize(static_cast<size_t>(m));
  this->Position.resize(static_cast<size_t>(m));
  for (int i = 0; i < m; ++i)
  {
    if (i % ProgressInterval == ProgressInterval - 1 &&
      !this->ReportProgress(DrawnShare + (WeighedShare - DrawnShare) * i / m))
    {
      return false;
    }
    double sum = 0.0;
    this->VisitPartners(i, [&sum](int, double w) { sum += w; });
    this->Heap[i] = { sum, this->Priority[i], i };
    this->Position[i] = i;
  }
  for (int p = m > 1 ? (m - 2) / 4 : -1; p >= 0; --p)
  {
    this->SiftDown(p);
  }
  return true;
}

//------------------------------------------------------------------------------
// False when the progress callback stopped the run.
bool vtkWeightedSampleEliminationKernel::Eliminate()
{
  // Virtual candidates go in weight order too; real ones go while their level
  // has more than its target, and are kept (they leave the heap but still
  // weigh on their neighbors) once it has not.
  const double removals = static_cast<double>(std::max<vtkIdType>(this->Remaining, 1));
  vtkIdType steps = 0;
  while (this->Remaining > 0)
  {
    if (++steps % ProgressInterval == 0 &&
      !this->ReportProgress(
        WeighedShare + (1.0 - WeighedShare) * (1.0 - this->Remaining / removals)))
    {
      return false;
    }
    const int e = this->Heap[0].Candidate;
    this->Heap[0] = this->Heap.back();
    this->Position[this->Heap[0].Candidate] = 0;
    this->Position[e] = -1;
    this->Heap.pop_back();
    if (!this->Heap.empty())
    {
      this->SiftDown(0);
    }
    const int level = this->LevelOf[e];
    if (level >= 0)
    {
      if (this->Surplus[level] == 0)
      {
        continue;
      }
      --this->Surplus[level];
      --this->Remaining;
    }
    this->Owner[this->Voxel[e]] = -1;
    // A smaller weight only moves down the heap; a kept candidate has none.
    this->VisitPartners(e, [this](int j, double w) {
      const int position = this->Position[j];
      if (position >= 0)
      {
        this->Heap[position].Weight -= w;
        this->SiftDown(position);
      }
    });
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkWeightedSampleEliminationKernel::SiftDown(int position)
{
  // A 4-ary heap: the children of p are 4 p + 1 .. 4 p + 4, one cache line of
  // nodes, and the heap is half as deep as a binary one (15 % faster on 128^3).
  const int n = static_cast<int>(this->Heap.size());
  const Node item = this->Heap[position];
  while (true)
  {
    const int first = 4 * position + 1;
    if (first >= n)
    {
      break;
    }
    int child = first;
    for (int c = first + 1; c < std::min(first + 4, n); ++c)
    {
      child = Above(this->Heap[c], this->Heap[child]) ? c : child;
    }
    if (!Above(this->Heap[child], item))
    {
      break;
    }
    this->Heap[position] = this->Heap[child];
    this->Position[this->Heap[position].Candidate] = position;
    position = child;
  }
  this->Heap[position] = item;
  this->Position[item.Candidate] = position;
}
