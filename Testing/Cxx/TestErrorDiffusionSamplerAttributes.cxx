// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Input arrays carried to the samples; the Density array follows the chosen
// mapping (identity, array range, custom range, transfer function, scale,
// component, magnitude); zero density and NaN give no samples.
#include "SamplerTestUtilities.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkPiecewiseFunction.h"
#include "vtkShortArray.h"

#include <cmath>
#include <limits>

using namespace bluenoise_test;

namespace
{
const int N = 24;

// Voxel index of output point p (the input has unit spacing, origin 0).
vtkIdType VoxelOf(vtkPolyData* out, vtkIdType p)
{
  double x[3];
  out->GetPoint(p, x);
  return std::lround(x[0]) + N * (std::lround(x[1]) + N * std::lround(x[2]));
}

// Checks Density == expected(voxel) at every sample; returns the sample count.
vtkIdType CheckDensity(vtkPolyData* out, const std::function<double(vtkIdType)>& expected,
  const std::string& what)
{
  auto* density = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("Density"));
  if (!Check(density != nullptr, what + ": Density array present"))
  {
    return 0;
  }
  int wrong = 0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    if (std::abs(density->GetValue(p) - expected(VoxelOf(out, p))) > 1e-6)
    {
      ++wrong;
    }
  }
  Check(wrong == 0, what + ": " + Str(wrong) + " wrong Density values");
  return out->GetNumberOfPoints();
}
}

int main()
{
  // A short "intensity" in [100, 1100), a 3-component int array, a double array with NaNs.
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(N, N, N);
  const vtkIdType voxels = N * N * N;
  vtkNew<vtkShortArray> intensity;
  intensity->SetName("intensity");
  vtkNew<vtkIntArray> triple;
  triple->SetName("triple");
  triple->SetNumberOfComponents(3);
  vtkNew<vtkDoubleArray> withNaN;
  withNaN->SetName("withNaN");
  for (vtkIdType id = 0; id < voxels; ++id)
  {
    intensity->InsertNextValue(static_cast<short>(100 + (id * 37) % 1000));
    const int t[3] = { static_cast<int>(id), static_cast<int>(-id), static_cast<int>(id % 7) };
    triple->InsertNextTypedTuple(t);
    withNaN->InsertNextValue(id % 3 == 0 ? std::numeric_limits<double>::quiet_NaN() : 0.25);
  }
  image->GetPointData()->SetScalars(intensity);
  image->GetPointData()->AddArray(triple);
  image->GetPointData()->AddArray(withNaN);

  auto value = [&](vtkIdType v) { return static_cast<double>(intensity->GetValue(v)); };

  // Default mapping: the array's range [100, 1099] to [0, 1].
  {
    vtkNew<vtkErrorDiffusionSampler> s;
    s->SetInputData(image);
    s->UseNumberOfPointsOff();
    s->Update();
    vtkPolyData* out = s->GetOutput();
    const vtkIdType n = CheckDensity(out, [&](vtkIdType v) { return (value(v) - 100.0) / 999.0; },
      "scalar range (array range)");
    Check(n > 0.45 * voxels && n < 0.55 * voxels, "about half the voxels sampled: " + Str(n));
    // Every input array carried with the right values.
    auto* outIntensity = vtkShortArray::SafeDownCast(out->GetPointData()->GetArray("intensity"));
    auto* outTriple = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("triple"));
    Check(outIntensity && outTriple && out->GetPointData()->GetArray("withNaN"),
      "all input arrays carried, types kept");
    if (outIntensity && outTriple)
    {
      int wrong = 0;
      for (vtkIdType p = 0; p < n; ++p)
      {
        const vtkIdType v = VoxelOf(out, p);
        wrong += outIntensity->GetValue(p) != intensity->GetValue(v);
        wrong += outTriple->GetTypedComponent(p, 1) != triple->GetTypedComponent(v, 1);
      }
      Check(wrong == 0, Str(wrong) + " carried values differ from the input");
      Check(out->GetPointData()->GetScalars() &&
          std::string(out->GetPointData()->GetScalars()->GetName()) == "intensity",
        "active scalars kept");
    }
  }
  // Custom range with a scale: values below the range give no samples.
  {
    auto out = Sample(image, [](vtkErrorDiffusionSampler* s) {
      s->SetDensityMappingToScalarRange();
      s->UseCustomScalarRangeOn();
      s->SetScalarRange(600, 1100);
      s->SetDensityScale(0.5);
    });
    CheckDensity(out, [&](vtkIdType v) { return std::max(0.0, (value(v) - 600.0) / 500.0 * 0.5); },
      "custom scalar range with scale");
    int below = 0;
    for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
    {
      below += value(VoxelOf(out, p)) <= 600.0;
    }
    Check(below == 0, Str(below) + " samples where the density is 0");
  }
  // Transfer function: zero opacity below 500 gives no samples there.
  {
    vtkNew<vtkPiecewiseFunction> tf;
    tf->AddPoint(100, 0.0);
    tf->AddPoint(500, 0.0);
    tf->AddPoint(1100, 0.8);
    auto out = Sample(image, [&](vtkErrorDiffusionSampler* s) {
      s->SetDensityMappingToTransferFunction();
      s->SetTransferFunction(tf);
    });
    const vtkIdType n =
      CheckDensity(out, [&](vtkIdType v) { return tf->GetValue(value(v)); }, "transfer function");
    int inZero = 0;
    double expected = 0.0;
    for (vtkIdType v = 0; v < voxels; ++v)
    {
      expected += tf->GetValue(value(v));
    }
    for (vtkIdType p = 0; p < n; ++p)
    {
      inZero += value(VoxelOf(out, p)) <= 500.0;
    }
    Check(inZero == 0, Str(inZero) + " samples where the opacity is 0");
    Check(std::abs(n - expected) < 0.01 * expected, "transfer function count " + Str(n) +
        " vs expected " + Str(expected));
    // Editing the function re-executes the filter (MTime includes it).
    vtkNew<vtkErrorDiffusionSampler> s;
    s->SetInputData(image);
    s->UseNumberOfPointsOff();
    s->SetDensityMappingToTransferFunction();
    s->SetTransferFunction(tf);
    s->Update();
    const vtkIdType before = s->GetOutput()->GetNumberOfPoints();
    tf->AddPoint(1100, 0.2);
    s->Update();
    Check(s->GetOutput()->GetNumberOfPoints() < before / 2, "transfer function edit re-executes");
  }
  // Component and magnitude of a multi-component array, identity mapping with a scale.
  {
    auto out = Sample(image, [](vtkErrorDiffusionSampler* s) {
      s->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "triple");
      s->SetComponent(2);
      s->SetDensityScale(0.1);
    });
    CheckDensity(out, [&](vtkIdType v) { return std::min(1.0, 0.1 * (v % 7)); }, "component 2");
    auto mag = Sample(image, [](vtkErrorDiffusionSampler* s) {
      s->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "triple");
      s->SetComponent(-1);
      s->SetDensityScale(1e-5);
    });
    CheckDensity(mag,
      [&](vtkIdType v) {
        const double m = std::sqrt(2.0 * v * v + (v % 7) * (v % 7));
        return std::min(1.0, 1e-5 * m);
      },
      "magnitude");
    // The number of components is the magnitude too (ParaView's "Magnitude" entry).
    auto entry = Sample(image, [](vtkErrorDiffusionSampler* s) {
      s->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "triple");
      s->SetComponent(3);
      s->SetDensityScale(1e-5);
    });
    Check(entry->GetNumberOfPoints() == mag->GetNumberOfPoints() &&
        entry->GetNumberOfPoints() > 0,
      "component 3 of 3 is the magnitude: " + Str(entry->GetNumberOfPoints()) + " points, " +
        Str(mag->GetNumberOfPoints()) + " with -1");
  }
  // NaN is density 0.
  {
    auto out = Sample(image, [](vtkErrorDiffusionSampler* s) {
      s->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "withNaN");
    });
    int onNaN = 0;
    for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
    {
      onNaN += VoxelOf(out, p) % 3 == 0;
    }
    Check(onNaN == 0 && out->GetNumberOfPoints() > 0, Str(onNaN) + " samples on NaN voxels");
    CheckDensity(out, [](vtkIdType) { return 0.25; }, "NaN array");
  }
  return Summary("TestErrorDiffusionSamplerAttributes");
}
