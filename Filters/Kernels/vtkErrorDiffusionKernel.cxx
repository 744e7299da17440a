// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionKernel.h"

#include "vtkErrorDiffusionChargeCurve.h"

#include <algorithm>
#include <utility>

//------------------------------------------------------------------------------
vtkErrorDiffusionKernel::vtkErrorDiffusionKernel() = default;

//------------------------------------------------------------------------------
vtkErrorDiffusionKernel::~vtkErrorDiffusionKernel() = default;

//------------------------------------------------------------------------------
void vtkErrorDiffusionKernel::PrepareCharges()
{
  auto curve = vtkErrorDiffusionChargeCurve::Get(this->GetParameters(), this->GetModulationScale());
  auto& recent = this->Recent;
  recent.erase(std::remove(recent.begin(), recent.end(), curve), recent.end());
  recent.insert(recent.begin(), std::move(curve));
  if (recent.size() > RecentCurves)
  {
    recent.pop_back();
  }
}

//------------------------------------------------------------------------------
float vtkErrorDiffusionKernel::ChargeAt(float minority) const
{
  return this->Recent.empty() ? 0.0f : this->Recent.front()->At(minority);
}
