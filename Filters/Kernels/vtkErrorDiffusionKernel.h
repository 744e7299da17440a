// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionKernel
 * @brief   The 3D error-diffusion algorithm, layer by layer, without the VTK pipeline.
 *
 * Turns a density volume g(x, y, z) in [0, 1] into a binary volume b whose
 * ones are the samples (paper section 3). The caller feeds the layers in z
 * order, one ProcessLayer() call each, and gets each layer's binary mask back:
 * the kernel itself only keeps two layers of accumulated error, so memory is
 * O(nx * ny) whatever nz is, and time is O(voxels).
 *
 * Scan order (rotated serpentine): layers are processed along +z; every four
 * layers form a scanning cycle in which the in-layer serpentine is rotated by
 * 90 degrees per layer. With u the direction of the first row and v the
 * direction in which rows advance, the four phases of a cycle are
 * (u, v) = (+x, +y), (+y, -x), (-x, -y), (-y, +x). Odd rows run against u.
 * The phase of a layer is its global z index modulo 4, so pieces of one volume
 * sampled separately share the phase of the whole volume.
 *
 * Error filter: A100, A-110, A010, A0-11, A-101, A001 with offsets written for
 * the first phase ((1,0,0) is the next voxel of the row, (0,1,0) the same
 * voxel of the next row, (0,0,1) the voxel below in the next layer); in other
 * phases and on odd rows the offsets turn and mirror with the scan. Weights and
 * m(g) come from a vtkErrorDiffusionParameterTable.
 *
 * Threshold: t = 0.5 + s * r * m(g) (shifted in the steady-state mode, see
 * below) with r uniform in [0, 1) from a seeded PCG32 generator and s the
 * ModulationScale (s = 1 is the paper's Eq. 1; s = 0.5, the default, is Zhou
 * and Fang's 0..255 code). For g > 0.5 the whole process is
 * mirrored: t = 0.5 - s * r * m(1 - g), so the pattern at density g is the
 * complement of the pattern at 1 - g given the same random numbers (the
 * paper's "the minority voxels of g and 1 - g are alike").
 *
 * Voxels with g <= 0 (NaN included) are never sampled and g >= 1 always
 * sampled. Neither takes part in the diffusion: they are treated like the
 * missing neighbours at a face of the volume, so the error of a voxel next to
 * them goes, renormalised, to its active targets (0 < g < 1) only. An empty
 * region stays empty, no error leaks across it, and the rim of the support
 * keeps the error of its neighbours, so it is sampled like the inside: on
 * the MRI brain ch2bet at 3e4 points the voxels within 1.5 voxels of empty
 * space get 1.01 of their expected samples (0.76 when empty voxels absorbed
 * the error). Deciding this for the targets in the next layer is why
 * ProcessLayer needs that layer's densities.
 *
 * Boundaries and start-up (the count N = sum of g is kept in expectation):
 * - BOUNDARY_RENORMALIZE, the paper-faithful behaviour: the threshold is the
 *   paper's, the scan starts with no accumulated error, and at every face the
 *   weights of the targets that exist are renormalised to sum 1. The count
 *   is exact, but the error must first charge up to its steady-state level C
 *   (the first layers come out empty) and the last layer receives all the
 *   charge the volume still carries (several times its density). On a 64^3
 *   cube the whole-volume mean anisotropy is 7 to 9 dB against about 0 dB for
 *   the interior.
 * - BOUNDARY_STEADY_STATE (default): the threshold is lowered by the
 *   steady-state charge, t = 0.5 - C(g) + s * r * m(g) (mirrored above 0.5),
 *   where C(g) is the mean error a voxel receives once the paper's process
 *   has settled at density g (calibrated per key level, see
 *   GetSteadyStateCharges, and interpolated like the other parameters). This
 *   only translates the error by C: the settled process makes the same
 *   decisions, but an empty buffer is now its mean state, so no charging is
 *   needed, a rise of density along the scan is followed at once, and error
 *   leaving the volume has zero mean. WarmUpLayers virtual layers with the
 *   first layer's density then settle the buffers' fluctuations, and the
 *   error the last layer passes on leaves the volume. Lateral faces and the
 *   faces of the support renormalise as above. Whole-volume and interior
 *   mean anisotropy agree within 0.15 dB at every key level from 8/255
 *   (128^3).
 *   Caveat: a region that starts after empty voxels (importance sampling)
 *   has no warm-up; at g = 0.01 its first 8 layers hold 2.6% too few
 *   samples (64^2 layers, 4 seeds; within 0.7% from g = 8/255 up).
 */
#ifndef vtkErrorDiffusionKernel_h
#define vtkErrorDiffusionKernel_h

#include "vtkErrorDiffusionParameterTable.h"
#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <array>
#include <cstdint>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionKernel
{
public:
  enum BoundaryModes
  {
    BOUNDARY_RENORMALIZE = 0,
    BOUNDARY_STEADY_STATE = 1
  };

  /**
   * METHOD_ERROR_DIFFUSION is the paper's algorithm. METHOD_WHITE_NOISE is the
   * hit-and-miss baseline (Sakamoto's PBVR): every voxel is drawn on its own
   * with probability g from the same generator, so both methods have the same
   * expected count for the same densities.
   */
  enum Methods
  {
    METHOD_ERROR_DIFFUSION = 0,
    METHOD_WHITE_NOISE = 1
  };

  /// The six filter targets, in the order of the table's coefficients.
  enum Target
  {
    TARGET_U = 0,       ///< A100: next voxel of the row
    TARGET_BACK_V = 1,  ///< A-110: previous voxel, next row
    TARGET_V = 2,       ///< A010: same voxel, next row
    TARGET_Z_BACKV = 3, ///< A0-11: same voxel of the previous row, next layer
    TARGET_Z_BACKU = 4, ///< A-101: previous voxel of the row, next layer
    TARGET_Z = 5        ///< A001: same voxel, next layer
  };

  /**
   * Where the scan of one layer goes, in memory indices of a layer stored x
   * fastest: voxel p of row q is at Start + q * VStride + p * UStride on even
   * rows and Start + q * VStride + (NU - 1 - p) * UStride on odd rows.
   */
  struct LayerScan
  {
    int Phase = 0;         ///< 0..3 within the scanning cycle
    int NU = 0;            ///< voxels per row
    int NV = 0;            ///< rows per layer
    vtkIdType UStride = 0; ///< memory step of +u (the first row's direction)
    vtkIdType VStride = 0; ///< memory step from one row to the next
    vtkIdType Start = 0;   ///< memory index of the first voxel scanned
  };

  static LayerScan GetLayerScan(int nx, int ny, int phase);

  /**
   * Offsets (dx, dy, dz) of the six targets for row q of a layer with the
   * given scan; used by tests to check the geometry the kernel runs.
   */
  static void GetTargetOffsets(const LayerScan& scan, int row, int offsets[6][3]);

  vtkErrorDiffusionKernel();

  void SetParameters(const vtkErrorDiffusionParameterTable& table) { this->Table = table; }
  const vtkErrorDiffusionParameterTable& GetParameters() const { return this->Table; }
  void SetModulationScale(double s) { this->ModulationScale = s; }
  void SetSeed(std::uint64_t seed) { this->Seed = seed; }
  void SetBoundaryMode(int mode) { this->BoundaryMode = mode; }
  void SetMethod(int method) { this->Method = method; }
  void SetWarmUpLayers(int n) { this->WarmUpLayers = n < 0 ? 0 : n; }

  /**
   * Start a run over nx * ny * nz voxels whose first layer has global z index
   * firstLayer (it sets the scan phase). Resets the error and the generator.
   */
  void Begin(int nx, int ny, int nz, int firstLayer = 0);

  /**
   * Sample the next layer. density: nx * ny values, x fastest; nextDensity:
   * the densities of the layer after it, in the same layout (ignored for the
   * last layer; nullptr before it means that no voxel of the next layer takes
   * error). mask receives 0 or 1 per voxel. Returns the number of samples.
   * The next call's density must hold what nextDensity held (it may be the
   * same buffer, unchanged).
   */
  vtkIdType ProcessLayer(const float* density, const float* nextDensity, unsigned char* mask);

  /// Layers processed since Begin().
  int GetLayersDone() const { return this->LayersDone; }

  /**
   * The steady-state charge C at each key level of the table: the mean error
   * a voxel receives once the paper's process has settled at that constant
   * density (measured on a 24 x 24 box, 64 layers after 64 settling layers,
   * away from the faces; cached per table and scale).
   */
  static std::vector<float> GetSteadyStateCharges(
    const vtkErrorDiffusionParameterTable& table, double modulationScale);

private:
  struct Generator
  {
    std::uint64_t State = 0;
    std::uint64_t Increment = 1;
    void Seed(std::uint64_t seed, std::uint64_t stream);
    inline float Uniform();
  };

  // The parameters of one density: weights, threshold base and signed
  // modulation (negative above g = 0.5).
  struct LevelParameters
  {
    float G = -1.0f; // the density they are for; -1: an empty cache entry
    float Weights[6] = { 0, 0, 0, 0, 0, 0 };
    float Base = 0.5f;
    float Modulation = 0.0f;
  };
  const LevelParameters& ParametersOf(float g);

  // next: the densities of the following layer, nullptr if it takes no error.
  // Record keeps in Current what each voxel received (GetSteadyStateCharges).
  template <bool Record = false>
  vtkIdType ScanLayer(const float* density, const float* next, unsigned char* mask, int phase);
  float ChargeAt(float g) const;
  vtkIdType DrawLayerIndependently(const float* density, unsigned char* mask);

  vtkErrorDiffusionParameterTable Table;
  double ModulationScale = 0.5;
  std::uint64_t Seed = 0;
  int BoundaryMode = BOUNDARY_STEADY_STATE;
  int Method = METHOD_ERROR_DIFFUSION;
  int WarmUpLayers = 8;

  int NX = 0;
  int NY = 0;
  int NZ = 0;
  int FirstLayer = 0;
  int LayersDone = 0;
  Generator Random;
  std::vector<float> KeyLevels;  // the table's key levels (1/255 units)
  std::vector<float> KeyCharges; // C at each key level
  std::vector<float> Current; // error accumulated for the layer being scanned
  std::vector<float> Next;    // error passed on to the following layer
  std::vector<float> OpenLayer; // the layer past the last one (steady state): all active
  std::array<LevelParameters, 256> ParameterCache;
  const float* TestedLayer = nullptr; // the last successor layer tested, and whether
  bool TestedLayerActive = false;     // all of its voxels were active
};

#endif
