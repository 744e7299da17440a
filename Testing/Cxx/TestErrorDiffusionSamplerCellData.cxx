// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// A cell-data array is sampled with one site per cell, at the cells' centres:
// the same points as the point image those centres make (rotated, shifted,
// anisotropic grid), cell arrays carried, the mask and the field data on the
// cell lattice, the same points streamed in slabs, flat (2D) images, and a
// clear error for a cell array selected as point data.
#include "SamplerTestUtilities.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"
#include "vtkPointDataToCellData.h"
#include "vtkRTAnalyticSource.h"

#include <cmath>

using namespace bluenoise_test;

namespace
{
const double Origin[3] = { 1.0, -2.0, 3.0 };
const double Spacing[3] = { 0.5, 1.0, 2.0 };
// A rotation about z by 30 degrees (row major).
const double Direction[9] = { 0.8660254037844387, -0.5, 0.0, 0.5, 0.8660254037844387, 0.0, 0.0,
  0.0, 1.0 };

float Heat(int i, int j, int k)
{
  return static_cast<float>(0.05 + 0.3 * (i + 2 * j + 3 * k) / 60.0);
}

// nx*ny*nz cells: a float cell array "heat" (active scalars) and an int "cell" (its index).
vtkSmartPointer<vtkImageData> MakeCellImage(int nx, int ny, int nz)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx + 1, ny + 1, nz > 0 ? nz + 1 : 1);
  image->SetOrigin(Origin);
  image->SetSpacing(Spacing);
  image->SetDirectionMatrix(Direction);
  const int layers = nz > 0 ? nz : 1;
  vtkNew<vtkFloatArray> heat;
  heat->SetName("heat");
  vtkNew<vtkIntArray> cell;
  cell->SetName("cell");
  for (int k = 0; k < layers; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        heat->InsertNextValue(Heat(i, j, k));
        cell->InsertNextValue(static_cast<int>(cell->GetNumberOfValues()));
      }
    }
  }
  image->GetCellData()->SetScalars(heat);
  image->GetCellData()->AddArray(cell);
  return image;
}

// The image of the cells' centres, built by hand: origin half a step inside.
vtkSmartPointer<vtkImageData> MakeCentreImage(int nx, int ny, int nz)
{
  auto image = MakeVolume(nx, ny, nz > 0 ? nz : 1, Heat, "heat");
  const double half[3] = { 0.5 * Spacing[0], 0.5 * Spacing[1], nz > 0 ? 0.5 * Spacing[2] : 0.0 };
  double origin[3];
  for (int r = 0; r < 3; ++r)
  {
    origin[r] = Origin[r] + Direction[3 * r] * half[0] + Direction[3 * r + 1] * half[1] +
      Direction[3 * r + 2] * half[2];
  }
  image->SetOrigin(origin);
  image->SetSpacing(Spacing);
  image->SetDirectionMatrix(Direction);
  return image;
}

void SampleCells(vtkErrorDiffusionSampler* s)
{
  s->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "heat");
  s->GenerateMaskOn();
}

bool SamePoints(vtkPolyData* a, vtkPolyData* b, double tolerance)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints())
  {
    return false;
  }
  for (vtkIdType p = 0; p < a->GetNumberOfPoints(); ++p)
  {
    double x[3], y[3];
    a->GetPoint(p, x);
    b->GetPoint(p, y);
    if (std::abs(x[0] - y[0]) > tolerance || std::abs(x[1] - y[1]) > tolerance ||
      std::abs(x[2] - y[2]) > tolerance)
    {
      return false;
    }
  }
  return true;
}

void CheckAgainstCentres(int nx, int ny, int nz, const std::string& what)
{
  auto cells = MakeCellImage(nx, ny, nz);
  auto centres = MakeCentreImage(nx, ny, nz);
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(cells);
  sampler->SetDensityMappingToIdentity();
  sampler->UseNumberOfPointsOff();
  SampleCells(sampler);
  sampler->Update();
  vtkPolyData* fromCells = sampler->GetOutput();
  auto fromCentres = Sample(centres);
  Check(fromCells->GetNumberOfPoints() > 10, what + ": points drawn (" +
      Str(fromCells->GetNumberOfPoints()) + ")");
  Check(SamePoints(fromCells, fromCentres, 1e-4), what + ": the points of the centre image");

  // Each sample carries the index of the cell it lies in.
  auto* cell = vtkIntArray::SafeDownCast(fromCells->GetPointData()->GetArray("cell"));
  int wrong = 0;
  for (vtkIdType p = 0; cell && p < fromCells->GetNumberOfPoints(); ++p)
  {
    double x[3];
    fromCells->GetPoint(p, x);
    int ijk[3];
    double pcoords[3];
    if (!cells->ComputeStructuredCoordinates(x, ijk, pcoords) ||
      cell->GetValue(p) != ijk[0] + nx * (ijk[1] + ny * ijk[2]))
    {
      ++wrong;
    }
  }
  Check(cell != nullptr && wrong == 0, what + ": cell array carried (" + Str(wrong) + " wrong)");

  // The mask and the recorded grid are the cell lattice.
  vtkImageData* mask = sampler->GetMaskOutput();
  int extent[6];
  mask->GetExtent(extent);
  const int expected[6] = { 0, nx - 1, 0, ny - 1, 0, nz > 0 ? nz - 1 : 0 };
  Check(std::equal(extent, extent + 6, expected), what + ": mask on the cell extent");
  auto* origin = vtkDoubleArray::SafeDownCast(
    fromCells->GetFieldData()->GetArray("SamplingGridOrigin"));
  Check(origin && std::abs(origin->GetValue(0) - centres->GetOrigin()[0]) < 1e-12 &&
      std::abs(origin->GetValue(2) - centres->GetOrigin()[2]) < 1e-12,
    what + ": SamplingGridOrigin at the first cell's centre");
}
}

int main()
{
  CheckAgainstCentres(20, 16, 12, "3D cells");
  CheckAgainstCentres(40, 30, 0, "2D cells");

  // Streamed in slabs: the same points as in one go (cells from a point source).
  vtkSmartPointer<vtkPolyData> whole;
  for (int slabs : { 1, 3 })
  {
    vtkNew<vtkRTAnalyticSource> source;
    source->SetWholeExtent(0, 32, 0, 24, 0, 40);
    vtkNew<vtkPointDataToCellData> toCells;
    toCells->SetInputConnection(source->GetOutputPort());
    toCells->PassPointDataOff();
    vtkNew<vtkErrorDiffusionSampler> sampler;
    sampler->SetInputConnection(toCells->GetOutputPort());
    sampler->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "RTData");
    sampler->SetNumberOfPoints(3000);
    sampler->SetNumberOfSlabs(slabs);
    sampler->JitterOn();
    sampler->Update();
    vtkPolyData* out = sampler->GetOutput();
    Check(std::abs(out->GetNumberOfPoints() - 3000) <= 2,
      "RTData cells, " + Str(slabs) + " slab(s): 3000 points (" + Str(out->GetNumberOfPoints()) +
        ")");
    if (!whole)
    {
      whole = vtkSmartPointer<vtkPolyData>::New();
      whole->DeepCopy(out);
    }
    else
    {
      Check(SamePoints(whole, out, 0.0), "RTData cells: the same points in 3 slabs as in one");
    }
  }

  // A cell array selected as point data: no such point array.
  {
    vtkNew<vtkErrorDiffusionSampler> sampler;
    sampler->SetInputData(MakeCellImage(8, 8, 8));
    sampler->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "heat");
    vtkNew<MessageObserver> messages;
    messages->Watch(sampler);
    sampler->Update();
    Check(sampler->GetOutput()->GetNumberOfPoints() == 0 && messages->ErrorCount > 0,
      "cell array selected as point data: an error and no points");
    // Found in the cells by POINTS_THEN_CELLS: the error says how to select it.
    messages->Clear();
    sampler->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS, "heat");
    sampler->Update();
    Check(messages->ErrorContains("FIELD_ASSOCIATION_CELLS") &&
        sampler->GetOutput()->GetNumberOfPoints() == 0,
      "cell array found by POINTS_THEN_CELLS: the error names FIELD_ASSOCIATION_CELLS");
    // The next good update works.
    messages->Clear();
    sampler->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, "heat");
    sampler->Update();
    Check(sampler->GetOutput()->GetNumberOfPoints() > 0 && messages->ErrorCount == 0,
      "then selected as cell data: points and no error");
  }
  return Summary("TestErrorDiffusionSamplerCellData");
}
