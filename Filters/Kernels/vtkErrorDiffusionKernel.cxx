// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionKernel.h"

#include "vtkErrorDiffusionChargeCurve.h"

//------------------------------------------------------------------------------
vtkErrorDiffusionKernel::vtkErrorDiffusionKernel() = default;

//------------------------------------------------------------------------------
vtkErrorDiffusionKernel::~vtkErrorDiffusionKernel() = default;

//------------------------------------------------------------------------------
void vtkErrorDiffusionKernel::PrepareCharges()
{
  this->Charges = vtkErrorDiffusionChargeCurve::Get(this->GetParameters(), this->GetModulationScale());
}

//------------------------------------------------------------------------------
float vtkErrorDiffusionKernel::ChargeAt(float minority) const
{
  return this->Charges ? this->Charges->At(minority) : 0.0f;
}
