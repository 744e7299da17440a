// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkBlueNoiseSpectrum on random point sets (duplicates, NaN,
// huge coordinates, all points on a plane or at one place, the sampler's grid
// field data with random values, extents up to 2^30 a side among them) and
// small images, one to three realizations, with random properties (weight,
// grid dimensions and bounds, input grid, spectrum image, and a
// MaximumNumberOfGridPoints of at most 2^18, so that no grid the field data
// declare is allocated beyond libFuzzer's memory limit).
//
// The promises checked: no crash and no sanitizer report; an update that
// reports an error leaves both outputs empty; one that does not gives finite
// figures; and the same filter then measures a good point set.
#include "FuzzUtilities.h"

#include "vtkBlueNoiseSpectrum.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

using namespace bluenoise_fuzz;

namespace
{
vtkSmartPointer<vtkPolyData> MakePoints(FuzzedDataProvider& fdp)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(fdp.ConsumeBool() ? VTK_FLOAT : VTK_DOUBLE);
  const int n = fdp.ConsumeIntegralInRange<int>(0, 300);
  points->SetNumberOfPoints(n);
  std::mt19937 random(fdp.ConsumeIntegral<uint32_t>());
  const double scale = PickDouble(fdp, 0, 100);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  // 0: random in a cube, 1: on a plane, 2: one place, 3: from the input bytes.
  const int layout = fdp.ConsumeIntegralInRange<int>(0, 3);
  for (int i = 0; i < n; ++i)
  {
    double x[3] = { coordinate(random) * scale, coordinate(random) * scale,
      coordinate(random) * scale };
    if (layout == 1)
    {
      x[2] = scale;
    }
    else if (layout == 2)
    {
      x[0] = x[1] = x[2] = scale;
    }
    else if (layout == 3)
    {
      for (double& c : x)
      {
        c = PickDouble(fdp, -10, 10);
      }
    }
    points->SetPoint(i, x);
  }
  const int duplicates = fdp.ConsumeIntegralInRange<int>(0, 8);
  for (int d = 0; d < duplicates && n > 1; ++d)
  {
    points->SetPoint(fdp.ConsumeIntegralInRange<int>(0, n - 1),
      points->GetPoint(fdp.ConsumeIntegralInRange<int>(0, n - 1)));
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  return polyData;
}

/// The sampler's grid description, with random (often malformed) contents.
void AddSamplingGrid(FuzzedDataProvider& fdp, vtkPolyData* polyData)
{
  const char* names[] = { "SamplingGridOrigin", "SamplingGridSpacing", "SamplingGridExtent",
    "SamplingGridDirection" };
  const int sizes[] = { 3, 3, 6, 9 };
  for (int a = 0; a < 4; ++a)
  {
    if (fdp.ConsumeIntegralInRange<int>(0, 5) == 0)
    {
      continue; // missing
    }
    vtkNew<vtkDoubleArray> array;
    array->SetName(names[a]);
    const int size = fdp.ConsumeIntegralInRange<int>(0, 7) == 0
      ? fdp.ConsumeIntegralInRange<int>(0, 10)
      : sizes[a];
    array->SetNumberOfValues(size);
    for (int i = 0; i < size; ++i)
    {
      double v = PickDouble(fdp, -2, 12);
      if (a == 2 && fdp.ConsumeBool())
      {
        v = fdp.ConsumeIntegralInRange<int>(-2, 14); // a plausible extent
      }
      else if (a == 2 && fdp.ConsumeIntegralInRange<int>(0, 3) == 0)
      {
        v = fdp.ConsumeIntegralInRange<int>(-(1 << 30), 1 << 30); // whole, but huge
      }
      array->SetValue(i, v);
    }
    polyData->GetFieldData()->AddArray(array);
  }
}

vtkSmartPointer<vtkImageData> MakeImage(FuzzedDataProvider& fdp)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(fdp.ConsumeIntegralInRange<int>(1, 12),
    fdp.ConsumeIntegralInRange<int>(1, 12), fdp.ConsumeIntegralInRange<int>(1, 12));
  image->SetSpacing(PickDouble(fdp, 0, 2), PickDouble(fdp, 0, 2), PickDouble(fdp, 0, 2));
  vtkSmartPointer<vtkDataArray> values;
  if (fdp.ConsumeBool())
  {
    values = vtkSmartPointer<vtkUnsignedCharArray>::New();
  }
  else
  {
    values = vtkSmartPointer<vtkFloatArray>::New();
  }
  values->SetName("mask");
  values->SetNumberOfComponents(fdp.ConsumeIntegralInRange<int>(1, 2));
  values->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < values->GetNumberOfValues(); ++i)
  {
    const double v = fdp.ConsumeIntegralInRange<int>(0, 7) == 0 ? PickDouble(fdp, -1, 3)
                                                                : fdp.ConsumeIntegralInRange<int>(0, 1);
    values->SetVariantValue(i, std::isfinite(v) || values->GetDataType() == VTK_FLOAT ? vtkVariant(v) : vtkVariant(0));
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

void Configure(FuzzedDataProvider& fdp, vtkBlueNoiseSpectrum* spectrum)
{
  spectrum->SetWeight(PickDouble(fdp, 0, 1));
  spectrum->SetUseInputGrid(fdp.ConsumeBool());
  // The grid's cost grows with its voxels: keep each input small.
  spectrum->SetGridDimensions(fdp.ConsumeIntegralInRange<int>(-1, 16),
    fdp.ConsumeIntegralInRange<int>(-1, 16), fdp.ConsumeIntegralInRange<int>(-1, 16));
  double bounds[6];
  for (double& b : bounds)
  {
    b = PickDouble(fdp, -5, 105);
  }
  spectrum->SetGridBounds(bounds);
  spectrum->SetUseGridBounds(fdp.ConsumeBool());
  spectrum->SetGenerateSpectrumImage(fdp.ConsumeBool());
  // 2^18 when the input is used up (the grids above need at most 16^3).
  const int shift = fdp.ConsumeIntegralInRange<int>(0, 18);
  spectrum->SetMaximumNumberOfGridPoints(vtkIdType(1) << (18 - shift));
}

/// The promises of an update that reported no error: finite figures.
void CheckResult(vtkBlueNoiseSpectrum* spectrum)
{
  vtkTable* table = spectrum->GetOutput();
  for (const char* name : { "PrincipalFrequency", "LowFrequencyRatio", "Symmetry", "TargetValue" })
  {
    vtkDataArray* array = vtkDataArray::SafeDownCast(table->GetFieldData()->GetAbstractArray(name));
    Require(array && array->GetNumberOfTuples() == 1, "a one-tuple field array", name);
    Require(std::isfinite(array->GetTuple1(0)), "a finite figure", name);
  }
}

/// The same filter, reset, measures 200 random points on a 16^3 grid.
void CheckGoodUpdate(vtkBlueNoiseSpectrum* spectrum, MessageObserver* observer)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  for (int i = 0; i < 200; ++i)
  {
    points->InsertNextPoint(coordinate(random), coordinate(random), coordinate(random));
  }
  auto good = vtkSmartPointer<vtkPolyData>::New();
  good->SetPoints(points);
  spectrum->RemoveAllInputConnections(0);
  spectrum->SetInputData(good);
  spectrum->SetWeight(0.02);
  spectrum->SetUseInputGrid(true);
  spectrum->SetUseGridBounds(false);
  spectrum->SetGridDimensions(16, 16, 16);
  spectrum->SetMaximumNumberOfGridPoints(4096);
  observer->Reset();
  spectrum->Update();
  Require(observer->NumberOfErrors == 0, "the next good update reports no error", observer->Errors);
  Require(spectrum->GetOutput()->GetNumberOfRows() > 0, "the next good update gives a spectrum");
  CheckResult(spectrum);
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Quiet();
  FuzzedDataProvider fdp(data, size);
  vtkNew<vtkBlueNoiseSpectrum> spectrum;
  vtkNew<MessageObserver> observer;
  observer->Watch(spectrum);

  const int realizations = fdp.ConsumeIntegralInRange<int>(1, 3);
  for (int r = 0; r < realizations; ++r)
  {
    if (fdp.ConsumeIntegralInRange<int>(0, 4) == 0)
    {
      spectrum->AddInputData(MakeImage(fdp));
    }
    else
    {
      auto points = MakePoints(fdp);
      if (fdp.ConsumeBool())
      {
        AddSamplingGrid(fdp, points);
      }
      spectrum->AddInputData(points);
    }
  }
  Configure(fdp, spectrum);
  spectrum->Update();

  if (observer->NumberOfErrors > 0)
  {
    Require(spectrum->GetOutput()->GetNumberOfRows() == 0, "an error leaves no table",
      observer->Errors);
    Require(spectrum->GetSpectrumImageOutput()->GetNumberOfPoints() == 0,
      "an error leaves no spectrum image", observer->Errors);
  }
  else
  {
    CheckResult(spectrum);
  }
  CheckGoodUpdate(spectrum, observer);
  return 0;
}
