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
 * copies the volume continued around its support (vtkVoxelMargin), lets the
 * peer run on that copy, and writes the mask: g >= 1 always a sample, g <= 0
 * (or NaN) never, the others as the peer decided. It returns the number of
 * samples.
 *
 * The continuation (ExtendSupport, default on) reaches the peer's interaction
 * reach at the smallest density where it is needed, GetMarginFactor() *
 * g^(-1/3) rounded up: the margin beyond the faces takes g from the smallest
 * active density on the faces, reduced until the extended volume holds at
 * most MaximumGrowth times the voxels (so a thin slab or a very sparse face
 * gets less than one reach, or none); the depth of the continuation into empty
 * and saturated voxels takes g from the smallest density on the border of the
 * support, at most MaximumDepth voxels, and at least the margin.
 *
 * Progress and abort: a callback set with SetProgressCallback() is called
 * with the fraction of the run done, in [0, 1), at least every
 * ProgressInterval voxels or candidates the peer visits (a few hundred times
 * per run at most); when it returns false the peer stops, and Sample()
 * returns -1 with GetAborted() true ("aborted" in `error`) and the mask
 * untouched. The kernel stays free of VTK's pipeline: the filter forwards its
 * own progress and abort flag.
 */
#ifndef vtkVoxelPointSetKernel_h
#define vtkVoxelPointSetKernel_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType
#include "vtkVoxelMargin.h"            // for the member

#include <cstdint>
#include <functional> // for std::function
#include <string>
#include <utility> // for std::move

class VTKFILTERSBLUENOISE_EXPORT vtkVoxelPointSetKernel
{
public:
  /// The extended volume holds at most this many times the voxels of the volume.
  static constexpr double MaximumGrowth = 2.0;
  /// The continuation into empty and saturated voxels reaches at most this far.
  static constexpr int MaximumDepth = 32;

  virtual ~vtkVoxelPointSetKernel();

  void SetSeed(std::uint64_t seed) { this->Seed = seed; }
  std::uint64_t GetSeed() const { return this->Seed; }

  /**
   * Called with the fraction done (in [0, 1)) while Sample() runs; return
   * false to stop it (see the class comment). Default none.
   */
  using ProgressCallback = std::function<bool(double)>;
  void SetProgressCallback(ProgressCallback callback) { this->Progress = std::move(callback); }

  /// Whether the last Sample() was stopped by the progress callback.
  bool GetAborted() const { return this->Aborted; }

  /// Sample the volume continued around its support and drop the continuation (default on).
  void SetExtendSupport(bool on) { this->ExtendSupport = on; }
  bool GetExtendSupport() const { return this->ExtendSupport; }

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

  /// The peer's interaction reach at density 1: its reach at g is this * g^(-1/3).
  virtual double GetMarginFactor() const = 0;

  /// Sample this->Margin's volume; false with the reason in `error` on failure.
  virtual bool Run(std::string* error) = 0;

  /// Whether active voxel v of the extended grid is a sample after Run().
  virtual bool IsSample(vtkIdType v) const = 0;

  /// The share of the progress of the volume's continuation, before Run().
  static constexpr double ExtendedShare = 0.1;

  /// Voxels or candidates a peer visits between two calls of ReportProgress().
  static constexpr vtkIdType ProgressInterval = vtkIdType(1) << 14;

  /**
   * For the peers, from Run(): report `fraction` of the run (after the
   * continuation's share; below 1 in all; only a fraction above the last one
   * reported goes to the callback). False when the callback
   * asks to stop: the peer then returns false from Run() at once (Aborted is
   * set, Sample() reports it).
   */
  bool ReportProgress(double fraction);

  std::uint64_t Seed = 0;
  bool ExtendSupport = true;
  double ExpectedCount = 0.0;
  vtkVoxelMargin Margin;
  bool Aborted = false;

private:
  bool Report(double fraction); // of the whole Sample()
  ProgressCallback Progress;
  double LastProgress = 0.0;

  vtkVoxelPointSetKernel(const vtkVoxelPointSetKernel&) = delete;
  vtkVoxelPointSetKernel& operator=(const vtkVoxelPointSetKernel&) = delete;
};

#endif
