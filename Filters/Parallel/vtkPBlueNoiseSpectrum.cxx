// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPBlueNoiseSpectrum.h"

#include "vtkCommunicator.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <numeric>

vtkStandardNewMacro(vtkPBlueNoiseSpectrum);
vtkCxxSetObjectMacro(vtkPBlueNoiseSpectrum, Controller, vtkMultiProcessController);

namespace
{
// Every process's buffer (lengths gathered first) on `root`, or on every
// process when `root` is negative, in process order.
template <typename T>
bool GatherAll(vtkMultiProcessController* controller, std::vector<T>& buffer, int root)
{
  const int processes = controller->GetNumberOfProcesses();
  const long long length = static_cast<long long>(buffer.size());
  std::vector<long long> lengths(static_cast<std::size_t>(processes), 0);
  const int gathered = root < 0 ? controller->AllGather(&length, lengths.data(), 1)
                                : controller->Gather(&length, lengths.data(), 1, root);
  if (!gathered)
  {
    return false;
  }
  std::vector<vtkIdType> counts(lengths.begin(), lengths.end());
  std::vector<vtkIdType> offsets(counts.size(), 0);
  std::partial_sum(counts.begin(), counts.end() - 1, offsets.begin() + 1);
  const bool receives = root < 0 || controller->GetLocalProcessId() == root;
  std::vector<T> all(receives ? static_cast<std::size_t>(offsets.back() + counts.back()) : 0);
  const int done = root < 0
    ? controller->AllGatherV(buffer.data(), all.data(), length, counts.data(), offsets.data())
    : controller->GatherV(buffer.data(), all.data(), length, counts.data(), offsets.data(), root);
  buffer.swap(all);
  return done != 0;
}
}

//------------------------------------------------------------------------------
vtkPBlueNoiseSpectrum::vtkPBlueNoiseSpectrum()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkPBlueNoiseSpectrum::~vtkPBlueNoiseSpectrum()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
bool vtkPBlueNoiseSpectrum::IsDistributed()
{
  return this->Controller && this->Controller->GetNumberOfProcesses() > 1;
}

//------------------------------------------------------------------------------
bool vtkPBlueNoiseSpectrum::IsRootProcess()
{
  return !this->IsDistributed() || this->Controller->GetLocalProcessId() == 0;
}

//------------------------------------------------------------------------------
int vtkPBlueNoiseSpectrum::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->IsDistributed())
  {
    return this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  }
  ShareOutputRequest(request, outputVector);
  // This process's piece of the whole extent.
  using SDDP = vtkStreamingDemandDrivenPipeline;
  for (int c = 0; c < inputVector[0]->GetNumberOfInformationObjects(); ++c)
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(c);
    if (inInfo->Has(SDDP::WHOLE_EXTENT()))
    {
      inInfo->Set(SDDP::UPDATE_EXTENT(), inInfo->Get(SDDP::WHOLE_EXTENT()), 6);
    }
    inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), this->Controller->GetLocalProcessId());
    inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), this->Controller->GetNumberOfProcesses());
    inInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkPBlueNoiseSpectrum::ShareDescriptions(std::vector<double>& records)
{
  return !this->IsDistributed() || GatherAll(this->Controller, records, -1);
}

//------------------------------------------------------------------------------
bool vtkPBlueNoiseSpectrum::GatherSamples(
  std::vector<long long>& voxels, std::vector<double>& values, long long counters[2])
{
  if (!this->IsDistributed())
  {
    return true;
  }
  long long sums[2] = { 0, 0 };
  const bool ok = GatherAll(this->Controller, voxels, 0) &&
    GatherAll(this->Controller, values, 0) &&
    this->Controller->Reduce(counters, sums, 2, vtkCommunicator::SUM_OP, 0);
  std::copy(sums, sums + 2, counters);
  return ok;
}

//------------------------------------------------------------------------------
bool vtkPBlueNoiseSpectrum::AllSucceeded(bool ok)
{
  if (!this->IsDistributed())
  {
    return ok;
  }
  const int local = ok ? 1 : 0;
  int all = 0;
  this->Controller->AllReduce(&local, &all, 1, vtkCommunicator::MIN_OP);
  return all == 1;
}

//------------------------------------------------------------------------------
bool vtkPBlueNoiseSpectrum::IsAborted()
{
  const bool aborted = this->Superclass::IsAborted();
  return this->IsDistributed() ? !this->AllSucceeded(!aborted) : aborted;
}

//------------------------------------------------------------------------------
void vtkPBlueNoiseSpectrum::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
}
