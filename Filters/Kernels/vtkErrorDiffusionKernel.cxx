// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionKernel.h"

#include "vtkErrorDiffusionChargeCurve.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkErrorDiffusionKernel::vtkErrorDiffusionKernel() = default;

//------------------------------------------------------------------------------
vtkErrorDiffusionKernel::~vtkErrorDiffusionKernel() = default;

//------------------------------------------------------------------------------
void vtkErrorDiffusionKernel::PrepareCharges()
{
  this->Charges = vtkErrorDiffusionChargeCurve::Get(this->GetParameters(), this->GetModulationScale());
  auto& recent = this->Recent;
  recent.erase(std::remove(recent.begin(), recent.end(), this->Charges), recent.end());
  recent.insert(recent.begin(), this->Charges);
  if (recent.size() > RecentCurves)
  {
    recent.pop_back();
  }
}

//------------------------------------------------------------------------------
float vtkErrorDiffusionKernel::ChargeAt(float minority) const
{
  return this->Charges ? this->Charges->At(minority) : 0.0f;
}
