// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// A point set without the sampler's grid (any point set: here 50 points on a
// sphere, as ParaView's Sphere source gives) is measured on a grid the filter
// assumes: one warning per execution names it (origin, spacing, extent), and
// the table's SpectrumGrid field data says which grid every spectrum used.
// The sampler's output, an image, or UseInputGrid off (the user's own grid)
// give no warning.
#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseSpectrum.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <cmath>
#include <string>

using namespace bluenoise_test;

namespace
{
vtkSmartPointer<vtkPolyData> SpherePoints(int n)
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i < n; ++i)
  {
    // A Fibonacci sphere of radius 0.5.
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(1.0 - z * z);
    const double phi = i * vtkMath::Pi() * (3.0 - std::sqrt(5.0));
    points->InsertNextPoint(0.5 * r * std::cos(phi), 0.5 * r * std::sin(phi), 0.5 * z);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  return data;
}

std::string GridText(vtkBlueNoiseSpectrum* spectrum)
{
  auto* text = vtkStringArray::SafeDownCast(
    spectrum->GetOutput()->GetFieldData()->GetAbstractArray("SpectrumGrid"));
  return text && text->GetNumberOfValues() == 1 ? text->GetValue(0) : std::string("(none)");
}

bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
}

int main()
{
  // 1. Plain points, twice as two realizations: one warning naming the grid.
  {
    auto sphere = SpherePoints(50);
    vtkNew<vtkBlueNoiseSpectrum> spectrum;
    vtkNew<MessageObserver> messages;
    messages->Watch(spectrum);
    spectrum->AddInputData(sphere);
    spectrum->AddInputData(sphere);
    spectrum->SetGridDimensions(16, 16, 16);
    spectrum->GenerateSpectrumImageOff();
    spectrum->Update();
    const std::string& w = messages->Warnings;
    Check(messages->ErrorCount == 0 && spectrum->GetOutput()->GetNumberOfRows() > 0,
      "plain points: a spectrum, no error ('" + messages->Errors + "')");
    Check(messages->WarningCount == 1, "plain points: one warning, got " +
        Str(messages->WarningCount) + ": '" + w + "'");
    Check(Contains(w, "no sampling grid") && Contains(w, "origin (") && Contains(w, "spacing (") &&
        Contains(w, "extent [0, 15, 0, 15, 0, 15]"),
      "the warning names the grid assumed: '" + w + "'");
    const std::string text = GridText(spectrum);
    Check(Contains(text, "points' bounds") && Contains(text, "extent [0, 15, 0, 15, 0, 15]"),
      "SpectrumGrid names the assumed grid: '" + text + "'");

    // Once per execution: a second execution warns once more.
    messages->Clear();
    spectrum->Modified();
    spectrum->Update();
    Check(messages->WarningCount == 1, "a second execution: one warning, got " +
        Str(messages->WarningCount));

    // UseInputGrid off: the grid is the user's choice, no warning.
    messages->Clear();
    spectrum->UseInputGridOff();
    spectrum->Update();
    Check(messages->WarningCount == 0 && Contains(GridText(spectrum), "points' bounds"),
      "UseInputGrid off: no warning, got '" + messages->Warnings + "'");
  }

  // 2. The sampler's output: its own grid, no warning.
  {
    auto cube = MakeConstantVolume(16, 0.1f);
    vtkNew<vtkErrorDiffusionSampler> sampler;
    sampler->SetInputData(cube);
    sampler->SetDensityMappingToIdentity();
    sampler->UseNumberOfPointsOff();
    vtkNew<vtkBlueNoiseSpectrum> spectrum;
    vtkNew<MessageObserver> messages;
    messages->Watch(spectrum);
    spectrum->SetInputConnection(sampler->GetOutputPort());
    spectrum->Update();
    Check(messages->WarningCount == 0 && messages->ErrorCount == 0,
      "sampler output: no warning, got '" + messages->Warnings + messages->Errors + "'");
    const std::string text = GridText(spectrum);
    Check(Contains(text, "SamplingGrid") && Contains(text, "extent [0, 15, 0, 15, 0, 15]"),
      "SpectrumGrid names the sampler's grid: '" + text + "'");

    // 3. The sampler's mask (an image): its own grid, no warning.
    messages->Clear();
    sampler->GenerateMaskOn();
    spectrum->SetInputConnection(sampler->GetOutputPort(1));
    spectrum->Update();
    Check(messages->WarningCount == 0 && Contains(GridText(spectrum), "image"),
      "an image: no warning, got '" + messages->Warnings + "', SpectrumGrid '" +
        GridText(spectrum) + "'");
  }
  return Summary("TestBlueNoiseSpectrumAssumedGrid");
}
