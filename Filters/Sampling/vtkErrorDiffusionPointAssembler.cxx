// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionPointAssembler.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <new>
#include <numeric>

#if defined(__linux__)
#include <sys/mman.h> // madvise
#endif

namespace
{
// dst[dstFirst + p] = src[srcFirst + ids[p]] for p in [0, n), value by value
// (a tuple assignment copies with a memcpy call per tuple).
struct GatherWorker
{
  template <typename SrcT, typename DstT>
  void operator()(SrcT* src, DstT* dst, const vtkIdType* ids, vtkIdType n, vtkIdType srcFirst,
    vtkIdType dstFirst) const
  {
    const auto in = vtk::DataArrayValueRange(src);
    auto out = vtk::DataArrayValueRange(dst);
    const int nc = src->GetNumberOfComponents();
    for (vtkIdType p = 0; p < n; ++p)
    {
      const vtkIdType from = (srcFirst + ids[p]) * nc;
      const vtkIdType to = (dstFirst + p) * nc;
      for (int c = 0; c < nc; ++c)
      {
        out[to + c] = in[from + c];
      }
    }
  }
};

// Room for up to `tuples` tuples, uninitialised (the array's count means
// nothing until EnsureTuples sets it). Large numeric arrays get memory aligned
// to 2 MB and advised for transparent huge pages (Linux): one page fault per
// 2 MB instead of one per 4 kB. The room is a hint: where the address space
// for all of it cannot be had, a quarter of it is tried, and so on, and
// EnsureTuples grows the array later.
void ReserveUninitialised(vtkAbstractArray* array, vtkIdType tuples)
{
  const int components = std::max(1, array->GetNumberOfComponents());
  const int valueSize = array->GetDataTypeSize();
  for (; tuples > 0; tuples /= 4)
  {
    const size_t bytes = static_cast<size_t>(tuples) * components * valueSize;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr size_t huge = size_t(2) << 20;
    if (bytes >= 4 * huge && valueSize > 0 && array->HasStandardMemoryLayout() &&
      vtkDataArray::SafeDownCast(array))
    {
      const size_t rounded = (bytes + huge - 1) / huge * huge;
      void* memory = nullptr;
      if (posix_memalign(&memory, huge, rounded) != 0)
      {
        continue;
      }
      madvise(memory, rounded, MADV_HUGEPAGE); // a hint: failure is harmless
      array->SetVoidArray(memory, static_cast<vtkIdType>(rounded / valueSize), /*save=*/0,
        vtkAbstractArray::VTK_DATA_ARRAY_FREE);
      return;
    }
#endif
    try
    {
      if (array->Resize(tuples))
      {
        return;
      }
    }
    catch (const std::bad_alloc&)
    {
      // VTK throws when the allocation fails; try less.
    }
  }
}

// Makes room for `tuples` tuples and sets the count; grows by at least half
// (VTK's Resize of a numeric array more than doubles), so appending layers
// costs amortised O(1) per tuple.
void EnsureTuples(vtkAbstractArray* array, vtkIdType tuples)
{
  const int components = std::max(1, array->GetNumberOfComponents());
  const vtkIdType capacity = array->GetSize() / components;
  if (tuples > capacity)
  {
    array->Resize(std::max(tuples, capacity + capacity / 2));
  }
  array->SetNumberOfTuples(tuples);
}

void Trim(vtkAbstractArray* array, vtkIdType tuples)
{
  array->SetNumberOfTuples(tuples);
  array->Squeeze();
}

template <typename T>
void WriteCentres(T* xyz, const double m[16], const int extent[6], int k,
  const std::vector<vtkIdType>& ids, const std::vector<vtkIdType>& rowEnds)
{
  const vtkIdType nx = extent[1] - extent[0] + 1;
  const double z = static_cast<double>(extent[4] + k);
  vtkIdType p = 0;
  for (size_t j = 0; j < rowEnds.size(); ++j)
  {
    if (p == rowEnds[j])
    {
      continue;
    }
    // The row's y and z part of the index-to-world transform, once per row.
    const double y = static_cast<double>(extent[2] + static_cast<vtkIdType>(j));
    double row[3];
    for (int r = 0; r < 3; ++r)
    {
      row[r] = m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3];
    }
    const vtkIdType rowStart = static_cast<vtkIdType>(j) * nx;
    for (; p < rowEnds[j]; ++p)
    {
      const double x = static_cast<double>(extent[0] + (ids[p] - rowStart));
      xyz[3 * p] = static_cast<T>(m[0] * x + row[0]);
      xyz[3 * p + 1] = static_cast<T>(m[4] * x + row[1]);
      xyz[3 * p + 2] = static_cast<T>(m[8] * x + row[2]);
    }
  }
}
}

//------------------------------------------------------------------------------
vtkErrorDiffusionPointAssembler::vtkErrorDiffusionPointAssembler() = default;

//------------------------------------------------------------------------------
vtkErrorDiffusionPointAssembler::~vtkErrorDiffusionPointAssembler() = default;

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::Begin(
  vtkImageData* image, vtkPointData* outPD, int pointsType)
{
  image->GetExtent(this->Extent);
  vtkImageData::ComputeIndexToPhysicalMatrix(image->GetOrigin(), image->GetSpacing(),
    image->GetDirectionMatrix()->GetData(), this->IndexToPhysical);
  this->Total = 0;
  this->OutputPointData = outPD;

  this->Coordinates = vtkSmartPointer<vtkDataArray>::Take(
    pointsType == VTK_DOUBLE ? static_cast<vtkDataArray*>(vtkDoubleArray::New())
                             : static_cast<vtkDataArray*>(vtkFloatArray::New()));
  this->Coordinates->SetNumberOfComponents(3);
  this->Coordinates->SetName("Points");
  this->Densities = vtkSmartPointer<vtkFloatArray>::New();
  this->Densities->SetName("Density");

  // Every image array gets a copy of the same kind, keeping the attribute
  // roles; arrays are paired by object, so unnamed arrays are carried too.
  this->Sources.clear();
  this->Targets.clear();
  vtkPointData* inPD = image->GetPointData();
  for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* source = inPD->GetAbstractArray(a);
    if (!source || (source->GetName() && std::strcmp(source->GetName(), "Density") == 0))
    {
      continue;
    }
    auto target = vtkSmartPointer<vtkAbstractArray>::Take(source->NewInstance());
    target->SetName(source->GetName());
    target->SetNumberOfComponents(source->GetNumberOfComponents());
    target->CopyComponentNames(source);
    if (source->HasInformation())
    {
      target->CopyInformation(source->GetInformation(), /*deep=*/1);
    }
    const int index = outPD->AddArray(target);
    for (int role = 0; role < vtkDataSetAttributes::NUM_ATTRIBUTES; ++role)
    {
      if (inPD->GetAbstractAttribute(role) == source)
      {
        outPD->SetActiveAttribute(index, role);
      }
    }
    this->Sources.push_back(source);
    this->Targets.push_back(target);
  }

  const vtkIdType nx = this->Extent[1] - this->Extent[0] + 1;
  const vtkIdType ny = this->Extent[3] - this->Extent[2] + 1;
  const vtkIdType nz = this->Extent[5] - this->Extent[4] + 1;

  // Room for one point per voxel (up to 2^28) at once: memory is committed
  // only where it is written, so the untouched tail costs address space, not
  // memory, and End() gives it back. Growing from a small array instead would
  // copy the points and fault in every copy. With the huge pages below, this
  // took the single-threaded filter on a 128^3 volume at g = 0.5 from 30 to
  // 18 ms.
  const vtkIdType reserve = std::min<vtkIdType>(nx * ny * nz, vtkIdType(1) << 28);
  ReserveUninitialised(this->Coordinates, reserve);
  ReserveUninitialised(this->Densities, reserve);
  for (vtkAbstractArray* target : this->Targets)
  {
    ReserveUninitialised(target, reserve);
  }
  this->LayerIds.resize(static_cast<size_t>(std::max<vtkIdType>(nx * ny, 0)) + 1);
  this->RowEnds.resize(static_cast<size_t>(std::max<vtkIdType>(ny, 0)));
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::Reserve(vtkIdType tuples)
{
  EnsureTuples(this->Coordinates, tuples);
  EnsureTuples(this->Densities, tuples);
  for (vtkAbstractArray* target : this->Targets)
  {
    EnsureTuples(target, tuples);
  }
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::AddLayer(
  int k, const float* density, const unsigned char* mask, vtkIdType count)
{
  if (count <= 0)
  {
    return;
  }
  const vtkIdType nx = this->Extent[1] - this->Extent[0] + 1;
  const vtkIdType layerSize = nx * static_cast<vtkIdType>(this->RowEnds.size());

  // Branch-free compaction: near g = 0.5 a branch per voxel would be
  // mispredicted half of the time. One slot past the samples is written.
  vtkIdType* ids = this->LayerIds.data();
  vtkIdType n = 0;
  for (size_t j = 0; j < this->RowEnds.size(); ++j)
  {
    const vtkIdType rowStart = static_cast<vtkIdType>(j) * nx;
    const unsigned char* bits = mask + rowStart;
    for (vtkIdType i = 0; i < nx; ++i)
    {
      ids[n] = rowStart + i;
      n += bits[i];
    }
    this->RowEnds[j] = n;
  }

  const vtkIdType first = this->Total;
  this->Reserve(first + n);

  if (auto* d = vtkDoubleArray::SafeDownCast(this->Coordinates))
  {
    WriteCentres(d->GetPointer(3 * first), this->IndexToPhysical, this->Extent, k, this->LayerIds,
      this->RowEnds);
  }
  else
  {
    WriteCentres(vtkFloatArray::SafeDownCast(this->Coordinates)->GetPointer(3 * first),
      this->IndexToPhysical, this->Extent, k, this->LayerIds, this->RowEnds);
  }

  float* values = this->Densities->GetPointer(first);
  for (vtkIdType p = 0; p < n; ++p)
  {
    values[p] = density[ids[p]];
  }

  const vtkIdType layerFirst = static_cast<vtkIdType>(k) * layerSize;
  for (size_t a = 0; a < this->Targets.size(); ++a)
  {
    auto* source = vtkDataArray::SafeDownCast(this->Sources[a]);
    auto* target = vtkDataArray::SafeDownCast(this->Targets[a]);
    if (source && target)
    {
      using Dispatcher = vtkArrayDispatch::Dispatch2SameValueType;
      GatherWorker worker;
      if (!Dispatcher::Execute(source, target, worker, ids, n, layerFirst, first))
      {
        worker(source, target, ids, n, layerFirst, first);
      }
      continue;
    }
    for (vtkIdType p = 0; p < n; ++p) // strings and other non-numeric arrays
    {
      this->Targets[a]->SetTuple(first + p, layerFirst + ids[p], this->Sources[a]);
    }
  }
  this->Total = first + n;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPoints> vtkErrorDiffusionPointAssembler::End()
{
  Trim(this->Coordinates, this->Total);
  Trim(this->Densities, this->Total);
  for (vtkAbstractArray* target : this->Targets)
  {
    Trim(target, this->Total);
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(this->Coordinates);
  if (this->OutputPointData)
  {
    this->OutputPointData->AddArray(this->Densities);
  }
  this->Sources.clear();
  this->Targets.clear();
  this->OutputPointData = nullptr;
  return points;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkCellArray> vtkErrorDiffusionPointAssembler::MakeVertices(vtkIdType n)
{
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  auto fill = [n, &verts](auto offsets, auto connectivity) {
    using ValueT = typename std::remove_reference<decltype(*offsets->GetPointer(0))>::type;
    ReserveUninitialised(offsets, n + 1);
    ReserveUninitialised(connectivity, n);
    offsets->SetNumberOfValues(n + 1);
    connectivity->SetNumberOfValues(n);
    std::iota(offsets->GetPointer(0), offsets->GetPointer(0) + n + 1, ValueT(0));
    std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, ValueT(0));
    verts->SetData(offsets, connectivity);
  };
  if (n < VTK_TYPE_INT32_MAX)
  {
    fill(vtkSmartPointer<vtkTypeInt32Array>::New(), vtkSmartPointer<vtkTypeInt32Array>::New());
  }
  else
  {
    fill(vtkSmartPointer<vtkTypeInt64Array>::New(), vtkSmartPointer<vtkTypeInt64Array>::New());
  }
  return verts;
}
