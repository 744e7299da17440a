// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseSpectrum.h"

#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersion.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkBlueNoiseSpectrum);

namespace
{
// The grid points (voxel centres) a realisation is binned to:
// x = Origin + D ((Lower + local ijk) * Spacing).
struct AnalysisGrid
{
  int Dimensions[3] = { 0, 0, 0 };
  int Lower[3] = { 0, 0, 0 };
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Spacing[3] = { 1.0, 1.0, 1.0 };
  double Inverse[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }; // D^-1

  std::size_t Size() const
  {
    return static_cast<std::size_t>(this->Dimensions[0]) * this->Dimensions[1] *
      this->Dimensions[2];
  }

  // Index (x fastest) of the grid point nearest to p, or -1 outside the grid.
  long long Locate(const double p[3]) const
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
};

enum class SignalKind
{
  ImageArray,    // an image's own grid, the array values are the counts
  Points,        // points binned to a grid
  WeightedPoints // an image's point or cell centres, weighted by the array, binned
};

struct Realisation
{
  vtkDataSet* Data = nullptr;
  SignalKind Kind = SignalKind::Points;
  vtkDataArray* Array = nullptr;
  bool CellArray = false;
  bool GridFromBounds = false; // rule 3: the grid is built over the bounds
  AnalysisGrid Grid;
};

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

// Rule 1 of the class comment. Returns false with `error` set for malformed
// field data; `found` tells whether the sampler's grid is there at all.
bool GridFromFieldData(vtkFieldData* fd, AnalysisGrid& grid, bool& found, std::string& error)
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
  found = hasOrigin || hasSpacing || hasExtent;
  if (!error.empty())
  {
    return false;
  }
  if (!found)
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
    if (extent[2 * a + 1] < extent[2 * a] || extent[2 * a] != std::floor(extent[2 * a]) ||
      extent[2 * a + 1] != std::floor(extent[2 * a + 1]))
    {
      error = "SamplingGridExtent is not an extent (i0 i1 j0 j1 k0 k1 with whole i0 <= i1 ...)";
      return false;
    }
    grid.Origin[a] = origin[a];
    grid.Spacing[a] = spacing[a];
    grid.Lower[a] = static_cast<int>(extent[2 * a]);
    grid.Dimensions[a] = static_cast<int>(extent[2 * a + 1] - extent[2 * a]) + 1;
  }
  const double d[3][3] = { { direction[0], direction[1], direction[2] },
    { direction[3], direction[4], direction[5] }, { direction[6], direction[7], direction[8] } };
  if (std::abs(vtkMath::Determinant3x3(d)) < 1e-12)
  {
    error = "SamplingGridDirection is singular";
    return false;
  }
  vtkMath::Invert3x3(d, grid.Inverse);
  return true;
}

// Checks the input array of an image realisation: one component of point or
// cell data.
bool CheckImageArray(vtkDataArray* array, int association, bool& cells, std::string& error)
{
  if (!array)
  {
    error = "no input array: select a point- or cell-data array with SetInputArrayToProcess "
            "(default: the active point scalars)";
    return false;
  }
  cells = (association == vtkDataObject::FIELD_ASSOCIATION_CELLS);
  if (!cells && association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    error = "the input array must be point or cell data";
    return false;
  }
  if (array->GetNumberOfComponents() != 1)
  {
    std::ostringstream msg;
    msg << "the input array '" << (array->GetName() ? array->GetName() : "") << "' has "
        << array->GetNumberOfComponents() << " components; counts need one";
    error = msg.str();
    return false;
  }
  return true;
}

void AddFieldValue(vtkFieldData* fd, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfValues(1);
  array->SetValue(0, value);
  fd->AddArray(array);
}

vtkSmartPointer<vtkDoubleArray> MakeColumn(const char* name, const std::vector<double>& values)
{
  auto column = vtkSmartPointer<vtkDoubleArray>::New();
  column->SetName(name);
  column->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), column->GetPointer(0));
  return column;
}

void SpectrumImageGeometry(const int dims[3], int extent[6], double spacing[3], double origin[3])
{
  for (int a = 0; a < 3; ++a)
  {
    extent[2 * a] = 0;
    extent[2 * a + 1] = dims[a] - 1;
    spacing[a] = 1.0 / dims[a];
    origin[a] = -static_cast<double>(dims[a] / 2) / dims[a];
  }
}
}

//------------------------------------------------------------------------------
vtkBlueNoiseSpectrum::vtkBlueNoiseSpectrum()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkBlueNoiseSpectrum::~vtkBlueNoiseSpectrum() = default;

//------------------------------------------------------------------------------
vtkImageData* vtkBlueNoiseSpectrum::GetSpectrumImageOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkBlueNoiseSpectrum::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkBlueNoiseSpectrum::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkImageData" : "vtkTable");
  return 1;
}

//------------------------------------------------------------------------------
int vtkBlueNoiseSpectrum::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Best guess of the spectrum image's shape; RequestData sets the real one
  // (a grid from field data is only known once the input data exists).
  int dims[3] = { this->GridDimensions[0], this->GridDimensions[1], this->GridDimensions[2] };
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  const auto wholeExtentKey = vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT();
  if (this->UseInputGrid && inInfo && inInfo->Has(wholeExtentKey))
  {
    int extent[6];
    inInfo->Get(wholeExtentKey, extent);
    vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
    const int cellShift = (arrayInfo->Has(vtkDataObject::FIELD_ASSOCIATION()) &&
                            arrayInfo->Get(vtkDataObject::FIELD_ASSOCIATION()) ==
                              vtkDataObject::FIELD_ASSOCIATION_CELLS)
      ? 1
      : 0;
    for (int a = 0; a < 3; ++a)
    {
      dims[a] = std::max(1, extent[2 * a + 1] - extent[2 * a] + 1 - cellShift);
    }
  }
  vtkInformation* imageInfo = outputVector->GetInformationObject(1);
  if (this->GenerateSpectrumImage && dims[0] >= 1 && dims[1] >= 1 && dims[2] >= 1)
  {
    int extent[6];
    double spacing[3], origin[3];
    SpectrumImageGeometry(dims, extent, spacing, origin);
    imageInfo->Set(wholeExtentKey, extent, 6);
    imageInfo->Set(vtkDataObject::SPACING(), spacing, 3);
    imageInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
    vtkDataObject::SetPointDataActiveScalarInfo(imageInfo, VTK_DOUBLE, 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkBlueNoiseSpectrum::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The spectrum needs every realisation whole.
  const auto sddp = vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT();
  for (int c = 0; c < inputVector[0]->GetNumberOfInformationObjects(); ++c)
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(c);
    if (inInfo->Has(sddp))
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), inInfo->Get(sddp), 6);
    }
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrum::IsAborted()
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 20220831)
  return this->CheckAbort();
#else
  return this->GetAbortExecute() != 0;
#endif
}

//------------------------------------------------------------------------------
int vtkBlueNoiseSpectrum::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkTable* table = vtkTable::GetData(outputVector, 0);
  vtkImageData* image = vtkImageData::GetData(outputVector, 1);
  table->Initialize();
  image->Initialize();

  // --- Realisations: every non-empty leaf of every connection.
  std::vector<Realisation> realisations;
  for (int c = 0; c < inputVector[0]->GetNumberOfInformationObjects(); ++c)
  {
    vtkDataObject* input = vtkDataObject::GetData(inputVector[0], c);
    std::vector<vtkDataObject*> leaves;
    if (auto composite = vtkCompositeDataSet::SafeDownCast(input))
    {
      vtkSmartPointer<vtkCompositeDataIterator> it;
      it.TakeReference(composite->NewIterator());
      it->SkipEmptyNodesOn();
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      {
        leaves.push_back(it->GetCurrentDataObject());
      }
    }
    else if (input)
    {
      leaves.push_back(input);
    }
    for (vtkDataObject* leaf : leaves)
    {
      Realisation r;
      r.Data = vtkDataSet::SafeDownCast(leaf);
      if (!vtkPointSet::SafeDownCast(leaf) && !vtkImageData::SafeDownCast(leaf))
      {
        vtkErrorMacro("Realisation " << realisations.size() << " is a " << leaf->GetClassName()
                                     << ": only point sets and images are supported.");
        return 0;
      }
      realisations.push_back(r);
    }
  }
  if (realisations.empty())
  {
    vtkErrorMacro("The input has no realisation: connect point sets, images or composite "
                  "datasets of those.");
    return 0;
  }

  // --- The analysis grid of each realisation (rules 1-3 of the class comment).
  bool needBounds = false;
  for (std::size_t i = 0; i < realisations.size(); ++i)
  {
    Realisation& r = realisations[i];
    if (r.Data->GetNumberOfPoints() == 0)
    {
      vtkErrorMacro("Realisation " << i << " (" << r.Data->GetClassName()
                                   << ") has no points: the spectrum is undefined for N = 0.");
      return 0;
    }
    std::string error;
    auto image = vtkImageData::SafeDownCast(r.Data);
    if (image)
    {
      int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
      r.Array = this->GetInputArrayToProcess(0, image, association);
      vtkInformation* selection = this->GetInputArrayInformation(0);
      if (!r.Array && selection->Has(vtkDataObject::FIELD_NAME()) &&
        std::string(selection->Get(vtkDataObject::FIELD_NAME())).empty())
      {
        // An empty name (ParaView before an array is picked): the active scalars.
        r.Array = image->GetPointData()->GetScalars();
        association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
      }
      if (!CheckImageArray(r.Array, association, r.CellArray, error))
      {
        vtkErrorMacro("Realisation " << i << ": " << error << ".");
        return 0;
      }
      const vtkIdType expected =
        r.CellArray ? image->GetNumberOfCells() : image->GetNumberOfPoints();
      if (r.Array->GetNumberOfTuples() != expected)
      {
        vtkErrorMacro("Realisation " << i << ": the input array has "
                                     << r.Array->GetNumberOfTuples() << " values for " << expected
                                     << (r.CellArray ? " cells." : " points."));
        return 0;
      }
    }
    bool found = false;
    if (this->UseInputGrid && image)
    {
      r.Kind = SignalKind::ImageArray;
      int dims[3];
      image->GetDimensions(dims);
      for (int a = 0; a < 3; ++a)
      {
        r.Grid.Dimensions[a] = r.CellArray ? std::max(1, dims[a] - 1) : dims[a];
      }
    }
    else if (this->UseInputGrid &&
      GridFromFieldData(r.Data->GetFieldData(), r.Grid, found, error) && found)
    {
      r.Kind = SignalKind::Points;
    }
    else if (!error.empty())
    {
      vtkErrorMacro("Realisation " << i << ": " << error << ".");
      return 0;
    }
    else
    {
      r.Kind = image ? SignalKind::WeightedPoints : SignalKind::Points;
      r.GridFromBounds = true;
      needBounds = true;
    }
  }

  if (needBounds)
  {
    double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
      VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    if (this->UseGridBounds)
    {
      std::copy(this->GridBounds, this->GridBounds + 6, bounds);
    }
    else
    {
      for (const Realisation& r : realisations)
      {
        if (!r.GridFromBounds)
        {
          continue;
        }
        double b[6];
        r.Data->GetBounds(b);
        for (int a = 0; a < 3; ++a)
        {
          bounds[2 * a] = std::min(bounds[2 * a], b[2 * a]);
          bounds[2 * a + 1] = std::max(bounds[2 * a + 1], b[2 * a + 1]);
        }
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      if (this->GridDimensions[a] < 2)
      {
        vtkErrorMacro("GridDimensions must be at least 2 on every axis, not "
          << this->GridDimensions[0] << " " << this->GridDimensions[1] << " "
          << this->GridDimensions[2] << ".");
        return 0;
      }
      if (!(std::isfinite(bounds[2 * a]) && std::isfinite(bounds[2 * a + 1]) &&
            bounds[2 * a] <= bounds[2 * a + 1]))
      {
        vtkErrorMacro("Invalid grid bounds on axis " << a << ": [" << bounds[2 * a] << ", "
                                                     << bounds[2 * a + 1] << "].");
        return 0;
      }
    }
    AnalysisGrid grid;
    for (int a = 0; a < 3; ++a)
    {
      grid.Dimensions[a] = this->GridDimensions[a];
      grid.Origin[a] = bounds[2 * a];
      const double extent = bounds[2 * a + 1] - bounds[2 * a];
      grid.Spacing[a] = extent > 0.0 ? extent / (this->GridDimensions[a] - 1) : 1.0;
    }
    for (Realisation& r : realisations)
    {
      if (r.GridFromBounds)
      {
        r.Grid = grid;
      }
    }
  }

  const int* dims = realisations[0].Grid.Dimensions;
  for (std::size_t i = 1; i < realisations.size(); ++i)
  {
    const int* d = realisations[i].Grid.Dimensions;
    if (!std::equal(d, d + 3, dims))
    {
      vtkErrorMacro("Realisation " << i << " has a " << d[0] << " x " << d[1] << " x " << d[2]
                                   << " grid but realisation 0 has " << dims[0] << " x " << dims[1]
                                   << " x " << dims[2]
                                   << ": all realisations must share one grid shape.");
      return 0;
    }
  }

  vtkBlueNoiseSpectrumKernel kernel;
  kernel.SetWeight(this->Weight);
  std::string error;
  if (!kernel.SetDimensions(dims[0], dims[1], dims[2], &error))
  {
    vtkErrorMacro("Cannot analyse the grid: " << error << ".");
    return 0;
  }

  // --- Feed the kernel.
  std::vector<float> counts;
  std::vector<double> converted;
  vtkIdType outside = 0;
  vtkIdType binned = 0;
  for (std::size_t i = 0; i < realisations.size(); ++i)
  {
    if (this->IsAborted())
    {
      return 1;
    }
    const Realisation& r = realisations[i];
    const vtkIdType outsideBefore = outside;
    bool ok = false;
    if (r.Kind == SignalKind::ImageArray)
    {
      if (auto bytes = vtkUnsignedCharArray::SafeDownCast(r.Array))
      {
        ok = kernel.AddRealisation(bytes->GetPointer(0), &error);
      }
      else if (auto floats = vtkFloatArray::SafeDownCast(r.Array))
      {
        ok = kernel.AddRealisation(floats->GetPointer(0), &error);
      }
      else if (auto doubles = vtkDoubleArray::SafeDownCast(r.Array))
      {
        ok = kernel.AddRealisation(doubles->GetPointer(0), &error);
      }
      else
      {
        converted.resize(r.Grid.Size());
        for (std::size_t v = 0; v < converted.size(); ++v)
        {
          converted[v] = r.Array->GetComponent(static_cast<vtkIdType>(v), 0);
        }
        ok = kernel.AddRealisation(converted.data(), &error);
      }
    }
    else
    {
      counts.assign(r.Grid.Size(), 0.0f);
      double p[3];
      if (r.Kind == SignalKind::Points)
      {
        vtkPoints* points = vtkPointSet::SafeDownCast(r.Data)->GetPoints();
        const vtkIdType n = points->GetNumberOfPoints();
        for (vtkIdType id = 0; id < n; ++id)
        {
          points->GetPoint(id, p);
          const long long index = r.Grid.Locate(p);
          if (index < 0)
          {
            ++outside;
            continue;
          }
          counts[index] += 1.0f;
        }
        binned += n;
      }
      else
      {
        // Values at the image's points, or at its cell centres (half a voxel
        // in, except along a flat axis of a 2D image).
        auto source = vtkImageData::SafeDownCast(r.Data);
        int extent[6];
        source->GetExtent(extent);
        int last[3];
        double offset[3];
        for (int a = 0; a < 3; ++a)
        {
          const bool flat = extent[2 * a + 1] == extent[2 * a];
          last[a] = (r.CellArray && !flat) ? extent[2 * a + 1] - 1 : extent[2 * a + 1];
          offset[a] = (r.CellArray && !flat) ? 0.5 : 0.0;
        }
        vtkIdType id = 0;
        for (int k = extent[4]; k <= last[2]; ++k)
        {
          for (int j = extent[2]; j <= last[1]; ++j)
          {
            for (int ii = extent[0]; ii <= last[0]; ++ii, ++id)
            {
              const double w = r.Array->GetComponent(id, 0);
              if (!(w >= 0.0 && w <= VTK_FLOAT_MAX))
              {
                vtkErrorMacro("Realisation " << i << ": the value " << w << " of tuple " << id
                                             << " is not a finite non-negative count.");
                return 0;
              }
              if (w == 0.0)
              {
                continue;
              }
              ++binned;
              source->TransformContinuousIndexToPhysicalPoint(
                ii + offset[0], j + offset[1], k + offset[2], p);
              const long long index = r.Grid.Locate(p);
              if (index < 0)
              {
                ++outside;
                continue;
              }
              counts[index] += static_cast<float>(w);
            }
          }
        }
      }
      ok = kernel.AddRealisation(counts.data(), &error);
    }
    if (!ok)
    {
      std::string reason = error;
      if (outside > outsideBefore)
      {
        reason += " (" + std::to_string(outside - outsideBefore) +
          " samples lie outside the analysis grid)";
      }
      vtkErrorMacro("Realisation " << i << ": " << reason << ".");
      return 0;
    }
    this->UpdateProgress(0.8 * static_cast<double>(i + 1) / realisations.size());
  }
  if (outside > 0)
  {
    vtkWarningMacro(<< outside << " of " << binned
                    << " input samples lie outside the analysis grid and were ignored.");
  }
  if (this->IsAborted())
  {
    return 1;
  }

  // --- The metric.
  vtkBlueNoiseSpectrumKernel::Result result;
  if (!kernel.Compute(result, &error))
  {
    vtkErrorMacro("Cannot compute the spectrum: " << error << ".");
    return 0;
  }
  if (!result.Warning.empty())
  {
    vtkWarningMacro("The spectrum is degenerate: " << result.Warning << ".");
  }
  this->UpdateProgress(0.9);

  table->AddColumn(MakeColumn("Frequency", result.Frequency));
  table->AddColumn(MakeColumn("RadialPower", result.RadialPower));
  table->AddColumn(MakeColumn("Anisotropy", result.Anisotropy));
  table->AddColumn(MakeColumn("AnisotropyDB", result.AnisotropyDB));
  table->AddColumn(MakeColumn("SRAPS_XY", result.SrapsXY));
  table->AddColumn(MakeColumn("SRAPS_XZ", result.SrapsXZ));
  table->AddColumn(MakeColumn("SRAPS_YZ", result.SrapsYZ));
  vtkNew<vtkIdTypeArray> shellCount;
  shellCount->SetName("ShellCount");
  shellCount->SetNumberOfValues(static_cast<vtkIdType>(result.ShellCount.size()));
  std::copy(result.ShellCount.begin(), result.ShellCount.end(), shellCount->GetPointer(0));
  table->AddColumn(shellCount);

  vtkFieldData* fd = table->GetFieldData();
  AddFieldValue(fd, "NumberOfPoints", result.NumberOfPoints);
  AddFieldValue(fd, "Density", result.Density);
  AddFieldValue(fd, "PrincipalFrequency", result.PrincipalFrequency);
  AddFieldValue(fd, "LowFrequencyRatio", result.LowFrequencyRatio);
  AddFieldValue(fd, "SymmetryCorrelation", result.SymmetryCorrelation);
  AddFieldValue(fd, "Symmetry", result.Symmetry);
  AddFieldValue(fd, "TargetValue", result.TargetValue);
  vtkNew<vtkIntArray> realisationCount;
  realisationCount->SetName("Realisations");
  realisationCount->SetNumberOfValues(1);
  realisationCount->SetValue(0, result.Realisations);
  fd->AddArray(realisationCount);
  vtkNew<vtkIntArray> gridDimensions;
  gridDimensions->SetName("GridDimensions");
  gridDimensions->SetNumberOfComponents(3);
  gridDimensions->SetNumberOfTuples(1);
  gridDimensions->SetTypedTuple(0, dims);
  fd->AddArray(gridDimensions);

  if (this->GenerateSpectrumImage)
  {
    int extent[6];
    double spacing[3], origin[3];
    SpectrumImageGeometry(dims, extent, spacing, origin);
    image->SetExtent(extent);
    image->SetSpacing(spacing);
    image->SetOrigin(origin);
    vtkNew<vtkDoubleArray> power;
    power->SetName("Power");
    power->SetNumberOfValues(static_cast<vtkIdType>(realisations[0].Grid.Size()));
    kernel.GetCentredPowerSpectrum(power->GetPointer(0));
    image->GetPointData()->SetScalars(power);
    outputVector->GetInformationObject(1)->Set(
      vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrum::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weight: " << this->Weight << "\n";
  os << indent << "UseInputGrid: " << this->UseInputGrid << "\n";
  os << indent << "GridDimensions: " << this->GridDimensions[0] << " " << this->GridDimensions[1]
     << " " << this->GridDimensions[2] << "\n";
  os << indent << "GridBounds: " << this->GridBounds[0] << " " << this->GridBounds[1] << " "
     << this->GridBounds[2] << " " << this->GridBounds[3] << " " << this->GridBounds[4] << " "
     << this->GridBounds[5] << "\n";
  os << indent << "UseGridBounds: " << this->UseGridBounds << "\n";
  os << indent << "GenerateSpectrumImage: " << this->GenerateSpectrumImage << "\n";
}
