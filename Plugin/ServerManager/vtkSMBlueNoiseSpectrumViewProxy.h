// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSMBlueNoiseSpectrumViewProxy
 * @brief   The Blue Noise Spectrum View: a line chart whose axis ranges stay put.
 *
 * The view of the plugin XML (BlueNoiseSpectrumView) sets fixed axis ranges
 * (frequency, power, anisotropy) so that one run compares with the next at a
 * glance. ParaView resets a chart view's display when data is first shown in
 * it (Apply) and on Reset Camera, which vtkSMContextViewProxy does by turning
 * every custom range off: here the ranges the user has on are kept, and an
 * axis whose Use Custom Range is off follows the data as in any chart.
 */
#ifndef vtkSMBlueNoiseSpectrumViewProxy_h
#define vtkSMBlueNoiseSpectrumViewProxy_h

#include "vtkSMContextViewProxy.h"
#include "vtkRemotingBlueNoiseModule.h" // for export macro

class VTKREMOTINGBLUENOISE_EXPORT vtkSMBlueNoiseSpectrumViewProxy : public vtkSMContextViewProxy
{
public:
  static vtkSMBlueNoiseSpectrumViewProxy* New();
  vtkTypeMacro(vtkSMBlueNoiseSpectrumViewProxy, vtkSMContextViewProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Keeps the axes' custom ranges (see the class comment).
  void ResetDisplay() override;

protected:
  vtkSMBlueNoiseSpectrumViewProxy() = default;
  ~vtkSMBlueNoiseSpectrumViewProxy() override = default;

private:
  vtkSMBlueNoiseSpectrumViewProxy(const vtkSMBlueNoiseSpectrumViewProxy&) = delete;
  void operator=(const vtkSMBlueNoiseSpectrumViewProxy&) = delete;
};

#endif
