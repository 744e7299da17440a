// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Bad input: a clear error and empty outputs, never a crash.
#include "SamplerTestUtilities.h"
#include "vtkPiecewiseFunction.h"
#include "vtkStringArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"

#include <cmath>
#include <fstream>
#include <limits>

using namespace bluenoise_test;

namespace
{
void Expect(vtkImageData* image, const std::function<void(vtkErrorDiffusionSampler*)>& configure,
  const std::string& message, const std::string& what)
{
  vtkNew<vtkErrorDiffusionSampler> sampler;
  vtkNew<MessageObserver> observer;
  observer->Watch(sampler);
  observer->Watch(sampler->GetExecutive());
  sampler->SetInputData(image);
  sampler->GenerateMaskOn();
  configure(sampler);
  sampler->Update();
  Check(observer->ErrorContains(message),
    what + ": expected an error containing '" + message + "', got '" + observer->Errors + "'");
  Check(sampler->GetOutput()->GetNumberOfPoints() == 0 &&
      sampler->GetMaskOutput()->GetNumberOfPoints() == 0,
    what + ": outputs are empty");
}
}

int main()
{
  auto good = MakeConstantVolume(8, 0.2f);
  auto none = [](vtkErrorDiffusionSampler*) {};

  auto noScalars = vtkSmartPointer<vtkImageData>::New();
  noScalars->SetDimensions(4, 4, 4);
  Expect(noScalars, none, "No density array", "no array");

  auto strings = vtkSmartPointer<vtkImageData>::New();
  strings->SetDimensions(2, 2, 2);
  vtkNew<vtkStringArray> names;
  names->SetName("names");
  names->SetNumberOfValues(8);
  strings->GetPointData()->AddArray(names);
  Expect(strings,
    [](vtkErrorDiffusionSampler* s) {
      s->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "names");
    },
    "is not numeric", "string array");

  Expect(good,
    [](vtkErrorDiffusionSampler* s) {
      s->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "missing");
    },
    "No density array", "unknown array name");

  auto cells = MakeConstantVolume(5, 0.2f);
  vtkNew<vtkFloatArray> cellValues;
  cellValues->SetName("cellValues");
  // A cell array is sampled per cell (TestErrorDiffusionSamplerCellData); one
  // with fewer tuples than the 64 cells is refused.
  cellValues->SetNumberOfValues(60);
  cellValues->Fill(0.5);
  cells->GetCellData()->AddArray(cellValues);
  Expect(cells,
    [](vtkErrorDiffusionSampler* s) {
      s->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "cellValues");
    },
    "60 tuples for 64 cells", "cell array of the wrong length");

  auto empty = vtkSmartPointer<vtkImageData>::New();
  empty->SetExtent(0, -1, 0, -1, 0, -1);
  vtkNew<vtkFloatArray> nothing;
  nothing->SetName("density");
  empty->GetPointData()->SetScalars(nothing);
  Expect(empty, none, "empty extent", "empty extent");

  Expect(good, [](vtkErrorDiffusionSampler* s) { s->SetComponent(2); }, "out of range",
    "component out of range");
  // Out-of-range values are clamped by the setters (as ParaView's domains
  // do); what no clamp can fix is an error.
  Expect(good,
    [](vtkErrorDiffusionSampler* s) {
      s->UseNumberOfPointsOff();
      s->SetDensityScale(std::numeric_limits<double>::quiet_NaN());
    },
    "DensityScale", "NaN scale");
  Expect(good,
    [](vtkErrorDiffusionSampler* s) {
      s->SetModulationScale(std::numeric_limits<double>::quiet_NaN());
    },
    "ModulationScale", "NaN modulation scale");
  Expect(good,
    [](vtkErrorDiffusionSampler* s) {
      s->SetDensityMappingToScalarRange();
      s->UseCustomScalarRangeOn();
      s->SetScalarRange(2.0, 1.0);
    },
    "ScalarRange must be finite", "inverted scalar range");
  Expect(good,
    [](vtkErrorDiffusionSampler* s) {
      s->SetDensityMappingToScalarRange();
      s->UseCustomScalarRangeOn();
      s->SetScalarRange(0.0, std::numeric_limits<double>::infinity());
    },
    "ScalarRange must be finite", "infinite scalar range");
  Expect(good,
    [](vtkErrorDiffusionSampler* s) { s->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_CUSTOM); },
    "no ParameterFile", "custom set without file");
  Expect(good,
    [](vtkErrorDiffusionSampler* s) {
      s->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_CUSTOM);
      s->SetParameterFile("/nonexistent/params.txt");
    },
    "cannot open", "missing parameter file");
  const std::string bad = "TestErrorDiffusionSamplerBadInput-params.txt";
  {
    std::ofstream out(bad);
    out << "# a table with a broken second line\n8 1 1 1 1 1 1 1\n16 1 1 1 1 1 1\n";
  }
  Expect(good,
    [&](vtkErrorDiffusionSampler* s) {
      s->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_CUSTOM);
      s->SetParameterFile(bad.c_str());
    },
    "line 3: expected 8 numbers", "malformed parameter file");

  // After an error, a good input works again with the same filter.
  vtkNew<vtkErrorDiffusionSampler> sampler;
  vtkNew<MessageObserver> observer;
  observer->Watch(sampler);
  observer->Watch(sampler->GetExecutive());
  sampler->SetInputData(good);
  sampler->UseNumberOfPointsOff();
  sampler->SetDensityScale(std::numeric_limits<double>::quiet_NaN());
  sampler->Update();
  sampler->SetDensityScale(1);
  sampler->Update();
  Check(sampler->GetOutput()->GetNumberOfPoints() > 0, "recovers after an error");

  // Point arrays without one tuple per voxel are left out with a warning,
  // never read past their end.
  {
    auto image = MakeConstantVolume(16, 0.2f);
    vtkNew<vtkFloatArray> shortArray;
    shortArray->SetName("short");
    shortArray->SetNumberOfValues(100);
    shortArray->Fill(1.0f);
    vtkNew<vtkFloatArray> emptyArray;
    emptyArray->SetName("empty");
    image->GetPointData()->AddArray(shortArray);
    image->GetPointData()->AddArray(emptyArray);
    vtkNew<vtkErrorDiffusionSampler> s;
    vtkNew<MessageObserver> messages;
    messages->Watch(s);
    s->SetInputData(image);
    s->SetNumberOfPoints(500);
    s->SetDensityMappingToIdentity();
    s->Update();
    vtkPolyData* out = s->GetOutput();
    Check(std::abs(out->GetNumberOfPoints() - 500) <= 2, "arrays of the wrong length: sampled");
    Check(!out->GetPointData()->GetArray("short") && !out->GetPointData()->GetArray("empty") &&
        out->GetPointData()->GetArray("density"),
      "arrays of the wrong length are not carried, the others are");
    Check(messages->Warnings.find("'short'") != std::string::npos &&
        messages->Warnings.find("'empty'") != std::string::npos,
      "a warning names them: '" + messages->Warnings + "'");
  }
  // A range of +-1e308, whose width overflows a double, maps like any other.
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(20, 20, 20);
    vtkNew<vtkDoubleArray> huge;
    huge->SetName("huge");
    huge->SetNumberOfValues(8000);
    for (vtkIdType i = 0; i < 8000; ++i)
    {
      const double t = static_cast<double>(i) / 7999.0;
      huge->SetValue(i, -1e308 * (1.0 - t) + 1e308 * t);
    }
    image->GetPointData()->SetScalars(huge);
    vtkNew<vtkErrorDiffusionSampler> s;
    s->SetInputData(image);
    s->SetNumberOfPoints(1000);
    s->Update();
    Check(std::abs(s->GetOutput()->GetNumberOfPoints() - 1000) <= 2,
      "range of +-1e308: " + Str(s->GetOutput()->GetNumberOfPoints()) + " points for 1000");
  }
  // A budget that yields no points is no error, but says why the output is
  // empty: NumberOfPoints 0, or a DensityScale whose expected count is below
  // one half; a budget that yields points says nothing. Every method.
  for (const int method : { 0, 1, 2, 3, 4 })
  {
    const std::string name = " (method " + Str(method) + ")";
    const struct
    {
      bool UseNumberOfPoints;
      vtkIdType Points;
      double Scale;
      const char* Why; // in the warning; empty: no warning, points drawn
      const char* What;
    } cases[] = {
      { true, 0, 1.0, "NumberOfPoints is 0", "NumberOfPoints 0" },
      { false, 100, 0.0, "expected number of points", "DensityScale 0" },
      // (Poisson disk draws one point where the others draw none: no warning then.)
      { false, 100, 1e-6, "expected number of points", "DensityScale 1e-6 (0.0001 expected)" },
      { true, 50, 1.0, "", "NumberOfPoints 50" },
    };
    for (const auto& c : cases)
    {
      vtkNew<vtkErrorDiffusionSampler> sampler;
      vtkNew<MessageObserver> messages;
      messages->Watch(sampler);
      sampler->SetInputData(good);
      sampler->SetDensityMappingToIdentity();
      sampler->SetMethod(method);
      sampler->SetUseNumberOfPoints(c.UseNumberOfPoints);
      sampler->SetNumberOfPoints(c.Points);
      sampler->SetDensityScale(c.Scale);
      sampler->Update();
      const vtkIdType points = sampler->GetOutput()->GetNumberOfPoints();
      Check(messages->ErrorCount == 0, std::string(c.What) + ": no error" + name);
      const bool poissonPoint =
        method == vtkErrorDiffusionSampler::METHOD_POISSON_DISK && c.Scale == 1e-6 && points == 1;
      if (*c.Why && !poissonPoint)
      {
        Check(points == 0 && messages->WarningCount == 1 &&
            messages->Warnings.find(c.Why) != std::string::npos &&
            messages->Warnings.find("no points were drawn") != std::string::npos,
          std::string(c.What) + ": one warning saying why there are no points, got '" +
            messages->Warnings + "'" + name);
      }
      else
      {
        Check(points > 0 && messages->WarningCount == 0,
          std::string(c.What) + ": points and no warning, got '" + messages->Warnings + "'" + name);
      }
    }
  }
  return Summary("TestErrorDiffusionSamplerBadInput");
}
