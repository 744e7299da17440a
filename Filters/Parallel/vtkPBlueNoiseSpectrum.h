// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPBlueNoiseSpectrum
 * @brief   vtkBlueNoiseSpectrum of a distributed data set, computed once.
 *
 * Under MPI (pvbatch, pvserver) each process asks its inputs for its own
 * piece, the piece of its rank among as many pieces as processes, whatever
 * piece the request from downstream names: structured sources then split
 * the whole extent and vtkErrorDiffusionSampler samples one piece per
 * process. What the pieces tell about their grids is combined on every
 * process, so every process builds the same analysis grid (the rules of
 * vtkBlueNoiseSpectrum applied to the whole): the union of the pieces'
 * SamplingGridExtent, which must share origin, spacing and direction; the
 * union of an image's piece extents; the union of the bounds. Points carry
 * world coordinates and are binned where they are; the voxel indices (8
 * bytes a point, 8 more with weights) and the non-zero values of image
 * pieces (each voxel from one piece: a piece leaves the face it shares with
 * the next piece to that one) are gathered on process 0 in process order,
 * which alone transforms, computes the metric and fills both outputs.
 *
 * The outputs of the other processes are empty (a table without columns, an
 * empty image): a table on every process would be appended once per process
 * when ParaView delivers it to the client. Both outputs announce the same
 * information on every process, and one update executes the filter once on
 * every process (see vtkBlueNoiseSpectrum).
 *
 * The metric is that of vtkBlueNoiseSpectrum on the data of all pieces
 * appended in process order: the same to the last bit for point sets and
 * images read as counts; for an image's weighted point centers (UseInputGrid
 * off) up to the rounding of the single-precision sums on voxels that gather
 * centers from several pieces.
 *
 * Composite inputs: leaves are matched across processes by their flat index.
 * Every process must execute the filter (it communicates), and an abort
 * request on one process stops all of them.
 *
 * @sa vtkBlueNoiseSpectrum vtkErrorDiffusionSampler
 */
#ifndef vtkPBlueNoiseSpectrum_h
#define vtkPBlueNoiseSpectrum_h

#include "vtkBlueNoiseSpectrum.h"
#include "vtkFiltersBlueNoiseModule.h" // for export macro

class vtkMultiProcessController;

class VTKFILTERSBLUENOISE_EXPORT vtkPBlueNoiseSpectrum : public vtkBlueNoiseSpectrum
{
public:
  static vtkPBlueNoiseSpectrum* New();
  vtkTypeMacro(vtkPBlueNoiseSpectrum, vtkBlueNoiseSpectrum);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes the data is distributed over. Default: the global
   * controller. With none, or a single process, this is vtkBlueNoiseSpectrum.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkPBlueNoiseSpectrum();
  ~vtkPBlueNoiseSpectrum() override;

  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool IsRootProcess() override;
  bool IsDistributed() override;
  bool ShareDescriptions(std::vector<double>& records) override;
  bool GatherSamples(
    std::vector<long long>& voxels, std::vector<double>& values, long long counters[2]) override;
  bool AllSucceeded(bool ok) override;
  bool IsAborted() override;

  vtkMultiProcessController* Controller = nullptr;

private:
  vtkPBlueNoiseSpectrum(const vtkPBlueNoiseSpectrum&) = delete;
  void operator=(const vtkPBlueNoiseSpectrum&) = delete;
};

#endif
