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
 * The kernel keeps the RecentCurves curves it used last (the least recently
 * used out first): a filter that keeps its kernel finds the levels it
 * calibrated when its user goes back to an earlier table or scale, and the
 * calibrations go with the kernel.
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

#include <cstddef>
#include <memory>
#include <vector>

class vtkErrorDiffusionChargeCurve;

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionKernel : public vtkErrorDiffusionScan
{
public:
  vtkErrorDiffusionKernel();
  vtkErrorDiffusionKernel(const vtkErrorDiffusionKernel&) = default;
  vtkErrorDiffusionKernel& operator=(const vtkErrorDiffusionKernel&) = default;
  ~vtkErrorDiffusionKernel() override;

  /// The number of charge curves a kernel keeps.
  static constexpr std::size_t RecentCurves = 8;

protected:
  /// The curve of the current table and scale (shared by the kernels that hold it).
  void PrepareCharges() override;
  float ChargeAt(float minority) const override;

private:
  // The curves used last, the current one first.
  std::vector<std::shared_ptr<vtkErrorDiffusionChargeCurve>> Recent;
};

#endif
