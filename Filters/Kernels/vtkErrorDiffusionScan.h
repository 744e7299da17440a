// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionScan
 * @brief   The 3D error-diffusion algorithm, layer by layer, without the VTK
 *          pipeline, for a given threshold charge.
 *
 * vtkErrorDiffusionKernel is this scan with the charge its process settles
 * at (vtkErrorDiffusionChargeCurve), the one the sampler runs; this class
 * takes the charge from ChargeAt() (none here) or SetFixedCharge(), and the
 * charge curve calibrates itself with it.
 *
 * Turns a density volume g(x, y, z) in [0, 1] into a binary volume b whose
 * ones are the samples (paper section 3). The caller feeds the layers in z
 * order, one ProcessLayer() call each, and gets each layer's binary mask back:
 * the kernel keeps two layers of accumulated error, so memory is O(nx * ny)
 * whatever the number of layers, time is O(voxels), and a volume can be fed in
 * slabs (streaming) with the same result.
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
 * Threshold: t = 0.5 - C(g) + s * r * m(g) with r uniform in [0, 1) from a
 * PCG32 generator (one number per active voxel, in scan order; each layer's
 * stream is chosen by the seed and the layer's global z index, so pieces and
 * slabs of a volume draw the numbers the whole volume draws), s the
 * ModulationScale (s = 1 is the paper's Eq. 1; s = 0.5, the default, is Zhou
 * and Fang's 0..255 code) and C(g) the charge (ChargeAt(); in
 * vtkErrorDiffusionKernel the steady-state charge of the paper's process,
 * vtkErrorDiffusionChargeCurve). Lowering the paper's threshold
 * 0.5 + s r m by C translates the error by C: in the interior of a constant
 * region this process makes the paper's decisions, but its empty buffer is
 * the settled mean state, so a region starts sampling at once (the paper's
 * process, started empty, spends C / g layers charging up: the first 60
 * layers at g = 0.01 come out nearly empty), density changes along the scan
 * are followed at once, and no standing charge is left to pile up where the
 * scan ends. For g > 0.5 the whole process is mirrored:
 * t = 0.5 + C(1 - g) - s r m(1 - g), so the pattern at density g is the
 * complement of the pattern at 1 - g (the paper's "the minority voxels of g
 * and 1 - g are alike"); with both halves translated to zero mean there is no
 * band where g crosses 0.5.
 *
 * Voxels with g <= 0 (NaN included) are never sampled and g >= 1 always
 * sampled. Neither takes part in the diffusion: they are treated like the
 * missing neighbors at a face of the volume. The error of a voxel goes to
 * its active targets (0 < g < 1, inside the volume) with their weights
 * renormalized to sum 1, so an empty region stays empty, no error leaks
 * across it, and the rim of a support is sampled like its inside. Deciding
 * this for the targets in the next layer is why ProcessLayer needs that
 * layer's densities.
 *
 * Density steps. Of its active targets, a voxel's error goes only to those
 * of a similar density (vtkBlueNoiseDensityClass::Similar, within a factor
 * of about 4), when it has any: a region next to a much denser or sparser one is sampled
 * like a region of its own, its rim like its inside. Error carried over such
 * a step (up to half a point, many voxels' worth of the sparse side's
 * density) would fire the sparse side's first voxels at once: twice its
 * density in the voxels along the step and too few just behind. Within a
 * smooth gradient neighbors are always similar.
 *
 * Exact counts. No error is lost: a voxel with no active target (an isolated
 * voxel, the end of the last row of a support) passes its error on to the
 * next active voxel of the scan, and the last layer (nextDensity == nullptr)
 * keeps what would go below it. The number of samples is therefore the sum of
 * the densities plus the error the run starts with minus the error left after
 * its last voxel (less than 1 in magnitude): exact to a point, in any volume,
 * at any density. The warm-up (below) is the only source of starting error;
 * its sum is removed, so it only shapes the first layers.
 *
 * Warm-up. A region starts from an empty buffer, which is the mean state but
 * not yet a settled pattern; WarmUp() scans virtual layers of the first
 * layer's densities before it (whole scanning cycles, so the first layer keeps
 * its phase) and keeps the error they leave, minus its mean over the active
 * voxels. Regions entered after empty voxels start without a warm-up; with
 * the translated threshold they reach their density within a few layers from
 * g = 0.004 on (every 16 layers hold their expected count within 1 % from
 * there; below it the first layers are thin and the next ones make up for
 * it).
 *
 * Methods: METHOD_ERROR_DIFFUSION (the above) or METHOD_WHITE_NOISE, the
 * hit-and-miss baseline of particle-based volume rendering: every voxel with
 * 0 < g < 1 is drawn on its own with probability g from the same generator.
 */
#ifndef vtkErrorDiffusionScan_h
#define vtkErrorDiffusionScan_h

#include "vtkErrorDiffusionParameterTable.h"
#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <algorithm>
#include <cstdint>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionScan
{
public:
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

  vtkErrorDiffusionScan();
  vtkErrorDiffusionScan(const vtkErrorDiffusionScan&) = default;
  vtkErrorDiffusionScan& operator=(const vtkErrorDiffusionScan&) = default;
  virtual ~vtkErrorDiffusionScan();

  void SetParameters(const vtkErrorDiffusionParameterTable& table) { this->Table = table; }
  const vtkErrorDiffusionParameterTable& GetParameters() const { return this->Table; }
  void SetModulationScale(double s) { this->ModulationScale = s; }
  double GetModulationScale() const { return this->ModulationScale; }
  void SetSeed(std::uint64_t seed) { this->Seed = seed; }
  void SetMethod(int method) { this->Method = method; }
  /// Virtual layers scanned before the first layer (see WarmUp). Default 8.
  void SetWarmUpLayers(int layers) { this->WarmUpLayers = std::max(layers, 0); }
  int GetWarmUpLayers() const { return this->WarmUpLayers; }

  /**
   * C(g) = charge at every density, whatever its sign, instead of ChargeAt()
   * (the charge curve's calibration runs the process this way).
   */
  void SetFixedCharge(float charge)
  {
    this->UseFixedCharge = true;
    this->FixedCharge = charge;
  }

  /**
   * Start a run over layers of nx * ny voxels whose first layer has global z
   * index firstLayer (it sets the scan phase). Resets the error and the
   * generator. The parameters above must be set before.
   */
  void Begin(int nx, int ny, int firstLayer = 0);

  /**
   * Scan `layers` virtual layers of the given densities (nx * ny values)
   * before the next layer, rounded up to whole scanning cycles so that layer
   * keeps its phase, then remove the mean of the error they leave over the
   * active voxels of `density`. Does nothing for white noise. The first
   * ProcessLayer() after Begin() calls it with its own densities and
   * WarmUpLayers unless it was called explicitly before.
   */
  void WarmUp(const float* density, int layers);

  /**
   * Shift the error held for the next layer so that, with the share in
   * transit, it sums to zero over the active voxels of `density` (that
   * layer's densities): what a warm-up leaves then shapes the next layers
   * but adds or takes no points.
   */
  void CenterCarriedError(const float* density);

  /**
   * Sample the next layer. density: nx * ny values, x fastest; nextDensity:
   * the densities of the layer after it in the same layout, or nullptr for
   * the last layer (no voxel below takes error). mask receives 0 or 1 per
   * voxel. Returns the number of samples. The next call's density must hold
   * what nextDensity held (it may be the same buffer, unchanged).
   */
  vtkIdType ProcessLayer(const float* density, const float* nextDensity, unsigned char* mask);

  /// Layers processed since Begin().
  int GetLayersDone() const { return this->LayersDone; }

  /**
   * The error the buffers hold: what the next layers will receive from the
   * ones scanned so far (and the share in transit to the next voxel).
   */
  double GetCarriedError() const;

  /// Frees the buffers of a run that is over: the error, the interior and the
  /// density classes of its layers (Begin and the scan make them again).
  void ReleaseLayerBuffers();

  /**
   * Trades those buffers with `other`'s, before Begin: a scan that starts
   * where another ended reuses its memory, whose pages are in place, rather
   * than the fresh pages of an allocation (a fault each on first touch).
   * Begin and the scan write every value before they read it.
   */
  void SwapLayerBuffers(vtkErrorDiffusionScan& other);

  /**
   * Run the process translated by the constant `charge` on a box at constant
   * density g (vtkErrorDiffusionChargeCurve says which box) and return the
   * mean error the voxels away from its faces receive.
   */
  static double MeasureReceivedError(const vtkErrorDiffusionParameterTable& table,
    double modulationScale, double g, float charge, int seed);

protected:
  /**
   * Called by Begin() for error diffusion without a fixed charge, after the
   * table and the scale are set: where a subclass prepares its charges.
   */
  virtual void PrepareCharges() {}

  /// C(g) for the minority density g <= 0.5 (see the class comment); 0 here.
  virtual float ChargeAt(float minority) const
  {
    (void)minority;
    return 0.0f;
  }

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
    float Weights[6] = { 0, 0, 0, 0, 0, 0 };
    float Base = 0.5f;
    float Modulation = 0.0f;
    bool Valid = false;
  };
  LevelParameters ParametersOf(float g);
  // The scan in a layout whose rows are `pitch` values apart (the error buffers').
  static LayerScan GetLayerScan(int nx, int ny, int phase, vtkIdType pitch);
  LevelParameters Evaluate(float g) const;

  // What the scan of a layer takes from one voxel to the next.
  struct RunState
  {
    float Carry = 0.0f;     // the share in transit to the next voxel scanned
    float CachedG = -1.0f;  // the density Level is for
    LevelParameters Level;
    vtkIdType Count = 0;    // samples so far
  };
  template <bool Record, bool Branchy>
  void ScanRun(const float* density, unsigned char* mask, vtkIdType idx, vtkIdType d,
    vtkIdType eidx, vtkIdType ed, vtkIdType ev, int n, float received, RunState& state);
  // next: the densities of the following layer, nullptr if there is none.
  // Record keeps in Current what each voxel received (MeasureReceivedError).
  template <bool Record = false>
  vtkIdType ScanLayer(const float* density, const float* next, unsigned char* mask, int layer);
  bool TestLayers(const float* density, const float* next, vtkIdType& active, bool& similar);
  float SpreadAtFace(float e, const float w[6], const bool valid[6], const bool similar[6],
    vtkIdType idx, vtkIdType d, vtkIdType v, void* reservoir);
  vtkIdType DrawLayerIndependently(const float* density, unsigned char* mask);
  void EndLayer();
  void SeedLayer(int layer);

  vtkErrorDiffusionParameterTable Table;
  double ModulationScale = 0.5;
  std::uint64_t Seed = 0;
  int Method = METHOD_ERROR_DIFFUSION;
  int WarmUpLayers = 8;

  int NX = 0;
  int NY = 0;
  int FirstLayer = 0;
  int LayersDone = 0;
  Generator Random;
  bool UseFixedCharge = false; // FixedCharge at every density (SetFixedCharge)
  float FixedCharge = 0.0f;
  vtkIdType Pitch = 0;        // row stride of Current and Next (see ErrorPitch)
  std::vector<float> Current; // error accumulated for the layer being scanned
  std::vector<float> Next;    // error passed on to the following layer
  float Carry = 0.0f;         // the share in transit to the next voxel scanned
  bool WarmedUp = false;
  // Parameters by density, indexed by the top bits of min(g, 1 - g) as a
  // float (2^-8 relative steps); filled as densities come up.
  std::vector<LevelParameters> ParameterTable;
  // In a layer with inactive voxels or density steps, each voxel's path
  // (FindInterior): 1 where the voxel's 3x3 neighborhood is active in the
  // layer and the next (all six targets are then active) and, with `steps`,
  // of densities similar to one another; 2 where it has no density.
  std::vector<unsigned char> Interior;
  std::vector<unsigned char> InteriorWork;
  std::vector<unsigned char> ClassLow, ClassHigh, ClassWork;
  std::vector<unsigned char> ClassCurrent, ClassNext; // of the layer and the next
  const float* ClassedLayer = nullptr;                // the densities ClassNext is of
  const unsigned char* FindInterior(const float* density, const float* next, bool steps);
  void ErodeActive(const float* density, const float* next, bool steps);
  const unsigned char* LayerPaths(
    const float* density, const float* next, unsigned char* mask, bool allActive, bool similar);
  void KeepSimilarInterior(const float* density, const float* next);
  // The last successor layer tested: how many of its voxels are active, and
  // the lowest and highest of their densities.
  struct LayerRange
  {
    vtkIdType Active = 0;
    float Low = 1.0f; // High < Low when none is active
    float High = 0.0f;
  };
  static LayerRange RangeOf(const float* g, size_t n);
  const float* TestedLayer = nullptr;
  LayerRange Tested;
};

#endif
