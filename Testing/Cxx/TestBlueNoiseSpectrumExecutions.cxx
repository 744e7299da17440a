// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// One update, one execution: the spectrum's StartEvent is counted over an
// update of the table port, then of the image port, then of both again, and
// through a consumer of the image port (as ParaView's post filter is), for
// the sampler's points, the points of a data set whose information announces
// no grid (the sampler's field data only), an image, GenerateSpectrumImage
// off, and ParaView's piece requests (piece 0 of 2 on both ports). Any second
// execution fails. The image port's announced whole extent must be the
// extent of the image it gets (empty when it gets none).
#include "TestBlueNoiseSpectrumUtilities.h"

#include "vtkBlueNoiseSpectrum.h"
#include "vtkCallbackCommand.h"
#include "vtkDoubleArray.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPassThrough.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRTAnalyticSource.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

using namespace spectrum_test;

namespace
{
using SDDP = vtkStreamingDemandDrivenPipeline;

void CountExecution(vtkObject*, unsigned long, void* clientData, void*)
{
  ++*static_cast<int*>(clientData);
}

// Updates one output port the way ParaView's UpdatePipeline does: the piece
// request set on the port, then the executive's Update(port).
void UpdatePiece(vtkAlgorithm* algorithm, int port, int piece, int pieces)
{
  auto sddp = SDDP::SafeDownCast(algorithm->GetExecutive());
  sddp->UpdateInformation();
  vtkInformation* outInfo = sddp->GetOutputInformation(port);
  outInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), piece);
  outInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), pieces);
  outInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  sddp->Update(port);
}

// The image port's whole extent against the image it holds.
void CheckAnnounced(vtkBlueNoiseSpectrum* filter, const std::string& what)
{
  int whole[6] = { 0, -1, 0, -1, 0, -1 };
  filter->GetOutputInformation(1)->Get(SDDP::WHOLE_EXTENT(), whole);
  int extent[6];
  filter->GetSpectrumImageOutput()->GetExtent(extent);
  const bool empty = extent[1] < extent[0];
  Check(empty ? whole[1] < whole[0] : std::equal(extent, extent + 6, whole),
    what + ": the image port announces [" + Str(whole[0]) + ", " + Str(whole[1]) + "] x [" +
      Str(whole[2]) + ", " + Str(whole[3]) + "] x [" + Str(whole[4]) + ", " + Str(whole[5]) +
      "] but holds [" + Str(extent[0]) + ", " + Str(extent[1]) + "] ...");
}

// Every update after the first must find the outputs up to date.
void CheckOneExecution(vtkBlueNoiseSpectrum* filter, bool image, const std::string& what)
{
  int executions = 0;
  vtkNew<vtkCallbackCommand> counter;
  counter->SetCallback(CountExecution);
  counter->SetClientData(&executions);
  const unsigned long tag = filter->AddObserver(vtkCommand::StartEvent, counter);
  vtkNew<vtkPassThrough> consumer; // a consumer of the image, as ParaView's post filter
  consumer->SetInputConnection(filter->GetOutputPort(1));

  const auto expect = [&](int expected, const std::string& step)
  {
    Check(executions == expected,
      what + ", " + step + ": " + Str(executions) + " executions, expected " + Str(expected));
  };
  filter->Modified();
  filter->Update(0);
  expect(1, "table port");
  Check(filter->GetOutput()->GetNumberOfRows() > 0, what + ": no spectrum rows");
  filter->Update(1);
  expect(1, "then image port");
  filter->Update(0);
  filter->Update(1);
  expect(1, "then both again");
  consumer->Update();
  expect(1, "then a consumer of the image port");
  UpdatePiece(filter, 0, 0, 2);
  UpdatePiece(filter, 1, 0, 2);
  UpdatePiece(filter, 0, 0, 2);
  expect(2, "then piece 0 of 2 on both ports");
  CheckAnnounced(filter, what);
  Check((filter->GetSpectrumImageOutput()->GetNumberOfPoints() > 0) == image,
    what + ": the image port " + (image ? "has no image" : "has an image"));
  filter->RemoveObserver(tag);
}

// Points at the set voxels of a random 20 x 24 x 16 mask, with the sampler's
// field data and nothing in the pipeline information.
vtkSmartPointer<vtkPolyData> FieldDataPoints(std::mt19937& rng)
{
  const int dims[3] = { 20, 24, 16 };
  auto data = MaskPoints(RandomMask(dims, 0.1, rng), dims,
    [](int i, int j, int k, double x[3])
    {
      x[0] = i;
      x[1] = j;
      x[2] = k;
    });
  const double origin[3] = { 0, 0, 0 };
  const double spacing[3] = { 1, 1, 1 };
  const int extent[6] = { 0, 19, 0, 23, 0, 15 };
  AddSamplingGrid(data, origin, spacing, extent);
  return data;
}
}

int main()
{
  std::mt19937 rng(99);
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(0, 23, 0, 19, 0, 15);
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputConnection(wavelet->GetOutputPort());
  sampler->SetDensityScale(0.2);
  {
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputConnection(sampler->GetOutputPort());
    CheckOneExecution(filter, true, "sampler points");
    filter->GenerateSpectrumImageOff();
    CheckOneExecution(filter, false, "sampler points, no image");
  }
  {
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(FieldDataPoints(rng));
    CheckOneExecution(filter, true, "field-data points");
    filter->GenerateSpectrumImageOff();
    CheckOneExecution(filter, false, "field-data points, no image");
  }
  {
    const int dims[3] = { 18, 16, 12 };
    const std::vector<unsigned char> mask = RandomMask(dims, 0.2, rng);
    vtkNew<vtkUnsignedCharArray> values;
    values->SetNumberOfValues(static_cast<vtkIdType>(mask.size()));
    std::copy(mask.begin(), mask.end(), values->GetPointer(0));
    vtkNew<vtkImageData> image;
    image->SetExtent(2, 19, 0, 15, -3, 8);
    image->GetPointData()->SetScalars(values);
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(image);
    CheckOneExecution(filter, true, "image");
    filter->GenerateSpectrumImageOff();
    CheckOneExecution(filter, false, "image, no image");
  }
  return bluenoise_test::Summary("TestBlueNoiseSpectrumExecutions");
}
