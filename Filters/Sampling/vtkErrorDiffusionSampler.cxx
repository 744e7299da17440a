// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionSampler.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkErrorDiffusionKernel.h"
#include "vtkErrorDiffusionLayerRunner.h"
#include "vtkErrorDiffusionPointAssembler.h"
#include "vtkErrorDiffusionParameterTable.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkMultiProcessController.h"
#include "vtkCommunicator.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <thread>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkErrorDiffusionSampler);
vtkCxxSetObjectMacro(vtkErrorDiffusionSampler, TransferFunction, vtkPiecewiseFunction);
vtkCxxSetObjectMacro(vtkErrorDiffusionSampler, Controller, vtkMultiProcessController);

namespace
{
// The mapping used for a scalar range of zero width.
constexpr int DENSITY_STEP = -1;

// Below this a second thread costs more than it saves.
constexpr vtkIdType MIN_VOXELS_FOR_WORKER_THREAD = 32768;

// Array value -> density in [0, 1].
struct DensityMap
{
  int Mode = vtkErrorDiffusionSampler::DENSITY_IDENTITY;
  double Low = 0.0;
  double InverseWidth = 1.0;
  double Scale = 1.0;
  vtkPiecewiseFunction* Function = nullptr;

  float operator()(double x) const
  {
    double g = x;
    if (this->Mode == vtkErrorDiffusionSampler::DENSITY_SCALAR_RANGE)
    {
      g = (x - this->Low) * this->InverseWidth;
    }
    else if (this->Mode == DENSITY_STEP)
    {
      g = x >= this->Low ? 1.0 : 0.0;
    }
    else if (this->Mode == vtkErrorDiffusionSampler::DENSITY_TRANSFER_FUNCTION)
    {
      g = std::isnan(x) ? 0.0 : this->Function->GetValue(x);
    }
    g *= this->Scale;
    if (!(g > 0.0)) // NaN too
    {
      return 0.0f;
    }
    return g >= 1.0 ? 1.0f : static_cast<float>(g);
  }
};

// Densities of the tuples [begin, end) of the array, in order.
struct LayerDensityWorker
{
  template <typename ArrayT>
  void operator()(ArrayT* array, vtkIdType begin, vtkIdType end, int component,
    const DensityMap& map, float* out) const
  {
    const auto tuples = vtk::DataArrayTupleRange(array, begin, end);
    if (component >= 0)
    {
      for (const auto tuple : tuples)
      {
        *out++ = map(static_cast<double>(tuple[component]));
      }
      return;
    }
    for (const auto tuple : tuples)
    {
      double sum = 0.0;
      for (const auto c : tuple)
      {
        sum += static_cast<double>(c) * static_cast<double>(c);
      }
      *out++ = map(std::sqrt(sum));
    }
  }
};

void FillLayerDensity(vtkDataArray* array, vtkIdType begin, vtkIdType end, int component,
  const DensityMap& map, float* out)
{
  LayerDensityWorker worker;
  if (!vtkArrayDispatch::Dispatch::Execute(array, worker, begin, end, component, map, out))
  {
    worker(array, begin, end, component, map, out);
  }
}

// The finite range of a component (or, for -1, of the tuple magnitude):
// VTK's GetFiniteRange is not cached across executions and walks the values
// through a generic path, a third of the filter's time on an 8-bit MRI.
// lo > hi when no value is finite.
struct FiniteRangeWorker
{
  template <typename ArrayT>
  void operator()(ArrayT* array, int component, double& lo, double& hi) const
  {
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    if (component < 0)
    {
      for (const auto tuple : vtk::DataArrayTupleRange(array))
      {
        double sum = 0.0;
        for (const auto c : tuple)
        {
          sum += static_cast<double>(c) * static_cast<double>(c);
        }
        const double m = std::sqrt(sum);
        if (std::isfinite(m))
        {
          lo = std::min(lo, m);
          hi = std::max(hi, m);
        }
      }
      return;
    }
    // The component's values, a stride apart; in the array's own type so the
    // loop stays cheap.
    using T = vtk::GetAPIType<ArrayT>;
    const auto values = vtk::DataArrayValueRange(array);
    const vtkIdType n = values.size();
    const int nc = array->GetNumberOfComponents();
    T low = std::numeric_limits<T>::max();
    T high = std::numeric_limits<T>::lowest();
    bool any = false;
    for (vtkIdType i = component; i < n; i += nc)
    {
      const T v = values[i];
      if (std::is_floating_point<T>::value && !std::isfinite(static_cast<double>(v)))
      {
        continue;
      }
      low = v < low ? v : low;
      high = v > high ? v : high;
      any = true;
    }
    if (any)
    {
      lo = static_cast<double>(low);
      hi = static_cast<double>(high);
    }
  }
};

void ComputeFiniteRange(vtkDataArray* array, int component, double range[2])
{
  FiniteRangeWorker worker;
  if (!vtkArrayDispatch::Dispatch::Execute(array, worker, component, range[0], range[1]))
  {
    worker(array, component, range[0], range[1]);
  }
}

void AddFieldArray(vtkFieldData* fd, vtkDataArray* array, const char* name, int components)
{
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(1);
  fd->AddArray(array);
}
}

//------------------------------------------------------------------------------
vtkErrorDiffusionSampler::vtkErrorDiffusionSampler()
{
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkErrorDiffusionSampler::~vtkErrorDiffusionSampler()
{
  this->SetTransferFunction(nullptr);
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkErrorDiffusionSampler::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->TransferFunction)
  {
    t = std::max(t, this->TransferFunction->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
vtkImageData* vtkErrorDiffusionSampler::GetMaskOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkErrorDiffusionSampler::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkErrorDiffusionSampler::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkErrorDiffusionSampler::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The mask lives on the input's grid.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* maskInfo = outputVector->GetInformationObject(1);
  const auto sddp = vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT();
  if (inInfo->Has(sddp))
  {
    maskInfo->CopyEntry(inInfo, sddp);
  }
  maskInfo->CopyEntry(inInfo, vtkDataObject::ORIGIN());
  maskInfo->CopyEntry(inInfo, vtkDataObject::SPACING());
  maskInfo->CopyEntry(inInfo, vtkDataObject::DIRECTION());
  vtkDataObject::SetPointDataActiveScalarInfo(maskInfo, VTK_UNSIGNED_CHAR, 1);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionSampler::IsAborted()
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 20220831)
  return this->CheckAbort();
#else
  return this->GetAbortExecute() != 0;
#endif
}

//------------------------------------------------------------------------------
vtkDataArray* vtkErrorDiffusionSampler::GetDensityArray(
  vtkImageData* input, vtkInformationVector** inputVector)
{
  int association = -1;
  vtkAbstractArray* abstractArray =
    this->GetInputAbstractArrayToProcess(0, inputVector, association);
  vtkInformation* selection = this->GetInputArrayInformation(0);
  if (!abstractArray && selection->Has(vtkDataObject::FIELD_NAME()) &&
    std::string(selection->Get(vtkDataObject::FIELD_NAME())).empty())
  {
    // An empty name (ParaView before the user picks an array): active scalars.
    abstractArray = input->GetPointData()->GetScalars();
    association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  }
  if (!abstractArray)
  {
    vtkErrorMacro("No density array: select a point-data array with SetInputArrayToProcess "
                  "(the input has no active scalars).");
    return nullptr;
  }
  const char* name = abstractArray->GetName() ? abstractArray->GetName() : "";
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    vtkErrorMacro("The density array '" << name << "' is not point data: only point data is "
                                        << "sampled.");
    return nullptr;
  }
  vtkDataArray* array = vtkDataArray::SafeDownCast(abstractArray);
  if (!array)
  {
    vtkErrorMacro("The density array '" << name << "' is not numeric ("
                                        << abstractArray->GetClassName() << ").");
    return nullptr;
  }
  const vtkIdType voxels = input->GetNumberOfPoints();
  if (array->GetNumberOfTuples() != voxels)
  {
    vtkErrorMacro("The density array has " << array->GetNumberOfTuples() << " tuples for "
                                           << voxels << " voxels.");
    return nullptr;
  }
  if (this->Component >= array->GetNumberOfComponents())
  {
    vtkErrorMacro("Component " << this->Component << " is out of range: the array '" << name
                               << "' has " << array->GetNumberOfComponents()
                               << " component(s).");
    return nullptr;
  }
  return array;
}

//------------------------------------------------------------------------------
int vtkErrorDiffusionSampler::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkImageData* mask = vtkImageData::GetData(outputVector, 1);
  output->Initialize();
  mask->Initialize();
  if (!input)
  {
    vtkErrorMacro("No input image.");
    return 0;
  }

  // --- Validate everything before any work, so bad input costs nothing. The
  // properties first: every piece of a distributed run sees the same ones, so
  // all pieces stop here or none does.
  if (!std::isfinite(this->DensityScale) || this->DensityScale < 0.0)
  {
    vtkErrorMacro("DensityScale must be finite and >= 0, not " << this->DensityScale << ".");
    return 0;
  }
  if (!std::isfinite(this->ModulationScale) || this->ModulationScale < 0.0)
  {
    vtkErrorMacro("ModulationScale must be finite and >= 0, not " << this->ModulationScale << ".");
    return 0;
  }
  if (this->DensityMapping == DENSITY_TRANSFER_FUNCTION &&
    (!this->TransferFunction || this->TransferFunction->GetSize() == 0))
  {
    vtkErrorMacro("DensityMapping is TransferFunction but no (or an empty) transfer function "
                  "is set.");
    return 0;
  }

  // One piece of several (pvbatch with MPI): the default scalar range is the
  // range over all pieces, so that equal values get equal densities
  // everywhere. Every piece takes part in that reduction, even one that has
  // nothing to sample, before it gives up.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const int pieces =
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  const bool distributed =
    pieces > 1 && this->Controller && this->Controller->GetNumberOfProcesses() > 1;
  const bool globalRange = distributed && this->DensityMapping == DENSITY_SCALAR_RANGE &&
    !this->UseCustomScalarRange;

  int extent[6];
  input->GetExtent(extent);
  const int nx = extent[1] - extent[0] + 1;
  const int ny = extent[3] - extent[2] + 1;
  const int nz = extent[5] - extent[4] + 1;
  const bool emptyPiece = nx <= 0 || ny <= 0 || nz <= 0;
  vtkDataArray* array = nullptr;
  if (emptyPiece && !distributed)
  {
    vtkErrorMacro("The input image has an empty extent [" << extent[0] << ", " << extent[1]
                                                          << ", " << extent[2] << ", " << extent[3]
                                                          << ", " << extent[4] << ", " << extent[5]
                                                          << "]: nothing to sample.");
  }
  else if (!emptyPiece)
  {
    array = this->GetDensityArray(input, inputVector);
  }

  double range[2] = { this->ScalarRange[0], this->ScalarRange[1] };
  if (this->DensityMapping == DENSITY_SCALAR_RANGE && !this->UseCustomScalarRange)
  {
    range[0] = std::numeric_limits<double>::infinity();
    range[1] = -range[0];
    if (array)
    {
      ComputeFiniteRange(array, this->Component, range);
    }
    if (globalRange)
    {
      const double local[2] = { range[0], -range[1] };
      double global[2] = { 0.0, 0.0 };
      this->Controller->AllReduce(local, global, 2, vtkCommunicator::MIN_OP);
      range[0] = global[0];
      range[1] = -global[1];
    }
  }
  if (!array)
  {
    // An empty piece of a distributed run is not an error: nothing to sample.
    return emptyPiece && distributed ? 1 : 0;
  }
  const vtkIdType voxels = static_cast<vtkIdType>(nx) * ny * nz;

  DensityMap map;
  map.Mode = this->DensityMapping;
  map.Scale = this->DensityScale;
  if (this->DensityMapping == DENSITY_TRANSFER_FUNCTION)
  {
    map.Function = this->TransferFunction;
  }
  else if (this->DensityMapping == DENSITY_SCALAR_RANGE)
  {
    if (!std::isfinite(range[0]) || !std::isfinite(range[1]) || range[0] > range[1])
    {
      vtkErrorMacro("Invalid scalar range [" << range[0] << ", " << range[1] << "].");
      return 0;
    }
    map.Low = range[0];
    if (range[1] > range[0])
    {
      map.InverseWidth = 1.0 / (range[1] - range[0]);
    }
    else
    {
      // A single value is the top of its own range: density 1 there (times
      // DensityScale), 0 below, so a constant field samples uniformly.
      vtkWarningMacro("The scalar range is the single value " << range[0]
                                                              << ": it maps to density 1.");
      map.Mode = DENSITY_STEP;
    }
  }

  vtkErrorDiffusionParameterTable table;
  if (this->ParameterSet == PARAMETERS_FIXED)
  {
    table = vtkErrorDiffusionParameterTable::Fixed();
  }
  else if (this->ParameterSet == PARAMETERS_OPTIMIZED)
  {
    table = vtkErrorDiffusionParameterTable::Optimized();
  }
  else if (this->ParameterSet == PARAMETERS_CUSTOM)
  {
    std::string error;
    if (this->ParameterFile.empty())
    {
      vtkErrorMacro("ParameterSet is Custom but no ParameterFile is set.");
      return 0;
    }
    if (!vtkErrorDiffusionParameterTable::ReadFile(this->ParameterFile, table, error))
    {
      vtkErrorMacro("Cannot use the parameter file: " << error);
      return 0;
    }
  }
  else
  {
    table = vtkErrorDiffusionParameterTable::Paper();
  }

  // --- Sample layer by layer: the scan on a worker thread, the points built
  // here as its layers come in (or both in turn on this thread).
  vtkErrorDiffusionKernel kernel;
  kernel.SetParameters(table);
  kernel.SetModulationScale(this->ModulationScale);
  kernel.SetSeed(static_cast<std::uint64_t>(static_cast<unsigned int>(this->Seed)));
  kernel.SetBoundaryMode(this->BoundaryMode);
  kernel.SetMethod(this->Method);
  kernel.SetWarmUpLayers(this->WarmUpLayers);
  kernel.Begin(nx, ny, nz, extent[4]);

  const vtkIdType layerSize = static_cast<vtkIdType>(nx) * ny;
  vtkSmartPointer<vtkUnsignedCharArray> maskArray;
  if (this->GenerateMask)
  {
    maskArray = vtkSmartPointer<vtkUnsignedCharArray>::New();
    maskArray->SetName("SampleMask");
    maskArray->SetNumberOfValues(voxels);
  }

  vtkErrorDiffusionPointAssembler assembler;
  assembler.Begin(input, output->GetPointData(),
    this->OutputPointsPrecision == DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT);
  vtkSmartPointer<vtkCellArray> vertices;

  vtkErrorDiffusionLayerRunner runner;
  runner.SetThreaded(this->UseWorkerThread && nz > 1 &&
    voxels >= MIN_VOXELS_FOR_WORKER_THREAD && std::thread::hardware_concurrency() > 1);
  // Voxels that belong to another piece get density 0, so each voxel of the
  // whole volume is sampled once: points the input flags as duplicate or
  // hidden, and, for one piece of several, the upper faces shared with the
  // next piece (structured pieces overlap by one plane of points).
  vtkUnsignedCharArray* ghosts = input->GetPointGhostArray();
  const unsigned char* ghostFlags = ghosts ? ghosts->GetPointer(0) : nullptr;
  bool sharedFace[3] = { false, false, false };
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (pieces > 1 && inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    int whole[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    for (int a = 0; a < 3; ++a)
    {
      sharedFace[a] = extent[2 * a + 1] < whole[2 * a + 1];
    }
  }
  runner.SetFill([&](int k, float* density) {
    const vtkIdType first = k * layerSize;
    FillLayerDensity(array, first, first + layerSize, this->Component, map, density);
    if (ghostFlags)
    {
      const unsigned char notOwned =
        vtkDataSetAttributes::DUPLICATEPOINT | vtkDataSetAttributes::HIDDENPOINT;
      for (vtkIdType i = 0; i < layerSize; ++i)
      {
        density[i] = (ghostFlags[first + i] & notOwned) ? 0.0f : density[i];
      }
    }
    if (sharedFace[0])
    {
      for (int j = 0; j < ny; ++j)
      {
        density[static_cast<vtkIdType>(j) * nx + nx - 1] = 0.0f;
      }
    }
    if (sharedFace[1])
    {
      std::fill(density + layerSize - nx, density + layerSize, 0.0f);
    }
    if (sharedFace[2] && k == nz - 1)
    {
      std::fill(density, density + layerSize, 0.0f);
    }
  });
  if (maskArray)
  {
    runner.SetMaskStorage([&](int k) { return maskArray->GetPointer(k * layerSize); });
  }
  const int progressStride = std::max(1, nz / 100);
  runner.SetConsume([&](const vtkErrorDiffusionLayerRunner::Layer& layer) {
    assembler.AddLayer(layer.Index, layer.Density, layer.Mask, layer.Count);
    if (layer.Index % progressStride == 0)
    {
      this->UpdateProgress(static_cast<double>(layer.Index + 1) / nz);
      return !this->IsAborted();
    }
    return true;
  });
  // The vertex cells need only the count: the scan thread makes them while
  // the points are being finished.
  runner.SetFinish([&](vtkIdType samples) {
    vertices = vtkErrorDiffusionPointAssembler::MakeVertices(samples);
  });

  this->UpdateProgress(0.0);
  if (!runner.Run(kernel, nx, ny, nz))
  {
    output->Initialize();
    if (!runner.GetError().empty())
    {
      vtkErrorMacro("Sampling failed: " << runner.GetError());
      return 0;
    }
    return 1; // aborted
  }
  output->SetPoints(assembler.End());
  output->SetVerts(vertices);

  // --- The sampling grid, for the spectrum.
  vtkFieldData* fd = output->GetFieldData();
  vtkNew<vtkDoubleArray> origin;
  AddFieldArray(fd, origin, "SamplingGridOrigin", 3);
  origin->SetTuple(0, input->GetOrigin());
  vtkNew<vtkDoubleArray> spacing;
  AddFieldArray(fd, spacing, "SamplingGridSpacing", 3);
  spacing->SetTuple(0, input->GetSpacing());
  vtkNew<vtkIntArray> gridExtent;
  AddFieldArray(fd, gridExtent, "SamplingGridExtent", 6);
  std::copy(extent, extent + 6, gridExtent->GetPointer(0));
  vtkNew<vtkDoubleArray> direction;
  AddFieldArray(fd, direction, "SamplingGridDirection", 9);
  direction->SetTuple(0, input->GetDirectionMatrix()->GetData());

  if (maskArray)
  {
    mask->SetExtent(extent);
    mask->SetOrigin(input->GetOrigin());
    mask->SetSpacing(input->GetSpacing());
    mask->SetDirectionMatrix(input->GetDirectionMatrix());
    mask->GetPointData()->SetScalars(maskArray);
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionSampler::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << this->Method << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "DensityMapping: " << this->DensityMapping << "\n";
  os << indent << "ScalarRange: " << this->ScalarRange[0] << ", " << this->ScalarRange[1] << "\n";
  os << indent << "UseCustomScalarRange: " << this->UseCustomScalarRange << "\n";
  os << indent << "TransferFunction: " << this->TransferFunction << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "ParameterSet: " << this->ParameterSet << "\n";
  os << indent << "ParameterFile: " << this->ParameterFile << "\n";
  os << indent << "ModulationScale: " << this->ModulationScale << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "BoundaryMode: " << this->BoundaryMode << "\n";
  os << indent << "WarmUpLayers: " << this->WarmUpLayers << "\n";
  os << indent << "GenerateMask: " << this->GenerateMask << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "UseWorkerThread: " << this->UseWorkerThread << "\n";
  os << indent << "Controller: " << this->Controller << "\n";
}
