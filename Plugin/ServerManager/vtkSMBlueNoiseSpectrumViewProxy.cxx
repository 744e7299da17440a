// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMBlueNoiseSpectrumViewProxy.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSMBlueNoiseSpectrumViewProxy);

//------------------------------------------------------------------------------
void vtkSMBlueNoiseSpectrumViewProxy::ResetDisplay()
{
  // The axes without a custom range are recomputed from the data at the next
  // render; those with one keep it.
  this->UpdateVTKObjects();
}

//------------------------------------------------------------------------------
void vtkSMBlueNoiseSpectrumViewProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
