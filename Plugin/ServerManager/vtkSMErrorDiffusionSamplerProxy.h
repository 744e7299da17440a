// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSMErrorDiffusionSamplerProxy
 * @brief   The sampler's proxy: Density Mapping = Color Map Opacity samples where the data is seen.
 *
 * With DensityMapping set to vtkErrorDiffusionSampler::DENSITY_COLOR_MAP_OPACITY,
 * the proxy's TransferFunction is, at every push of its properties (Apply,
 * or a property set from Python), the opacity function of the colour map of
 * the array selected in Scalars: the function a user edits in the Color Map
 * Editor and volume-renders with (vtkSMTransferFunctionManager makes it if
 * the array has none yet). Editing it modifies the function the sampler
 * holds, so the samples follow at the next update. Other mappings leave
 * TransferFunction alone.
 */
#ifndef vtkSMErrorDiffusionSamplerProxy_h
#define vtkSMErrorDiffusionSamplerProxy_h

#include "vtkRemotingBlueNoiseModule.h" // for export macro
#include "vtkSMSourceProxy.h"

class VTKREMOTINGBLUENOISE_EXPORT vtkSMErrorDiffusionSamplerProxy : public vtkSMSourceProxy
{
public:
  static vtkSMErrorDiffusionSamplerProxy* New();
  vtkTypeMacro(vtkSMErrorDiffusionSamplerProxy, vtkSMSourceProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Links TransferFunction to the colour map's opacity first (see the class comment).
  void UpdateVTKObjects() override;

protected:
  vtkSMErrorDiffusionSamplerProxy() = default;
  ~vtkSMErrorDiffusionSamplerProxy() override = default;

private:
  vtkSMErrorDiffusionSamplerProxy(const vtkSMErrorDiffusionSamplerProxy&) = delete;
  void operator=(const vtkSMErrorDiffusionSamplerProxy&) = delete;

  void LinkColorMapOpacity();
};

#endif
