// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBlueNoiseSpectrum
 * @brief   3D blue-noise spectrum metric of point sets or count volumes.
 *
 * vtkBlueNoiseSpectrum measures how "blue" a 3D point distribution is, with
 * the metric of Zhang et al. (section 4, Eq. 2-11): radially averaged power
 * spectrum, anisotropy, low-frequency ratio L(g), segmented radially averaged
 * power spectra (SRAPS) and their symmetry S(g), and the target
 * T(g) = w L(g) + (1 - w) S(g). The computation is vtkBlueNoiseSpectrumKernel's;
 * its class comment gives every definition exactly (shell rounding, Hermitian
 * counting, tie rules, zero-variance and zero-power conventions).
 *
 * Input (port 0, repeatable): every connection is a vtkPointSet (e.g. the
 * vtkPolyData of vtkErrorDiffusionSampler), a vtkImageData, or a composite
 * dataset of those; each non-empty leaf is one realization. Realizations are
 * averaged (mean of their periodograms) and must all give the same grid shape.
 *
 * The analysis grid of a realization, when UseInputGrid is on (default):
 * 1. a point set carrying the sampler's field data `SamplingGridOrigin` (3),
 *    `SamplingGridSpacing` (3), `SamplingGridExtent` (6: i0 i1 j0 j1 k0 k1)
 *    and optionally `SamplingGridDirection` (9, row major, index to physical:
 *    x = origin + D (ijk * spacing)) uses that grid;
 * 2. an image uses its own extent and geometry: the signal is the array chosen
 *    with SetInputArrayToProcess(0, ...) (default: active point scalars; a
 *    cell-data array uses the cell grid), one component, read as counts (the
 *    sampler's uint8 mask counts one point per set voxel);
 * 3. otherwise GridDimensions points (default 64^3) spread evenly over the
 *    union of the bounds of all such realizations, or over GridBounds when
 *    UseGridBounds is on; the first and last grid points lie on the bounds.
 * With UseInputGrid off, rule 3 applies to every realization (an image then
 * contributes its point or cell centers weighted by the array values). With
 * UseInputGrid on, a point set that falls to rule 3 (it carries no sampling
 * grid: any point set not made by the sampler) gives a warning, once per
 * execution, naming the grid assumed (origin, spacing, extent): the spectrum
 * describes blue noise only for points drawn on that grid.
 * Points go to the nearest grid point (voxel center); points outside the grid
 * are dropped with a warning giving their number.
 *
 * Output port 0, vtkTable, one row per radial shell 1 .. nmax: `Frequency`
 * (cycles per voxel), `RadialPower`, `Anisotropy`, `AnisotropyDB` (floored at
 * -300 dB), `SRAPS_XY`, `SRAPS_XZ`, `SRAPS_YZ` (vtkDoubleArray) and
 * `ShellCount` (vtkIdTypeArray, full-spectrum sample count), and
 * `PrincipalFrequencyMarker`: RadialPower at the shell nearest the principal
 * frequency f_g, NaN elsewhere (a chart marks f_g with it). Field data:
 * one-tuple vtkDoubleArrays `NumberOfPoints` (mean over realizations),
 * `Density`, `PrincipalFrequency`, `LowFrequencyRatio`, `SymmetryCorrelation`,
 * `Symmetry`, `TargetValue`, vtkIntArrays `Realizations` (1 tuple) and
 * `GridDimensions` (3 components), and the vtkStringArray `SpectrumGrid`: the
 * first realization's grid in words (which rule gave it, origin, spacing,
 * extent), shown in ParaView's Information tab.
 *
 * Output port 1, vtkImageData (when GenerateSpectrumImage is on): the averaged
 * power spectrum P(f) = |B(f)|^2 / N as the point array `Power` (double), zero
 * frequency centered: spacing 1/Lx, 1/Ly, 1/Lz, origin -floor(L/2)/L per axis,
 * so point coordinates are frequencies in cycles per voxel and (0, 0, 0) is the
 * point of index floor(L/2) on every axis; the DC value is 0.
 *
 * Errors (vtkErrorMacro, both outputs empty): no realization, a realization
 * without points or with N = 0 inside the grid, no or a multi-component array,
 * an input grid with a dimension below 2, realizations of different grid
 * shapes, negative or non-finite counts, malformed SamplingGrid field data, a
 * singular direction matrix, a grid of more than MaximumNumberOfGridPoints
 * points, memory that cannot be allocated (std::bad_alloc is caught). The
 * execution still succeeds, with the empty outputs: a failed one would stop
 * the pipeline before what shows the table (ParaView's chart), which would go
 * on showing the last good spectrum. A mask
 * with every voxel set (g = 1) has no power off DC: a warning, and L = 0,
 * anisotropy 0, S = 1 by convention.
 *
 * Pipeline: the whole spectrum needs every realization in full, so the filter
 * asks for the whole extent and piece 0 of 1 of its inputs (each process of a
 * parallel run computes the full metric of what it is given; vtkPBlueNoiseSpectrum
 * computes it once from the pieces of all processes). One update executes the
 * filter once for both outputs. The spectrum image's whole extent is announced
 * in RequestInformation from what the input's information tells: an image's
 * extent, the sampled image's extent that vtkErrorDiffusionSampler's output
 * information carries, or GridDimensions with UseInputGrid off; an empty extent
 * when GenerateSpectrumImage is off. A point set whose information carries no
 * extent may still hold the sampler's grid in its field data, which only the
 * data tells: then the whole extent is announced empty and set by RequestData,
 * so that no consumer can ask for an extent the data will not have. (A point
 * set whose information carries an extent but whose data has no sampling grid
 * uses GridDimensions, which differs from what was announced; a consumer that
 * asks for the announced extent then executes the filter again.)
 *
 * Memory, at its peak during an execution: the kernel's buffers
 * (vtkBlueNoiseSpectrumKernel::BufferBytes: about 8 bytes per grid point for
 * one realization, 12 for several), 16 bytes per binned point (28 for
 * weighted image centers), and 8 bytes per grid point for the spectrum
 * image (TestBlueNoiseSpectrumMemory measures it). A grid whose buffers
 * exceed the memory the system has available (MemAvailable, on Linux) is an
 * error that names the grid, before anything is allocated; the kernel's
 * buffers are freed when the execution ends.
 *
 * @sa vtkBlueNoiseSpectrumKernel vtkErrorDiffusionSampler
 */
#ifndef vtkBlueNoiseSpectrum_h
#define vtkBlueNoiseSpectrum_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkTableAlgorithm.h"

#include <cstddef> // for std::size_t
#include <iosfwd>  // for std::ostringstream
#include <vector>  // for the hooks of distributed subclasses

class vtkBlueNoiseSpectrumKernel;
class vtkImageData;

class VTKFILTERSBLUENOISE_EXPORT vtkBlueNoiseSpectrum : public vtkTableAlgorithm
{
public:
  static vtkBlueNoiseSpectrum* New();
  vtkTypeMacro(vtkBlueNoiseSpectrum, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Weight w of the low-frequency ratio in T = w L + (1 - w) S, in [0, 1].
   * Default 0.02.
   */
  vtkSetClampMacro(Weight, double, 0.0, 1.0);
  vtkGetMacro(Weight, double);
  ///@}

  ///@{
  /**
   * Use the grid the input carries (sampler field data, or an image's own
   * grid) when there is one. Off forces GridDimensions for every
   * realization. Default on.
   */
  vtkSetMacro(UseInputGrid, bool);
  vtkGetMacro(UseInputGrid, bool);
  vtkBooleanMacro(UseInputGrid, bool);
  ///@}

  ///@{
  /**
   * Number of grid points (Lx, Ly, Lz) of the analysis grid built over the
   * bounds when the input carries no grid (or UseInputGrid is off). Each is
   * clamped to at least 2 (as ParaView's domain does). Default 64 64 64.
   */
  virtual void SetGridDimensions(int lx, int ly, int lz);
  void SetGridDimensions(const int dims[3])
  {
    this->SetGridDimensions(dims[0], dims[1], dims[2]);
  }
  vtkGetVector3Macro(GridDimensions, int);
  ///@}

  ///@{
  /**
   * Bounds (xmin, xmax, ymin, ymax, zmin, zmax) of that grid, used instead of
   * the data bounds when UseGridBounds is on. Default off, (0, 1, 0, 1, 0, 1).
   */
  vtkSetVector6Macro(GridBounds, double);
  vtkGetVector6Macro(GridBounds, double);
  vtkSetMacro(UseGridBounds, bool);
  vtkGetMacro(UseGridBounds, bool);
  vtkBooleanMacro(UseGridBounds, bool);
  ///@}

  ///@{
  /**
   * The largest analysis grid, in grid points (Lx Ly Lz), that the filter
   * transforms: a larger one, whichever rule gave it, is an error before
   * anything is allocated. Memory grows by about 8 bytes a grid point (see
   * Memory above), and a point set's field data may declare any extent up to
   * 2^30 a side. Default 1024^3 (2^30: about 8.6 GB for the transform); at
   * least 8.
   */
  vtkSetClampMacro(MaximumNumberOfGridPoints, vtkIdType, 8, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfGridPoints, vtkIdType);
  ///@}

  ///@{
  /**
   * Produce the centered power spectrum image on output port 1. Default on.
   */
  vtkSetMacro(GenerateSpectrumImage, bool);
  vtkGetMacro(GenerateSpectrumImage, bool);
  vtkBooleanMacro(GenerateSpectrumImage, bool);
  ///@}

  /// Output port 1: the centered power spectrum.
  vtkImageData* GetSpectrumImageOutput();

  /// Add one more realization (a new connection on the repeatable input port).
  void AddInputData(vtkDataObject* input) { this->AddInputDataObject(0, input); }

  /**
   * The number of realizations this process transformed in its last
   * execution: all of them in a serial run, none on the processes of a
   * distributed run (vtkPBlueNoiseSpectrum) that only contribute samples.
   */
  vtkGetMacro(NumberOfTransformedRealizations, int);

protected:
  vtkBlueNoiseSpectrum();
  ~vtkBlueNoiseSpectrum() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  ///@{
  /**
   * Where the work happens, for distributed subclasses (vtkPBlueNoiseSpectrum).
   * The serial filter computes everything from what its own process holds.
   * - IsRootProcess(): whether this process transforms the realizations,
   *   computes the metric and fills the outputs (the others leave them empty).
   * - IsDistributed(): whether the pieces of one realization may lie on other
   *   processes (image pieces are then sent voxel by voxel, each voxel once).
   * - ShareDescriptions(records): `records` holds this process's grid
   *   descriptions (vtkBlueNoiseSpectrumGrid::Description::Pack); on return it
   *   holds those of every process, in the same order on every process.
   * - GatherSamples(voxels, values, counters): one realization's binned samples
   *   of this process (values empty: one point each) and its counters (samples
   *   outside the grid, samples binned); on return, on the root process, those
   *   of every process in process order, the counters summed.
   * - AllSucceeded(ok): true when every process succeeded; each process
   *   reports its own errors.
   * - IsAborted(): the abort flag, the same on every process.
   */
  virtual bool IsRootProcess() { return true; }
  virtual bool IsDistributed() { return false; }
  virtual bool ShareDescriptions(std::vector<double>& records);
  virtual bool GatherSamples(
    std::vector<long long>& voxels, std::vector<double>& values, long long counters[2]);
  virtual bool AllSucceeded(bool ok) { return ok; }
  virtual bool IsAborted();
  ///@}

  /**
   * Both outputs come from one execution: the piece asked for on one output
   * becomes the request of the other too, so that the executive records one
   * request for both and a later request of the other output finds it met.
   */
  static void ShareOutputRequest(vtkInformation* request, vtkInformationVector* outputVector);

  double Weight = 0.02;
  bool UseInputGrid = true;
  int GridDimensions[3] = { 64, 64, 64 };
  double GridBounds[6] = { 0.0, 1.0, 0.0, 1.0, 0.0, 1.0 };
  bool UseGridBounds = false;
  bool GenerateSpectrumImage = true;
  vtkIdType MaximumNumberOfGridPoints = vtkIdType(1) << 30;
  int NumberOfTransformedRealizations = 0;

private:
  vtkBlueNoiseSpectrum(const vtkBlueNoiseSpectrum&) = delete;
  void operator=(const vtkBlueNoiseSpectrum&) = delete;

  struct Realization; // one realization: this process's piece and the whole's grid

  // The steps of RequestData.
  bool ValidateInputs(vtkInformationVector** inputVector, std::vector<Realization>& pieces);
  bool DescribePiece(Realization& piece, int index);
  bool CombinePieces(std::vector<Realization>& pieces, std::vector<Realization>& realizations);
  bool BuildGrids(std::vector<Realization>& realizations);
  bool ChooseGrid(Realization& r, std::size_t i, double bounds[6], std::ostringstream& error);
  void GridsOverBounds(
    std::vector<Realization>& realizations, const double bounds[6], std::ostringstream& error);
  int Accumulate(const std::vector<Realization>& realizations, vtkBlueNoiseSpectrumKernel& kernel);
  bool AddRealization(const Realization& realization, int index, vtkBlueNoiseSpectrumKernel& kernel,
    long long counters[2]);
  bool AnnouncedDimensions(vtkInformationVector** inputVector, int dims[3]);
};

#endif
