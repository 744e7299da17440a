// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionKernel
 * @brief   The sampler's 3D error diffusion: vtkErrorDiffusionScan with the
 *          charge its process settles at.
 *
 * The threshold of the scan is lowered by C(g), the steady-state charge of
 * the paper's process at density g (vtkErrorDiffusionChargeCurve, calibrated
 * for the kernel's parameter table and modulation scale when a run begins and
 * a density first needs it). See vtkErrorDiffusionScan for the algorithm and
 * the interface.
 *
 * The dependencies go one way: the charge curve calibrates itself with a
 * plain vtkErrorDiffusionScan, and this class asks the curve.
 *
 * @sa vtkErrorDiffusionScan vtkErrorDiffusionChargeCurve
 */
#ifndef vtkErrorDiffusionKernel_h
#define vtkErrorDiffusionKernel_h

#include "vtkErrorDiffusionScan.h"
#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <memory>

class vtkErrorDiffusionChargeCurve;

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionKernel : public vtkErrorDiffusionScan
{
public:
  vtkErrorDiffusionKernel();
  vtkErrorDiffusionKernel(const vtkErrorDiffusionKernel&) = default;
  vtkErrorDiffusionKernel& operator=(const vtkErrorDiffusionKernel&) = default;
  ~vtkErrorDiffusionKernel() override;

protected:
  /// The curve of the current table and scale (shared by the process's kernels).
  void PrepareCharges() override;
  float ChargeAt(float minority) const override;

private:
  std::shared_ptr<vtkErrorDiffusionChargeCurve> Charges;
};

#endif
