// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseSpectrum.h"

#include "vtkBlueNoiseSpectrumGrid.h"
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
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersion.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <new>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkBlueNoiseSpectrum);

namespace
{
using Description = vtkBlueNoiseSpectrumGrid::Description;

enum class SignalKind
{
  ImageArray,    // an image's own grid, the array values are the counts
  Points,        // points binned to a grid
  WeightedPoints // an image's point or cell centers, weighted by the array, binned
};

// One realization's samples on this process: voxel indices of the analysis
// grid and their values (empty: one point each), and the counters of the
// "outside the grid" warning.
struct Samples
{
  std::vector<long long> Voxels;
  std::vector<double> Values;
  long long Counters[2] = { 0, 0 }; // outside the grid, binned
};

// The non-empty leaves of one input connection with their flat indices (0 for
// a data set that is not composite).
std::vector<std::pair<int, vtkDataObject*>> Leaves(vtkDataObject* input)
{
  std::vector<std::pair<int, vtkDataObject*>> leaves;
  if (auto composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      leaves.emplace_back(static_cast<int>(it->GetCurrentFlatIndex()), it->GetCurrentDataObject());
    }
  }
  else if (input)
  {
    leaves.emplace_back(0, input);
  }
  return leaves;
}

// Checks the input array of an image realization: one component of point or
// cell data, one value per point or cell.
bool CheckImageArray(
  vtkImageData* image, vtkDataArray* array, int association, bool& cells, std::string& error)
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
  std::ostringstream msg;
  const vtkIdType expected = cells ? image->GetNumberOfCells() : image->GetNumberOfPoints();
  if (array->GetNumberOfComponents() != 1)
  {
    msg << "the input array '" << (array->GetName() ? array->GetName() : "") << "' has "
        << array->GetNumberOfComponents() << " components; counts need one";
  }
  else if (array->GetNumberOfTuples() != expected)
  {
    msg << "the input array has " << array->GetNumberOfTuples() << " values for " << expected
        << (cells ? " cells" : " points");
  }
  error = msg.str();
  return error.empty();
}

// The grid an image's array lives on, as an extent: its points, or its cells
// (one fewer along every axis that is not flat).
void SignalExtent(const int pointExtent[6], bool cells, int extent[6])
{
  for (int a = 0; a < 3; ++a)
  {
    const bool flat = pointExtent[2 * a + 1] == pointExtent[2 * a];
    extent[2 * a] = pointExtent[2 * a];
    extent[2 * a + 1] = (cells && !flat) ? pointExtent[2 * a + 1] - 1 : pointExtent[2 * a + 1];
  }
}

// Calls visit(id, i, j, k) for the points or cells of an image piece that the
// piece owns: the extent its SamplingGridExtent field data names (the
// sampler's mask: pieces that do not overlap), else VTK's rule that
// structured pieces share their faces' points with the next piece, which
// owns them unless the face is the whole extent's.
template <typename Visit>
void ForEachOwned(vtkImageData* image, bool cells, const int wholePoints[6], Visit visit)
{
  int pointExtent[6], extent[6];
  image->GetExtent(pointExtent);
  SignalExtent(pointExtent, cells, extent);
  auto* owned = vtkIntArray::SafeDownCast(image->GetFieldData()->GetArray("SamplingGridExtent"));
  const bool named = !cells && owned && owned->GetNumberOfValues() == 6;
  int last[3];
  for (int a = 0; a < 3; ++a)
  {
    const bool shared = !cells && pointExtent[2 * a + 1] < wholePoints[2 * a + 1];
    last[a] = named ? std::min(extent[2 * a + 1], owned->GetValue(2 * a + 1))
                    : (shared ? extent[2 * a + 1] - 1 : extent[2 * a + 1]);
  }
  vtkIdType id = 0;
  for (int k = extent[4]; k <= extent[5]; ++k)
  {
    for (int j = extent[2]; j <= extent[3]; ++j)
    {
      for (int i = extent[0]; i <= extent[1]; ++i, ++id)
      {
        if (i <= last[0] && j <= last[1] && k <= last[2])
        {
          visit(id, i, j, k);
        }
      }
    }
  }
}

// Rule 3's grid: GridDimensions (at least 2 each, by its setter) over finite bounds.
void CheckBoundsGrid(const double bounds[6], std::ostringstream& error)
{
  for (int a = 0; a < 3 && error.tellp() == 0; ++a)
  {
    if (!(std::isfinite(bounds[2 * a]) && std::isfinite(bounds[2 * a + 1]) &&
          bounds[2 * a] <= bounds[2 * a + 1]))
    {
      error << "Invalid grid bounds on axis " << a << ": [" << bounds[2 * a] << ", "
            << bounds[2 * a + 1] << "].";
    }
  }
}

// Realization i's grid against realization 0's: one shape, at least 2 on every axis.
void CheckShape(const int* dims, const int* first, std::size_t i, std::ostringstream& error)
{
  if (i == 0 && (dims[0] < 2 || dims[1] < 2 || dims[2] < 2))
  {
    error << "Cannot analyze the grid: grid dimensions " << dims[0] << " x " << dims[1] << " x "
          << dims[2] << " are invalid: every dimension must be at least 2.";
  }
  else if (!std::equal(dims, dims + 3, first))
  {
    error << "Realization " << i << " has a " << dims[0] << " x " << dims[1] << " x " << dims[2]
          << " grid but realization 0 has " << first[0] << " x " << first[1] << " x " << first[2]
          << ": all realizations must share one grid shape.";
  }
}

// The grid's points against MaximumNumberOfGridPoints, counted in double:
// extents of field data reach 2^30 a side, whose product no integer holds.
void CheckGridSize(const int* dims, bool fromFieldData, vtkIdType maximum, std::ostringstream& error)
{
  const double points = static_cast<double>(dims[0]) * dims[1] * dims[2];
  if (points > static_cast<double>(maximum))
  {
    error << "Cannot analyze the grid: the " << dims[0] << " x " << dims[1] << " x " << dims[2]
          << " grid" << (fromFieldData ? " of the SamplingGridExtent field data" : "") << " has "
          << points << " points, more than MaximumNumberOfGridPoints (" << maximum << ").";
  }
}

// The memory the system can give without swapping (MemAvailable); 0 when
// unknown.
double AvailableMemoryBytes()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kib = 0.0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
  {
    if (key == "MemAvailable:")
    {
      return kib * 1024.0;
    }
  }
  return 0.0;
}

// A grid within MaximumNumberOfGridPoints whose buffers the memory cannot
// hold is an error before they are allocated: with overcommit their
// allocation succeeds, and writing them gets the process killed.
void CheckGridMemory(const int* dims, bool fromFieldData, bool severalRealizations, bool image,
  std::ostringstream& error)
{
  const double available = AvailableMemoryBytes();
  const double bytes =
    vtkBlueNoiseSpectrumKernel::BufferBytes(dims[0], dims[1], dims[2], severalRealizations) +
    (image ? 8.0 * dims[0] * dims[1] * dims[2] : 0.0);
  if (available > 0.0 && bytes > available)
  {
    error << "Cannot analyze the grid: the " << dims[0] << " x " << dims[1] << " x " << dims[2]
          << " grid" << (fromFieldData ? " of the SamplingGridExtent field data" : "")
          << " cannot be allocated: it needs " << std::setprecision(3) << bytes / 1e9 << " GB for its transform"
          << (image ? " and spectrum image" : "") << ", more than the " << available / 1e9
          << " GB of memory available.";
  }
}

// Runs step(), which returns false with `error` when it fails; a failed
// allocation inside it (std::bad_alloc) is such a failure too, so that a grid
// too large for the memory ends in an error and empty outputs, not an abort.
template <typename Step>
bool Guarded(std::string& error, Step step)
{
  try
  {
    return step();
  }
  catch (const std::bad_alloc&)
  {
    error = "out of memory";
    return false;
  }
}

// Points to their nearest grid points; the grid points are computed in
// parallel, kept in point order.
void BinPoints(vtkPointSet* data, const vtkBlueNoiseSpectrumGrid& grid, Samples& samples)
{
  vtkPoints* points = data->GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  std::vector<long long> located(static_cast<std::size_t>(n));
  vtkSMPTools::For(0, n,
    [&](vtkIdType first, vtkIdType last)
    {
      double p[3];
      for (vtkIdType id = first; id < last; ++id)
      {
        points->GetPoint(id, p);
        located[id] = grid.Locate(p);
      }
    });
  samples.Voxels.reserve(located.size());
  for (long long voxel : located)
  {
    if (voxel >= 0)
    {
      samples.Voxels.push_back(voxel);
    }
  }
  samples.Counters[0] += n - static_cast<long long>(samples.Voxels.size());
  samples.Counters[1] += n;
}

// An image's point or cell centers (half a voxel in, except along a flat axis
// of a 2D image), weighted by the array values, to their nearest grid points.
bool BinImageCentres(vtkImageData* image, vtkDataArray* array, bool cells, const int wholePoints[6],
  const vtkBlueNoiseSpectrumGrid& grid, Samples& samples, std::string& error)
{
  int extent[6];
  image->GetExtent(extent);
  double offset[3];
  for (int a = 0; a < 3; ++a)
  {
    offset[a] = (cells && extent[2 * a + 1] != extent[2 * a]) ? 0.5 : 0.0;
  }
  bool ok = true;
  ForEachOwned(image, cells, wholePoints,
    [&](vtkIdType id, int i, int j, int k)
    {
      const double w = array->GetComponent(id, 0);
      if (!ok || w == 0.0)
      {
        return;
      }
      if (!(w >= 0.0 && w <= VTK_FLOAT_MAX))
      {
        std::ostringstream msg;
        msg << "the value " << w << " of tuple " << id << " is not a finite non-negative count";
        error = msg.str();
        ok = false;
        return;
      }
      ++samples.Counters[1];
      double p[3];
      image->TransformContinuousIndexToPhysicalPoint(
        i + offset[0], j + offset[1], k + offset[2], p);
      const long long voxel = grid.Locate(p);
      if (voxel < 0)
      {
        ++samples.Counters[0];
        return;
      }
      samples.Voxels.push_back(voxel);
      samples.Values.push_back(static_cast<float>(w));
    });
  return ok;
}

// The non-zero values of an image piece with their voxels in the whole
// image's signal grid, each voxel from one piece.
void ImageArraySamples(
  vtkImageData* image, vtkDataArray* array, bool cells, const int wholePoints[6], Samples& samples)
{
  int whole[6];
  SignalExtent(wholePoints, cells, whole);
  const long long nx = whole[1] - whole[0] + 1;
  const long long ny = whole[3] - whole[2] + 1;
  ForEachOwned(image, cells, wholePoints,
    [&](vtkIdType id, int i, int j, int k)
    {
      const double v = array->GetComponent(id, 0);
      if (v != 0.0)
      {
        samples.Voxels.push_back((i - whole[0]) + nx * ((j - whole[2]) + ny * (k - whole[4])));
        samples.Values.push_back(v);
      }
    });
}

// An image's array as one realization on its own grid: uint8, float and
// double arrays as they are, other types converted to double.
bool AddImageArray(vtkBlueNoiseSpectrumKernel& kernel, vtkDataArray* array, std::string& error)
{
  if (auto bytes = vtkUnsignedCharArray::SafeDownCast(array))
  {
    return kernel.AddRealization(bytes->GetPointer(0), &error);
  }
  if (auto floats = vtkFloatArray::SafeDownCast(array))
  {
    return kernel.AddRealization(floats->GetPointer(0), &error);
  }
  if (auto doubles = vtkDoubleArray::SafeDownCast(array))
  {
    return kernel.AddRealization(doubles->GetPointer(0), &error);
  }
  std::vector<double> converted(static_cast<std::size_t>(array->GetNumberOfTuples()));
  for (std::size_t v = 0; v < converted.size(); ++v)
  {
    converted[v] = array->GetComponent(static_cast<vtkIdType>(v), 0);
  }
  return kernel.AddRealization(converted.data(), &error);
}

// Gathered samples into the kernel: an image's values as a volume, points as
// samples (their values are the float weights they were binned with).
bool AddGathered(vtkBlueNoiseSpectrumKernel& kernel, SignalKind kind, std::size_t voxels,
  const Samples& samples, std::string& error)
{
  if (kind == SignalKind::ImageArray)
  {
    std::vector<double> volume(voxels, 0.0);
    for (std::size_t s = 0; s < samples.Voxels.size(); ++s)
    {
      volume[samples.Voxels[s]] = samples.Values[s];
    }
    return kernel.AddRealization(volume.data(), &error);
  }
  std::vector<float> weights(samples.Values.begin(), samples.Values.end());
  return kernel.AddSamples(samples.Voxels.data(), weights.empty() ? nullptr : weights.data(),
    samples.Voxels.size(), &error);
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

// RadialPower at the shell nearest the principal frequency f_g, NaN elsewhere:
// a chart draws it as one marker on the power curve.
std::vector<double> MarkerColumn(const vtkBlueNoiseSpectrumKernel::Result& result)
{
  std::vector<double> marker(result.Frequency.size(), std::numeric_limits<double>::quiet_NaN());
  if (!marker.empty() && std::isfinite(result.PrincipalFrequency))
  {
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < marker.size(); ++i)
    {
      if (std::abs(result.Frequency[i] - result.PrincipalFrequency) <
        std::abs(result.Frequency[nearest] - result.PrincipalFrequency))
      {
        nearest = i;
      }
    }
    marker[nearest] = result.RadialPower[nearest];
  }
  return marker;
}

void FillTable(vtkTable* table, const vtkBlueNoiseSpectrumKernel::Result& result)
{
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
  table->AddColumn(MakeColumn("PrincipalFrequencyMarker", MarkerColumn(result)));

  vtkFieldData* fd = table->GetFieldData();
  AddFieldValue(fd, "NumberOfPoints", result.NumberOfPoints);
  AddFieldValue(fd, "Density", result.Density);
  AddFieldValue(fd, "PrincipalFrequency", result.PrincipalFrequency);
  AddFieldValue(fd, "LowFrequencyRatio", result.LowFrequencyRatio);
  AddFieldValue(fd, "SymmetryCorrelation", result.SymmetryCorrelation);
  AddFieldValue(fd, "Symmetry", result.Symmetry);
  AddFieldValue(fd, "TargetValue", result.TargetValue);
  vtkNew<vtkIntArray> realizationCount;
  realizationCount->SetName("Realizations");
  realizationCount->SetNumberOfValues(1);
  realizationCount->SetValue(0, result.Realizations);
  fd->AddArray(realizationCount);
  vtkNew<vtkIntArray> gridDimensions;
  gridDimensions->SetName("GridDimensions");
  gridDimensions->SetNumberOfComponents(3);
  gridDimensions->SetNumberOfTuples(1);
  gridDimensions->SetTypedTuple(0, result.Dimensions);
  fd->AddArray(gridDimensions);
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

// The spectrum image's whole extent when the grid was not known, or known
// differently, when it was announced (see the class comment).
void SetSpectrumWholeExtent(vtkInformation* imageInfo, const int dims[3])
{
  int extent[6];
  double spacing[3], origin[3];
  SpectrumImageGeometry(dims, extent, spacing, origin);
  int announced[6] = { 0, -1, 0, -1, 0, -1 };
  imageInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), announced);
  if (!std::equal(extent, extent + 6, announced))
  {
    // The request was for the announced extent, which may lie outside this one:
    // the next request from that port would fail the executive's check.
    imageInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    imageInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent, 6);
  }
}

// The spectrum image lives in frequency space: its axes are the frequency
// axes, whatever the direction of an input image. Set explicitly: from VTK 9.3
// an image output takes the input image's direction unless the filter sets it.
const double SpectrumImageDirection[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };

bool FillSpectrumImage(vtkBlueNoiseSpectrumKernel& kernel, const int dims[3], vtkImageData* image)
{
  double* values = kernel.NewCenteredPowerSpectrum();
  if (!values)
  {
    return false;
  }
  int extent[6];
  double spacing[3], origin[3];
  SpectrumImageGeometry(dims, extent, spacing, origin);
  image->SetExtent(extent);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  vtkNew<vtkDoubleArray> power;
  power->SetName("Power");
  power->SetArray(values, static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2], 0,
    vtkAbstractArray::VTK_DATA_ARRAY_FREE);
  image->GetPointData()->SetScalars(power);
  return true;
}
}

//------------------------------------------------------------------------------
// One realization: this process's piece of it (Data null when it has none),
// its description (this piece's, then, once combined, the whole's), and the
// analysis grid with the kind of signal.
struct vtkBlueNoiseSpectrum::Realization
{
  Description Whole;
  vtkDataSet* Data = nullptr;
  vtkDataArray* Array = nullptr;
  SignalKind Kind = SignalKind::Points;
  bool GridFromBounds = false; // rule 3: the grid is built over the bounds
  vtkBlueNoiseSpectrumGrid Grid;
  std::string GridText; // the grid in words, for the table's SpectrumGrid field data
};

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
bool vtkBlueNoiseSpectrum::AnnouncedDimensions(vtkInformationVector** inputVector, int dims[3])
{
  std::copy(this->GridDimensions, this->GridDimensions + 3, dims);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  const auto wholeExtentKey = vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT();
  if (this->UseInputGrid && inInfo && inInfo->Has(wholeExtentKey))
  {
    // An image's extent, or the sampled image's extent the sampler's output
    // information carries.
    int extent[6];
    inInfo->Get(wholeExtentKey, extent);
    vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
    const bool cells = vtkImageData::SafeDownCast(inInfo->Get(vtkDataObject::DATA_OBJECT())) &&
      arrayInfo->Has(vtkDataObject::FIELD_ASSOCIATION()) &&
      arrayInfo->Get(vtkDataObject::FIELD_ASSOCIATION()) == vtkDataObject::FIELD_ASSOCIATION_CELLS;
    int signal[6];
    SignalExtent(extent, cells, signal);
    for (int a = 0; a < 3; ++a)
    {
      dims[a] = signal[2 * a + 1] - signal[2 * a] + 1;
    }
  }
  else if (this->UseInputGrid)
  {
    return false; // a point set: its field data may hold a grid
  }
  return dims[0] >= 2 && dims[1] >= 2 && dims[2] >= 2;
}

//------------------------------------------------------------------------------
int vtkBlueNoiseSpectrum::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* imageInfo = outputVector->GetInformationObject(1);
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  int dims[3];
  if (this->GenerateSpectrumImage && this->AnnouncedDimensions(inputVector, dims))
  {
    double spacing[3], origin[3];
    SpectrumImageGeometry(dims, extent, spacing, origin);
    imageInfo->Set(vtkDataObject::SPACING(), spacing, 3);
    imageInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
    vtkDataObject::SetPointDataActiveScalarInfo(imageInfo, VTK_DOUBLE, 1);
  }
  imageInfo->Set(vtkDataObject::DIRECTION(), SpectrumImageDirection, 9);
  imageInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  return 1;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrum::SetGridDimensions(int lx, int ly, int lz)
{
  // A grid needs two points per axis for a frequency other than 0.
  const int dims[3] = { std::max(2, lx), std::max(2, ly), std::max(2, lz) };
  if (!std::equal(dims, dims + 3, this->GridDimensions))
  {
    std::copy(dims, dims + 3, this->GridDimensions);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrum::ShareOutputRequest(
  vtkInformation* request, vtkInformationVector* outputVector)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int from = request->Has(SDDP::FROM_OUTPUT_PORT())
    ? std::max(0, request->Get(SDDP::FROM_OUTPUT_PORT()))
    : 0;
  vtkInformation* fromInfo = outputVector->GetInformationObject(from);
  vtkInformation* otherInfo = outputVector->GetInformationObject(1 - from);
  otherInfo->CopyEntry(fromInfo, SDDP::UPDATE_PIECE_NUMBER());
  otherInfo->CopyEntry(fromInfo, SDDP::UPDATE_NUMBER_OF_PIECES());
  otherInfo->CopyEntry(fromInfo, SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS());
}

//------------------------------------------------------------------------------
int vtkBlueNoiseSpectrum::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  ShareOutputRequest(request, outputVector);
  // The spectrum needs every realization whole.
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
bool vtkBlueNoiseSpectrum::ShareDescriptions(std::vector<double>&)
{
  return true;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrum::GatherSamples(std::vector<long long>&, std::vector<double>&, long long*)
{
  return true;
}

//------------------------------------------------------------------------------
int vtkBlueNoiseSpectrum::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkTable* table = vtkTable::GetData(outputVector, 0);
  vtkImageData* image = vtkImageData::GetData(outputVector, 1);
  table->Initialize();
  image->Initialize();
  image->SetDirectionMatrix(SpectrumImageDirection);
  this->NumberOfTransformedRealizations = 0;
  // Bad input is reported (vtkErrorMacro) and leaves empty outputs, yet the
  // execution succeeds: a failed one would leave what is downstream (the
  // chart that shows the table) holding the last good spectrum.
  // An aborted input (an empty sampler output) is no error: stop before checking it.
  if (this->IsAborted())
  {
    return 1;
  }

  std::vector<Realization> pieces;
  std::vector<Realization> realizations;
  if (!this->ValidateInputs(inputVector, pieces) || !this->CombinePieces(pieces, realizations) ||
    !this->BuildGrids(realizations))
  {
    return 1;
  }
  vtkBlueNoiseSpectrumKernel kernel;
  kernel.SetWeight(this->Weight);
  const int accumulated = this->Accumulate(realizations, kernel);
  if (accumulated < 0)
  {
    return 1;
  }
  const int* dims = realizations[0].Grid.Dimensions;
  if (this->GenerateSpectrumImage)
  {
    SetSpectrumWholeExtent(outputVector->GetInformationObject(1), dims);
  }
  if (accumulated == 0 || !this->IsRootProcess())
  {
    return 1; // aborted, or another process computes
  }

  vtkBlueNoiseSpectrumKernel::Result result;
  std::string error;
  if (!Guarded(error, [&] { return kernel.Compute(result, &error); }))
  {
    vtkErrorMacro("Cannot compute the spectrum: " << error << ".");
    return 1;
  }
  if (!result.Warning.empty())
  {
    vtkWarningMacro("The spectrum is degenerate: " << result.Warning << ".");
  }
  this->UpdateProgress(0.9);
  FillTable(table, result);
  vtkNew<vtkStringArray> gridText; // the grid, where users see it (Information tab)
  gridText->SetName("SpectrumGrid");
  gridText->InsertNextValue(realizations[0].GridText);
  table->GetFieldData()->AddArray(gridText);
  if (this->GenerateSpectrumImage && !FillSpectrumImage(kernel, dims, image))
  {
    vtkErrorMacro("Cannot allocate the " << dims[0] << " x " << dims[1] << " x " << dims[2]
                                         << " spectrum image.");
    table->Initialize();
    return 1;
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrum::ValidateInputs(
  vtkInformationVector** inputVector, std::vector<Realization>& pieces)
{
  // Every non-empty leaf of every connection is a realization.
  bool ok = true;
  for (int c = 0; ok && c < inputVector[0]->GetNumberOfInformationObjects(); ++c)
  {
    for (const auto& leaf : Leaves(vtkDataObject::GetData(inputVector[0], c)))
    {
      Realization piece;
      piece.Whole.Connection = c;
      piece.Whole.Leaf = leaf.first;
      piece.Data = vtkDataSet::SafeDownCast(leaf.second);
      if (!vtkPointSet::SafeDownCast(leaf.second) && !vtkImageData::SafeDownCast(leaf.second))
      {
        vtkErrorMacro("Realization " << pieces.size() << " is a " << leaf.second->GetClassName()
                                     << ": only point sets and images are supported.");
        ok = false;
        break;
      }
      ok = this->DescribePiece(piece, static_cast<int>(pieces.size()));
      pieces.push_back(piece);
      if (!ok)
      {
        break;
      }
    }
  }
  return this->AllSucceeded(ok);
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrum::DescribePiece(Realization& piece, int index)
{
  Description& d = piece.Whole;
  d.NumberOfPoints = piece.Data->GetNumberOfPoints();
  if (d.NumberOfPoints > 0)
  {
    piece.Data->GetBounds(d.Bounds);
  }
  std::string error;
  auto image = vtkImageData::SafeDownCast(piece.Data);
  if (image)
  {
    d.IsImage = true;
    image->GetExtent(d.ImageExtent);
    int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    piece.Array = this->GetInputArrayToProcess(0, image, association);
    vtkInformation* selection = this->GetInputArrayInformation(0);
    if (!piece.Array && selection->Has(vtkDataObject::FIELD_NAME()) &&
      std::string(selection->Get(vtkDataObject::FIELD_NAME())).empty())
    {
      // An empty name (ParaView before an array is picked): the active scalars.
      piece.Array = image->GetPointData()->GetScalars();
      association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    }
    // A piece without points (of a distributed image) has nothing to check.
    if (d.NumberOfPoints > 0 &&
      !CheckImageArray(image, piece.Array, association, d.CellArray, error))
    {
      vtkErrorMacro("Realization " << index << ": " << error << ".");
      return false;
    }
  }
  else if (this->UseInputGrid && !d.ReadSamplingGrid(piece.Data->GetFieldData(), error))
  {
    vtkErrorMacro("Realization " << index << ": " << error << ".");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrum::CombinePieces(
  std::vector<Realization>& pieces, std::vector<Realization>& realizations)
{
  std::vector<double> records(pieces.size() * Description::PackedSize);
  for (std::size_t i = 0; i < pieces.size(); ++i)
  {
    pieces[i].Whole.Pack(records.data() + i * Description::PackedSize);
  }
  if (!this->ShareDescriptions(records))
  {
    return false;
  }
  // One realization per (connection, leaf), in that order, merged over the
  // pieces of every process; this process's piece keeps its data.
  std::vector<Description> all(records.size() / Description::PackedSize);
  for (std::size_t i = 0; i < all.size(); ++i)
  {
    all[i].Unpack(records.data() + i * Description::PackedSize);
  }
  std::stable_sort(all.begin(), all.end(),
    [](const Description& a, const Description& b)
    { return std::make_pair(a.Connection, a.Leaf) < std::make_pair(b.Connection, b.Leaf); });
  std::string error;
  for (const Description& piece : all)
  {
    const bool same = !realizations.empty() &&
      realizations.back().Whole.Connection == piece.Connection &&
      realizations.back().Whole.Leaf == piece.Leaf;
    if (!same)
    {
      realizations.emplace_back();
      realizations.back().Whole = piece;
    }
    else if (!realizations.back().Whole.Merge(piece, error))
    {
      vtkErrorMacro("Realization " << realizations.size() - 1 << ": " << error << ".");
      return false;
    }
  }
  for (Realization& realization : realizations)
  {
    for (const Realization& piece : pieces)
    {
      if (piece.Whole.Connection == realization.Whole.Connection &&
        piece.Whole.Leaf == realization.Whole.Leaf)
      {
        realization.Data = piece.Data;
        realization.Array = piece.Array;
      }
    }
  }
  if (realizations.empty())
  {
    vtkErrorMacro("The input has no realization: connect point sets, images or composite "
                  "datasets of those.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// The analysis grid of each realization (rules 1-3 of the class comment),
// checked against one another and against the limits.
bool vtkBlueNoiseSpectrum::BuildGrids(std::vector<Realization>& realizations)
{
  double bounds[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  bool needBounds = false;
  std::ostringstream error;
  for (std::size_t i = 0; i < realizations.size() && error.tellp() == 0; ++i)
  {
    needBounds = this->ChooseGrid(realizations[i], i, bounds, error) || needBounds;
  }
  if (needBounds && error.tellp() == 0)
  {
    this->GridsOverBounds(realizations, bounds, error);
  }
  for (std::size_t i = 0; i < realizations.size() && error.tellp() == 0; ++i)
  {
    CheckShape(realizations[i].Grid.Dimensions, realizations[0].Grid.Dimensions, i, error);
  }
  if (error.tellp() == 0)
  {
    const Realization& first = realizations[0];
    const bool fromFieldData = first.Kind == SignalKind::Points && !first.GridFromBounds;
    CheckGridSize(first.Grid.Dimensions, fromFieldData, this->MaximumNumberOfGridPoints, error);
    if (error.tellp() == 0)
    {
      CheckGridMemory(first.Grid.Dimensions, fromFieldData, realizations.size() > 1,
        this->GenerateSpectrumImage != 0, error);
    }
  }
  if (error.tellp() != 0)
  {
    vtkErrorMacro(<< error.str());
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
// Realization i's grid when the input gives one: an image's own (rule 1) or
// the sampler's (rule 2). Returns true when it is to span the bounds (rule
// 3), whose union it widens `bounds` by.
bool vtkBlueNoiseSpectrum::ChooseGrid(
  Realization& r, std::size_t i, double bounds[6], std::ostringstream& error)
{
  const Description& d = r.Whole;
  if (d.NumberOfPoints == 0)
  {
    error << "Realization " << i << " ("
          << (r.Data ? r.Data->GetClassName() : (d.IsImage ? "vtkImageData" : "vtkPointSet"))
          << ") has no points: the spectrum is undefined for N = 0.";
    return false;
  }
  if (this->UseInputGrid && d.IsImage)
  {
    r.Kind = SignalKind::ImageArray;
    int signal[6];
    SignalExtent(d.ImageExtent, d.CellArray, signal);
    const int dims[3] = { signal[1] - signal[0] + 1, signal[3] - signal[2] + 1,
      signal[5] - signal[4] + 1 };
    r.Grid.SetDimensions(dims);
    std::ostringstream text;
    text << "the input image's own grid: extent [" << signal[0] << ", " << signal[1] << ", "
         << signal[2] << ", " << signal[3] << ", " << signal[4] << ", " << signal[5] << "]";
    r.GridText = text.str();
    return false;
  }
  if (this->UseInputGrid && d.HasSamplingGrid)
  {
    r.Kind = SignalKind::Points;
    r.Grid.SetFromSamplingGrid(d);
    r.GridText = "the sampler's grid (SamplingGrid field data): " + r.Grid.Describe();
    return false;
  }
  r.Kind = d.IsImage ? SignalKind::WeightedPoints : SignalKind::Points;
  r.GridFromBounds = true;
  vtkBlueNoiseSpectrumGrid::UniteBounds(bounds, d.Bounds);
  return true;
}

//------------------------------------------------------------------------------
// GridDimensions over GridBounds, or over the points' `bounds`, for the
// realizations that carry no grid of their own (rule 3).
void vtkBlueNoiseSpectrum::GridsOverBounds(
  std::vector<Realization>& realizations, const double bounds[6], std::ostringstream& error)
{
  const double* over = this->UseGridBounds ? this->GridBounds : bounds;
  CheckBoundsGrid(over, error);
  bool assumed = false; // a point set without the sampler's grid, UseInputGrid on
  for (Realization& r : realizations)
  {
    if (r.GridFromBounds)
    {
      r.Grid.SetFromBounds(this->GridDimensions, over);
      r.GridText = std::string("GridDimensions over the ") +
        (this->UseGridBounds ? "GridBounds" : "points' bounds") + ": " + r.Grid.Describe();
      assumed = assumed || (this->UseInputGrid && !r.Whole.IsImage);
    }
  }
  // Points that carry no grid may lie anywhere: the spectrum of a grid the
  // filter made up means something only if they were drawn on it. Once per
  // execution, naming the grid.
  if (assumed && error.tellp() == 0)
  {
    const Realization& r = *std::find_if(realizations.begin(), realizations.end(),
      [](const Realization& x) { return x.GridFromBounds && !x.Whole.IsImage; });
    vtkWarningMacro("The input points carry no sampling grid (the SamplingGridOrigin, "
                    "SamplingGridSpacing and SamplingGridExtent field data of "
                    "vtkErrorDiffusionSampler): the spectrum assumes "
      << r.GridText
      << ". It describes blue noise only for points drawn on that grid (the table's "
         "SpectrumGrid field data names it).");
  }
}

//------------------------------------------------------------------------------
int vtkBlueNoiseSpectrum::Accumulate(
  const std::vector<Realization>& realizations, vtkBlueNoiseSpectrumKernel& kernel)
{
  // Only the root process transforms, so only it needs the kernel's buffers.
  const int* dims = realizations[0].Grid.Dimensions;
  std::string error;
  const bool ready = !this->IsRootProcess() ||
    Guarded(error, [&] { return kernel.SetDimensions(dims[0], dims[1], dims[2], &error); });
  if (!ready)
  {
    vtkErrorMacro("Cannot analyze the grid: " << error << ".");
  }
  if (!this->AllSucceeded(ready))
  {
    return -1;
  }
  long long outside = 0;
  long long binned = 0;
  for (std::size_t i = 0; i < realizations.size(); ++i)
  {
    if (this->IsAborted())
    {
      return 0;
    }
    long long counters[2] = { 0, 0 };
    if (!this->AddRealization(realizations[i], static_cast<int>(i), kernel, counters))
    {
      return -1;
    }
    outside += counters[0];
    binned += counters[1];
    this->UpdateProgress(0.8 * static_cast<double>(i + 1) / realizations.size());
  }
  if (outside > 0 && this->IsRootProcess())
  {
    vtkWarningMacro(<< outside << " of " << binned
                    << " input samples lie outside the analysis grid and were ignored.");
  }
  return this->IsAborted() ? 0 : 1;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrum::AddRealization(
  const Realization& r, int index, vtkBlueNoiseSpectrumKernel& kernel, long long counters[2])
{
  std::string error;
  bool ok = true;
  if (r.Kind == SignalKind::ImageArray && !this->IsDistributed())
  {
    ok = Guarded(error, [&] { return AddImageArray(kernel, r.Array, error); });
  }
  else
  {
    // This process's samples, then every process's on the root process.
    Samples samples;
    auto image = vtkImageData::SafeDownCast(r.Data);
    auto points = vtkPointSet::SafeDownCast(r.Data);
    ok = Guarded(error,
      [&]
      {
        if (r.Kind == SignalKind::ImageArray && image)
        {
          ImageArraySamples(image, r.Array, r.Whole.CellArray, r.Whole.ImageExtent, samples);
        }
        else if (r.Kind == SignalKind::WeightedPoints && image)
        {
          return BinImageCentres(
            image, r.Array, r.Whole.CellArray, r.Whole.ImageExtent, r.Grid, samples, error);
        }
        else if (points)
        {
          BinPoints(points, r.Grid, samples);
        }
        return true;
      });
    if (!ok)
    {
      vtkErrorMacro("Realization " << index << ": " << error << ".");
    }
    if (!this->AllSucceeded(ok) ||
      !this->GatherSamples(samples.Voxels, samples.Values, samples.Counters))
    {
      return false;
    }
    std::copy(samples.Counters, samples.Counters + 2, counters);
    ok = !this->IsRootProcess() ||
      Guarded(error, [&] { return AddGathered(kernel, r.Kind, r.Grid.Size(), samples, error); });
  }
  if (!ok)
  {
    if (counters[0] > 0)
    {
      error += " (" + std::to_string(counters[0]) + " samples lie outside the analysis grid)";
    }
    vtkErrorMacro("Realization " << index << ": " << error << ".");
  }
  this->NumberOfTransformedRealizations += (ok && this->IsRootProcess()) ? 1 : 0;
  // The root process may fail alone (N = 0 inside the grid): all stop together.
  return this->AllSucceeded(ok);
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
  os << indent << "MaximumNumberOfGridPoints: " << this->MaximumNumberOfGridPoints << "\n";
  os << indent << "NumberOfTransformedRealizations: " << this->NumberOfTransformedRealizations
     << "\n";
}
