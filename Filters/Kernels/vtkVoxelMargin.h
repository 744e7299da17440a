// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkVoxelMargin
 * @brief   A density volume continued beyond its faces, for point-set kernels.
 *
 * A point process run on a box is denser along the faces than inside: a
 * sample there has no neighbours beyond the face to keep others away (a
 * maximal Poisson-disk set on a 64^3 cube at g = 16/255 puts 1.5 times the
 * mean count into its first layer), which shows in the spectrum as power along
 * the axes (mean anisotropy about 3 dB instead of 0). The point-set kernels
 * therefore sample the volume extended by a margin of m voxels on every side,
 * each outside voxel taking the density of the nearest face voxel (clamped
 * coordinates), and keep only the samples inside ("minus sampling"): the inside
 * then looks like part of a larger volume. Reflecting the points at the faces
 * instead pairs every sample near a face with its own image and empties the
 * first layer; a periodic continuation couples unrelated faces.
 *
 * Extend() builds the extended copy (Extent = Dims + 2 m per axis, x fastest),
 * ToExtended() and IsInside() convert between the two grids. Memory: 4 bytes
 * per extended voxel.
 *
 * DensityLevel() sorts densities into levels of LevelsPerOctave per halving
 * of g, the grain at which the kernels keep the count of each density (on
 * the voxel grid, how densely a point process packs depends on g in steps
 * that the continuous formulas do not have).
 */
#ifndef vtkVoxelMargin_h
#define vtkVoxelMargin_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkVoxelMargin
{
public:
  static constexpr int LevelsPerOctave = 8;
  static constexpr int NumberOfLevels = 40 * LevelsPerOctave;

  /// floor(LevelsPerOctave log2 g) shifted to 0 .. NumberOfLevels - 1 (clamped) for g in (0, 1).
  static int DensityLevel(float g);

  /**
   * The smallest density in (0, 1) on the faces of an nx x ny x nz volume, 1
   * if there is none (the faces are empty or saturated: no margin is needed).
   */
  static float SmallestFaceDensity(int nx, int ny, int nz, const float* density);

  /// Copy the volume into the grid extended by `margin` >= 0 voxels per side.
  void Extend(int nx, int ny, int nz, const float* density, int margin);

  const float* GetDensity() const { return this->Density.data(); }
  const int* GetExtent() const { return this->Extent; }
  int GetMargin() const { return this->Margin; }
  vtkIdType GetNumberOfVoxels() const { return static_cast<vtkIdType>(this->Density.size()); }

  /// The extended index of the voxel `inner` of the original volume.
  vtkIdType ToExtended(vtkIdType inner) const;

  /// Whether extended voxel v lies in the original volume.
  bool IsInside(vtkIdType v) const;

private:
  int Dims[3] = { 0, 0, 0 };
  int Extent[3] = { 0, 0, 0 };
  int Margin = 0;
  std::vector<float> Density;
};

#endif
