// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionSampler
 * @brief   Blue-noise importance sampling of a volume by 3D error diffusion.
 *
 * vtkErrorDiffusionSampler turns a vtkImageData into sample points whose local
 * density follows a density derived from one of the image's point-data arrays,
 * with a blue-noise distribution (random, even, isotropic): the density-
 * dependent 3D error diffusion of Zhang et al. (rotated-serpentine scan,
 * modulated threshold, six density-dependent coefficients from Table 1). The
 * algorithm lives in vtkErrorDiffusionKernel (scan order, threshold, the
 * mirroring of g > 0.5, faces, exact counts).
 *
 * Input: vtkImageData with 1D, 2D or 3D extent (a 2D image is sampled as one
 * layer). The density comes from the point-data array chosen with
 * SetInputArrayToProcess(0, ...) (default: the active scalars), any numeric
 * type; Component selects the component (-1 or the number of components: the
 * magnitude). The value
 * becomes a density by DensityMapping (see vtkSamplingDensity for the exact
 * definitions):
 * - DENSITY_IDENTITY: the value is the density;
 * - DENSITY_SCALAR_RANGE: [lo, hi] maps linearly to [0, 1], with [lo, hi] the
 *   array's finite range, or ScalarRange when UseCustomScalarRange is on;
 * - DENSITY_TRANSFER_FUNCTION: TransferFunction maps value to density
 *   (typically the opacity function a ParaView user volume-renders with);
 *   without a function, a ramp over the finite range (as DENSITY_SCALAR_RANGE).
 * The result is multiplied by a scale and clamped to [0, 1]; NaN gives 0. The
 * expected number of points is the sum of the densities over the voxels.
 *
 * Point budget. With UseNumberOfPoints on (the default) the scale is solved so
 * that the expected number of points is NumberOfPoints (vtkSamplingBudget: one
 * pass over the values, exact for 8- and 16-bit data); a budget above what the
 * volume can hold (every voxel of positive density drawn) gives a warning
 * naming that maximum, and all those voxels are sampled. With it off, the
 * scale is DensityScale. The error diffusion draws the expected number to
 * within one point (see vtkErrorDiffusionKernel), white noise within its
 * binomial spread.
 *
 * Output port 0: vtkPolyData, one vertex cell per sample, at voxel centers in
 * world coordinates (origin, spacing and direction matrix honored), or, with
 * Jitter on, at a point drawn uniformly inside the voxel (deterministic per
 * Seed; for rendering, where points on a lattice read as lines). Every input
 * point-data array with one tuple per voxel is copied for the sampled voxels
 * (others are left out with a warning), and a float array `Density` holds the
 * density each sample was drawn with (an input array of that name is
 * replaced). Field data: `SamplingGridOrigin` (3), `SamplingGridSpacing` (3),
 * `SamplingGridExtent` (6, the extent that was sampled) and
 * `SamplingGridDirection` (9, row major), so a spectrum can rebuild the grid
 * (jittered points bin back to their voxels); `DensityScale` (the scale used)
 * and `ExpectedNumberOfPoints` (the sum of the densities).
 *
 * Output port 1: when GenerateMask is on, the binary sample mask as
 * vtkImageData (uint8 array `SampleMask`, 1 where a sample was drawn) on the
 * sampled extent; otherwise an empty image with an empty whole extent, which
 * costs nothing and never makes the filter execute again.
 *
 * Pieces and streaming. A request for piece p of n samples the p-th of n
 * z-slabs of the whole extent (full layers, so the scan runs as for the whole
 * volume): it first scans up to OverlapLayers layers above its slab to settle
 * the error pattern it enters with, and its own count is exact. The density
 * scale and range come from the whole volume (the statistics pass reads it;
 * vtkPErrorDiffusionSampler reduces the pieces' statistics instead). With
 * NumberOfSlabs > 1 the input is requested in that many z-slabs, one after
 * the other (the statistics first, when needed, then the sampling), and the
 * scan carries its state from slab to slab: the output is the same as in one
 * go, and the input is never held whole. Readers that produce sub-extents
 * (vtkImageReader / vtkImageReader2 on raw files, vtkNrrdReader on raw NRRD,
 * vtkXMLImageDataReader on VTI with raw appended data) then read one slab at
 * a time; others deliver more than asked for, which is correct but saves
 * nothing. vtkMetaImageReader (VTK 9.2) is not one of them: it reads the
 * whole file (bluenoise-sample reads raw MetaImage through a vtkImageReader2
 * of its own, from the parsed header, instead). The points and the mask
 * (GenerateMask) still grow with the output.
 *
 * Threads. A volume of two parts or more (PartLayers, PartVoxels) sampled
 * by error diffusion (any of its three methods) or white noise is cut into z-parts
 * that are sampled side by side, each thread taking the lowest part no
 * thread holds as soon as its own is done; the threads meet only every
 * half second or so, when this thread reports progress and honors abort.
 * The lowest part not written yet adds its points to the output as it
 * scans, the others hold theirs compacted until their turn. Each part but the first scans OverlapLayers
 * layers before its own, as a piece does, and its relaxation sees the last
 * MaximumRadius of them below its first layer (vtkBlueNoiseRelaxation's
 * context) but moves nothing into them; the two passes of the energy relaxed
 * method run one after the other in each part, each with that context. The
 * parts depend on the volume only, so the output does not depend on the
 * threads; the seams between them cost little, more with the energy relaxed
 * method, whose passes lower L(g) more away from them
 * (TestErrorDiffusionSamplerParts measures them). A part's
 * buffers exist from its first layer to its last, so memory grows with the
 * threads, not with the parts. A volume of one part, or the one part left
 * to scan (the slab of a streamed volume, the last part), is scanned on a
 * worker thread while this thread relaxes and builds the points, the densities
 * mapped and the relaxed layers' points built by whichever of the two has time
 * (UseWorkerThread, when more than one thread is allowed). So are parts
 * side by side with the threads they leave idle (fewer parts left than
 * threads, or threads done while the others' parts run on): a part's next
 * chunk of layers started while a thread is idle scans on a worker thread
 * beside the thread that relaxes it (a volume of 8 parts on 16 threads uses
 * all 16; the relaxed methods gain most, the paper's method, whose scan is
 * the longer stage, little). The pass over the values that a point budget
 * or an unset scalar range needs before the scan runs on as many threads
 * as are allowed.
 *
 * Time O(voxels); memory besides the input and the output a few layers (per
 * part side by side), and the compacted samples of the parts that wait for
 * their turn to write (12 bytes a point and 8 a row of voxels), freed when
 * the execution ends. Progress is reported per layer (for parts side by
 * side, where the threads meet; for METHOD_POISSON_DISK and
 * METHOD_SAMPLE_ELIMINATION every so many voxels or candidates the kernel
 * visits); abort is honored there too and leaves an empty output.
 *
 * A budget that yields no points (NumberOfPoints 0, or a DensityScale that
 * makes the expected count below one half) gives a warning saying so.
 *
 * Bad input (no array, a non-numeric array, component out of range, empty
 * extent, non-finite DensityScale or ModulationScale, an empty custom scalar
 * range, an unreadable or malformed parameter file, slabs whose arrays
 * differ) gives a vtkErrorMacro and empty outputs, and the request succeeds
 * (downstream filters see the empty output); the next good update works.
 *
 * @sa vtkErrorDiffusionKernel vtkSamplingDensity vtkSamplingBudget
 * vtkErrorDiffusionParameterTable vtkBlueNoiseSpectrum vtkPErrorDiffusionSampler
 */
#ifndef vtkErrorDiffusionSampler_h
#define vtkErrorDiffusionSampler_h

#include "vtkErrorDiffusionKernel.h"   // for the Methods enum
#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSamplingDensity.h" // for the Mappings enum

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkImageData;
class vtkPiecewiseFunction;
class vtkSamplingBudget;

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionSampler : public vtkPolyDataAlgorithm
{
public:
  static vtkErrorDiffusionSampler* New();
  vtkTypeMacro(vtkErrorDiffusionSampler, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods
  {
    METHOD_ERROR_DIFFUSION = vtkErrorDiffusionKernel::METHOD_ERROR_DIFFUSION,
    METHOD_WHITE_NOISE = vtkErrorDiffusionKernel::METHOD_WHITE_NOISE,
    METHOD_RELAXED_ERROR_DIFFUSION = 2,
    METHOD_POISSON_DISK = 3,
    METHOD_SAMPLE_ELIMINATION = 4,
    METHOD_ENERGY_RELAXED_ERROR_DIFFUSION = 5
  };

  enum DensityMappings
  {
    DENSITY_IDENTITY = vtkSamplingDensity::IDENTITY,
    DENSITY_SCALAR_RANGE = vtkSamplingDensity::SCALAR_RANGE,
    DENSITY_TRANSFER_FUNCTION = vtkSamplingDensity::TRANSFER_FUNCTION,
    DENSITY_COLOR_MAP_OPACITY = 3
  };

  enum ParameterSets
  {
    PARAMETERS_PAPER = 0,
    PARAMETERS_FIXED = 1,
    PARAMETERS_CUSTOM = 2,
    PARAMETERS_OPTIMIZED = 3
  };

  ///@{
  /**
   * How the points are drawn, all with the same density mapping and point
   * budget:
   * - METHOD_RELAXED_ERROR_DIFFUSION (default): the 3D error diffusion, then
   *   one sweep of one-voxel moves that spreads the samples closer than the
   *   blue-noise spacing (vtkBlueNoiseRelaxation, densities up to 1/4): less
   *   low-frequency energy than a Poisson-disk set, the same count, in about
   *   twice the time of METHOD_ERROR_DIFFUSION (most around g = 1/8, where
   *   the samples to check are many and most are near another; nothing more
   *   above 1/4; Documentation/Results.md has the figures);
   * - METHOD_ENERGY_RELAXED_ERROR_DIFFUSION: the 3D error diffusion, then
   *   two passes that move each sample (densities up to 1/4) by a voxel, to
   *   the neighbor of the 26 where its Gaussian energy (the repulsion of the
   *   samples around it) is lowest (vtkBlueNoiseRelaxation::RULE_ENERGY):
   *   the least low-frequency energy of all the methods, below Poisson-disk
   *   sampling's and sample elimination's, the count exact, in several
   *   times the time of the default;
   * - METHOD_ERROR_DIFFUSION: the paper's 3D error diffusion as it is;
   * - METHOD_WHITE_NOISE: hit-and-miss sampling, every voxel drawn on its own
   *   with probability g (white noise, the baseline of particle-based volume
   *   rendering), the count within its binomial spread;
   * - METHOD_POISSON_DISK: variable-radius Poisson-disk sampling on the voxel
   *   grid (vtkPoissonDiskKernel), the count within about 0.5 %;
   * - METHOD_SAMPLE_ELIMINATION: weighted sample elimination (Yuksel 2015,
   *   vtkWeightedSampleEliminationKernel), the count exact.
   * The last two need the whole volume (or piece) in memory, ignore
   * NumberOfSlabs, and are two to three orders of magnitude slower.
   */
  vtkSetClampMacro(Method, int, METHOD_ERROR_DIFFUSION, METHOD_ENERGY_RELAXED_ERROR_DIFFUSION);
  vtkGetMacro(Method, int);
  void SetMethodToErrorDiffusion() { this->SetMethod(METHOD_ERROR_DIFFUSION); }
  void SetMethodToWhiteNoise() { this->SetMethod(METHOD_WHITE_NOISE); }
  void SetMethodToRelaxedErrorDiffusion() { this->SetMethod(METHOD_RELAXED_ERROR_DIFFUSION); }
  void SetMethodToPoissonDisk() { this->SetMethod(METHOD_POISSON_DISK); }
  void SetMethodToSampleElimination() { this->SetMethod(METHOD_SAMPLE_ELIMINATION); }
  void SetMethodToEnergyRelaxedErrorDiffusion()
  {
    this->SetMethod(METHOD_ENERGY_RELAXED_ERROR_DIFFUSION);
  }
  ///@}

  /**
   * Whether `method` scans with error diffusion (the paper's and both relaxed
   * ones): the methods that read ParameterSet and keep the count exact.
   */
  static bool IsErrorDiffusion(int method);

  ///@{
  /**
   * Component of the density array to use; -1, or the number of components
   * (ParaView's "Magnitude" entry), uses the magnitude. Default 0.
   */
  vtkSetClampMacro(Component, int, -1, VTK_INT_MAX);
  vtkGetMacro(Component, int);
  ///@}

  ///@{
  /**
   * How array values become densities (see the class comment). Default
   * DENSITY_SCALAR_RANGE. DENSITY_COLOR_MAP_OPACITY maps as
   * DENSITY_TRANSFER_FUNCTION; it says where the function comes from: the
   * application keeps TransferFunction the opacity function of the colour map
   * the array is rendered with (ParaView's proxy does, so that a user samples
   * where they see and re-samples as they edit the colour map).
   */
  vtkSetClampMacro(DensityMapping, int, DENSITY_IDENTITY, DENSITY_COLOR_MAP_OPACITY);
  vtkGetMacro(DensityMapping, int);
  void SetDensityMappingToIdentity() { this->SetDensityMapping(DENSITY_IDENTITY); }
  void SetDensityMappingToScalarRange() { this->SetDensityMapping(DENSITY_SCALAR_RANGE); }
  void SetDensityMappingToTransferFunction()
  {
    this->SetDensityMapping(DENSITY_TRANSFER_FUNCTION);
  }
  void SetDensityMappingToColorMapOpacity() { this->SetDensityMapping(DENSITY_COLOR_MAP_OPACITY); }
  ///@}

  ///@{
  /**
   * The range mapped to [0, 1] by DENSITY_SCALAR_RANGE when
   * UseCustomScalarRange is on (otherwise the array's own finite range is
   * used); it must be finite with ScalarRange[1] > ScalarRange[0]. Default
   * [0, 1], off.
   */
  vtkSetVector2Macro(ScalarRange, double);
  vtkGetVector2Macro(ScalarRange, double);
  vtkSetMacro(UseCustomScalarRange, bool);
  vtkGetMacro(UseCustomScalarRange, bool);
  vtkBooleanMacro(UseCustomScalarRange, bool);
  ///@}

  ///@{
  /**
   * The function from array value to density used by
   * DENSITY_TRANSFER_FUNCTION (values outside [0, 1] are clamped). Default
   * none: a ramp over the array's finite range.
   */
  virtual void SetTransferFunction(vtkPiecewiseFunction*);
  vtkGetObjectMacro(TransferFunction, vtkPiecewiseFunction);
  ///@}

  ///@{
  /**
   * The point budget: with UseNumberOfPoints on (default), the density scale
   * is solved so that the expected number of points is NumberOfPoints
   * (default 100000). With it off, DensityScale (finite, >= 0, default 1)
   * multiplies the mapped densities.
   */
  vtkSetMacro(UseNumberOfPoints, bool);
  vtkGetMacro(UseNumberOfPoints, bool);
  vtkBooleanMacro(UseNumberOfPoints, bool);
  vtkSetClampMacro(NumberOfPoints, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(NumberOfPoints, vtkIdType);
  vtkSetClampMacro(DensityScale, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DensityScale, double);
  ///@}

  ///@{
  /**
   * Diffusion coefficients and modulation strengths: PARAMETERS_OPTIMIZED
   * (default: this project's own search, lower T(g) than Table 1 at every
   * level of Testing/QualityReport.md; see
   * vtkErrorDiffusionParameterTable::Optimized), PARAMETERS_PAPER (Table 1 of
   * the paper), PARAMETERS_FIXED (the un-optimized baseline of the paper's
   * Fig. 8) or PARAMETERS_CUSTOM (read from ParameterFile, in the format
   * described in vtkErrorDiffusionParameterTable). The paper's method as it
   * is: Method ERROR_DIFFUSION with PARAMETERS_PAPER.
   */
  vtkSetClampMacro(ParameterSet, int, PARAMETERS_PAPER, PARAMETERS_OPTIMIZED);
  vtkGetMacro(ParameterSet, int);
  vtkSetStdStringFromCharMacro(ParameterFile);
  vtkGetCharFromStdStringMacro(ParameterFile);
  ///@}

  ///@{
  /**
   * Factor s of the threshold modulation, t = 0.5 - C(g) + s * r * m(g) with
   * r uniform in [0, 1): s = 1 reads the paper's Eq. 1 literally; s = 0.5 is
   * the scale of Zhou and Fang's 2D code, with which Table 1 gives the lower
   * low-frequency ratio L(g). In [0, 2]. Default 0.5.
   */
  vtkSetClampMacro(ModulationScale, double, 0.0, 2.0);
  vtkGetMacro(ModulationScale, double);
  ///@}

  ///@{
  /**
   * Seed of the threshold noise (and of the jitter). The same seed gives the
   * same points, bit for bit. Default 0.
   */
  vtkSetClampMacro(Seed, int, 0, VTK_INT_MAX);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /**
   * Virtual layers (rounded up to whole scanning cycles of 4) scanned with the
   * first layer's densities before it, so that the first layers are sampled
   * from a settled error pattern (see vtkErrorDiffusionKernel::WarmUp). They
   * add no points and no error. A piece or z-part that scans overlap layers
   * first (OverlapLayers) is warmed up only for the layers its overlap is
   * short of: the overlap settles the pattern on the volume's own layers. In
   * [0, 4096]. Default 8.
   */
  vtkSetClampMacro(WarmUpLayers, int, 0, 4096);
  vtkGetMacro(WarmUpLayers, int);
  ///@}

  ///@{
  /**
   * Place each point uniformly inside its voxel instead of at its center
   * (deterministic per Seed and voxel). Points on the voxel lattice render,
   * in perspective, as lines radiating from the view center; jittered ones
   * read as the blue noise they are. The SamplingGrid field data still
   * describes the voxels, so the spectrum of the points does not change.
   * Default off.
   */
  vtkSetMacro(Jitter, bool);
  vtkGetMacro(Jitter, bool);
  vtkBooleanMacro(Jitter, bool);
  ///@}

  ///@{
  /**
   * Produce the binary mask on output port 1. Default off.
   */
  vtkSetMacro(GenerateMask, bool);
  vtkGetMacro(GenerateMask, bool);
  vtkBooleanMacro(GenerateMask, bool);
  ///@}

  ///@{
  /**
   * Precision of the output points: vtkAlgorithm::SINGLE_PRECISION (default)
   * or vtkAlgorithm::DOUBLE_PRECISION.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /**
   * Run the error-diffusion scan on a worker thread while the calling thread
   * (for parts side by side paired with idle threads, the thread that
   * holds the part; see the class comment) relaxes and builds the output
   * points from the layers already scanned,
   * the densities of the layers ahead mapped and the points of relaxed layers
   * built by whichever thread has time (the scan itself is sequential: each
   * voxel depends on the one before). Used when
   * vtkSMPTools runs more than one thread (with its
   * Sequential backend, the default of Debian's VTK and ParaView, when
   * VTK_SMP_MAX_THREADS, or else the hardware, allows more than one) and the
   * volume has at least 32768 voxels and two layers; the output is identical
   * either way. Default on.
   */
  vtkSetMacro(UseWorkerThread, bool);
  vtkGetMacro(UseWorkerThread, bool);
  vtkBooleanMacro(UseWorkerThread, bool);
  ///@}

  ///@{
  /**
   * Request the input in this many z-slabs, one after the other, instead of
   * whole (streaming; see the class comment). In [1, 65536]. Default 1.
   */
  vtkSetClampMacro(NumberOfSlabs, int, 1, 65536);
  vtkGetMacro(NumberOfSlabs, int);
  ///@}

  ///@{
  /**
   * For piece p > 0 of several, and for each z-part but the first (see
   * PartLayers): layers before it scanned first to settle the error pattern
   * it enters with. In [0, 4096]. Default 8: the relaxation's largest search
   * radius (vtkBlueNoiseRelaxation::MaximumRadius), so that its context
   * below a part is whole. The overlap stands in for the warm-up
   * (WarmUpLayers), which makes up only what it is short of; longer overlaps
   * leave the seams as they are.
   */
  vtkSetClampMacro(OverlapLayers, int, 0, 4096);
  vtkGetMacro(OverlapLayers, int);
  ///@}

  ///@{
  /**
   * The size of the z-parts the error-diffusion methods and white noise
   * sample side by side, one per thread: each
   * part has at least PartLayers layers (in [2, 65536], default 64) and
   * PartVoxels voxels (at least 256, default 2^22), so a volume smaller
   * than two parts is sampled in one. The parts depend on the volume alone,
   * never on the threads, so the output does not either; but it does depend
   * on these two. Each part but the first scans OverlapLayers layers before
   * its own first, as a piece does (see the class comment), so shorter
   * parts rescan more: they pay only where they give threads parts that
   * would have none (a volume of 512 layers has 8 parts by default, 16 of
   * 32 layers, each rescanning a quarter of its layers again). Where the
   * density sits in a few parts (a ball in an empty box), shorter ones
   * also keep more threads busy.
   */
  vtkSetClampMacro(PartLayers, int, 2, 65536);
  vtkGetMacro(PartLayers, int);
  vtkSetClampMacro(PartVoxels, vtkIdType, 256, VTK_ID_MAX);
  vtkGetMacro(PartVoxels, vtkIdType);
  ///@}

  ///@{
  /**
   * The z-parts of the last execution (see PartLayers): how many, and part
   * i's layers (global z): range[0] the first it scans (its overlap
   * included), range[1] and range[2] the first and the last it samples.
   * Empty (0, and a range of -1) before the first execution and for an i out
   * of range.
   */
  int GetNumberOfParts();
  void GetPartRange(int i, int range[3]);
  ///@}

  /**
   * How many z-parts a volume of `layers` layers of `layerVoxels` voxels
   * each is sampled in, by the current Method, PartLayers and PartVoxels (1
   * for the whole-volume methods). The threads sample the parts of one slab
   * side by side, so a caller that streams a volume (NumberOfSlabs) keeps
   * them busy with slabs of at least as many parts as threads.
   */
  int GetNumberOfPartsFor(vtkIdType layers, vtkIdType layerVoxels) const;

  /// Output port 1: the mask image.
  vtkImageData* GetMaskOutput();

  /// Includes the transfer function's modification time.
  vtkMTimeType GetMTime() override;

protected:
  vtkErrorDiffusionSampler();
  ~vtkErrorDiffusionSampler() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The layers whose values the statistics pass (range, budget) reads for
   * piece `piece` of `pieces` of the whole extent: here the whole z range,
   * so that every piece maps values alike.
   */
  virtual void GetStatisticsLayers(
    const int whole[6], int piece, int pieces, int& first, int& last);

  /**
   * Combine the statistics of the pieces (vtkPErrorDiffusionSampler: over the
   * processes). Returns false to fail the run. Here: nothing to do.
   */
  virtual bool ReduceStatistics(vtkSamplingBudget& statistics);

  int Method = METHOD_RELAXED_ERROR_DIFFUSION;
  int Component = 0;
  int DensityMapping = DENSITY_SCALAR_RANGE;
  double ScalarRange[2] = { 0.0, 1.0 };
  bool UseCustomScalarRange = false;
  vtkPiecewiseFunction* TransferFunction = nullptr;
  bool UseNumberOfPoints = true;
  vtkIdType NumberOfPoints = 100000;
  double DensityScale = 1.0;
  int ParameterSet = PARAMETERS_OPTIMIZED;
  std::string ParameterFile;
  double ModulationScale = 0.5;
  int Seed = 0;
  int WarmUpLayers = 8;
  bool Jitter = false;
  bool GenerateMask = false;
  int OutputPointsPrecision = SINGLE_PRECISION;
  bool UseWorkerThread = true;
  int NumberOfSlabs = 1;
  int OverlapLayers = 8;
  int PartLayers = 64;
  vtkIdType PartVoxels = vtkIdType(1) << 22;

private:
  vtkErrorDiffusionSampler(const vtkErrorDiffusionSampler&) = delete;
  void operator=(const vtkErrorDiffusionSampler&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;

  bool IsAborted();
  int Execute(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  bool SamplesCells();
  int ValueMapping() const;
  bool ValidateProperties();
  void PlanRun(const int whole[6], int piece, int pieces);
  void PlanParts(bool atOnce);
  bool StartRun(vtkInformation* outInfo, vtkInformationVector** inputVector);
  bool RunCoveredSteps(vtkImageData* input, vtkInformationVector** inputVector);
  bool CollectStatistics(vtkImageData* input, vtkInformationVector** inputVector);
  bool FinishStatistics();
  bool SampleSlab(vtkImageData* input, vtkInformationVector** inputVector);
  bool StartAssembly(vtkImageData* input);
  bool ScanSlab(vtkImageData* input, vtkDataArray* array);
  bool ScanParts(vtkImageData* input, vtkDataArray* array);
  bool WorkerThreadFor(int layers) const;
  bool SampleWhole(vtkImageData* input, vtkDataArray* array);
  void FinishOutput(vtkImageData* input, vtkPolyData* output, vtkImageData* mask);
  void WarnIfEmpty(vtkIdType points, double expected);
  vtkDataArray* GetDensityArray(vtkImageData* input, vtkInformationVector** inputVector);
};

#endif
