// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMErrorDiffusionSamplerProxy.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMTransferFunctionManager.h"

#include <string>

vtkStandardNewMacro(vtkSMErrorDiffusionSamplerProxy);

namespace
{
// vtkErrorDiffusionSampler::DENSITY_COLOR_MAP_OPACITY (the filters' module is
// not a dependency of this one: the value is part of the plugin XML's enumeration).
constexpr int ColorMapOpacity = 3;
}

//------------------------------------------------------------------------------
void vtkSMErrorDiffusionSamplerProxy::UpdateVTKObjects()
{
  this->LinkColorMapOpacity();
  this->Superclass::UpdateVTKObjects();
}

//------------------------------------------------------------------------------
void vtkSMErrorDiffusionSamplerProxy::LinkColorMapOpacity()
{
  if (!this->GetProperty("DensityMapping") || !this->GetProperty("TransferFunction") ||
    !this->GetProperty("Scalars") ||
    vtkSMPropertyHelper(this, "DensityMapping").GetAsInt() != ColorMapOpacity)
  {
    return;
  }
  // Scalars holds (port, connection, field association, attribute type, name).
  const char* name = vtkSMPropertyHelper(this, "Scalars").GetAsString(4);
  vtkSMSessionProxyManager* pxm = this->GetSessionProxyManager();
  if (!name || std::string(name).empty() || !pxm)
  {
    return; // no array yet: the filter ramps over the range until there is one
  }
  vtkNew<vtkSMTransferFunctionManager> manager;
  vtkSMProxy* opacity = manager->GetOpacityTransferFunction(name, pxm);
  vtkSMPropertyHelper transfer(this, "TransferFunction");
  if (opacity && transfer.GetAsProxy() != opacity)
  {
    transfer.Set(opacity);
  }
}

//------------------------------------------------------------------------------
void vtkSMErrorDiffusionSamplerProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
