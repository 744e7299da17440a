// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Streaming: with NumberOfSlabs > 1 the sampler asks its input for z-slabs,
// one after the other (the statistics of the point budget first, then the
// sampling), never for the whole extent, and its output is bit for bit the
// output of one request for the whole volume. One Update fires one StartEvent.
// A streamed run whose input fails between slabs leaves no plan behind: the
// next update, of a smaller volume, asks only for that volume's layers.
#include "SamplerTestUtilities.h"
#include "vtkBlueNoiseRelaxation.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageAlgorithm.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRTAnalyticSource.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

using namespace bluenoise_test;

namespace
{
struct Watch
{
  int Executions = 0;
  int LargestLayers = 0; // the most layers one execution produced
};

void OnSourceEnd(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* watch = static_cast<Watch*>(clientData);
  auto* source = vtkRTAnalyticSource::SafeDownCast(caller);
  int extent[6];
  vtkImageData::SafeDownCast(source->GetOutputDataObject(0))->GetExtent(extent);
  ++watch->Executions;
  watch->LargestLayers = std::max(watch->LargestLayers, extent[5] - extent[4] + 1);
}

void OnStart(vtkObject*, unsigned long, void* clientData, void*)
{
  ++*static_cast<int*>(clientData);
}

// Passes its input through, but drops the arrays of a request that starts
// above layer FailAbove (bad input in the middle of a streamed volume).
class FailingPass : public vtkImageAlgorithm
{
public:
  static FailingPass* New();
  vtkTypeMacro(FailingPass, vtkImageAlgorithm);
  int FailAbove = VTK_INT_MAX;
  std::vector<std::array<int, 6>> Requests;

protected:
  int RequestData(vtkInformation*, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override
  {
    vtkImageData* input = vtkImageData::GetData(inputVector[0]);
    vtkImageData* output = vtkImageData::GetData(outputVector);
    std::array<int, 6> extent;
    input->GetExtent(extent.data());
    this->Requests.push_back(extent);
    output->ShallowCopy(input);
    if (extent[4] > this->FailAbove)
    {
      // Failing here would hang VTK 9.2's executive (it repeats a failed
      // continuation forever): the slab comes without its array instead.
      output->GetPointData()->Initialize();
    }
    return 1;
  }
};
vtkStandardNewMacro(FailingPass);

void StalePlan()
{
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(0, 15, 0, 15, 0, 31);
  vtkNew<FailingPass> pass;
  pass->SetInputConnection(source->GetOutputPort());
  pass->FailAbove = 0; // the second slab fails
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputConnection(pass->GetOutputPort());
  sampler->SetNumberOfSlabs(4);
  sampler->SetNumberOfPoints(500);
  vtkNew<MessageObserver> messages;
  for (vtkObject* o : { static_cast<vtkObject*>(sampler), static_cast<vtkObject*>(pass),
         static_cast<vtkObject*>(sampler->GetExecutive()),
         static_cast<vtkObject*>(pass->GetExecutive()) })
  {
    messages->Watch(o);
  }
  sampler->Update();
  Check(messages->ErrorContains("No density array"), "the bad slab is reported: '" + messages->Errors + "'");
  Check(sampler->GetOutput()->GetNumberOfPoints() == 0, "the failed run has an empty output");

  messages->Clear();
  pass->FailAbove = VTK_INT_MAX;
  pass->Modified();
  pass->Requests.clear();
  source->SetWholeExtent(0, 15, 0, 15, 0, 11);
  sampler->Update();
  bool inside = !pass->Requests.empty();
  for (const auto& e : pass->Requests)
  {
    inside = inside && e[4] >= 0 && e[5] <= 11 && e[4] <= e[5];
  }
  Check(inside, "after the failed run, every request lies in the new volume's layers 0-11 (" +
      Str(pass->Requests.size()) + " requests, the first from layer " +
      Str(pass->Requests.empty() ? -1 : pass->Requests.front()[4]) + ")");
  Check(messages->ErrorCount == 0, "the next update has no error: '" + messages->Errors + "'");
  const vtkIdType n = sampler->GetOutput()->GetNumberOfPoints();
  Check(n >= 495 && n <= 505, "the next update samples the new volume: " + Str(n) + " points");
}

bool SameArray(vtkDataArray* a, vtkDataArray* b)
{
  return a && b && a->GetNumberOfValues() == b->GetNumberOfValues() &&
    a->GetDataType() == b->GetDataType() &&
    std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0),
      static_cast<size_t>(a->GetNumberOfValues()) * a->GetDataTypeSize()) == 0;
}

struct Run
{
  vtkSmartPointer<vtkPolyData> Points;
  vtkSmartPointer<vtkImageData> Mask;
  Watch Source;
  int Starts = 0;
};

Run Sample(int slabs, bool budget)
{
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(0, 47, 0, 39, 0, 63);
  Run run;
  vtkNew<vtkCallbackCommand> end;
  end->SetCallback(OnSourceEnd);
  end->SetClientData(&run.Source);
  source->AddObserver(vtkCommand::EndEvent, end);
  vtkNew<vtkErrorDiffusionSampler> sampler;
  vtkNew<vtkCallbackCommand> start;
  start->SetCallback(OnStart);
  start->SetClientData(&run.Starts);
  sampler->AddObserver(vtkCommand::StartEvent, start);
  sampler->SetInputConnection(source->GetOutputPort());
  sampler->SetNumberOfSlabs(slabs);
  sampler->SetUseNumberOfPoints(budget);
  sampler->SetNumberOfPoints(6000);
  sampler->SetDensityScale(0.2);
  sampler->SetJitter(true);
  sampler->SetSeed(11);
  sampler->GenerateMaskOn();
  sampler->Update();
  run.Points = vtkSmartPointer<vtkPolyData>::New();
  run.Points->DeepCopy(sampler->GetOutput());
  run.Mask = vtkSmartPointer<vtkImageData>::New();
  run.Mask->DeepCopy(sampler->GetMaskOutput());
  return run;
}
}

int main()
{
  for (bool budget : { true, false })
  {
    const std::string what = budget ? "point budget" : "density scale";
    const Run whole = Sample(1, budget);
    const Run slabs = Sample(5, budget);
    const vtkIdType n = whole.Points->GetNumberOfPoints();
    Check(n > 1000, what + ": " + Str(n) + " points");
    Check(slabs.Points->GetNumberOfPoints() == n &&
        SameArray(whole.Points->GetPoints()->GetData(), slabs.Points->GetPoints()->GetData()) &&
        SameArray(whole.Points->GetPointData()->GetArray("Density"),
          slabs.Points->GetPointData()->GetArray("Density")) &&
        SameArray(whole.Points->GetPointData()->GetArray("RTData"),
          slabs.Points->GetPointData()->GetArray("RTData")),
      what + ": 5 slabs give the points of one request, bit for bit");
    Check(SameArray(whole.Mask->GetPointData()->GetScalars(), slabs.Mask->GetPointData()->GetScalars()),
      what + ": and the same mask");
    // The statistics pass reads the volume in slabs as well (the budget, or
    // the range of the default ScalarRange mapping).
    Check(whole.Source.Executions == 1 && slabs.Source.Executions == 10,
      what + ": the source executed " + Str(whole.Source.Executions) + " and " +
        Str(slabs.Source.Executions) + " times (1 and 5 + 5 expected)");
    // A slab, the layer after it, and the layers the relaxation still holds.
    Check(slabs.Source.LargestLayers <= 64 / 5 + 2 + vtkBlueNoiseRelaxation::MaximumRadius + 2,
      what + ": the largest slab had " + Str(slabs.Source.LargestLayers) + " of 64 layers");
    Check(whole.Starts == 1 && slabs.Starts == 1,
      what + ": one StartEvent per Update (" + Str(slabs.Starts) + " when streamed)");
  }
  StalePlan();
  return Summary("TestErrorDiffusionSamplerStreaming");
}
