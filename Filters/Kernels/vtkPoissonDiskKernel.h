// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPoissonDiskKernel
 * @brief   Variable-radius maximal Poisson-disk sampling on the voxel grid.
 *
 * A peer of vtkErrorDiffusionKernel on the same interface: a density volume
 * g(x, y, z) in [0, 1] (one float per voxel, x fastest) becomes a 0/1 mask of
 * sample voxels whose count is close to the sum of g. Candidates are the voxel
 * centers, so the points lie on the grid the blue-noise spectrum bins them on.
 *
 * Voxel classes (as in the error-diffusion kernel): g >= 1 is always a sample
 * and g <= 0 (NaN included) never; their own density takes no part in the
 * conflicts below (near the support they stand in as virtual voxels, see
 * Border). The others (0 < g < 1) are the active voxels.
 *
 * Definitions:
 * - Radius: r(v) = c(g(v)) * g(v)^(-1/3) in voxel units. The radius scale c
 *   is calibrated per density level (see Count), about 0.82 to 0.99.
 * - Conflict: two active voxels a != b conflict iff
 *     |a - b|^2 + h(a, b) < min(r(a), r(b))^2,
 *   |a - b| the distance of their centers and h(a, b) in [0, 1) a hash of the
 *   seed and the unordered pair (vtkBlueNoiseRandom::PairUniform; GetRadius
 *   and GetPairDither give both terms). So no two samples are closer than
 *   sqrt(min(r_a, r_b)^2 - 1), no pair at distance >= min(r_a, r_b)
 *   conflicts, and of the pairs in between the fraction r^2 - |a - b|^2 does.
 *   Squared distances of voxel centers are integers: without the dither the
 *   count would jump between plateaus as c varies (by 30 % at g = 8/255, by a
 *   factor 2.5 at 32/255) and no c would give the expected count; a wider
 *   dither packs worse (on 64^3 at 32/255, L = 0.308 with width 1, 0.352 with
 *   width 2). The smaller radius governs a pair so that a sparse sample never
 *   clears the voxels of a denser region: each side of a density step is
 *   packed at its own radius, and an isolated low-density voxel cannot punch
 *   a hole.
 * - Algorithm: random sequential addition. The active voxels are visited once
 *   each in a random order (Fisher-Yates shuffle driven by a PCG32 stream
 *   seeded with Seed); a voxel becomes a sample unless it conflicts with an
 *   earlier sample. The result is a maximal Poisson-disk set of the voxel
 *   grid: every active voxel that is not a sample conflicts with a sample.
 *   Each new sample marks the active voxels it conflicts with (those within
 *   its radius), so a visit costs O(1) and a sample O(r^3); rows whose largest
 *   radius cannot reach the sample are skipped (vtkVoxelBall). This order
 *   gives a lower L(g) than an active-list (Bridson) growth over the same
 *   voxels, or than candidates jittered inside their voxels for the conflict
 *   test (the figures are in the commit that chose it).
 * - Border (ExtendSupport, default on): the kernel samples the volume
 *   continued around its support (vtkVoxelMargin): a margin beyond the faces
 *   and the empty and saturated voxels near the support become virtual active
 *   voxels with the density of the nearest active voxel, at most about one
 *   radius deep (g_f^(-1/3) voxels, g_f the smallest density there, c being
 *   below 1; see vtkVoxelPointSetKernel for the limits). They take part in the
 *   conflicts; their samples are dropped. Without it the first layer holds
 *   1.5 times its share at 16/255, the mean anisotropy is 1.5 to 4.1 dB
 *   instead of 0, and the voxels within 1.5 voxels of a region of g = 0 get
 *   1.35 times their expected count (0.99 to 1.05 with it, the error-diffusion
 *   kernel 1.02 to 1.05); a margin two or three times as wide changes L by
 *   less than 1 %.
 * - Count: the active voxels are grouped into density levels
 *   (vtkVoxelMargin::DensityLevel, 8 per octave of g, merged upwards until a
 *   level expects MinimumLevelCount samples), each with its own c. On the grid
 *   the packing of a maximal set depends on g in steps that c g^(-1/3) does
 *   not follow: with one c for all, the slabs of a ramp from g = 0.01 to 0.25
 *   miss their share by up to 15 %, with a c per level by 1 %. Each Sample()
 *   searches the c of every level at once by whole re-runs with the same order
 *   and dither, counting the real samples: c = 0.87 first, then per level
 *   steps of log(count / target) / 3 in log c (a maximal set in 3D has count
 *   ~ c^-3; at least 1 %, four times the last step while the count does not
 *   change: a plateau of the lattice) until its target is bracketed, then
 *   regula falsi in (log c, log count), bisecting where the count is flat.
 *   Only the levels off their target move (all of them when every level is on
 *   target but the total is not). A level is on target within
 *   max(CountTolerance, 0.5 / sqrt(target)) relative (between seeds the count
 *   of a maximal set has a standard deviation of 0.3 to 0.5 sqrt(count)). The
 *   search stops when every level is on target and the total is within
 *   CountTolerance of sum g, or after MaximumPasses runs; the run with the
 *   smallest sum of level misses is the result (re-run if it was not the
 *   last). A maximal set has at least one sample per group of mutually
 *   reachable active voxels, so a far smaller sum g is not reached.
 *
 * Output: mask[v] = 1 for the samples (active or saturated), 0 elsewhere.
 * Same seed, same densities => same mask.
 *
 * Cost: per run, one visit per active voxel plus about (4/3) pi r^3 voxels per
 * sample, i.e. O(voxels); 2 to 9 runs (6 on a constant 8/255, where the first
 * c lies on a plateau). Memory, per voxel of the extended volume: 5 bytes
 * (density copy, virtual flag), 4 (g^-1/3), 2 (level), 1 (state), and 8 per
 * active voxel (the order); 4 bytes per row.
 */
#ifndef vtkPoissonDiskKernel_h
#define vtkPoissonDiskKernel_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType
#include "vtkVoxelBall.h"              // for the member
#include "vtkVoxelPointSetKernel.h"

#include <cstdint>
#include <string>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkPoissonDiskKernel : public vtkVoxelPointSetKernel
{
public:
  static constexpr double InitialRadiusScale = 0.87;
  static constexpr double MinimumLevelCount = 500.0; ///< samples expected per density level

  vtkPoissonDiskKernel();
  ~vtkPoissonDiskKernel() override;

  /// Relative count tolerance that ends the search for c (default 0.005).
  void SetCountTolerance(double tolerance) { this->CountTolerance = tolerance; }
  double GetCountTolerance() const { return this->CountTolerance; }

  /// Largest number of runs in the search for c (default 10, at least 1).
  void SetMaximumPasses(int passes) { this->MaximumPasses = passes < 1 ? 1 : passes; }
  int GetMaximumPasses() const { return this->MaximumPasses; }

  ///@{
  /// Figures of the last successful Sample().
  int GetNumberOfPasses() const { return this->Passes; } ///< runs made
  int GetNumberOfLevels() const; ///< density levels with a radius scale of their own
  ///@}

  ///@{
  /// The conflict rule of the last Sample(), for voxel indices of the volume:
  /// r(v) (0 for a voxel that is not active) and h(a, b).
  double GetRadius(vtkIdType voxel) const;
  double GetPairDither(vtkIdType a, vtkIdType b) const;
  ///@}

protected:
  /// The reach g^(-1/3): at least one radius, c being below 1.
  double GetMarginFactor() const override { return 1.0; }
  bool Run(std::string* error) override;
  bool IsSample(vtkIdType v) const override;

private:
  struct Level;
  bool Prepare();
  bool Search();
  vtkIdType RunPass(double progressBegin, double progressWidth);
  void MarkConflicts(vtkIdType sample);
  double RadiusOf(vtkIdType v) const;

  double CountTolerance = 0.005;
  int MaximumPasses = 10;
  int Passes = 0;
  std::uint64_t DitherKey = 0;

  // Everything below is on the extended grid.
  std::vector<unsigned char> State;   // sample and covered bits per voxel
  std::vector<float> Factor;          // g^(-1/3) of active voxels, 0 elsewhere
  std::vector<std::uint16_t> LevelOf; // density level of active voxels
  std::vector<Level> Levels;
  std::vector<float> RowReach2; // largest r^2 of each row (y + ny * z) in the current run
  std::vector<vtkIdType> Order; // the active voxels in visiting order
  vtkVoxelBall Ball;
};

#endif
