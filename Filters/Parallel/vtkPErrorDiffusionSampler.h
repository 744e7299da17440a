// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPErrorDiffusionSampler
 * @brief   vtkErrorDiffusionSampler for distributed runs (MPI).
 *
 * Each process samples its piece, a z-slab of full layers (see
 * vtkErrorDiffusionSampler), after scanning up to OverlapLayers layers above
 * it from the data, so the error pattern it enters with is settled and the
 * seam between two pieces does not show. What must be global is reduced over
 * the processes of the controller: the statistics of the values (the finite
 * range of the ScalarRange mapping and the point budget), so a value maps to
 * the same density in every piece and the pieces' counts add up to
 * NumberOfPoints. Each process reads only its piece (and the overlap).
 *
 * Every process of the controller must execute the filter for the same
 * request (a piece with no layers takes part in the reductions and gives an
 * empty output). Without a controller, or with one process, this is
 * vtkErrorDiffusionSampler.
 *
 * @sa vtkErrorDiffusionSampler vtkPBlueNoiseSpectrum
 */
#ifndef vtkPErrorDiffusionSampler_h
#define vtkPErrorDiffusionSampler_h

#include "vtkErrorDiffusionSampler.h"
#include "vtkFiltersBlueNoiseModule.h" // for export macro

class vtkMultiProcessController;

class VTKFILTERSBLUENOISE_EXPORT vtkPErrorDiffusionSampler : public vtkErrorDiffusionSampler
{
public:
  static vtkPErrorDiffusionSampler* New();
  vtkTypeMacro(vtkPErrorDiffusionSampler, vtkErrorDiffusionSampler);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The processes the statistics are reduced over. Default: the global
   * controller.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkPErrorDiffusionSampler();
  ~vtkPErrorDiffusionSampler() override;

  void GetStatisticsLayers(
    const int whole[6], int piece, int pieces, int& first, int& last) override;
  bool ReduceStatistics(vtkSamplingBudget& statistics) override;

  vtkMultiProcessController* Controller = nullptr;

private:
  vtkPErrorDiffusionSampler(const vtkPErrorDiffusionSampler&) = delete;
  void operator=(const vtkPErrorDiffusionSampler&) = delete;

  bool Distributed() const;
};

#endif
