// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSamplingLattice.h"

#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

//------------------------------------------------------------------------------
void vtkSamplingLattice::CellExtent(const int points[6], int cells[6])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    const int lo = points[2 * axis];
    const int hi = points[2 * axis + 1];
    cells[2 * axis] = lo;
    // An empty axis stays empty; a single point keeps its flat cells' centre.
    cells[2 * axis + 1] = hi > lo ? hi - 1 : hi;
  }
}

//------------------------------------------------------------------------------
void vtkSamplingLattice::PointExtent(const int cells[6], const int whole[6], int points[6])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    const bool flat = whole[2 * axis + 1] <= whole[2 * axis];
    points[2 * axis] = cells[2 * axis];
    points[2 * axis + 1] =
      flat || cells[2 * axis + 1] < cells[2 * axis] ? cells[2 * axis + 1] : cells[2 * axis + 1] + 1;
  }
}

//------------------------------------------------------------------------------
void vtkSamplingLattice::CellOrigin(const int points[6], const double origin[3],
  const double spacing[3], const double direction[9], double cellOrigin[3])
{
  // Half a step along every axis that has cells, in world coordinates.
  double half[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    half[axis] = points[2 * axis + 1] > points[2 * axis] ? 0.5 * spacing[axis] : 0.0;
  }
  for (int row = 0; row < 3; ++row)
  {
    cellOrigin[row] = origin[row] + direction[3 * row] * half[0] +
      direction[3 * row + 1] * half[1] + direction[3 * row + 2] * half[2];
  }
}

//------------------------------------------------------------------------------
void vtkSamplingLattice::ToCellLattice(vtkInformation* info)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (!info->Has(SDDP::WHOLE_EXTENT()))
  {
    return;
  }
  int points[6];
  info->Get(SDDP::WHOLE_EXTENT(), points);
  int cells[6];
  CellExtent(points, cells);
  info->Set(SDDP::WHOLE_EXTENT(), cells, 6);
  double origin[3] = { 0.0, 0.0, 0.0 };
  double spacing[3] = { 1.0, 1.0, 1.0 };
  double direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  if (info->Has(vtkDataObject::ORIGIN()))
  {
    info->Get(vtkDataObject::ORIGIN(), origin);
  }
  if (info->Has(vtkDataObject::SPACING()))
  {
    info->Get(vtkDataObject::SPACING(), spacing);
  }
  if (info->Has(vtkDataObject::DIRECTION()))
  {
    info->Get(vtkDataObject::DIRECTION(), direction);
  }
  double cellOrigin[3];
  CellOrigin(points, origin, spacing, direction, cellOrigin);
  info->Set(vtkDataObject::ORIGIN(), cellOrigin, 3);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkSamplingLattice::FromCells(vtkImageData* image)
{
  int points[6];
  image->GetExtent(points);
  int cells[6];
  CellExtent(points, cells);
  const double* direction = image->GetDirectionMatrix()->GetData();
  double cellOrigin[3];
  CellOrigin(points, image->GetOrigin(), image->GetSpacing(), direction, cellOrigin);

  auto lattice = vtkSmartPointer<vtkImageData>::New();
  lattice->SetExtent(cells);
  lattice->SetOrigin(cellOrigin);
  lattice->SetSpacing(image->GetSpacing());
  lattice->SetDirectionMatrix(direction);
  vtkPointData* sites = lattice->GetPointData();
  sites->ShallowCopy(image->GetCellData());

  // The same bits mean other things on cells: translate what is not owned.
  vtkUnsignedCharArray* cellGhosts = image->GetCellGhostArray();
  if (cellGhosts)
  {
    auto pointGhosts = vtkSmartPointer<vtkUnsignedCharArray>::New();
    pointGhosts->SetName(vtkDataSetAttributes::GhostArrayName());
    const vtkIdType n = cellGhosts->GetNumberOfValues();
    pointGhosts->SetNumberOfValues(n);
    const unsigned char* in = cellGhosts->GetPointer(0);
    unsigned char* out = pointGhosts->GetPointer(0);
    std::transform(in, in + n, out, [](unsigned char flags) {
      unsigned char site = 0;
      if (flags & vtkDataSetAttributes::DUPLICATECELL)
      {
        site |= vtkDataSetAttributes::DUPLICATEPOINT;
      }
      if (flags & vtkDataSetAttributes::HIDDENCELL)
      {
        site |= vtkDataSetAttributes::HIDDENPOINT;
      }
      return site;
    });
    sites->RemoveArray(vtkDataSetAttributes::GhostArrayName());
    sites->AddArray(pointGhosts);
  }
  return lattice;
}
