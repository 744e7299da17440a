// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseSpectrumGrid.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMath.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
// A field-data array read as `count` doubles. False when it is absent, and
// also when it is malformed, which then sets `error`.
bool ReadFieldValues(
  vtkFieldData* fd, const char* name, int count, double* values, std::string& error)
{
  vtkDataArray* array = fd ? fd->GetArray(name) : nullptr;
  if (!array)
  {
    return false;
  }
  const vtkIdType n = array->GetNumberOfTuples() * array->GetNumberOfComponents();
  if (n != count)
  {
    std::ostringstream msg;
    msg << "field-data array " << name << " has " << n << " values, expected " << count;
    error = msg.str();
    return false;
  }
  const int nc = array->GetNumberOfComponents();
  for (int i = 0; i < count; ++i)
  {
    values[i] = array->GetComponent(i / nc, i % nc);
    if (!std::isfinite(values[i]))
    {
      error = std::string("field-data array ") + name + " holds a non-finite value";
      return false;
    }
  }
  return true;
}

// Writes `n` values at `out` and moves past them (and the reverse).
template <typename T>
void Put(double*& out, const T* values, int n)
{
  for (int i = 0; i < n; ++i)
  {
    *out++ = static_cast<double>(values[i]);
  }
}

template <typename T>
void Take(const double*& in, T* values, int n)
{
  for (int i = 0; i < n; ++i)
  {
    values[i] = static_cast<T>(*in++);
  }
}

// The arrays of a description after its six scalars, in packing order.
template <typename D, typename Visit>
void VisitArrays(D& d, Visit visit)
{
  visit(d.ImageExtent, 6);
  visit(d.Origin, 3);
  visit(d.Spacing, 3);
  visit(d.Direction, 9);
  visit(d.Extent, 6);
  visit(d.Bounds, 6);
}

void UniteExtents(int* into, const int* extent)
{
  for (int a = 0; a < 3; ++a)
  {
    into[2 * a] = std::min(into[2 * a], extent[2 * a]);
    into[2 * a + 1] = std::max(into[2 * a + 1], extent[2 * a + 1]);
  }
}
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumGrid::Description::Pack(double* out) const
{
  const double head[6] = { static_cast<double>(this->Connection), static_cast<double>(this->Leaf),
    static_cast<double>(this->NumberOfPoints), this->IsImage ? 1.0 : 0.0,
    this->CellArray ? 1.0 : 0.0, this->HasSamplingGrid ? 1.0 : 0.0 };
  Put(out, head, 6);
  VisitArrays(*this, [&out](const auto* values, int n) { Put(out, values, n); });
  static_assert(PackedSize == 6 + 6 + 3 + 3 + 9 + 6 + 6, "PackedSize and the layout differ");
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumGrid::Description::Unpack(const double* in)
{
  double head[6];
  Take(in, head, 6);
  this->Connection = static_cast<int>(head[0]);
  this->Leaf = static_cast<int>(head[1]);
  this->NumberOfPoints = static_cast<vtkIdType>(head[2]);
  this->IsImage = head[3] != 0.0;
  this->CellArray = head[4] != 0.0;
  this->HasSamplingGrid = head[5] != 0.0;
  VisitArrays(*this, [&in](auto* values, int n) { Take(in, values, n); });
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumGrid::Description::Merge(const Description& piece, std::string& error)
{
  const bool mine = this->NumberOfPoints > 0;
  const bool theirs = piece.NumberOfPoints > 0;
  if (mine && theirs && (piece.IsImage != this->IsImage || piece.CellArray != this->CellArray))
  {
    error = "its pieces are not all images, or not all point sets, with the same kind of array";
    return false;
  }
  if ((piece.HasSamplingGrid && mine && !this->HasSamplingGrid) ||
    (this->HasSamplingGrid && theirs && !piece.HasSamplingGrid))
  {
    error = "some of its pieces have points but no SamplingGrid field data while others have it";
    return false;
  }
  if (piece.HasSamplingGrid && this->HasSamplingGrid &&
    !(std::equal(piece.Origin, piece.Origin + 3, this->Origin) &&
      std::equal(piece.Spacing, piece.Spacing + 3, this->Spacing) &&
      std::equal(piece.Direction, piece.Direction + 9, this->Direction)))
  {
    error = "its pieces' SamplingGrid field data differ in origin, spacing or direction";
    return false;
  }
  if (piece.HasSamplingGrid && !this->HasSamplingGrid)
  {
    this->HasSamplingGrid = true;
    std::copy(piece.Origin, piece.Origin + 3, this->Origin);
    std::copy(piece.Spacing, piece.Spacing + 3, this->Spacing);
    std::copy(piece.Direction, piece.Direction + 9, this->Direction);
    std::copy(piece.Extent, piece.Extent + 6, this->Extent);
  }
  else if (piece.HasSamplingGrid)
  {
    UniteExtents(this->Extent, piece.Extent);
  }
  if (theirs)
  {
    if (!mine)
    {
      this->IsImage = piece.IsImage;
      this->CellArray = piece.CellArray;
    }
    UniteExtents(this->ImageExtent, piece.ImageExtent);
    vtkBlueNoiseSpectrumGrid::UniteBounds(this->Bounds, piece.Bounds);
  }
  this->NumberOfPoints += piece.NumberOfPoints;
  return true;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumGrid::Description::ReadSamplingGrid(vtkFieldData* fd, std::string& error)
{
  double origin[3], spacing[3], extent[6];
  double direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  const bool hasOrigin = ReadFieldValues(fd, "SamplingGridOrigin", 3, origin, error);
  const bool hasSpacing =
    error.empty() && ReadFieldValues(fd, "SamplingGridSpacing", 3, spacing, error);
  const bool hasExtent =
    error.empty() && ReadFieldValues(fd, "SamplingGridExtent", 6, extent, error);
  if (error.empty())
  {
    ReadFieldValues(fd, "SamplingGridDirection", 9, direction, error);
  }
  this->HasSamplingGrid = hasOrigin || hasSpacing || hasExtent;
  if (!error.empty())
  {
    return false;
  }
  if (!this->HasSamplingGrid)
  {
    return true;
  }
  if (!(hasOrigin && hasSpacing && hasExtent))
  {
    error = "the field data has only part of SamplingGridOrigin, SamplingGridSpacing and "
            "SamplingGridExtent";
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    if (spacing[a] == 0.0)
    {
      error = "SamplingGridSpacing has a zero component";
      return false;
    }
    // Whole numbers, and small enough that the extent and its width are ints.
    const double limit = VTK_INT_MAX / 2;
    if (extent[2 * a + 1] < extent[2 * a] || extent[2 * a] != std::floor(extent[2 * a]) ||
      extent[2 * a + 1] != std::floor(extent[2 * a + 1]) || !(std::abs(extent[2 * a]) <= limit) ||
      !(std::abs(extent[2 * a + 1]) <= limit))
    {
      error = "SamplingGridExtent is not an extent (i0 i1 j0 j1 k0 k1 with whole i0 <= i1 ...)";
      return false;
    }
  }
  const double d[3][3] = { { direction[0], direction[1], direction[2] },
    { direction[3], direction[4], direction[5] }, { direction[6], direction[7], direction[8] } };
  if (std::abs(vtkMath::Determinant3x3(d)) < 1e-12)
  {
    error = "SamplingGridDirection is singular";
    return false;
  }
  std::copy(origin, origin + 3, this->Origin);
  std::copy(spacing, spacing + 3, this->Spacing);
  std::copy(direction, direction + 9, this->Direction);
  for (int i = 0; i < 6; ++i)
  {
    this->Extent[i] = static_cast<int>(extent[i]);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumGrid::SetFromSamplingGrid(const Description& description)
{
  for (int a = 0; a < 3; ++a)
  {
    this->Origin[a] = description.Origin[a];
    this->Spacing[a] = description.Spacing[a];
    this->Lower[a] = description.Extent[2 * a];
    this->Dimensions[a] = description.Extent[2 * a + 1] - description.Extent[2 * a] + 1;
  }
  const double* v = description.Direction;
  const double d[3][3] = { { v[0], v[1], v[2] }, { v[3], v[4], v[5] }, { v[6], v[7], v[8] } };
  vtkMath::Invert3x3(d, this->Inverse);
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumGrid::SetFromBounds(const int dimensions[3], const double bounds[6])
{
  for (int a = 0; a < 3; ++a)
  {
    this->Dimensions[a] = dimensions[a];
    this->Lower[a] = 0;
    this->Origin[a] = bounds[2 * a];
    const double extent = bounds[2 * a + 1] - bounds[2 * a];
    this->Spacing[a] = extent > 0.0 ? extent / (dimensions[a] - 1) : 1.0;
  }
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumGrid::SetDimensions(const int dimensions[3])
{
  std::copy(dimensions, dimensions + 3, this->Dimensions);
}

//------------------------------------------------------------------------------
std::size_t vtkBlueNoiseSpectrumGrid::Size() const
{
  return static_cast<std::size_t>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2];
}

//------------------------------------------------------------------------------
std::string vtkBlueNoiseSpectrumGrid::Describe() const
{
  std::ostringstream text;
  text.precision(6);
  text << "origin (" << this->Origin[0] << ", " << this->Origin[1] << ", " << this->Origin[2]
       << "), spacing (" << this->Spacing[0] << ", " << this->Spacing[1] << ", "
       << this->Spacing[2] << "), extent [";
  for (int a = 0; a < 3; ++a)
  {
    text << (a ? ", " : "") << this->Lower[a] << ", " << this->Lower[a] + this->Dimensions[a] - 1;
  }
  text << "]";
  return text.str();
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumGrid::UniteBounds(double into[6], const double bounds[6])
{
  for (int a = 0; a < 3; ++a)
  {
    into[2 * a] = std::min(into[2 * a], bounds[2 * a]);
    into[2 * a + 1] = std::max(into[2 * a + 1], bounds[2 * a + 1]);
  }
}

//------------------------------------------------------------------------------
long long vtkBlueNoiseSpectrumGrid::Locate(const double p[3]) const
{
  const double d[3] = { p[0] - this->Origin[0], p[1] - this->Origin[1], p[2] - this->Origin[2] };
  long long index = 0;
  long long stride = 1;
  for (int a = 0; a < 3; ++a)
  {
    const double c =
      (this->Inverse[a][0] * d[0] + this->Inverse[a][1] * d[1] + this->Inverse[a][2] * d[2]) /
        this->Spacing[a] -
      this->Lower[a];
    const double r = std::floor(c + 0.5);
    if (!(r >= 0.0 && r < this->Dimensions[a]))
    {
      return -1;
    }
    index += static_cast<long long>(r) * stride;
    stride *= this->Dimensions[a];
  }
  return index;
}
