// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPErrorDiffusionSampler.h"

#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkSamplingBudget.h"

#include <vector>

vtkStandardNewMacro(vtkPErrorDiffusionSampler);
vtkCxxSetObjectMacro(vtkPErrorDiffusionSampler, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
vtkPErrorDiffusionSampler::vtkPErrorDiffusionSampler()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkPErrorDiffusionSampler::~vtkPErrorDiffusionSampler()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
bool vtkPErrorDiffusionSampler::Distributed() const
{
  return this->Controller && this->Controller->GetNumberOfProcesses() > 1;
}

//------------------------------------------------------------------------------
// Each process counts the values of its own piece; ReduceStatistics adds them.
void vtkPErrorDiffusionSampler::GetStatisticsLayers(
  const int whole[6], int piece, int pieces, int& first, int& last)
{
  if (!this->Distributed() || pieces <= 1)
  {
    this->Superclass::GetStatisticsLayers(whole, piece, pieces, first, last);
    return;
  }
  const long long layers = static_cast<long long>(whole[5]) - whole[4] + 1;
  first = whole[4] + static_cast<int>(layers * piece / pieces);
  last = whole[4] + static_cast<int>(layers * (piece + 1) / pieces) - 1;
}

//------------------------------------------------------------------------------
// Every process gathers every histogram and merges them in rank order, so all
// get the same statistics, bit for bit.
bool vtkPErrorDiffusionSampler::ReduceStatistics(vtkSamplingBudget& statistics)
{
  if (!this->Distributed())
  {
    return true;
  }
  const std::vector<double> mine = statistics.Serialize();
  const int processes = this->Controller->GetNumberOfProcesses();
  std::vector<double> all(mine.size() * static_cast<size_t>(processes));
  if (!this->Controller->AllGather(mine.data(), all.data(), static_cast<vtkIdType>(mine.size())))
  {
    vtkErrorMacro("Cannot gather the statistics of the pieces.");
    return false;
  }
  statistics.Reset();
  for (int p = 0; p < processes; ++p)
  {
    vtkSamplingBudget piece;
    piece.Deserialize(std::vector<double>(all.begin() + p * mine.size(),
      all.begin() + (p + 1) * mine.size()));
    statistics.Merge(piece);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPErrorDiffusionSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
}
