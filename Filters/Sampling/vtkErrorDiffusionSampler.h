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
 * algorithm itself lives in vtkErrorDiffusionKernel (see there for the scan
 * order, the threshold, the mirroring of g > 0.5 and the boundary handling).
 *
 * Input: vtkImageData with 1D, 2D or 3D extent (a 2D image is sampled as one
 * layer). The density comes from the point-data array chosen with
 * SetInputArrayToProcess(0, ...) (default: the active scalars), any numeric
 * type; Component selects the component (-1: the magnitude). The value x
 * becomes a density by DensityMapping:
 * - DENSITY_IDENTITY: g = x;
 * - DENSITY_SCALAR_RANGE: g = (x - lo) / (hi - lo) with [lo, hi] the array's
 *   finite range (of the chosen component or magnitude) or ScalarRange when
 *   UseCustomScalarRange is on; a range of zero width maps values at or above
 *   it to 1 and values below it to 0, with a warning;
 * - DENSITY_TRANSFER_FUNCTION: g = TransferFunction(x) (typically the opacity
 *   function of the scalar a ParaView user colours by).
 * Then g is multiplied by DensityScale and clamped to [0, 1]; NaN gives 0. The
 * expected number of points is the sum of g over the voxels.
 *
 * Output port 0: vtkPolyData, one vertex cell per sample, at voxel centres in
 * world coordinates (origin, spacing and direction matrix honoured). Every
 * input point-data array is copied for the sampled voxels, and a float array
 * `Density` holds the density each sample was drawn with (an input array of
 * that name is replaced). Field data records the sampling grid so a spectrum
 * can rebuild it: `SamplingGridOrigin` (3), `SamplingGridSpacing` (3),
 * `SamplingGridExtent` (6, the extent that was sampled) and
 * `SamplingGridDirection` (9, row major).
 *
 * Output port 1: when GenerateMask is on, the binary sample mask as vtkImageData
 * (uint8 array `SampleMask`, 1 where a sample was drawn) on the input's
 * geometry; otherwise an empty image.
 *
 * The filter samples whatever extent the pipeline hands it: under pvbatch with
 * MPI each rank samples its own piece (pieces do not exchange error, so piece
 * faces are treated like volume faces). Each voxel of the whole volume is
 * sampled by one piece: the plane a piece shares with the next one
 * (structured pieces overlap by one plane of points) is left to that one,
 * and points flagged DUPLICATEPOINT or HIDDENPOINT in the input's ghost array
 * are never sampled. The default scalar range is the range over all pieces
 * (see SetController). Time is
 * O(voxels); extra memory besides the output is a few layers (two of error,
 * four of densities and masks). The output arrays reserve address space for
 * one point per voxel (up to 2^28) so they never grow by copying; only what
 * is written is committed, and the rest is released at the end (see
 * vtkErrorDiffusionPointAssembler). The scan runs on a worker thread while
 * this thread builds the points (UseWorkerThread). Progress is reported per
 * layer; abort is honoured between layers.
 *
 * Bad input (no array, non-numeric array, cell data, empty extent, component
 * out of range, negative or non-finite DensityScale or ModulationScale, a
 * missing transfer function, an unreadable or malformed parameter file) gives a
 * vtkErrorMacro and empty outputs.
 *
 * @sa vtkErrorDiffusionKernel vtkErrorDiffusionParameterTable vtkBlueNoiseSpectrum
 */
#ifndef vtkErrorDiffusionSampler_h
#define vtkErrorDiffusionSampler_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string>

class vtkDataArray;
class vtkImageData;
class vtkMultiProcessController;
class vtkPiecewiseFunction;

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionSampler : public vtkPolyDataAlgorithm
{
public:
  static vtkErrorDiffusionSampler* New();
  vtkTypeMacro(vtkErrorDiffusionSampler, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum DensityMappings
  {
    DENSITY_IDENTITY = 0,
    DENSITY_SCALAR_RANGE = 1,
    DENSITY_TRANSFER_FUNCTION = 2
  };

  enum ParameterSets
  {
    PARAMETERS_PAPER = 0,
    PARAMETERS_FIXED = 1,
    PARAMETERS_CUSTOM = 2,
    PARAMETERS_OPTIMIZED = 3
  };

  enum Methods
  {
    METHOD_ERROR_DIFFUSION = 0,
    METHOD_WHITE_NOISE = 1
  };

  enum BoundaryModes
  {
    BOUNDARY_RENORMALIZE = 0,
    BOUNDARY_STEADY_STATE = 1
  };

  ///@{
  /**
   * METHOD_ERROR_DIFFUSION (default): the blue-noise 3D error diffusion.
   * METHOD_WHITE_NOISE: hit-and-miss sampling, every voxel drawn on its own
   * with probability g (white noise, the baseline of particle-based volume
   * rendering), with the same density mapping and the same expected count.
   */
  vtkSetClampMacro(Method, int, METHOD_ERROR_DIFFUSION, METHOD_WHITE_NOISE);
  vtkGetMacro(Method, int);
  void SetMethodToErrorDiffusion() { this->SetMethod(METHOD_ERROR_DIFFUSION); }
  void SetMethodToWhiteNoise() { this->SetMethod(METHOD_WHITE_NOISE); }
  ///@}

  ///@{
  /**
   * Component of the density array to use; -1 uses the magnitude. Default 0.
   */
  vtkSetClampMacro(Component, int, -1, VTK_INT_MAX);
  vtkGetMacro(Component, int);
  ///@}

  ///@{
  /**
   * How array values become densities (see the class comment). Default
   * DENSITY_SCALAR_RANGE.
   */
  vtkSetClampMacro(DensityMapping, int, DENSITY_IDENTITY, DENSITY_TRANSFER_FUNCTION);
  vtkGetMacro(DensityMapping, int);
  void SetDensityMappingToIdentity() { this->SetDensityMapping(DENSITY_IDENTITY); }
  void SetDensityMappingToScalarRange() { this->SetDensityMapping(DENSITY_SCALAR_RANGE); }
  void SetDensityMappingToTransferFunction()
  {
    this->SetDensityMapping(DENSITY_TRANSFER_FUNCTION);
  }
  ///@}

  ///@{
  /**
   * The range mapped to [0, 1] by DENSITY_SCALAR_RANGE when
   * UseCustomScalarRange is on (otherwise the array's own range is used).
   * Default [0, 1], off.
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
   * DENSITY_TRANSFER_FUNCTION. Not owned exclusively (reference counted).
   */
  virtual void SetTransferFunction(vtkPiecewiseFunction*);
  vtkGetObjectMacro(TransferFunction, vtkPiecewiseFunction);
  ///@}

  ///@{
  /**
   * Multiplies the mapped density before it is clamped to [0, 1]; the way to
   * choose the number of points. Must be finite and >= 0. Default 1.
   */
  vtkSetMacro(DensityScale, double);
  vtkGetMacro(DensityScale, double);
  ///@}

  ///@{
  /**
   * Diffusion coefficients and modulation strengths: PARAMETERS_PAPER (Table 1
   * of the paper, default), PARAMETERS_FIXED (the un-optimised baseline of the
   * paper's Fig. 8), PARAMETERS_CUSTOM (read from ParameterFile, in the
   * format described in vtkErrorDiffusionParameterTable) or
   * PARAMETERS_OPTIMIZED (this project's own search, lower T(g) than Table 1;
   * see vtkErrorDiffusionParameterTable::Optimized).
   */
  vtkSetClampMacro(ParameterSet, int, PARAMETERS_PAPER, PARAMETERS_OPTIMIZED);
  vtkGetMacro(ParameterSet, int);
  vtkSetStdStringFromCharMacro(ParameterFile);
  vtkGetCharFromStdStringMacro(ParameterFile);
  ///@}

  ///@{
  /**
   * Factor s in the threshold t = 0.5 + s * r * m(g), r uniform in [0, 1).
   * s = 1 reads the paper's Eq. 1 literally; s = 0.5 is the scale of Zhou and
   * Fang's 2D code. Must be finite and >= 0. Default 0.5: with Table 1 it gives
   * the lower low-frequency ratio L(g) at every key level (128^3, 4 seeds:
   * 0.0903 against 0.0935 at g = 8/255, 0.407 against 0.432 at 32/255; the
   * bluenoise-boundary-study program prints both).
   */
  vtkSetMacro(ModulationScale, double);
  vtkGetMacro(ModulationScale, double);
  ///@}

  ///@{
  /**
   * Seed of the threshold noise. The same seed gives the same points, bit for
   * bit. Default 0.
   */
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

  ///@{
  /**
   * Boundary handling: BOUNDARY_STEADY_STATE (default) starts the scan with
   * the error buffers charged as if the scan had been running and lets the
   * last layer pass its error out of the volume; BOUNDARY_RENORMALIZE is the
   * paper-faithful behaviour (empty first layers, error piled into the last
   * layer). WarmUpLayers (rounded up to whole scanning cycles of 4) is the
   * number of virtual layers used to settle the buffers. Default 8.
   */
  vtkSetClampMacro(BoundaryMode, int, BOUNDARY_RENORMALIZE, BOUNDARY_STEADY_STATE);
  vtkGetMacro(BoundaryMode, int);
  vtkSetClampMacro(WarmUpLayers, int, 0, 4096);
  vtkGetMacro(WarmUpLayers, int);
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
   * builds the output points, attributes and progress from the layers already
   * scanned. The scan itself is sequential (each voxel depends on the one
   * before), so this is the parallelism the method has; the output is
   * identical either way. Used when the volume has at least 32768 voxels and
   * two layers and the machine more than one hardware thread. Default on.
   */
  vtkSetMacro(UseWorkerThread, bool);
  vtkGetMacro(UseWorkerThread, bool);
  vtkBooleanMacro(UseWorkerThread, bool);
  ///@}

  ///@{
  /**
   * The controller used when the filter samples one piece of several (under
   * pvbatch or pvserver with MPI): with DENSITY_SCALAR_RANGE and no custom
   * range, the range is reduced over all processes so that a value maps to
   * the same density in every piece, and a piece with an empty extent gives
   * an empty output without an error. Default: the global controller; set
   * nullptr to map each piece by its own range.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

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
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Method = METHOD_ERROR_DIFFUSION;
  int Component = 0;
  int DensityMapping = DENSITY_SCALAR_RANGE;
  double ScalarRange[2] = { 0.0, 1.0 };
  bool UseCustomScalarRange = false;
  vtkPiecewiseFunction* TransferFunction = nullptr;
  double DensityScale = 1.0;
  int ParameterSet = PARAMETERS_PAPER;
  std::string ParameterFile;
  double ModulationScale = 0.5;
  int Seed = 0;
  int BoundaryMode = BOUNDARY_STEADY_STATE;
  int WarmUpLayers = 8;
  bool GenerateMask = false;
  int OutputPointsPrecision = SINGLE_PRECISION;
  bool UseWorkerThread = true;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkErrorDiffusionSampler(const vtkErrorDiffusionSampler&) = delete;
  void operator=(const vtkErrorDiffusionSampler&) = delete;

  bool IsAborted();
  // The selected point array if it can be sampled; nullptr after an error.
  vtkDataArray* GetDensityArray(vtkImageData* input, vtkInformationVector** inputVector);
};

#endif
