// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkVoxelPointSetKernel
 * @brief   Base of the point-set peers of error diffusion: a whole density volume in, a mask out.
 *
 * The peers (vtkPoissonDiskKernel, vtkWeightedSampleEliminationKernel) take
 * the volume at once, where vtkErrorDiffusionKernel takes it layer by layer:
 * Sample() receives nx * ny * nz densities g in [0, 1] (x fastest, index
 * x + nx * (y + ny * z)) and fills a mask of as many bytes with 1 for the
 * sample voxels and 0 elsewhere. A sampler can hold either peer through this
 * class.
 *
 * What Sample() does for every peer: it checks the input (each dimension at
 * least 1, no null pointer; else -1, the reason in `error`, the mask
 * untouched), sums the expected count (sum of g clamped to [0, 1], NaN as 0),
 * copies the volume with a margin beyond its faces (vtkVoxelMargin; the
 * margin is ceil(GetMarginFactor() * g_f^(-1/3)) voxels per side, g_f the
 * smallest active density on the faces, and 0 with SetExtendFaces(false)),
 * lets the peer run on that copy, and writes the mask: g >= 1 always a sample,
 * g <= 0 (or NaN) never, the others as the peer decided. It returns the
 * number of samples.
 */
#ifndef vtkVoxelPointSetKernel_h
#define vtkVoxelPointSetKernel_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType
#include "vtkVoxelMargin.h"            // for the member

#include <cstdint>
#include <string>

class VTKFILTERSBLUENOISE_EXPORT vtkVoxelPointSetKernel
{
public:
  virtual ~vtkVoxelPointSetKernel();

  void SetSeed(std::uint64_t seed) { this->Seed = seed; }
  std::uint64_t GetSeed() const { return this->Seed; }

  /// Sample a margin beyond the faces and drop it (default on).
  void SetExtendFaces(bool on) { this->ExtendFaces = on; }
  bool GetExtendFaces() const { return this->ExtendFaces; }

  /**
   * Sample nx * ny * nz densities (x fastest) into mask (as many bytes).
   * Returns the number of samples, or -1 with the reason in `error`.
   */
  vtkIdType Sample(int nx, int ny, int nz, const float* density, unsigned char* mask,
    std::string* error = nullptr);

  ///@{
  /// Figures of the last Sample() that got past the input check.
  double GetExpectedCount() const { return this->ExpectedCount; } ///< sum of g
  int GetMargin() const { return this->Margin.GetMargin(); }      ///< voxels per side
  ///@}

protected:
  vtkVoxelPointSetKernel() = default;

  /// The margin in units of g_f^(-1/3): the peer's interaction reach at density 1.
  virtual double GetMarginFactor() const = 0;

  /// Sample this->Margin's volume; false with the reason in `error` on failure.
  virtual bool Run(std::string* error) = 0;

  /// Whether active voxel v of the extended grid is a sample after Run().
  virtual bool IsSample(vtkIdType v) const = 0;

  std::uint64_t Seed = 0;
  bool ExtendFaces = true;
  double ExpectedCount = 0.0;
  vtkVoxelMargin Margin;

private:
  vtkVoxelPointSetKernel(const vtkVoxelPointSetKernel&) = delete;
  vtkVoxelPointSetKernel& operator=(const vtkVoxelPointSetKernel&) = delete;
};

#endif
