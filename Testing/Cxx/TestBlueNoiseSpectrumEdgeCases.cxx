// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Edge cases of the kernel and the filter: a non-cubic grid, bad input (clear
// errors, empty outputs, unchanged state), grids beyond MaximumNumberOfGridPoints
// or the memory, a single point through the filter and a full mask (g = 1: a
// warning, no NaN anywhere).
#include "TestBlueNoiseSpectrumUtilities.h"

#include "vtkBlueNoiseSpectrum.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <limits>
#include <string>

using namespace spectrum_test;
using bluenoise_test::MessageObserver;

// Under AddressSanitizer an impossible allocation fails as it does without it
// (a null pointer or std::bad_alloc) instead of ending the program: the
// filter's handling of that failure is what GridLimits tests.
extern "C" const char* __asan_default_options()
{
  return "allocator_may_return_null=1";
}

namespace
{
void NonCubicWhiteNoise(std::mt19937& rng)
{
  const int dims[3] = { 32, 48, 64 };
  const double g = 0.2;
  const std::string what = "white noise on 32x48x64";
  const std::vector<unsigned char> mask = RandomMask(dims, g, rng);
  Result r;
  std::string error;
  if (!Check(vtkBlueNoiseSpectrumKernel::Evaluate(mask.data(), dims, 0.02, r, &error),
        what + ": " + error))
  {
    return;
  }
  CheckFinite(r, what);
  // Shells are 1 / Lmin wide; the corner (1/2, 1/2, 1/2) lies on shell
  // round(32 sqrt(3) / 2) = 28.
  Check(r.RadialPower.size() == 28, what + ": " + Str(r.RadialPower.size()) + " shells");
  for (std::size_t i = 0; i < r.Frequency.size(); ++i)
  {
    Check(r.Frequency[i] == (i + 1) / 32.0, what + ": frequency of shell " + Str(i + 1));
  }
  Check(TotalCount(r) == 32 * 48 * 64 - 1, what + ": shell counts add up to " + Str(TotalCount(r)));
  double meanDB = 0.0;
  for (std::size_t i = 3; i < r.RadialPower.size(); ++i)
  {
    const double tolerance = std::max(0.05, 4.0 / std::sqrt(r.ShellCount[i] / 2.0));
    if (r.ShellCount[i] >= 1000 || i < 16)
    {
      Check(std::abs(r.RadialPower[i] / (1.0 - g) - 1.0) <= tolerance,
        what + " shell " + Str(i + 1) + ": power " + Str(r.RadialPower[i]));
    }
    if (i < 16)
    {
      meanDB += r.AnisotropyDB[i] / 13.0;
    }
  }
  Check(std::abs(meanDB) < 0.5, what + ": mean anisotropy " + Str(meanDB) + " dB");
}

void KernelErrors()
{
  vtkBlueNoiseSpectrumKernel kernel;
  std::string error;
  Result r;
  std::vector<unsigned char> zeros(8 * 8 * 8, 0);
  Check(!kernel.AddRealization(zeros.data(), &error) && error.find("not set") != std::string::npos,
    "AddRealization without dimensions: '" + error + "'");
  Check(!kernel.SetDimensions(1, 8, 8, &error) && error.find("at least 2") != std::string::npos,
    "SetDimensions(1, 8, 8): '" + error + "'");
  Check(kernel.SetDimensions(8, 8, 8, &error), "SetDimensions(8, 8, 8): " + error);
  Check(!kernel.Compute(r, &error) && error.find("no realization") != std::string::npos,
    "Compute without realizations: '" + error + "'");
  Check(!kernel.AddRealization(zeros.data(), &error) && error.find("N = 0") != std::string::npos,
    "empty mask: '" + error + "'");

  // A good realization, then bad ones that must not change the result.
  std::vector<float> counts(8 * 8 * 8, 0.0f);
  counts[3] = 1.0f;
  counts[100] = 2.5f;
  Check(kernel.AddRealization(counts.data(), &error), "good counts: " + error);
  Result before;
  kernel.Compute(before);
  std::vector<float> bad = counts;
  bad[17] = -1.0f;
  Check(!kernel.AddRealization(bad.data(), &error) &&
      error.find("finite and non-negative") != std::string::npos,
    "negative count: '" + error + "'");
  bad[17] = std::numeric_limits<float>::quiet_NaN();
  Check(!kernel.AddRealization(bad.data(), &error) && error.find("(1, 2, 0)") != std::string::npos,
    "NaN count names its voxel: '" + error + "'");
  bad[17] = std::numeric_limits<float>::infinity();
  Check(!kernel.AddRealization(bad.data(), &error), "infinite count accepted");
  Check(kernel.GetNumberOfRealizations() == 1,
    "rejected realizations were counted: " + Str(kernel.GetNumberOfRealizations()));
  Result after;
  kernel.Compute(after);
  CheckSameResult(after, before, 0.0, "after rejected realizations");

  kernel.SetWeight(2.0);
  Check(kernel.GetWeight() == 1.0, "weight not clamped to 1: " + Str(kernel.GetWeight()));
  kernel.SetWeight(-1.0);
  Check(kernel.GetWeight() == 0.0, "weight not clamped to 0: " + Str(kernel.GetWeight()));

  // Reset keeps the shape.
  kernel.Reset();
  Check(kernel.GetNumberOfRealizations() == 0, "Reset kept realizations");
  Check(kernel.AddRealization(counts.data(), &error), "after Reset: " + error);
}

void FullMask(std::mt19937& rng)
{
  const int dims[3] = { 16, 16, 16 };
  const std::vector<unsigned char> ones(Voxels(dims), 1);
  Result r;
  std::string error;
  if (!Check(vtkBlueNoiseSpectrumKernel::Evaluate(ones.data(), dims, 0.02, r, &error),
        "full mask: " + error))
  {
    return;
  }
  CheckFinite(r, "full mask");
  Check(!r.Warning.empty(), "full mask: no warning");
  Check(r.Density == 1.0, "full mask: g = " + Str(r.Density));
  Check(r.LowFrequencyRatio == 0.0, "full mask: L = " + Str(r.LowFrequencyRatio));
  Check(r.SymmetryCorrelation == 0.0 && r.Symmetry == 1.0,
    "full mask: C = " + Str(r.SymmetryCorrelation) + ", S = " + Str(r.Symmetry));
  CheckClose(r.TargetValue, 0.98, 1e-15, "full mask T");
  for (std::size_t i = 0; i < r.RadialPower.size(); ++i)
  {
    Check(r.RadialPower[i] == 0.0 && r.Anisotropy[i] == 0.0 && r.AnisotropyDB[i] == -300.0,
      "full mask shell " + Str(i + 1) + ": power " + Str(r.RadialPower[i]) + ", anisotropy " +
        Str(r.Anisotropy[i]) + " (" + Str(r.AnisotropyDB[i]) + " dB)");
  }

  // A constant realization contributes exactly zero to the average.
  vtkBlueNoiseSpectrumKernel kernel;
  kernel.SetDimensions(16, 16, 16);
  const std::vector<unsigned char> noise = RandomMask(dims, 0.2, rng);
  const std::vector<float> threes(Voxels(dims), 3.0f);
  kernel.AddRealization(noise.data());
  Result single;
  kernel.Compute(single);
  kernel.AddRealization(threes.data());
  Result mixed;
  kernel.Compute(mixed);
  Check(mixed.Warning.empty(), "mixed realizations: unexpected warning");
  for (std::size_t i = 0; i < mixed.RadialPower.size(); ++i)
  {
    CheckClose(mixed.RadialPower[i], single.RadialPower[i] / 2, 1e-14,
      "constant + noise shell " + Str(i + 1));
  }
}

// Table, field data and image of the filter all empty.
bool OutputsEmpty(vtkBlueNoiseSpectrum* filter)
{
  vtkTable* table = filter->GetOutput();
  vtkImageData* image = filter->GetSpectrumImageOutput();
  return table->GetNumberOfColumns() == 0 && table->GetNumberOfRows() == 0 &&
    table->GetFieldData()->GetNumberOfArrays() == 0 && image->GetNumberOfPoints() == 0;
}

void ExpectFilterError(vtkDataObject* input, const std::string& expected, const std::string& what)
{
  vtkNew<vtkBlueNoiseSpectrum> filter;
  vtkNew<MessageObserver> observer;
  observer->Watch(filter);
  observer->Watch(filter->GetExecutive());
  filter->SetInputData(input);
  filter->Update();
  Check(observer->ErrorContains(expected),
    what + ": expected an error with '" + expected + "', got '" + observer->Errors + "'");
  Check(OutputsEmpty(filter), what + ": outputs not empty");
}

vtkSmartPointer<vtkImageData> MaskImage(const int dims[3], vtkDataArray* values)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(dims[0], dims[1], dims[2]);
  image->GetPointData()->SetScalars(values);
  return image;
}

void FilterErrors()
{
  vtkNew<vtkPolyData> empty;
  ExpectFilterError(empty, "has no points", "empty poly data");

  vtkNew<vtkMultiBlockDataSet> noBlocks;
  ExpectFilterError(noBlocks, "has no realization", "empty multiblock");

  const int dims[3] = { 8, 8, 8 };
  vtkNew<vtkFloatArray> withNaN;
  withNaN->SetNumberOfValues(512);
  withNaN->FillValue(1.0f);
  withNaN->SetValue(5, std::numeric_limits<float>::quiet_NaN());
  ExpectFilterError(MaskImage(dims, withNaN), "finite and non-negative", "NaN in an image");

  vtkNew<vtkDoubleArray> twoComponents;
  twoComponents->SetNumberOfComponents(2);
  twoComponents->SetNumberOfTuples(512);
  twoComponents->Fill(1.0);
  ExpectFilterError(MaskImage(dims, twoComponents), "components", "two-component array");

  const int flat[3] = { 8, 8, 1 };
  vtkNew<vtkUnsignedCharArray> layer;
  layer->SetNumberOfValues(64);
  layer->FillValue(0);
  layer->SetValue(9, 1);
  ExpectFilterError(MaskImage(flat, layer), "at least 2", "one-layer image");

  vtkNew<vtkImageData> noArray;
  noArray->SetDimensions(4, 4, 4);
  ExpectFilterError(noArray, "no input array", "image without scalars");

  // Two realizations of different shapes.
  vtkNew<vtkUnsignedCharArray> small;
  small->SetNumberOfValues(512);
  small->FillValue(0);
  small->SetValue(3, 1);
  const int other[3] = { 8, 8, 6 };
  vtkNew<vtkUnsignedCharArray> smaller;
  smaller->SetNumberOfValues(384);
  smaller->FillValue(0);
  smaller->SetValue(3, 1);
  vtkNew<vtkMultiBlockDataSet> mismatched;
  mismatched->SetBlock(0, MaskImage(dims, small));
  mismatched->SetBlock(1, MaskImage(other, smaller));
  ExpectFilterError(mismatched, "share one grid shape", "mismatched realizations");

  // Malformed sampler field data.
  vtkNew<vtkPolyData> malformed;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  malformed->SetPoints(points);
  vtkNew<vtkDoubleArray> origin;
  origin->SetName("SamplingGridOrigin");
  origin->SetNumberOfComponents(2);
  origin->SetNumberOfTuples(1);
  malformed->GetFieldData()->AddArray(origin);
  ExpectFilterError(malformed, "SamplingGridOrigin has 2 values", "malformed field data");

  // An extent beyond the range of int (found by fuzzing: it was converted to int
  // regardless, which is undefined).
  vtkNew<vtkPolyData> huge;
  huge->SetPoints(points);
  const char* names[] = { "SamplingGridOrigin", "SamplingGridSpacing", "SamplingGridExtent" };
  const double values[3][6] = { { 0, 0, 0 }, { 1, 1, 1 }, { 0, 7, 0, 7, -1e300, 7 } };
  for (int a = 0; a < 3; ++a)
  {
    vtkNew<vtkDoubleArray> array;
    array->SetName(names[a]);
    const int n = a == 2 ? 6 : 3;
    array->SetNumberOfValues(n);
    for (int i = 0; i < n; ++i)
    {
      array->SetValue(i, values[a][i]);
    }
    huge->GetFieldData()->AddArray(array);
  }
  ExpectFilterError(huge, "SamplingGridExtent is not an extent", "extent beyond int");

  // Every point outside the grid: N = 0, and the error says why.
  vtkNew<vtkPolyData> away;
  vtkNew<vtkPoints> far;
  far->InsertNextPoint(5.0, 0.5, 0.5);
  far->InsertNextPoint(-3.0, 0.5, 0.5);
  away->SetPoints(far);
  vtkNew<vtkBlueNoiseSpectrum> filter;
  vtkNew<MessageObserver> observer;
  observer->Watch(filter);
  observer->Watch(filter->GetExecutive());
  filter->SetInputData(away);
  filter->SetGridDimensions(8, 8, 8);
  filter->SetGridBounds(0.0, 1.0, 0.0, 1.0, 0.0, 1.0);
  filter->UseGridBoundsOn();
  filter->Update();
  Check(observer->ErrorContains("N = 0") &&
      observer->ErrorContains("2 samples lie outside the analysis grid"),
    "all points outside: '" + observer->Errors + "'");
  Check(OutputsEmpty(filter), "all points outside: outputs not empty");
}

// One point whose sampler field data declare `extent` (origin 0, spacing 1).
vtkSmartPointer<vtkPolyData> WithSamplingGrid(const double extent[6])
{
  auto data = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  data->SetPoints(points);
  const char* names[] = { "SamplingGridOrigin", "SamplingGridSpacing", "SamplingGridExtent" };
  const double values[2][3] = { { 0, 0, 0 }, { 1, 1, 1 } };
  for (int a = 0; a < 3; ++a)
  {
    vtkNew<vtkDoubleArray> array;
    array->SetName(names[a]);
    array->SetNumberOfValues(a == 2 ? 6 : 3);
    for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
    {
      array->SetValue(i, a == 2 ? extent[i] : values[a][i]);
    }
    data->GetFieldData()->AddArray(array);
  }
  return data;
}

// Updates a filter on `input` that expects an error with `expected` (empty
// outputs) or, with `expected` empty, a spectrum.
void ExpectUpdate(vtkBlueNoiseSpectrum* filter, vtkDataObject* input, const std::string& expected,
  const std::string& what)
{
  vtkNew<MessageObserver> observer;
  observer->Watch(filter);
  observer->Watch(filter->GetExecutive());
  filter->SetInputData(input);
  filter->Update();
  if (expected.empty())
  {
    Check(observer->Errors.empty() && filter->GetOutput()->GetNumberOfRows() > 0,
      what + ": expected a spectrum, got '" + observer->Errors + "'");
    return;
  }
  Check(observer->ErrorContains(expected),
    what + ": expected an error with '" + expected + "', got '" + observer->Errors + "'");
  Check(OutputsEmpty(filter), what + ": outputs not empty");
}

// Field data may declare extents up to 2^30 a side, whose grids aborted on
// their allocation: every grid beyond MaximumNumberOfGridPoints is an error
// before any allocation, whichever rule gave it, and a grid within the limit
// that the memory cannot hold is an error too.
void GridLimits()
{
  const std::string beyond = "more than MaximumNumberOfGridPoints";
  const double wide[6] = { 0, 1073741823, 0, 1, 0, 1 };
  const double span[6] = { -1073741823, 1073741823, -1073741823, 1073741823, -1073741823,
    1073741823 };
  vtkNew<vtkBlueNoiseSpectrum> filter;
  Check(filter->GetMaximumNumberOfGridPoints() == 1073741824, "the default limit is 1024^3");
  ExpectUpdate(filter, WithSamplingGrid(wide), beyond, "a 2^30 x 2 x 2 field-data grid");
  ExpectUpdate(filter, WithSamplingGrid(span), beyond, "a (2^31 - 1)^3 field-data grid");

  // The limit is the property's: an 8^3 grid needs 512.
  const double small[6] = { 0, 7, 0, 7, 0, 7 };
  filter->SetMaximumNumberOfGridPoints(511);
  ExpectUpdate(filter, WithSamplingGrid(small), beyond, "an 8^3 grid at a limit of 511");
  filter->SetMaximumNumberOfGridPoints(512);
  ExpectUpdate(filter, WithSamplingGrid(small), "", "an 8^3 grid at a limit of 512");
  filter->SetGridDimensions(9, 8, 8);
  filter->UseInputGridOff();
  ExpectUpdate(filter, WithSamplingGrid(small), beyond, "GridDimensions 9 8 8 at a limit of 512");

  // No limit: a 2^30 x 2^20 x 2 grid (2^54 bytes) the memory cannot hold.
  const double impossible[6] = { 0, 1073741823, 0, 1048575, 0, 1 };
  filter->UseInputGridOn();
  filter->SetMaximumNumberOfGridPoints(VTK_ID_MAX);
  ExpectUpdate(filter, WithSamplingGrid(impossible),
    "1073741824 x 1048576 x 2 grid of the SamplingGridExtent field data cannot be allocated",
    "a 2^54-byte grid without limit");
  // The same filter then measures a small grid.
  ExpectUpdate(filter, WithSamplingGrid(small), "", "an 8^3 grid after the failures");
}

void FilterSinglePointAndFullMask()
{
  // One point, grid from GridDimensions over GridBounds.
  vtkNew<vtkPolyData> one;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.3, 0.6, 0.2);
  one->SetPoints(points);
  vtkNew<vtkBlueNoiseSpectrum> filter;
  filter->SetInputData(one);
  filter->SetGridDimensions(16, 16, 16);
  filter->SetGridBounds(0.0, 1.0, 0.0, 1.0, 0.0, 1.0);
  filter->UseGridBoundsOn();
  filter->Update();
  Result r;
  if (ResultFromTable(filter->GetOutput(), r))
  {
    Check(
      r.RadialPower.size() == 14, "filter, one point: " + Str(r.RadialPower.size()) + " shells");
    for (std::size_t i = 0; i < r.RadialPower.size(); ++i)
    {
      Check(std::abs(r.RadialPower[i] - 1.0) <= 1e-9 && std::abs(r.Anisotropy[i]) <= 1e-9,
        "filter, one point, shell " + Str(i + 1) + ": power " + Str(r.RadialPower[i]) +
          ", anisotropy " + Str(r.Anisotropy[i]));
    }
    Check(r.NumberOfPoints == 1.0, "filter, one point: N = " + Str(r.NumberOfPoints));
  }

  // Full mask through the filter: a warning and nothing but finite numbers.
  const int dims[3] = { 12, 12, 12 };
  vtkNew<vtkUnsignedCharArray> ones;
  ones->SetNumberOfValues(12 * 12 * 12);
  ones->FillValue(1);
  vtkNew<vtkBlueNoiseSpectrum> full;
  vtkNew<MessageObserver> observer;
  observer->Watch(full);
  full->SetInputData(MaskImage(dims, ones));
  full->Update();
  Check(observer->ErrorCount == 0, "full mask: unexpected error '" + observer->Errors + "'");
  Check(observer->Warnings.find("g = 1") != std::string::npos,
    "full mask: expected a warning about g = 1, got '" + observer->Warnings + "'");
  vtkTable* table = full->GetOutput();
  Check(table->GetNumberOfRows() > 0, "full mask: empty table");
  bool finite = true;
  for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
  {
    // The marker column is NaN but at the principal frequency, by design.
    const bool marker = std::string(table->GetColumnName(c)) == "PrincipalFrequencyMarker";
    vtkDataArray* column = marker ? nullptr : vtkDataArray::SafeDownCast(table->GetColumn(c));
    for (vtkIdType i = 0; column && i < column->GetNumberOfTuples(); ++i)
    {
      finite = finite && std::isfinite(column->GetComponent(i, 0));
    }
  }
  vtkFieldData* fd = table->GetFieldData();
  for (int a = 0; a < fd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = fd->GetArray(a);
    for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
    {
      finite = finite && std::isfinite(array->GetComponent(0, static_cast<int>(i)));
    }
  }
  Check(finite, "full mask: a NaN or infinity in the table");
  if (ResultFromTable(table, r))
  {
    Check(r.LowFrequencyRatio == 0.0 && r.Symmetry == 1.0,
      "full mask through the filter: L = " + Str(r.LowFrequencyRatio) + ", S = " + Str(r.Symmetry));
  }
}

// GridDimensions below 2 are clamped to 2 (the XML's domain), and the filter runs.
void GridDimensionsClamp()
{
  vtkNew<vtkBlueNoiseSpectrum> filter;
  filter->SetGridDimensions(1, -4, 5);
  const int* dims = filter->GetGridDimensions();
  Check(dims[0] == 2 && dims[1] == 2 && dims[2] == 5,
    "SetGridDimensions(1, -4, 5) gives " + Str(dims[0]) + " " + Str(dims[1]) + " " + Str(dims[2]));
  const vtkMTimeType before = filter->GetMTime();
  filter->SetGridDimensions(0, 2, 5);
  Check(filter->GetMTime() == before, "the same clamped dimensions do not modify the filter");
  vtkNew<vtkPolyData> two;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.1, 0.2, 0.3);
  points->InsertNextPoint(0.7, 0.8, 0.9);
  two->SetPoints(points);
  filter->SetInputData(two);
  filter->Update();
  Check(filter->GetOutput()->GetNumberOfRows() > 0, "the clamped grid gives a spectrum");
}
}

int main()
{
  std::mt19937 rng(31);
  NonCubicWhiteNoise(rng);
  KernelErrors();
  FullMask(rng);
  FilterErrors();
  GridLimits();
  FilterSinglePointAndFullMask();
  GridDimensionsClamp();
  return bluenoise_test::Summary("TestBlueNoiseSpectrumEdgeCases");
}
