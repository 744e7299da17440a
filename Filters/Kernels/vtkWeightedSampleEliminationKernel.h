// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkWeightedSampleEliminationKernel
 * @brief   Yuksel's weighted sample elimination (2015) on the voxel grid, variable density.
 *
 * A peer of vtkErrorDiffusionKernel on the same interface: a density volume
 * g(x, y, z) in [0, 1] (one float per voxel, x fastest) becomes a 0/1 mask of
 * exactly round(sum of g) sample voxels. C. Yuksel, "Sample Elimination for
 * Generating Poisson Disk Sample Sets", Computer Graphics Forum 34(2), 2015.
 *
 * Voxel classes (as in the error-diffusion kernel): g >= 1 is always a sample
 * and g <= 0 (NaN included) never; neither is a candidate (near the support
 * they stand in as virtual voxels, see Border). The others (0 < g < 1) are the
 * active voxels; S is the sum of their g and T = round(S) of them are kept, so
 * the count is the number of saturated voxels plus T (round(sum of g) up to
 * the rounding of S alone).
 *
 * Definitions:
 * - Border (ExtendSupport, default on): the kernel samples the volume
 *   continued around its support (vtkVoxelMargin): a margin beyond the faces
 *   and the empty and saturated voxels near the support become virtual active
 *   voxels with the density of the nearest active voxel, about one reach 2 r
 *   deep (r below at the smallest density there; see vtkVoxelPointSetKernel
 *   for the limits). Their candidates are drawn, weigh and are eliminated like
 *   the others, but count for no target and are dropped at the end. Without
 *   it candidates near a face have fewer neighbors, keep lower weights and
 *   survive more often (the first layer holds 1.4 times its share at 32/255
 *   on 64^3, the mean anisotropy is 2 to 4.7 dB instead of 0, and the voxels
 *   within 1.5 voxels of a region of g = 0 get 1.33 times their expected
 *   count, 1.00 to 1.03 with it); reflecting the candidates at the faces
 *   instead empties the first layer, each candidate there being 1 voxel from
 *   its own image.
 * - Candidates: active voxel v is a candidate iff u_v < min(1, k g(v)), u_v
 *   uniform from a PCG32 stream seeded with Seed, drawn in index order of the
 *   extended grid, k = CandidateRatio (default 5): white noise proportional to
 *   the density, at most one candidate per voxel, about k T of them in the
 *   volume. Should fewer than T real candidates be drawn (small volumes),
 *   every active voxel is a candidate.
 * - Radius (the paper's r_max for the local density, in voxel units): the
 *   densest packing of spheres of radius r leaves 4 sqrt(2) r^3 of volume per
 *   sphere, so r(v) = (1 / (4 sqrt(2) g(v)))^(1/3).
 * - Weight of a pair of candidates i, j at distance d (centers, voxel units):
 *   with D = 2 min(r_i, r_j) and d^ = max(d, delta D),
 *     w_ij = (1 - d^ / D)^8 if d < D, else 0,
 *   with the paper's weight limiting delta = 0.65 (1 - (T / M)^1.5), M the
 *   number of real candidates (delta = 0 with
 *   SetWeightLimiting(false)). In constant density D = 2 r_max, the paper's
 *   weight. The smaller radius governs a pair so that every partner of i lies
 *   within 2 r_i: neighborhoods are found from each candidate's own radius and
 *   are symmetric without stored adjacency lists, and a sparse candidate does
 *   not weigh on a denser region beyond the denser region's own reach.
 * - Elimination: W_i = sum of w_ij over the other candidates. The candidate
 *   with the largest W (ties: a random priority per candidate, then the lower
 *   number; many weights tie exactly on the lattice) leaves, and its w_ij are
 *   subtracted from the W of its partners (indexed 4-ary max-heap). Every
 *   density level (vtkVoxelMargin::DensityLevel, 8 per octave of g) has its
 *   own target: round(cumulative S) minus round(previous cumulative S) over
 *   the levels in order of g, so the targets add up to T (a level with fewer
 *   candidates passes the difference to the next one). A candidate whose level
 *   has reached its target is kept instead of eliminated (it leaves the heap
 *   and still weighs on its neighbors); virtual candidates have no target.
 *   It ends when every level is at its target, so the count is exact by
 *   construction. The levels make the density follow g: on the grid the
 *   final weights at which a density stops losing candidates depend on g in
 *   steps (which lattice distances fall below D), and a single global
 *   elimination leaves the slabs of a ramp from g = 0.01 to 0.25 up to 27 %
 *   off their share, the levels 2 %. At constant density there is one level:
 *   the paper's algorithm.
 *
 * Output: mask[v] = 1 for the samples, 0 elsewhere. Same seed, same densities
 * => same mask.
 *
 * Cost: one pass over the voxels to draw the candidates, then two scans of the
 * ball of radius 2 r around each candidate (weights, then elimination):
 * (4/3) pi (2 r)^3 k g = 5.9 k voxel visits per voxel for each, plus
 * O(M log M) for the heap, whose updates (random memory accesses) take most of
 * the time. Memory, per voxel of the extended volume: 5 bytes (density copy,
 * virtual flag) and 4 (the candidate of each voxel); about 40 bytes per
 * candidate; 4 bytes per row.
 */
#ifndef vtkWeightedSampleEliminationKernel_h
#define vtkWeightedSampleEliminationKernel_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType
#include "vtkVoxelBall.h"              // for the member
#include "vtkVoxelPointSetKernel.h"

#include <cstdint>
#include <string>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkWeightedSampleEliminationKernel : public vtkVoxelPointSetKernel
{
public:
  static constexpr double Alpha = 8.0;
  static constexpr double Beta = 0.65;
  static constexpr double Gamma = 1.5;

  vtkWeightedSampleEliminationKernel();
  ~vtkWeightedSampleEliminationKernel() override;

  /// k: candidates per expected sample (default 5, at least 1).
  void SetCandidateRatio(double k) { this->CandidateRatio = k < 1.0 ? 1.0 : k; }
  double GetCandidateRatio() const { return this->CandidateRatio; }

  /// The paper's weight limiting (default on).
  void SetWeightLimiting(bool on) { this->WeightLimiting = on; }
  bool GetWeightLimiting() const { return this->WeightLimiting; }

  /// Candidates of the last successful Sample(), virtual ones included.
  vtkIdType GetNumberOfCandidates() const { return this->Candidates; }

protected:
  /// The reach 2 r = 2 (4 sqrt(2))^(-1/3) g^(-1/3).
  double GetMarginFactor() const override;
  /// Fails with 2^31 candidates or more.
  bool Run(std::string* error) override;
  bool IsSample(vtkIdType v) const override;

private:
  // A heap entry: a candidate and its current weight W.
  struct Node
  {
    double Weight;
    std::uint32_t Priority;
    std::int32_t Candidate;
  };
  static bool Above(const Node& a, const Node& b);

  vtkIdType DrawCandidates(vtkIdType target);
  template <typename Visit>
  void VisitPartners(int i, Visit&& visit);
  bool ComputeWeights();
  void SetLevelTargets(const std::vector<double>& sums);
  bool Eliminate();
  void SiftDown(int position);

  double CandidateRatio = 5.0;
  bool WeightLimiting = true;
  vtkIdType Candidates = 0;
  double LimitFraction = 0.0; // delta

  // Everything below is on the extended grid.
  std::vector<std::int32_t> Owner;     // candidate of each voxel, -1 for none (or eliminated)
  std::vector<vtkIdType> Voxel;        // voxel of each candidate
  std::vector<float> Radius;           // r of each candidate
  std::vector<std::uint32_t> Priority; // random tie-break of each candidate
  std::vector<std::int16_t> LevelOf;   // density level of each real candidate, -1 if virtual
  std::vector<Node> Heap;              // max-heap of the candidates that may still go
  std::vector<std::int32_t> Position;  // each candidate's place in Heap, -1 once out
  std::vector<vtkIdType> Surplus;      // candidates each level has beyond its target
  vtkIdType Remaining = 0;             // sum of Surplus
  std::vector<float> RowReach2;        // (2 * largest r of the row's candidates)^2
  vtkVoxelBall Ball;
};

#endif
