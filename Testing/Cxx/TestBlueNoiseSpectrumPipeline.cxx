// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The filter against the kernel: points at voxel centers with the sampler's
// grid field data (rotated, offset extent), an image mask (uint8, a converted
// integer type, cell data), averaged realizations (two connections, a
// multiblock), a grid built over the bounds, the spectrum image's geometry and
// the outside-points warning. A rotated input image (directly, and through the
// sampler) gives an axis-aligned spectrum image, the sampler's points staying in
// world coordinates.
#include "TestBlueNoiseSpectrumUtilities.h"

#include "vtkBlueNoiseSpectrum.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShortArray.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>

using namespace spectrum_test;
using bluenoise_test::MessageObserver;

namespace
{
const int Dims[3] = { 20, 24, 16 };
const int Lower[3] = { 2, 3, -1 };
const double Origin[3] = { 1.0, 2.0, 3.0 };
const double Spacing[3] = { 0.5, 0.25, 1.0 };
// 90 degrees about z, row major, index to physical.
const double Direction[9] = { 0, -1, 0, 1, 0, 0, 0, 0, 1 };

// The set voxels of `mask` as points at voxel centers, with the sampler's grid.
vtkSmartPointer<vtkPolyData> SamplerPoints(const std::vector<unsigned char>& mask)
{
  auto data = MaskPoints(mask, Dims,
    [](int i, int j, int k, double x[3])
    {
      const double s[3] = { (i + Lower[0]) * Spacing[0], (j + Lower[1]) * Spacing[1],
        (k + Lower[2]) * Spacing[2] };
      for (int a = 0; a < 3; ++a)
      {
        x[a] = Origin[a] + Direction[3 * a] * s[0] + Direction[3 * a + 1] * s[1] +
          Direction[3 * a + 2] * s[2];
      }
    });
  const int extent[6] = { Lower[0], Lower[0] + Dims[0] - 1, Lower[1], Lower[1] + Dims[1] - 1,
    Lower[2], Lower[2] + Dims[2] - 1 };
  AddSamplingGrid(data, Origin, Spacing, extent, Direction);
  return data;
}

// The mask as an image on the same grid: the active scalars, or with `cells`
// a cell-data array named "cellmask".
template <typename ArrayT>
vtkSmartPointer<vtkImageData> MaskImage(
  const std::vector<unsigned char>& mask, bool cells, const double* direction = Direction)
{
  vtkNew<ArrayT> values;
  values->SetNumberOfTuples(static_cast<vtkIdType>(mask.size()));
  for (std::size_t v = 0; v < mask.size(); ++v)
  {
    values->SetComponent(static_cast<vtkIdType>(v), 0, mask[v]);
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  const int c = cells ? 1 : 0;
  image->SetExtent(Lower[0], Lower[0] + Dims[0] - 1 + c, Lower[1], Lower[1] + Dims[1] - 1 + c,
    Lower[2], Lower[2] + Dims[2] - 1 + c);
  image->SetOrigin(Origin[0], Origin[1], Origin[2]);
  image->SetSpacing(Spacing[0], Spacing[1], Spacing[2]);
  image->SetDirectionMatrix(direction);
  if (cells)
  {
    values->SetName("cellmask");
    image->GetCellData()->AddArray(values);
  }
  else
  {
    image->GetPointData()->SetScalars(values);
  }
  return image;
}

Result KernelResult(const std::vector<std::vector<unsigned char>>& masks, const int dims[3],
  std::vector<double>* spectrum = nullptr)
{
  vtkBlueNoiseSpectrumKernel kernel;
  kernel.SetDimensions(dims[0], dims[1], dims[2]);
  for (const auto& mask : masks)
  {
    kernel.AddRealization(mask.data());
  }
  Result r;
  kernel.Compute(r);
  if (spectrum)
  {
    kernel.GetCenteredPowerSpectrum(*spectrum);
  }
  return r;
}

// `warning`: a part of the one warning expected, none when empty.
void CheckFilter(vtkBlueNoiseSpectrum* filter, const Result& expected, const std::string& what,
  const std::string& warning = std::string())
{
  vtkNew<MessageObserver> observer;
  observer->Watch(filter);
  filter->Update();
  Check(observer->ErrorCount == 0 &&
      observer->WarningCount == (warning.empty() ? 0 : 1) &&
      observer->Warnings.find(warning) != std::string::npos,
    what + ": unexpected messages '" + observer->Errors + observer->Warnings + "'");
  Result r;
  if (ResultFromTable(filter->GetOutput(), r))
  {
    CheckSameResult(r, expected, 1e-12, what);
  }
}

// Spacing 1/L, and the point of index floor(L/2) at frequency 0.
bool CheckImageGeometry(vtkImageData* image, const int dims[3], const std::string& what)
{
  int d[3];
  image->GetDimensions(d);
  if (!Check(d[0] == dims[0] && d[1] == dims[1] && d[2] == dims[2],
        what + ": image dimensions " + Str(d[0]) + " " + Str(d[1]) + " " + Str(d[2])))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    CheckClose(image->GetSpacing()[a], 1.0 / dims[a], 1e-15, what + " spacing");
  }
  double center[3];
  int c[3] = { dims[0] / 2, dims[1] / 2, dims[2] / 2 };
  image->GetPoint(image->ComputePointId(c), center);
  return Check(std::abs(center[0]) + std::abs(center[1]) + std::abs(center[2]) < 1e-15,
    what + ": index floor(L/2) is at " + Str(center[0]) + " " + Str(center[1]) + " " +
      Str(center[2]) + ", not at frequency 0");
}

void CheckImage(vtkImageData* image, const int dims[3], const std::vector<double>& spectrum,
  const std::string& what)
{
  if (!CheckImageGeometry(image, dims, what))
  {
    return;
  }
  int c[3] = { dims[0] / 2, dims[1] / 2, dims[2] / 2 };
  vtkDataArray* power = image->GetPointData()->GetArray("Power");
  if (!Check(power && power->GetNumberOfTuples() == static_cast<vtkIdType>(spectrum.size()),
        what + ": no Power array of the right size"))
  {
    return;
  }
  bool same = true;
  for (std::size_t i = 0; i < spectrum.size(); ++i)
  {
    same = same && Close(power->GetComponent(static_cast<vtkIdType>(i), 0), spectrum[i], 1e-12);
  }
  Check(same, what + ": Power differs from the kernel's centered spectrum");
  Check(power->GetComponent(image->ComputePointId(c), 0) == 0.0, what + ": DC is not 0");
}

// The spectrum image's axes are the frequency axes, whatever the input's
// direction: an identity direction on the data and in the output information.
void CheckAxisAligned(vtkBlueNoiseSpectrum* filter, const std::string& what)
{
  Check(filter->GetSpectrumImageOutput()->GetDirectionMatrix()->IsIdentity(),
    what + ": the spectrum image is rotated");
  double direction[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
  vtkInformation* info = filter->GetOutputInformation(1);
  if (Check(info->Has(vtkDataObject::DIRECTION()),
        what + ": no DIRECTION in the spectrum image's information"))
  {
    info->Get(vtkDataObject::DIRECTION(), direction);
    bool identity = true;
    for (int e = 0; e < 9; ++e)
    {
      identity = identity && direction[e] == (e % 4 == 0 ? 1.0 : 0.0);
    }
    Check(identity, what + ": the spectrum image's information has a rotated DIRECTION");
  }
}
}

int main()
{
  std::mt19937 rng(4242);
  const std::vector<unsigned char> mask = RandomMask(Dims, 0.1, rng);
  const std::vector<unsigned char> second = RandomMask(Dims, 0.15, rng);
  std::vector<double> spectrum;
  const Result single = KernelResult({ mask }, Dims, &spectrum);

  // Points with the sampler's field data.
  {
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(SamplerPoints(mask));
    CheckFilter(filter, single, "sampler points");
    CheckImage(filter->GetSpectrumImageOutput(), Dims, spectrum, "sampler points");
    int wholeExtent[6];
    filter->GetOutputInformation(1)->Get(
      vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent);
    Check(wholeExtent[1] == Dims[0] - 1 && wholeExtent[3] == Dims[1] - 1 &&
        wholeExtent[5] == Dims[2] - 1,
      "sampler points: WHOLE_EXTENT of the spectrum image not corrected");
    vtkDataArray* grid = filter->GetOutput()->GetFieldData()->GetArray("GridDimensions");
    Check(grid && grid->GetComponent(0, 0) == Dims[0] && grid->GetComponent(0, 1) == Dims[1] &&
        grid->GetComponent(0, 2) == Dims[2],
      "sampler points: GridDimensions field array");

    filter->GenerateSpectrumImageOff();
    filter->Update();
    Check(filter->GetSpectrumImageOutput()->GetNumberOfPoints() == 0,
      "GenerateSpectrumImage off still produced an image");
  }

  // Image masks: uint8 point data (used directly), short (converted), cells.
  {
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(MaskImage<vtkUnsignedCharArray>(mask, false));
    CheckFilter(filter, single, "uint8 image");
    CheckImage(filter->GetSpectrumImageOutput(), Dims, spectrum, "uint8 image");
    int wholeExtent[6];
    filter->UpdateInformation();
    filter->GetOutputInformation(1)->Get(
      vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent);
    Check(wholeExtent[1] == Dims[0] - 1 && wholeExtent[3] == Dims[1] - 1 &&
        wholeExtent[5] == Dims[2] - 1,
      "uint8 image: RequestInformation announces a wrong WHOLE_EXTENT");
    CheckAxisAligned(filter, "uint8 image (rotated)");
  }

  // A rotated image through the sampler: points on the image's voxel centers in
  // world coordinates, and the same axis-aligned spectrum of their grid.
  {
    vtkSmartPointer<vtkImageData> image = MaskImage<vtkUnsignedCharArray>(mask, false);
    vtkNew<vtkErrorDiffusionSampler> sampler;
    sampler->SetInputData(image);
    sampler->SetDensityMappingToIdentity();
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputConnection(sampler->GetOutputPort());
    filter->Update();
    vtkPolyData* points = sampler->GetOutput();
    const vtkIdType n = points->GetNumberOfPoints();
    int offCenter = 0;
    for (vtkIdType p = 0; p < n; ++p)
    {
      double x[3], ijk[3];
      points->GetPoint(p, x);
      image->TransformPhysicalPointToContinuousIndex(x, ijk);
      for (int a = 0; a < 3; ++a)
      {
        const double i = std::round(ijk[a]);
        offCenter += (std::abs(ijk[a] - i) > 1e-4 || i < Lower[a] || i >= Lower[a] + Dims[a]);
      }
    }
    Check(n > 0 && offCenter == 0,
      "sampler on a rotated image: " + Str(offCenter) + " coordinates of " + Str(n) +
        " points off the image's voxel centers in world coordinates");
    Result r;
    if (ResultFromTable(filter->GetOutput(), r))
    {
      CheckClose(r.NumberOfPoints, static_cast<double>(n), 0.0, "sampler on a rotated image: N");
    }
    CheckImageGeometry(filter->GetSpectrumImageOutput(), Dims, "sampler on a rotated image");
    CheckAxisAligned(filter, "sampler on a rotated image");
  }
  {
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(MaskImage<vtkShortArray>(mask, false));
    CheckFilter(filter, single, "int16 image");
    // ParaView's empty array name before a pick means the active scalars.
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "");
    CheckFilter(filter, single, "empty array name");
  }
  {
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(MaskImage<vtkDoubleArray>(mask, true));
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "cellmask");
    CheckFilter(filter, single, "cell-data image");
  }

  // Images with UseInputGrid off: their point (or cell-center) positions,
  // weighted by the values, binned to GridDimensions over the bounds.
  {
    const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(MaskImage<vtkUnsignedCharArray>(mask, false, identity));
    filter->UseInputGridOff();
    filter->SetGridDimensions(Dims[0], Dims[1], Dims[2]);
    CheckFilter(filter, single, "image points over the bounds");

    vtkNew<vtkBlueNoiseSpectrum> cells;
    cells->SetInputData(MaskImage<vtkDoubleArray>(mask, true, identity));
    cells->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "cellmask");
    cells->UseInputGridOff();
    cells->SetGridDimensions(Dims[0], Dims[1], Dims[2]);
    // The cell centers' lattice, moved a quarter voxel so that a point half a
    // voxel off its center would not tie.
    double centers[6];
    for (int a = 0; a < 3; ++a)
    {
      centers[2 * a] = Origin[a] + (Lower[a] + 0.75) * Spacing[a];
      centers[2 * a + 1] = Origin[a] + (Lower[a] + Dims[a] - 0.25) * Spacing[a];
    }
    cells->SetGridBounds(centers);
    cells->UseGridBoundsOn();
    CheckFilter(cells, single, "image cell centers over GridBounds");
  }

  // Two realizations: two connections, and a multiblock of two.
  const Result averaged = KernelResult({ mask, second }, Dims);
  {
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->AddInputData(SamplerPoints(mask));
    filter->AddInputData(MaskImage<vtkUnsignedCharArray>(second, false));
    CheckFilter(filter, averaged, "two connections");
  }
  {
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetBlock(0, SamplerPoints(mask));
    blocks->SetBlock(1, SamplerPoints(second));
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(blocks);
    CheckFilter(filter, averaged, "multiblock");
  }

  // No field data: GridDimensions over the bounds. Points on integer
  // coordinates with both corners set span exactly Dims grid points.
  {
    std::vector<unsigned char> spanning = mask;
    spanning.front() = 1;
    spanning.back() = 1;
    vtkSmartPointer<vtkPolyData> data = MaskPoints(spanning, Dims,
      [](int i, int j, int k, double x[3])
      {
        x[0] = 10.0 + 2.0 * i;
        x[1] = -5.0 + 0.5 * j;
        x[2] = 3.0 * k;
      });
    vtkPoints* points = data->GetPoints();
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(data);
    filter->SetGridDimensions(Dims[0], Dims[1], Dims[2]);
    // Plain points: the grid is assumed, and the warning names it.
    CheckFilter(filter, KernelResult({ spanning }, Dims), "grid over the bounds",
      "extent [0, " + Str(Dims[0] - 1) + ", 0, " + Str(Dims[1] - 1) + ", 0, " +
        Str(Dims[2] - 1) + "]");

    // The sampler's points with UseInputGrid off use GridDimensions too.
    vtkNew<vtkBlueNoiseSpectrum> forced;
    forced->SetInputData(SamplerPoints(mask));
    forced->UseInputGridOff();
    forced->SetGridDimensions(9, 10, 11);
    forced->Update();
    Result r;
    if (ResultFromTable(forced->GetOutput(), r))
    {
      // The corner frequency (4/9, 1/2, 5/11) lies on shell round(9 |f|) = 7.
      Check(r.Frequency.size() == 7,
        "UseInputGrid off: " + Str(r.Frequency.size()) + " shells on a 9x10x11 grid");
      CheckClose(r.NumberOfPoints, single.NumberOfPoints, 0.0, "UseInputGrid off: N");
    }
    const int odd[3] = { 9, 10, 11 };
    CheckImageGeometry(forced->GetSpectrumImageOutput(), odd, "UseInputGrid off");

    // Grid bounds that leave points out: a warning with their number.
    vtkNew<vtkBlueNoiseSpectrum> cropped;
    vtkNew<MessageObserver> observer;
    observer->Watch(cropped);
    cropped->SetInputData(data);
    cropped->SetGridDimensions(8, 8, 8);
    cropped->SetGridBounds(10.0, 20.0, -5.0, 0.0, 0.0, 20.0);
    cropped->UseGridBoundsOn();
    cropped->Update();
    vtkIdType inside = 0;
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double x[3];
      points->GetPoint(i, x);
      inside +=
        (x[0] <= 20.0 + 10.0 / 14 && x[1] <= 0.0 + 5.0 / 14 && x[2] <= 20.0 + 20.0 / 14) ? 1 : 0;
    }
    const std::string count =
      Str(points->GetNumberOfPoints() - inside) + " of " + Str(points->GetNumberOfPoints());
    Check(observer->Warnings.find(count) != std::string::npos,
      "cropped grid: expected a warning about " + count + " points, got '" + observer->Warnings +
        "'");
    if (ResultFromTable(cropped->GetOutput(), r))
    {
      CheckClose(r.NumberOfPoints, static_cast<double>(inside), 0.0, "cropped grid: N");
    }
  }

  // Weight reaches the target.
  {
    vtkNew<vtkBlueNoiseSpectrum> filter;
    filter->SetInputData(SamplerPoints(mask));
    filter->SetWeight(0.5);
    filter->Update();
    Result r;
    if (ResultFromTable(filter->GetOutput(), r))
    {
      CheckClose(r.TargetValue, 0.5 * single.LowFrequencyRatio + 0.5 * single.Symmetry, 1e-14,
        "Weight 0.5: T");
    }
    filter->SetWeight(7.0);
    Check(filter->GetWeight() == 1.0, "Weight not clamped: " + Str(filter->GetWeight()));
  }
  return bluenoise_test::Summary("TestBlueNoiseSpectrumPipeline");
}
