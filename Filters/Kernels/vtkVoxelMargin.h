// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkVoxelMargin
 * @brief   A density volume continued around its support, for point-set kernels.
 *
 * A point process is denser along the border of the region it samples than
 * inside: a sample there has no neighbors beyond the border to keep others
 * away. At the faces of a box (a maximal Poisson-disk set on a 64^3 cube at
 * g = 16/255 puts 1.5 times the mean count into its first layer) this shows
 * in the spectrum as power along the axes (mean anisotropy 1.5 to 4.7 dB
 * instead of 0); at the rim of a region of g = 0 inside the volume the voxels
 * within 1.5 voxels of it get 1.35 times their expected count. The point-set
 * kernels therefore sample a continued volume and keep only the samples of the
 * real voxels ("minus sampling"), so that the border looks like the inside:
 *
 * - the grid is extended by a margin of m voxels on every side (Extent =
 *   Dims + 2 m per axis, x fastest; outside voxels start empty);
 * - every voxel that is not active (outside, g <= 0 or NaN, g >= 1) within
 *   `depth` steps (26-neighborhood, so Chebyshev distance) of an active voxel
 *   (0 < g < 1) becomes a virtual voxel. At step k it takes the density of its
 *   nearest neighbor (faces before edges before corners, then index order)
 *   that is active or became virtual before step k: the density of the
 *   support's border continues outwards, into the margin (at a flat face as
 *   the face's own column), the empty regions and the saturated ones.
 *
 * The kernels sample virtual voxels like real ones but neither count nor
 * output them. Reflecting the points at the faces instead pairs every sample
 * near a face with its own image and empties the first layer; a periodic
 * continuation couples unrelated faces.
 *
 * DensityLevel() sorts densities into levels of LevelsPerOctave per halving
 * of g, the grain at which the kernels keep the count of each density (on
 * the voxel grid, how densely a point process packs depends on g in steps
 * that the continuous formulas do not have).
 *
 * Cost: one pass over the extended grid that checks the 26 neighbors of each
 * voxel that is not active, then the breadth-first growth over the virtual
 * voxels. Memory: 5 bytes per extended voxel, 8 per voxel of a growth front.
 */
#ifndef vtkVoxelMargin_h
#define vtkVoxelMargin_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <functional> // for the progress callback
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkVoxelMargin
{
public:
  static constexpr int LevelsPerOctave = 8;
  static constexpr int NumberOfLevels = 40 * LevelsPerOctave;

  /// floor(LevelsPerOctave log2 g) shifted to 0 .. NumberOfLevels - 1 (clamped) for g in (0, 1).
  static int DensityLevel(float g);

  /// Whether a voxel of density g is active: 0 < g < 1.
  static bool IsActive(float g) { return g > 0.0f && g < 1.0f; }

  ///@{
  /**
   * The smallest active density of an nx x ny x nz volume on its faces, or on
   * the border of its support (active voxels on a face or next to a voxel that
   * is not active, 6-neighborhood); 1 if there is none.
   */
  static float SmallestFaceDensity(int nx, int ny, int nz, const float* density);
  static float SmallestBorderDensity(int nx, int ny, int nz, const float* density);
  ///@}

  /// Copy the volume into the grid extended by `margin` voxels per side and
  /// continue it `depth` steps around its support (both at least 0).
  /// `progress`, when set, is called with the fraction done every so many
  /// voxels; false from it stops the extension, and Extend returns false.
  bool Extend(int nx, int ny, int nz, const float* density, int margin, int depth,
    const std::function<bool(double)>& progress = nullptr);

  const float* GetDensity() const { return this->Density.data(); }
  const int* GetExtent() const { return this->Extent; }
  int GetMargin() const { return this->Margin; }
  vtkIdType GetNumberOfVoxels() const { return static_cast<vtkIdType>(this->Density.size()); }

  /// The extended index of the voxel `inner` of the original volume.
  vtkIdType ToExtended(vtkIdType inner) const;

  /// Whether extended voxel v lies in the original volume.
  bool IsInside(vtkIdType v) const;

  /// Whether extended voxel v is an active voxel of the original volume (not virtual).
  bool IsReal(vtkIdType v) const
  {
    return !this->Virtual[v] && IsActive(this->Density[v]) && this->IsInside(v);
  }

private:
  bool Grow(int depth, const std::function<bool(double)>& progress);
  bool Pull(vtkIdType v, int step);

  int Dims[3] = { 0, 0, 0 };
  int Extent[3] = { 0, 0, 0 };
  int Margin = 0;
  std::vector<float> Density;
  std::vector<unsigned char> Virtual; // the step that made a voxel virtual, 0 if real
};

#endif
