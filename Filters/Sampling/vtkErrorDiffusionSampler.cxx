// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionSampler.h"

#include "vtkBlueNoiseRelaxation.h"
#include "vtkBlueNoiseThreads.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorDiffusionLayerBacklog.h"
#include "vtkErrorDiffusionLayerRunner.h"
#include "vtkErrorDiffusionParameterTable.h"
#include "vtkErrorDiffusionPointAssembler.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPoissonDiskKernel.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSamplingBudget.h"
#include "vtkSamplingLattice.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVersionMacros.h"
#include "vtkWeightedSampleEliminationKernel.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <new>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkErrorDiffusionSampler);
vtkCxxSetObjectMacro(vtkErrorDiffusionSampler, TransferFunction, vtkPiecewiseFunction);

namespace
{
// Poisson disk and sample elimination take their piece at once, not by layers.
bool IsWholeVolumeMethod(int method)
{
  return method == vtkErrorDiffusionSampler::METHOD_POISSON_DISK ||
    method == vtkErrorDiffusionSampler::METHOD_SAMPLE_ELIMINATION;
}

// The relaxation passes after the scan, by their rules
// (vtkBlueNoiseRelaxation::Rules): none for the other methods.
std::vector<int> RelaxationRules(int method)
{
  switch (method)
  {
    case vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION:
      return { vtkBlueNoiseRelaxation::RULE_SPACING };
    case vtkErrorDiffusionSampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION:
      return { vtkBlueNoiseRelaxation::RULE_ENERGY, vtkBlueNoiseRelaxation::RULE_ENERGY };
    default:
      return {};
  }
}

// Below this a second thread costs more than it saves.
constexpr vtkIdType MinimumVoxelsForWorkerThread = 32768;

// Layers [first, last] split into `parts` contiguous ranges, as even as can be.
std::vector<std::array<int, 2>> SplitLayers(int first, int last, int parts)
{
  std::vector<std::array<int, 2>> ranges;
  const long long count = static_cast<long long>(last) - first + 1;
  if (count <= 0)
  {
    return ranges;
  }
  parts = static_cast<int>(std::min<long long>(std::max(parts, 1), count));
  for (int p = 0; p < parts; ++p)
  {
    const int begin = first + static_cast<int>(count * p / parts);
    const int end = first + static_cast<int>(count * (p + 1) / parts) - 1;
    ranges.push_back({ begin, end });
  }
  return ranges;
}

bool Contains(const int outer[6], const int inner[6])
{
  for (int a = 0; a < 3; ++a)
  {
    if (inner[2 * a] < outer[2 * a] || inner[2 * a + 1] > outer[2 * a + 1])
    {
      return false;
    }
  }
  return true;
}

void AddFieldArray(vtkFieldData* fd, vtkDataArray* array, const char* name, int components)
{
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(1);
  fd->AddArray(array);
}

// Clears the voxels of the last n points the closing correction took back.
// Points are appended in the mask's order (layer after layer, x fastest), so
// theirs are the mask's last n set voxels. (They once came back from the
// points' coordinates, which single precision far from the origin rounds to
// another voxel, even one outside the mask: an out-of-bounds write found by
// fuzzing.)
void ClearLastVoxels(vtkUnsignedCharArray* mask, vtkIdType begin, vtkIdType end, vtkIdType n)
{
  unsigned char* values = mask->GetPointer(0);
  for (vtkIdType i = end - 1; i >= begin && n > 0; --i)
  {
    if (values[i])
    {
      values[i] = 0;
      --n;
    }
  }
}

// The parameter table of a ParameterSet; false with the reason for a bad file.
bool SelectTable(
  int set, const std::string& file, vtkErrorDiffusionParameterTable& table, std::string& error)
{
  switch (set)
  {
    case vtkErrorDiffusionSampler::PARAMETERS_FIXED:
      table = vtkErrorDiffusionParameterTable::Fixed();
      return true;
    case vtkErrorDiffusionSampler::PARAMETERS_OPTIMIZED:
      table = vtkErrorDiffusionParameterTable::Optimized();
      return true;
    case vtkErrorDiffusionSampler::PARAMETERS_CUSTOM:
      if (file.empty())
      {
        error = "ParameterSet is Custom but no ParameterFile is set.";
        return false;
      }
      if (!vtkErrorDiffusionParameterTable::ReadFile(file, table, error))
      {
        error = "Cannot use the parameter file: " + error;
        return false;
      }
      return true;
    default:
      table = vtkErrorDiffusionParameterTable::Paper();
      return true;
  }
}
}

//------------------------------------------------------------------------------
// The state of one run: its plan (which layers each step reads, which z-part
// samples which layers) and what is carried from one step (one execution of a
// streamed run) to the next.
class vtkErrorDiffusionSampler::vtkInternals
{
public:
  class SlabScan;
  class Schedule;

  struct Step
  {
    bool Statistics = false;
    int First = 0; // layers of the step
    int Last = -1;
  };

  // One z-part of the sampled layers: its own scan (from its overlap on) and
  // relaxation. A run in one part adds each final layer to the output at
  // once; of parts scanned side by side only the writer does, the others
  // keep their final layers compacted until they are the writer (see
  // Schedule). Parts live from run to run, the first one's kernel with the
  // charge curves it calibrated; a part's buffers (its kernel's error, its
  // relaxation's layers, its runner's slots) exist only from its first chunk
  // to its last, so parts side by side hold the memory of one part a thread.
  // A part that a thread starts after it ended another takes over that one's
  // buffers.
  struct Part : public vtkErrorDiffusionLayerBacklog::Sink
  {
    vtkInternals* Run = nullptr;
    int First = 0; // sampled layers
    int Last = -1;
    int ScanFirst = 0; // first layer scanned (overlap included)
    vtkErrorDiffusionKernel Kernel;
    std::vector<vtkBlueNoiseRelaxation> Relaxations; // its passes, one after the other
    vtkErrorDiffusionLayerBacklog Backlog; // the relaxation's final layers, to Emit
    vtkErrorDiffusionLayerRunner Runner;   // its chunks, when parts run side by side
    vtkSamplingDensity::ValueTable Values; // its fills' own: parts fill side by side
    vtkErrorDiffusionPointAssembler::HeldLayers Held; // final layers not written yet
    bool Direct = true;   // the writer: its layers go straight into the output
    bool Started = false; // its buffers are made (Start)

    // A final layer of samples: into the points (or held, see above), and
    // into the mask unless the kernel wrote it there. From the thread that
    // scans the part, or from the scan thread for a relaxed layer (the
    // backlog emits one layer at a time, under its lock).
    void Emit(int z, const float* density, const unsigned char* mask, vtkIdType count)
    {
      vtkInternals& run = *this->Run;
      if (this->Direct)
      {
        run.Assembler.AddLayer(z, density, mask, count);
      }
      else
      {
        run.Assembler.Hold(z, density, mask, this->Held);
      }
      if (run.Mask)
      {
        unsigned char* stored = run.Mask->GetPointer((z - run.Sampled[4]) * run.LayerSize());
        if (stored != mask)
        {
          std::copy(mask, mask + run.LayerSize(), stored);
        }
      }
    }

    void Emit(const vtkBlueNoiseRelaxation::Layer& layer) override
    {
      this->Emit(layer.Z, layer.Density, layer.Mask, layer.Count);
    }

    // A layer the scan finished: final, or on to the relaxation first.
    void Receive(int z, const float* density, const unsigned char* mask, vtkIdType count)
    {
      if (z < this->First)
      {
        // An overlap layer: it settles the scan, and the last few are what the
        // relaxation of the part's first layers sees below them.
        // Each pass returns it at once, as it came.
        if (this->Run->Relaxing() && z >= this->RelaxFirst())
        {
          for (vtkBlueNoiseRelaxation& pass : this->Relaxations)
          {
            pass.Push(z, density, mask);
          }
        }
        return;
      }
      if (!this->Run->Relaxing())
      {
        this->Emit(z, density, mask, count);
        return;
      }
      this->Relax(0, z, density, mask);
      if (z == this->Last)
      {
        this->FlushFrom(0);
        this->Backlog.EmitAll();
      }
    }

    // Layer z into relaxation pass `pass`; what it returns on to the next
    // pass, or from the last one to the backlog. (A pass copies what it keeps
    // of a layer in Push, or returns it as it came: the layers one pass
    // returns need not outlive the next pass's Push.)
    void Relax(size_t pass, int z, const float* density, const unsigned char* mask)
    {
      if (pass + 1 == this->Relaxations.size())
      {
        this->Backlog.BeforePush();
        this->Backlog.AfterPush(this->Relaxations[pass].Push(z, density, mask));
        return;
      }
      for (const auto& layer : this->Relaxations[pass].Push(z, density, mask))
      {
        this->Relax(pass + 1, layer.Z, layer.Density, layer.Mask);
      }
    }

    // After the part's last layer: passes `pass` on flushed in turn.
    void FlushFrom(size_t pass)
    {
      if (pass + 1 == this->Relaxations.size())
      {
        this->Backlog.AfterPush(this->Relaxations[pass].Flush());
        return;
      }
      for (const auto& layer : this->Relaxations[pass].Flush())
      {
        this->Relax(pass + 1, layer.Z, layer.Density, layer.Mask);
      }
      this->FlushFrom(pass + 1);
    }

    // Its kernel's warm-up: the `layers` of settling (WarmUpLayers) that its
    // overlap layers do not give already. The overlap settles the pattern on
    // the volume's own layers, so that a part does not scan both.
    int WarmUp(int layers) const
    {
      return std::max(0, layers - (this->First - this->ScanFirst));
    }

    // The first layer the relaxation sees: the overlap layers its search reaches.
    int RelaxFirst() const
    {
      return std::max(this->ScanFirst, this->First - vtkBlueNoiseRelaxation::MaximumRadius);
    }

    // Before its first chunk: the kernel a copy of the run's first kernel as
    // it began (its settings and charge curves) but its own warm-up (see
    // WarmUp), and the relaxation begun. With the buffers of `ended` (a part
    // done with its chunks, or null): its memory is in place, where fresh
    // pages would cost a fault each.
    void Start(const vtkErrorDiffusionKernel& begun, std::uint64_t seed, int warmUp, Part* ended)
    {
      vtkInternals& run = *this->Run;
      this->Kernel = begun;
      if (ended)
      {
        this->TakeBuffers(*ended);
      }
      this->Kernel.SetWarmUpLayers(this->WarmUp(warmUp));
      this->Kernel.Begin(run.NX(), run.NY(), this->ScanFirst);
      this->StartRelaxation(seed);
      this->Held.SetRoom((this->Last - this->First + 1) * run.LayerSize()); // a point a voxel
    }

    void StartRelaxation(std::uint64_t seed)
    {
      vtkInternals& run = *this->Run;
      this->Relaxations.resize(run.RelaxationRules.size());
      for (size_t pass = 0; pass < this->Relaxations.size(); ++pass)
      {
        // Another order each pass: a seed of its own.
        this->Relaxations[pass].SetRule(run.RelaxationRules[pass]);
        this->Relaxations[pass].Begin(
          run.NX(), run.NY(), this->RelaxFirst(), seed + 0x9E3779B97F4A7C15ULL * pass, this->First);
      }
      this->Backlog.SetSink(this);
      this->Started = true;
    }

    // The buffers of a part that ended (Start), which keeps none.
    void TakeBuffers(Part& ended)
    {
      this->Kernel.SwapLayerBuffers(ended.Kernel);
      this->Runner.SwapBuffers(ended.Runner);
      std::swap(this->Relaxations, ended.Relaxations);
      std::swap(this->Values, ended.Values);
      ended.Release();
    }

    // After its last chunk (and DropAheadPoints, which reads the kernel's
    // error). Its held layers are not touched: the writer may be writing them.
    void Release()
    {
      this->Kernel.ReleaseLayerBuffers();
      this->Relaxations = std::vector<vtkBlueNoiseRelaxation>();
      this->Runner.ReleaseBuffers();
      this->Values = vtkSamplingDensity::ValueTable();
    }

    // This part's turn to write (one thread writes to the output at a
    // time): its held layers after the output's points (with the threads
    // when the others are idle: `spread`), and its next ones straight into
    // the output.
    void BecomeWriter(bool spread)
    {
      if (this->Direct)
      {
        return;
      }
      this->Direct = true;
      vtkErrorDiffusionPointAssembler& assembler = this->Run->Assembler;
      assembler.WriteHeld(this->Held, assembler.Grow(this->Held.GetNumberOfPoints()), spread);
      this->Held.Release(); // a writer holds no more
    }

    // Error diffusion cannot take a point back: a scan that ends on negative
    // error fired that many points ahead of their mass, in the last layers
    // that have points (see vtkErrorDiffusionKernel); they go, from the
    // output when this part writes there (they are its last points), else
    // from the layers it holds.
    void DropAheadPoints(bool diffusion)
    {
      vtkInternals& run = *this->Run;
      const double leftover = this->Kernel.GetCarriedError();
      if (!diffusion || leftover > -0.5)
      {
        return;
      }
      const vtkIdType n = static_cast<vtkIdType>(std::llround(-leftover));
      const vtkIdType removed =
        this->Direct ? run.Assembler.RemoveLast(n) : this->Held.DropLast(n);
      if (run.Mask)
      {
        const vtkIdType layer = run.LayerSize();
        ClearLastVoxels(run.Mask, (this->First - run.Sampled[4]) * layer,
          (this->Last - run.Sampled[4] + 1) * layer, removed);
      }
    }
  };

  // The plan, made in RequestUpdateExtent before the first execution.
  int Whole[6] = { 0, -1, 0, -1, 0, -1 };
  int Sampled[6] = { 0, -1, 0, -1, 0, -1 }; // the piece: full layers
  int ScanFirst = 0;                        // first layer scanned (overlap included)
  bool Piece = false;                       // one piece of several
  bool Cells = false;                       // the sites are the input's cells
  std::vector<Step> Steps;
  std::vector<std::unique_ptr<Part>> Parts; // at least one
  // The first part's kernel as it began the run, without its buffers: what
  // the other parts start from (Part::Start).
  vtkErrorDiffusionKernel Begun;
  size_t Current = 0;
  bool Running = false;
  bool Executing = false; // inside RequestData (see RequestData)
  bool NeedsStatistics = false; // every piece takes part, even one without layers
  std::vector<int> RelaxationRules; // of its passes (vtkBlueNoiseRelaxation::Rules)
  bool Relaxing() const { return !this->RelaxationRules.empty(); } // layers held back

  // The run.
  vtkSamplingDensity Density;
  vtkSamplingBudget Statistics;
  vtkErrorDiffusionPointAssembler Assembler;
  vtkSmartPointer<vtkPolyData> Points;
  vtkSmartPointer<vtkUnsignedCharArray> Mask;
  std::vector<double> LayerSums; // expected points per sampled layer
  bool AssemblerStarted = false;
  double ProgressTotal = 1.0;
  double ProgressDone = 0.0;

  vtkInternals() { this->Parts.emplace_back(new Part); }

  Part& First() { return *this->Parts.front(); }

  // What a run held goes when it ends, or when a new pass of the pipeline
  // drops an unfinished one: the parts but the first (whose kernel outlives
  // the run), what they held, the points and the mask.
  void EndRun()
  {
    for (auto& part : this->Parts)
    {
      part->Backlog.Clear();
      part->Held.Release();
      part->Release();
    }
    this->Begun = vtkErrorDiffusionKernel();
    this->Points = nullptr;
    this->Mask = nullptr;
  }

  int NX() const { return this->Whole[1] - this->Whole[0] + 1; }
  int NY() const { return this->Whole[3] - this->Whole[2] + 1; }
  vtkIdType LayerSize() const { return static_cast<vtkIdType>(this->NX()) * this->NY(); }
  int SampledLayers() const { return std::max(0, this->Sampled[5] - this->Sampled[4] + 1); }

  // The input extent a step needs: full layers, the layer after a sampling
  // step's last one when the scan goes on past it, and the layers the
  // relaxation has not released yet (their attributes are read when it does).
  void StepExtent(const Step& step, int extent[6]) const
  {
    std::copy(this->Whole, this->Whole + 4, extent);
    extent[4] = step.First;
    extent[5] = step.Last;
    if (!step.Statistics && step.Last < this->Sampled[5])
    {
      extent[5] = step.Last + 1;
    }
    if (!step.Statistics && this->Relaxing())
    {
      extent[4] = std::min(step.First,
        std::max(this->Sampled[4],
          step.First -
            static_cast<int>(this->RelaxationRules.size()) * (vtkBlueNoiseRelaxation::MaximumRadius + 2)));
    }
  }
};

//------------------------------------------------------------------------------
vtkErrorDiffusionSampler::vtkErrorDiffusionSampler()
  : Internals(new vtkInternals)
{
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkErrorDiffusionSampler::~vtkErrorDiffusionSampler()
{
  this->SetTransferFunction(nullptr);
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
bool vtkErrorDiffusionSampler::IsErrorDiffusion(int method)
{
  return method == METHOD_ERROR_DIFFUSION || !RelaxationRules(method).empty();
}

//------------------------------------------------------------------------------
int vtkErrorDiffusionSampler::GetNumberOfParts()
{
  const vtkInternals& run = *this->Internals;
  return run.Steps.empty() ? 0 : static_cast<int>(run.Parts.size());
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionSampler::GetPartRange(int i, int range[3])
{
  range[0] = range[1] = range[2] = -1;
  if (i >= 0 && i < this->GetNumberOfParts())
  {
    const vtkInternals::Part& part = *this->Internals->Parts[static_cast<size_t>(i)];
    range[0] = part.ScanFirst;
    range[1] = part.First;
    range[2] = part.Last;
  }
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
  // The mask lives on the input's grid; without it the port announces an
  // empty extent, which an empty image satisfies: asking for that port never
  // makes the filter execute again.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* maskInfo = outputVector->GetInformationObject(1);
  const auto wholeKey = vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT();
  // A new pass of the pipeline (a run's steps never call for one): a run left
  // unfinished, its input having failed between steps, is dropped, so that
  // the plan is made again for this input.
  if (!this->Internals->Executing)
  {
    this->Internals->Running = false;
    this->Internals->EndRun();
  }
  const int empty[6] = { 0, -1, 0, -1, 0, -1 };
  maskInfo->CopyEntry(inInfo, wholeKey);
  maskInfo->CopyEntry(inInfo, vtkDataObject::ORIGIN());
  maskInfo->CopyEntry(inInfo, vtkDataObject::SPACING());
  maskInfo->CopyEntry(inInfo, vtkDataObject::DIRECTION());
  if (this->SamplesCells())
  {
    vtkSamplingLattice::ToCellLattice(maskInfo);
  }
  if (!this->GenerateMask || !inInfo->Has(wholeKey))
  {
    maskInfo->Set(wholeKey, empty, 6);
  }
  vtkDataObject::SetPointDataActiveScalarInfo(maskInfo, VTK_UNSIGNED_CHAR, 1);
  return 1;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionSampler::GetStatisticsLayers(
  const int whole[6], int, int, int& first, int& last)
{
  first = whole[4];
  last = whole[5];
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionSampler::ReduceStatistics(vtkSamplingBudget&)
{
  return true;
}

//------------------------------------------------------------------------------
// The request of the run's current step (planned first when the run starts).
int vtkErrorDiffusionSampler::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (this->Internals->Executing)
  {
    return 1; // a request from within this execution (see RequestData)
  }
  // The piece is that of the port asked for; the other port gets the same
  // request, so that asking for it next does not execute the filter again.
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int from =
    request->Has(SDDP::FROM_OUTPUT_PORT()) ? std::max(0, request->Get(SDDP::FROM_OUTPUT_PORT())) : 0;
  vtkInformation* outInfo = outputVector->GetInformationObject(from);
  vtkInformation* otherInfo = outputVector->GetInformationObject(1 - from);
  otherInfo->CopyEntry(outInfo, SDDP::UPDATE_PIECE_NUMBER());
  otherInfo->CopyEntry(outInfo, SDDP::UPDATE_NUMBER_OF_PIECES());
  otherInfo->CopyEntry(outInfo, SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS());
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInternals& run = *this->Internals;
  int inputWhole[6] = { 0, -1, 0, -1, 0, -1 };
  inInfo->Get(SDDP::WHOLE_EXTENT(), inputWhole);
  // The plan is made on the sites' lattice: the points, or the cells.
  const bool cells = this->SamplesCells();
  int whole[6];
  std::copy(inputWhole, inputWhole + 6, whole);
  if (cells)
  {
    vtkSamplingLattice::CellExtent(inputWhole, whole);
  }
  if (run.Running && (cells != run.Cells || !std::equal(whole, whole + 6, run.Whole)))
  {
    run.Running = false; // the plan of another input
  }
  if (!run.Running)
  {
    const int piece =
      outInfo->Has(SDDP::UPDATE_PIECE_NUMBER()) ? outInfo->Get(SDDP::UPDATE_PIECE_NUMBER()) : 0;
    const int pieces = outInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES())
      ? outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES())
      : 1;
    this->PlanRun(whole, piece, pieces);
    run.Cells = cells;
    // The last output's arrays that nothing else holds are written again
    // (the executive empties the output before RequestData).
    run.Assembler.Recycle(vtkPolyData::GetData(outputVector, 0));
  }
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  if (run.Current < run.Steps.size())
  {
    run.StepExtent(run.Steps[run.Current], extent);
  }
  // The mask is the sampled extent (a z-slab for a piece), whatever extent
  // the pipeline translated the piece into for that port.
  const int empty[6] = { 0, -1, 0, -1, 0, -1 };
  vtkInformation* maskInfo = outputVector->GetInformationObject(1);
  maskInfo->Set(SDDP::UPDATE_EXTENT(), this->GenerateMask ? run.Sampled : empty, 6);
  if (cells)
  {
    const int sites[6] = { extent[0], extent[1], extent[2], extent[3], extent[4], extent[5] };
    vtkSamplingLattice::PointExtent(sites, inputWhole, extent);
  }
  // The request is the extent alone: the piece is already in it.
  inInfo->Set(SDDP::UPDATE_EXTENT(), extent, 6);
  inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  return 1;
}

//------------------------------------------------------------------------------
// The plan of a run: the piece's layers, the overlap above it, and the steps
// (statistics slabs, then sampling slabs), each one input request.
void vtkErrorDiffusionSampler::PlanRun(const int whole[6], int piece, int pieces)
{
  vtkInternals& run = *this->Internals;
  std::copy(whole, whole + 6, run.Whole);
  run.Piece = pieces > 1;
  std::copy(run.Whole, run.Whole + 6, run.Sampled);
  const auto parts = SplitLayers(run.Whole[4], run.Whole[5], pieces);
  const bool emptyPiece = piece >= static_cast<int>(parts.size());
  run.Sampled[4] = emptyPiece ? 0 : parts[piece][0];
  run.Sampled[5] = emptyPiece ? -1 : parts[piece][1];
  // The whole-volume methods take their piece at once, without overlap.
  const bool atOnce = IsWholeVolumeMethod(this->Method);
  const int slabs = atOnce ? 1 : this->NumberOfSlabs;
  run.RelaxationRules = RelaxationRules(this->Method);
  run.ScanFirst =
    std::max(run.Whole[4], run.Sampled[4] - (run.Piece && !atOnce ? this->OverlapLayers : 0));
  run.Steps.clear();
  run.Current = 0;
  vtkSamplingDensity probe;
  probe.SetMapping(this->ValueMapping(), this->Component, this->TransferFunction);
  if (this->UseCustomScalarRange)
  {
    probe.SetRange(this->ScalarRange[0], this->ScalarRange[1]);
  }
  run.NeedsStatistics = probe.NeedsStatistics(this->UseNumberOfPoints);
  if (run.NeedsStatistics)
  {
    int first = 0, last = -1;
    this->GetStatisticsLayers(run.Whole, piece, pieces, first, last);
    for (const auto& slab : SplitLayers(first, last, slabs))
    {
      run.Steps.push_back({ true, slab[0], slab[1] });
    }
  }
  for (const auto& slab : SplitLayers(run.ScanFirst, run.Sampled[5], slabs))
  {
    run.Steps.push_back({ false, slab[0], slab[1] });
  }
  this->PlanParts(atOnce);
}

//------------------------------------------------------------------------------
// The z-parts of the sampled layers, by the volume's size alone (so that the
// output does not depend on the threads): parts of at least PartLayers layers
// and PartVoxels voxels, each scanning OverlapLayers layers before its own
// first. The whole-volume methods and volumes below two parts' size are
// sampled in one part.
void vtkErrorDiffusionSampler::PlanParts(bool atOnce)
{
  vtkInternals& run = *this->Internals;
  const int count = atOnce ? 1 : this->GetNumberOfPartsFor(run.SampledLayers(), run.LayerSize());
  const auto ranges = SplitLayers(run.Sampled[4], run.Sampled[5], count);
  run.Parts.resize(std::max<size_t>(1, ranges.size()));
  for (size_t p = 0; p < run.Parts.size(); ++p)
  {
    if (!run.Parts[p])
    {
      run.Parts[p].reset(new vtkInternals::Part);
    }
    vtkInternals::Part& part = *run.Parts[p];
    part.Run = &run;
    part.First = p < ranges.size() ? ranges[p][0] : run.Sampled[4];
    part.Last = p < ranges.size() ? ranges[p][1] : run.Sampled[5];
    part.ScanFirst =
      p == 0 ? run.ScanFirst : std::max(run.Whole[4], part.First - this->OverlapLayers);
  }
}

//------------------------------------------------------------------------------
int vtkErrorDiffusionSampler::GetNumberOfPartsFor(vtkIdType layers, vtkIdType layerVoxels) const
{
  if (IsWholeVolumeMethod(this->Method) || layers <= 0 || layerVoxels <= 0)
  {
    return 1;
  }
  // Through double: layers times voxels may pass what vtkIdType holds.
  const double byVoxels = static_cast<double>(layers) * layerVoxels / this->PartVoxels;
  const double count = std::min(static_cast<double>(layers / this->PartLayers), std::floor(byVoxels));
  return static_cast<int>(std::max(1.0, std::min(count, 65536.0)));
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
// The mapping vtkSamplingDensity applies: the colour map's opacity is a
// transfer function.
int vtkErrorDiffusionSampler::ValueMapping() const
{
  return this->DensityMapping == DENSITY_COLOR_MAP_OPACITY ? DENSITY_TRANSFER_FUNCTION
                                                           : this->DensityMapping;
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionSampler::SamplesCells()
{
  vtkInformation* selection = this->GetInputArrayInformation(0);
  return selection->Has(vtkDataObject::FIELD_ASSOCIATION()) &&
    selection->Get(vtkDataObject::FIELD_ASSOCIATION()) == vtkDataObject::FIELD_ASSOCIATION_CELLS;
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionSampler::ValidateProperties()
{
  if (!std::isfinite(this->DensityScale))
  {
    vtkErrorMacro("DensityScale must be finite and >= 0, not " << this->DensityScale << ".");
    return false;
  }
  if (!std::isfinite(this->ModulationScale))
  {
    vtkErrorMacro("ModulationScale must be finite, in [0, 2], not " << this->ModulationScale << ".");
    return false;
  }
  if (this->DensityMapping == DENSITY_SCALAR_RANGE && this->UseCustomScalarRange &&
    !(std::isfinite(this->ScalarRange[0]) && std::isfinite(this->ScalarRange[1]) &&
      this->ScalarRange[1] > this->ScalarRange[0]))
  {
    vtkErrorMacro("ScalarRange must be finite with ScalarRange[1] > ScalarRange[0], not ["
      << this->ScalarRange[0] << ", " << this->ScalarRange[1] << "].");
    return false;
  }
  return true;
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
    // (The sites' data: the cell data when the sites are the cells.)
    abstractArray = input->GetPointData()->GetScalars();
    association = this->Internals->Cells ? vtkDataObject::FIELD_ASSOCIATION_CELLS
                                         : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  }
  if (!abstractArray)
  {
    vtkErrorMacro("No density array: select a point- or cell-data array with "
                  "SetInputArrayToProcess (the input has no active scalars).");
    return nullptr;
  }
  const char* name = abstractArray->GetName() ? abstractArray->GetName() : "";
  const int expected = this->Internals->Cells ? vtkDataObject::FIELD_ASSOCIATION_CELLS
                                              : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  if (association == vtkDataObject::FIELD_ASSOCIATION_CELLS && association != expected)
  {
    vtkErrorMacro("The density array '" << name << "' was found in the cell data: select it "
                                        << "with the association FIELD_ASSOCIATION_CELLS to "
                                        << "sample one site per cell.");
    return nullptr;
  }
  if (association != expected)
  {
    vtkErrorMacro("The density array '" << name << "' is neither point nor cell data.");
    return nullptr;
  }
  vtkDataArray* array = vtkDataArray::SafeDownCast(abstractArray);
  if (!array)
  {
    vtkErrorMacro("The density array '" << name << "' is not numeric ("
                                        << abstractArray->GetClassName() << ").");
    return nullptr;
  }
  if (array->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkErrorMacro("The density array '" << name << "' has " << array->GetNumberOfTuples()
                                        << " tuples for " << input->GetNumberOfPoints()
                                        << (this->Internals->Cells ? " cells." : " voxels."));
    return nullptr;
  }
  // Component == the number of components is the magnitude: ParaView's
  // component selector (vtkSMNumberOfComponentsDomain) gives "Magnitude" that value.
  const int components = array->GetNumberOfComponents();
  if (this->Component > components)
  {
    vtkErrorMacro("Component " << this->Component << " is out of range: the array '" << name
                               << "' has " << components << " component(s) (" << components
                               << " or -1: the magnitude).");
    return nullptr;
  }
  this->Internals->Density.SetComponent(this->Component == components ? -1 : this->Component);
  return array;
}

//------------------------------------------------------------------------------
// Before the first step: check the properties and set the run up.
bool vtkErrorDiffusionSampler::StartRun(vtkInformation*, vtkInformationVector**)
{
  vtkInternals& run = *this->Internals;
  if (!this->ValidateProperties())
  {
    return false;
  }
  vtkErrorDiffusionParameterTable table;
  std::string error;
  const bool diffusion = IsErrorDiffusion(this->Method);
  if (diffusion && !SelectTable(this->ParameterSet, this->ParameterFile, table, error))
  {
    vtkErrorMacro(<< error);
    return false;
  }
  const bool function = this->TransferFunction && this->TransferFunction->GetSize() > 0;
  // A transfer-function mapping without a function ramps over the range.
  const int mapping = (this->ValueMapping() == DENSITY_TRANSFER_FUNCTION && !function)
    ? DENSITY_SCALAR_RANGE
    : this->ValueMapping();
  run.Density.SetMapping(mapping, this->Component, this->TransferFunction);
  if (mapping == DENSITY_SCALAR_RANGE && this->UseCustomScalarRange)
  {
    run.Density.SetRange(this->ScalarRange[0], this->ScalarRange[1]);
  }
  run.Statistics.Reset();
  // The first part's kernel is kept from run to run with the charge curves
  // it used last (Begin resets the rest); the other parts start from it as
  // it began (Part::Start) and share its curves.
  vtkErrorDiffusionKernel& kernel = run.First().Kernel;
  kernel.SetParameters(table);
  kernel.SetModulationScale(this->ModulationScale);
  kernel.SetSeed(static_cast<std::uint64_t>(this->Seed));
  kernel.SetMethod(this->Method == METHOD_WHITE_NOISE
      ? vtkErrorDiffusionKernel::METHOD_WHITE_NOISE
      : vtkErrorDiffusionKernel::METHOD_ERROR_DIFFUSION);
  kernel.SetWarmUpLayers(run.First().WarmUp(this->WarmUpLayers));
  kernel.Begin(run.NX(), run.NY(), run.ScanFirst);
  if (run.Parts.size() > 1)
  {
    run.Begun = kernel;
    run.Begun.ReleaseLayerBuffers();
  }
  for (auto& part : run.Parts)
  {
    part->Held.Clear();
    part->Direct = true;
    part->Started = false;
  }
  run.Points = vtkSmartPointer<vtkPolyData>::New();
  run.Mask = nullptr;
  run.AssemblerStarted = false;
  run.LayerSums.assign(static_cast<size_t>(run.SampledLayers()), 0.0);
  run.ProgressDone = 0.0;
  run.ProgressTotal = 0.0;
  for (const auto& step : run.Steps)
  {
    // Counting values costs about a quarter of sampling them.
    run.ProgressTotal += (step.Statistics ? 0.25 : 1.0) * (step.Last - step.First + 1);
  }
  run.ProgressTotal = std::max(run.ProgressTotal, 1.0);
  const bool statistics = !run.Steps.empty() && run.Steps.front().Statistics;
  return statistics || this->FinishStatistics();
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionSampler::CollectStatistics(
  vtkImageData* input, vtkInformationVector** inputVector)
{
  vtkInternals& run = *this->Internals;
  const vtkInternals::Step& step = run.Steps[run.Current];
  vtkDataArray* array = this->GetDensityArray(input, inputVector);
  if (!array)
  {
    return false;
  }
  int extent[6];
  input->GetExtent(extent);
  vtkUnsignedCharArray* ghosts = input->GetPointGhostArray();
  const vtkIdType layer = run.LayerSize();
  // A few million values at a time, to report progress and honor abort;
  // split over threads of its own where vtkSMPTools' backend would not.
  const int chunk = static_cast<int>(std::max<vtkIdType>(1, (vtkIdType(1) << 22) / layer));
  const int threads = vtkBlueNoiseThreads::OwnThreads();
  for (int z = step.First; z <= step.Last; z += chunk)
  {
    const int last = std::min(step.Last, z + chunk - 1);
    const vtkIdType begin = (z - extent[4]) * layer;
    const vtkIdType end = (last - extent[4] + 1) * layer;
    run.Density.CollectStatistics(
      array, begin, end, ghosts ? ghosts->GetPointer(0) : nullptr, run.Statistics, threads);
    run.ProgressDone += 0.25 * (last - z + 1);
    this->UpdateProgress(run.ProgressDone / run.ProgressTotal);
    if (this->IsAborted())
    {
      return false;
    }
  }
  const bool lastStatistics =
    run.Current + 1 >= run.Steps.size() || !run.Steps[run.Current + 1].Statistics;
  return !lastStatistics || this->FinishStatistics();
}

//------------------------------------------------------------------------------
// After the statistics (or without them): the range and the density scale.
bool vtkErrorDiffusionSampler::FinishStatistics()
{
  vtkInternals& run = *this->Internals;
  if (run.NeedsStatistics && !this->ReduceStatistics(run.Statistics))
  {
    return false;
  }
  const auto budget = this->UseNumberOfPoints
    ? vtkSamplingDensity::Budget::Points(static_cast<double>(this->NumberOfPoints))
    : vtkSamplingDensity::Budget::Scale(this->DensityScale);
  const auto outcome = run.Density.Finish(run.NeedsStatistics ? &run.Statistics : nullptr, budget);
  if (outcome.Note)
  {
    vtkWarningMacro("Density: " << outcome.Note << ".");
  }
  if (outcome.OutOfReach)
  {
    vtkWarningMacro("NumberOfPoints " << this->NumberOfPoints << " is more than the volume can "
                                      << "hold: at most " << outcome.Reachable
                                      << " voxels have a positive density, and all are sampled.");
  }
  return true;
}

//------------------------------------------------------------------------------
// The output arrays at the first sampling step; the next slab's arrays after.
bool vtkErrorDiffusionSampler::StartAssembly(vtkImageData* input)
{
  vtkInternals& run = *this->Internals;
  std::string error;
  if (run.AssemblerStarted)
  {
    if (!run.Assembler.SetSource(input, error))
    {
      vtkErrorMacro("Cannot stream the input: " << error << ".");
      return false;
    }
    return true;
  }
  run.Assembler.Begin(input, run.Sampled, run.Points->GetPointData(),
    this->OutputPointsPrecision == DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT);
  run.Assembler.SetJitter(this->Jitter, static_cast<std::uint64_t>(this->Seed));
  run.First().StartRelaxation(static_cast<std::uint64_t>(this->Seed)); // the others: Part::Start
  for (const std::string& name : run.Assembler.GetSkippedArrays())
  {
    vtkWarningMacro("The point array '" << name << "' does not have one tuple per voxel: it is "
                                        << "not carried to the samples.");
  }
  if (this->GenerateMask)
  {
    run.Mask = vtkSmartPointer<vtkUnsignedCharArray>::New();
    run.Mask->SetName("SampleMask");
    run.Mask->SetNumberOfValues(run.LayerSize() * run.SampledLayers());
  }
  run.AssemblerStarted = true;
  return true;
}

//------------------------------------------------------------------------------
// The stages of one part's scan of layers [first, last]
// (vtkErrorDiffusionLayerRunner): densities from the input, finished layers to
// the part's points (through the relaxation for the default method); with
// `report`, progress and abort from the calling thread (the scan of a run in
// one part), else nothing that is not the part's own (parts side by side).
class vtkErrorDiffusionSampler::vtkInternals::SlabScan
  : public vtkErrorDiffusionLayerRunner::Stages
{
public:
  SlabScan(vtkErrorDiffusionSampler* filter, Part& part, vtkImageData* input,
    vtkDataArray* array, int first, int last, double report)
    : Filter(filter)
    , Run(*filter->Internals)
    , Work(part)
    , First(first)
    , Array(array)
    , LayerSize(Run.LayerSize())
    , Report(report)
    , ProgressStride(std::max(1, (last - first + 1) / 100))
  {
    input->GetExtent(this->Extent);
    vtkUnsignedCharArray* ghosts = input->GetPointGhostArray();
    this->Ghosts = ghosts ? ghosts->GetPointer(0) : nullptr;
  }

  void Fill(int k, float* density) override
  {
    const int z = this->First + k;
    const vtkIdType begin = (z - this->Extent[4]) * this->LayerSize;
    const double sum =
      this->Run.Density.Fill(
        this->Array, begin, begin + this->LayerSize, this->Ghosts, density, this->Work.Values);
    if (z >= this->Work.First && z <= this->Work.Last)
    {
      this->Run.LayerSums[z - this->Run.Sampled[4]] = sum;
    }
  }

  // The kernel writes a final layer's mask straight into the mask output
  // (not a relaxed one: the relaxation moves samples first).
  unsigned char* MaskStorage(int k) override
  {
    const int z = this->First + k;
    if (!this->Run.Mask || this->Run.Relaxing() || z < this->Work.First)
    {
      return nullptr;
    }
    return this->Run.Mask->GetPointer((z - this->Run.Sampled[4]) * this->LayerSize);
  }

  void BeforeScan(int k, const float* density) override
  {
    if (this->First + k == this->Work.First && this->Work.ScanFirst < this->Work.First)
    {
      this->Work.Kernel.CenterCarriedError(density); // the overlap shapes, but adds nothing
    }
  }

  bool Idle() override { return this->Run.Relaxing() && this->Work.Backlog.EmitOne(); }

  bool Consume(const vtkErrorDiffusionLayerRunner::Layer& l) override
  {
    this->Work.Receive(this->First + l.Index, l.Density, l.Mask, l.Count);
    if (this->Report <= 0.0)
    {
      return true;
    }
    this->Run.ProgressDone += this->Report;
    if (l.Index % this->ProgressStride == 0)
    {
      this->Filter->UpdateProgress(this->Run.ProgressDone / this->Run.ProgressTotal);
    }
    return !this->Filter->IsAborted();
  }

private:
  vtkErrorDiffusionSampler* Filter;
  vtkInternals& Run;
  Part& Work;
  int First;
  vtkDataArray* Array;
  vtkIdType LayerSize;
  double Report; // the progress a layer adds (in layers of the step), or 0: none
  int ProgressStride;
  int Extent[6];
  const unsigned char* Ghosts = nullptr;
};

//------------------------------------------------------------------------------
// Whether a scan of `layers` layers runs on a worker thread beside the
// calling one: when allowed and there is enough to overlap.
bool vtkErrorDiffusionSampler::WorkerThreadFor(int layers) const
{
  return this->UseWorkerThread && layers > 1 &&
    this->Internals->LayerSize() * layers >= MinimumVoxelsForWorkerThread &&
    vtkBlueNoiseThreads::Available() > 1;
}

//------------------------------------------------------------------------------
// One sampling step of a scanning method: the layers of one slab through the
// kernel on the runner, in one part or in parts side by side.
bool vtkErrorDiffusionSampler::ScanSlab(vtkImageData* input, vtkDataArray* array)
{
  vtkInternals& run = *this->Internals;
  if (run.Parts.size() > 1)
  {
    return this->ScanParts(input, array);
  }
  const vtkInternals::Step& step = run.Steps[run.Current];
  vtkInternals::Part& part = run.First();
  const int layers = step.Last - step.First + 1;
  vtkErrorDiffusionLayerRunner runner;
  runner.SetThreaded(this->WorkerThreadFor(layers));
  vtkInternals::SlabScan stages(this, part, input, array, step.First, step.Last, 1.0);
  if (!runner.Run(part.Kernel, stages, run.NX(), run.NY(), layers, step.Last < run.Sampled[5]))
  {
    part.Backlog.Clear();
    if (!runner.GetError().empty())
    {
      vtkErrorMacro("Sampling failed: " << runner.GetError());
    }
    return false;
  }
  part.Backlog.EmitAll(); // before the next step's input replaces this one
  return true;
}

//------------------------------------------------------------------------------
// The parts of one step scanned side by side, in epochs with no wait between
// threads within one: in an epoch each thread takes the lowest part that no
// thread holds and is not done, scans it a chunk of layers at a time, and
// takes the next when that part is done, until the epoch's time is up. The
// lowest part whose points are not all in the output (the writer) adds its
// layers to the output as they come; the others hold theirs. A part becomes
// the writer at the start of a chunk once every part below it is in the
// output: the thread that finishes the writer writes the held layers of the
// parts after it that are done too, and hands the output on to the first one
// that is not. So the points are in z order, part after part, whatever the
// threads and their timing. Between epochs the calling thread (which any
// backend may leave out of the epoch's threads) reports progress and honors
// abort. The last part left, or every part when one thread is allowed, is
// scanned by the calling thread at once, reporting layer by layer, with the
// scan on a worker thread beside it as a volume of one part does. Threads
// the epoch's parts leave idle (fewer parts left than threads, or threads
// done with the parts they could take) pair up with the parts: a chunk
// started while one is free runs its scan on a worker thread beside the
// part's thread, and in a longer chunk (the two overlap within a chunk
// only).
class vtkErrorDiffusionSampler::vtkInternals::Schedule
{
public:
  Schedule(vtkErrorDiffusionSampler* self, vtkImageData* input, vtkDataArray* array);

  // Every part of the step on up to `threads` threads; false on an error
  // (reported) or an abort.
  bool Scan(int threads);

private:
  using Clock = std::chrono::steady_clock;

  struct Share
  {
    Part* Target;
    int Next; // layers of the step still to scan: Next .. Last
    int Last;
    bool Busy = false; // a thread holds it
    bool Done = false; // scanned, its points in the output or held
  };

  void Work(Clock::time_point end);
  Share* Take();
  bool ScanChunk(Share& share);
  bool TakePair(int layers);
  bool ScanRest(Share& share);
  void Finish(Share& share);
  void Fail(const std::string& error);
  double ProgressPerLayer() const;
  bool LastLeft();

  vtkErrorDiffusionSampler* Self;
  vtkInternals& Run;
  vtkImageData* Input;
  vtkDataArray* Array;
  bool Diffusion;
  std::vector<Share> Shares;
  int Chunk = 2;           // layers a part scans between two looks at the others
  static constexpr int PairedChunks = 8; // chunks a paired part scans at once
  int Threads = 1;         // the threads the module may use
  double ProgressBase = 0; // where progress stood before the step
  double Layers = 0;       // the step's layers to scan, overlaps included
  std::atomic<bool> Stop{ false };

  std::mutex Mutex; // guards the members below
  size_t Started = 0; // shares started, the lowest ones
  size_t Writer = 0;  // the lowest share whose points are not all in the output
  size_t Left = 0;    // shares not done
  int Working = 0;    // threads in the epoch's Work
  int Pairs = 0;      // worker threads of chunks paired (ScanChunk)
  vtkIdType Scanned = 0;
  std::vector<Part*> Spares; // parts ended, whose buffers the next part started takes
  std::string Error;
};

//------------------------------------------------------------------------------
vtkErrorDiffusionSampler::vtkInternals::Schedule::Schedule(
  vtkErrorDiffusionSampler* self, vtkImageData* input, vtkDataArray* array)
  : Self(self)
  , Run(*self->Internals)
  , Input(input)
  , Array(array)
  , Diffusion(IsErrorDiffusion(self->Method))
{
  const Step& step = this->Run.Steps[this->Run.Current];
  for (auto& part : this->Run.Parts)
  {
    const int first = std::max(step.First, part->ScanFirst);
    const int last = std::min(step.Last, part->Last);
    if (first <= last)
    {
      part->Direct = this->Shares.empty();
      this->Shares.push_back({ part.get(), first, last });
      this->Layers += last - first + 1;
    }
  }
  this->Left = this->Shares.size();
  this->Chunk = static_cast<int>(std::max<vtkIdType>(
    2, (vtkIdType(1) << 20) / std::max<vtkIdType>(1, this->Run.LayerSize())));
  this->ProgressBase = this->Run.ProgressDone;
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionSampler::vtkInternals::Schedule::Scan(int threads)
{
  threads = std::max(1, threads);
  this->Threads = threads;
  // Long enough that a thread's wait for the others' chunks at its end is
  // little beside it, short enough for a progress bar and an abort.
  const auto epoch = std::chrono::milliseconds(500);
  while (this->Left > 0 && !this->Stop)
  {
    if (this->Left == 1 || threads == 1)
    {
      this->ScanRest(*this->Take());
      continue;
    }
    // Counted before they start, so that none takes a thread for a pair
    // that another is about to use.
    this->Working = std::min(threads, static_cast<int>(this->Left));
    const Clock::time_point end = Clock::now() + epoch;
    vtkBlueNoiseThreads::ForEach(this->Working, [&](int) { this->Work(end); });
    this->Run.ProgressDone = this->ProgressBase + this->ProgressPerLayer() * this->Scanned;
    this->Self->UpdateProgress(this->Run.ProgressDone / this->Run.ProgressTotal);
    this->Stop = this->Stop || this->Self->IsAborted();
  }
  for (Part* spare : this->Spares)
  {
    spare->Release();
  }
  if (!this->Error.empty())
  {
    vtkErrorWithObjectMacro(this->Self, "Sampling failed: " << this->Error);
  }
  const Step& step = this->Run.Steps[this->Run.Current];
  this->Run.ProgressDone = this->ProgressBase + (step.Last - step.First + 1);
  return !this->Stop;
}

//------------------------------------------------------------------------------
// The progress a scanned layer stands for: the step's layers over those its
// parts scan, overlaps included.
double vtkErrorDiffusionSampler::vtkInternals::Schedule::ProgressPerLayer() const
{
  const Step& step = this->Run.Steps[this->Run.Current];
  return (step.Last - step.First + 1) / this->Layers;
}

//------------------------------------------------------------------------------
// One thread's share of an epoch: parts, a chunk at a time, until none is
// left to take, or the epoch's time is up, or the part at hand is the last
// one left (it is then left to the next epoch, or to ScanRest).
void vtkErrorDiffusionSampler::vtkInternals::Schedule::Work(Clock::time_point end)
{
  struct Leave // its thread is free for a pair once it leaves
  {
    Schedule& Of;
    ~Leave()
    {
      std::lock_guard<std::mutex> lock(this->Of.Mutex);
      --this->Of.Working;
    }
  } leave{ *this };
  while (!this->Stop && Clock::now() < end)
  {
    Share* share = this->Take();
    if (!share)
    {
      return;
    }
    while (share->Next <= share->Last && Clock::now() < end && !this->LastLeft())
    {
      if (!this->ScanChunk(*share))
      {
        return;
      }
    }
    if (share->Next <= share->Last)
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      share->Busy = false;
      return;
    }
    this->Finish(*share);
  }
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionSampler::vtkInternals::Schedule::LastLeft()
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  return this->Left == 1;
}

//------------------------------------------------------------------------------
// The lowest share no thread holds and not done, started if it was not, with
// the buffers of a part that ended; null if none.
vtkErrorDiffusionSampler::vtkInternals::Schedule::Share*
vtkErrorDiffusionSampler::vtkInternals::Schedule::Take()
{
  Share* share = nullptr;
  Part* spare = nullptr;
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    for (size_t s = this->Writer; s < this->Started && !share; ++s)
    {
      share = this->Shares[s].Busy || this->Shares[s].Done ? nullptr : &this->Shares[s];
    }
    if (!share && this->Started < this->Shares.size())
    {
      share = &this->Shares[this->Started++];
      if (!share->Target->Started && !this->Spares.empty())
      {
        spare = this->Spares.back();
        this->Spares.pop_back();
      }
    }
    if (!share)
    {
      return nullptr;
    }
    share->Busy = true;
  }
  if (!share->Target->Started)
  {
    share->Target->Start(
      this->Run.Begun, static_cast<std::uint64_t>(this->Self->Seed), this->Self->WarmUpLayers, spare);
  }
  else if (spare)
  {
    spare->Release();
  }
  return share;
}

//------------------------------------------------------------------------------
// A chunk of a share's layers, the writer's held layers written first.
bool vtkErrorDiffusionSampler::vtkInternals::Schedule::ScanChunk(Share& share)
{
  bool writer;
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    writer = &this->Shares[this->Writer] == &share;
  }
  Part& part = *share.Target;
  if (writer)
  {
    part.BecomeWriter(false); // the other threads are scanning
  }
  // Paired, longer chunks: the scan and the layers behind it overlap within
  // a chunk only.
  const auto last = [&](int chunk) { return std::min(share.Last, share.Next + chunk - 1); };
  const bool paired = this->TakePair(last(PairedChunks * this->Chunk) - share.Next + 1);
  const int to = last((paired ? PairedChunks : 1) * this->Chunk);
  const int layers = to - share.Next + 1;
  part.Runner.SetThreaded(paired);
  SlabScan stages(this->Self, part, this->Input, this->Array, share.Next, to, 0.0);
  const bool done =
    part.Runner.Run(part.Kernel, stages, this->Run.NX(), this->Run.NY(), layers, to < part.Last);
  if (paired)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    --this->Pairs;
  }
  if (!done)
  {
    this->Fail(part.Runner.GetError().empty() ? "a part stopped" : part.Runner.GetError());
    return false;
  }
  share.Next = to + 1;
  std::lock_guard<std::mutex> lock(this->Mutex);
  this->Scanned += layers;
  return !this->Stop;
}

//------------------------------------------------------------------------------
// Whether a chunk of `layers` layers gets a worker thread: when one of the
// threads the module may use is neither in the epoch's Work nor another
// chunk's worker, and the chunk is worth one (WorkerThreadFor).
bool vtkErrorDiffusionSampler::vtkInternals::Schedule::TakePair(int layers)
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  const bool paired =
    this->Working + this->Pairs < this->Threads && this->Self->WorkerThreadFor(layers);
  this->Pairs += paired ? 1 : 0;
  return paired;
}

//------------------------------------------------------------------------------
// The rest of the writer's layers at once, on the calling thread.
bool vtkErrorDiffusionSampler::vtkInternals::Schedule::ScanRest(Share& share)
{
  Part& part = *share.Target;
  part.BecomeWriter(true); // the last part left: the other threads are idle
  const int layers = share.Last - share.Next + 1;
  part.Runner.SetThreaded(this->Self->WorkerThreadFor(layers));
  SlabScan stages(
    this->Self, part, this->Input, this->Array, share.Next, share.Last, this->ProgressPerLayer());
  if (!part.Runner.Run(
        part.Kernel, stages, this->Run.NX(), this->Run.NY(), layers, share.Last < part.Last))
  {
    if (part.Runner.GetError().empty())
    {
      this->Stop = true; // aborted
    }
    else
    {
      this->Fail(part.Runner.GetError());
    }
    return false;
  }
  share.Next = share.Last + 1;
  this->Scanned += layers;
  this->Finish(share);
  return true;
}

//------------------------------------------------------------------------------
// A share scanned. Its part, if it ended, drops the points it fired ahead of
// their mass (see FinishOutput) and becomes a spare; spares go once no part
// is left to start, before held layers grow the output. When the share was
// the writer, this thread owns the output: it writes the held layers of the
// shares done after it, up to the first one not done, which takes over at
// its next chunk (or when it is done).
void vtkErrorDiffusionSampler::vtkInternals::Schedule::Finish(Share& share)
{
  Part& part = *share.Target;
  part.Backlog.EmitAll(); // before the next step's input replaces this one
  const bool ended = share.Last == part.Last;
  if (ended)
  {
    part.DropAheadPoints(this->Diffusion);
  }
  size_t s = static_cast<size_t>(&share - this->Shares.data());
  std::vector<Part*> spares;
  bool last;
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    share.Done = true;
    share.Busy = false;
    last = --this->Left == 0;
    if (ended)
    {
      this->Spares.push_back(&part);
    }
    if (this->Started == this->Shares.size())
    {
      spares.swap(this->Spares);
    }
    if (this->Writer != s)
    {
      s = this->Shares.size(); // not the writer: nothing to write
    }
  }
  for (Part* spare : spares)
  {
    spare->Release(); // its buffers only: the writer may be writing its held layers
  }
  while (s < this->Shares.size())
  {
    Part& done = *this->Shares[s].Target;
    done.BecomeWriter(last); // after the last share, the other threads are idle
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Writer = ++s;
    s = s < this->Shares.size() && this->Shares[s].Done ? s : this->Shares.size();
  }
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionSampler::vtkInternals::Schedule::Fail(const std::string& error)
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  if (this->Error.empty())
  {
    this->Error = error;
  }
  this->Stop = true;
}

//------------------------------------------------------------------------------
// One sampling step in parts side by side (see Schedule), on as many threads
// as the module may use.
bool vtkErrorDiffusionSampler::ScanParts(vtkImageData* input, vtkDataArray* array)
{
  vtkInternals::Schedule schedule(this, input, array);
  return schedule.Scan(vtkBlueNoiseThreads::Available());
}

//------------------------------------------------------------------------------
// The whole-volume methods (Poisson disk, sample elimination): every density
// at once, then the layers of the mask into the output.
bool vtkErrorDiffusionSampler::SampleWhole(vtkImageData* input, vtkDataArray* array)
{
  vtkInternals& run = *this->Internals;
  int extent[6];
  input->GetExtent(extent);
  const vtkIdType layer = run.LayerSize();
  const vtkIdType voxels = layer * run.SampledLayers();
  vtkUnsignedCharArray* ghostArray = input->GetPointGhostArray();
  const unsigned char* ghosts = ghostArray ? ghostArray->GetPointer(0) : nullptr;
  std::vector<float> density;
  std::vector<unsigned char> mask;
  try
  {
    density.resize(static_cast<size_t>(voxels));
    mask.resize(static_cast<size_t>(voxels));
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro("Not enough memory for the whole volume the method needs (" << voxels
                                                                              << " voxels).");
    return false;
  }
  // Progress over what is left of the run: the densities mapped (a share as
  // for the statistics), the kernel's own reports, then the points built.
  const double base = run.ProgressDone;
  const double width = std::max(run.ProgressTotal - base, 0.0);
  const double filled = 0.05, sampled = 0.95;
  const auto report = [&](double fraction) {
    run.ProgressDone = base + width * fraction;
    this->UpdateProgress(run.ProgressDone / run.ProgressTotal);
    return !this->IsAborted();
  };
  vtkSamplingDensity::ValueTable values;
  for (int z = run.Sampled[4]; z <= run.Sampled[5]; ++z)
  {
    const vtkIdType begin = (z - extent[4]) * layer;
    const vtkIdType k = z - run.Sampled[4];
    run.LayerSums[k] =
      run.Density.Fill(array, begin, begin + layer, ghosts, density.data() + k * layer, values);
  }
  if (!report(filled))
  {
    return false;
  }
  std::unique_ptr<vtkVoxelPointSetKernel> kernel;
  if (this->Method == METHOD_POISSON_DISK)
  {
    kernel.reset(new vtkPoissonDiskKernel);
  }
  else
  {
    kernel.reset(new vtkWeightedSampleEliminationKernel);
  }
  kernel->SetSeed(static_cast<std::uint64_t>(this->Seed));
  // The kernel reports every so many voxels or candidates it visits; an
  // abort stops it there, and the filter leaves an empty output.
  kernel->SetProgressCallback(
    [&](double fraction) { return report(filled + (sampled - filled) * fraction); });
  std::string error;
  if (kernel->Sample(run.NX(), run.NY(), run.SampledLayers(), density.data(), mask.data(), &error) < 0)
  {
    if (!kernel->GetAborted())
    {
      vtkErrorMacro("Sampling failed: " << error);
    }
    return false;
  }
  if (!report(sampled))
  {
    return false;
  }
  for (vtkIdType k = 0; k < run.SampledLayers(); ++k)
  {
    const unsigned char* bits = mask.data() + k * layer;
    run.First().Emit(run.Sampled[4] + static_cast<int>(k), density.data() + k * layer, bits,
      std::count(bits, bits + layer, 1));
  }
  run.ProgressDone = run.ProgressTotal;
  return !this->IsAborted();
}

//------------------------------------------------------------------------------
// One sampling step: the layers of one slab (or the whole volume) into the
// output.
bool vtkErrorDiffusionSampler::SampleSlab(vtkImageData* input, vtkInformationVector** inputVector)
{
  vtkDataArray* array = this->GetDensityArray(input, inputVector);
  if (!array || !this->StartAssembly(input))
  {
    return false;
  }
  const bool whole = IsWholeVolumeMethod(this->Method);
  return whole ? this->SampleWhole(input, array) : this->ScanSlab(input, array);
}

//------------------------------------------------------------------------------
// After the last step: the closing correction, the points and their cells,
// the field data and the mask.
void vtkErrorDiffusionSampler::FinishOutput(
  vtkImageData* input, vtkPolyData* output, vtkImageData* maskOutput)
{
  vtkInternals& run = *this->Internals;
  double expected = 0.0;
  for (double sum : run.LayerSums)
  {
    expected += sum;
  }
  vtkPolyData* points = run.Points;
  if (run.AssemblerStarted)
  {
    if (run.Parts.size() == 1) // parts side by side dropped theirs in ScanParts
    {
      run.First().DropAheadPoints(IsErrorDiffusion(this->Method));
    }
    points->SetPoints(run.Assembler.End());
    points->SetVerts(run.Assembler.MakeVertices(points->GetNumberOfPoints()));
  }
  output->ShallowCopy(points);
  this->WarnIfEmpty(output->GetNumberOfPoints(), expected);

  vtkFieldData* fd = output->GetFieldData();
  const double* origin = input->GetOrigin();
  const double* spacing = input->GetSpacing();
  const double* direction = input->GetDirectionMatrix()->GetData();
  vtkNew<vtkDoubleArray> originArray;
  AddFieldArray(fd, originArray, "SamplingGridOrigin", 3);
  originArray->SetTuple(0, const_cast<double*>(origin));
  vtkNew<vtkDoubleArray> spacingArray;
  AddFieldArray(fd, spacingArray, "SamplingGridSpacing", 3);
  spacingArray->SetTuple(0, spacing);
  vtkNew<vtkIntArray> extentArray;
  AddFieldArray(fd, extentArray, "SamplingGridExtent", 6);
  std::copy(run.Sampled, run.Sampled + 6, extentArray->GetPointer(0));
  vtkNew<vtkDoubleArray> directionArray;
  AddFieldArray(fd, directionArray, "SamplingGridDirection", 9);
  directionArray->SetTuple(0, direction);
  vtkNew<vtkDoubleArray> scaleArray;
  AddFieldArray(fd, scaleArray, "DensityScale", 1);
  scaleArray->SetValue(0, run.Density.GetScale());
  vtkNew<vtkDoubleArray> expectedArray;
  AddFieldArray(fd, expectedArray, "ExpectedNumberOfPoints", 1);
  expectedArray->SetValue(0, expected);

  if (run.Mask)
  {
    maskOutput->SetExtent(run.Sampled);
    maskOutput->SetOrigin(origin);
    maskOutput->SetSpacing(spacing);
    maskOutput->SetDirectionMatrix(direction);
    maskOutput->GetPointData()->SetScalars(run.Mask);
    // The mask's pieces do not overlap: say which extent this one owns.
    vtkNew<vtkIntArray> owned;
    AddFieldArray(maskOutput->GetFieldData(), owned, "SamplingGridExtent", 6);
    std::copy(run.Sampled, run.Sampled + 6, owned->GetPointer(0));
  }
}

//------------------------------------------------------------------------------
// A budget that asks for no points gives an empty output that looks like a
// failure without an error: say why. (A budget above an all-zero volume is
// already reported by FinishStatistics; a piece of several may be empty where
// the whole is not, so a piece only warns about NumberOfPoints = 0.)
void vtkErrorDiffusionSampler::WarnIfEmpty(vtkIdType points, double expected)
{
  if (points > 0)
  {
    return;
  }
  if (this->UseNumberOfPoints && this->NumberOfPoints == 0)
  {
    vtkWarningMacro("NumberOfPoints is 0: no points were drawn (set a positive NumberOfPoints).");
  }
  else if (!this->UseNumberOfPoints && !this->Internals->Piece && expected < 0.5)
  {
    vtkWarningMacro("The expected number of points (the sum of the densities over the voxels) is "
      << expected << " with DensityScale " << this->DensityScale
      << ": no points were drawn (raise DensityScale, or use NumberOfPoints).");
  }
}

//------------------------------------------------------------------------------
// The steps the input at hand covers (all of them, for an input held whole).
bool vtkErrorDiffusionSampler::RunCoveredSteps(vtkImageData* input, vtkInformationVector** inputVector)
{
  vtkInternals& run = *this->Internals;
  int have[6];
  input->GetExtent(have);
  const size_t first = run.Current;
  while (run.Current < run.Steps.size())
  {
    int need[6];
    run.StepExtent(run.Steps[run.Current], need);
    if (!Contains(have, need))
    {
      break;
    }
    const bool done = run.Steps[run.Current].Statistics ? this->CollectStatistics(input, inputVector)
                                                        : this->SampleSlab(input, inputVector);
    if (!done)
    {
      return false;
    }
    ++run.Current;
  }
  if (run.Current == first && run.Current < run.Steps.size())
  {
    int need[6];
    run.StepExtent(run.Steps[run.Current], need);
    vtkErrorMacro("The input delivered the extent [" << have[0] << ", " << have[1] << ", "
      << have[2] << ", " << have[3] << ", " << have[4] << ", " << have[5] << "] where ["
      << need[0] << ", " << need[1] << ", " << need[2] << ", " << need[3] << ", " << need[4]
      << ", " << need[5] << "] was requested.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkErrorDiffusionSampler::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInternals& running = *this->Internals;
  if (running.Executing)
  {
    // ParaView may process events while this filter reports progress, and a
    // render they start may ask for this output again before this execution
    // is over: that request gets the output as it stands; this execution,
    // its state and its output stay as they are.
    return 1;
  }
  running.Executing = true;
  const int status = this->Execute(request, inputVector, outputVector);
  running.Executing = false;
  return status;
}

//------------------------------------------------------------------------------
int vtkErrorDiffusionSampler::Execute(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* image = vtkImageData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkImageData* mask = vtkImageData::GetData(outputVector, 1);
  vtkInternals& run = *this->Internals;
  const auto continueKey = vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING();
  // An error (already reported) or an abort ends the run with empty outputs.
  // The request still succeeds: a failed request leaves the consumers'
  // requests of this run behind (a later run without the mask then rejects
  // the mask request left from this one), and ParaView would execute the
  // filter again on every update only to repeat the error.
  const auto fail = [&]() {
    run.Running = false;
    run.EndRun();
    run.Assembler.Recycle(nullptr);
    output->Initialize();
    mask->Initialize();
    request->Remove(continueKey);
    return 1;
  };
  if (!image)
  {
    vtkErrorMacro("No input image.");
    return fail();
  }
  // The sites sampled: the image's points, or its cells' centres.
  vtkSmartPointer<vtkImageData> input = image;
  if (run.Cells)
  {
    input = vtkSamplingLattice::FromCells(image);
  }
  if (!run.Running)
  {
    output->Initialize();
    mask->Initialize();
    // A piece without layers (more pieces than layers) samples nothing, but
    // still takes part in what the pieces share (ReduceStatistics).
    if (!run.Piece && (run.SampledLayers() == 0 || run.NX() <= 0 || run.NY() <= 0))
    {
      vtkErrorMacro("The input image has an empty extent: nothing to sample.");
      return fail();
    }
    this->UpdateProgress(0.0);
    if (!this->StartRun(request, inputVector))
    {
      return fail();
    }
    run.Running = true;
  }
  if (!this->RunCoveredSteps(input.Get(), inputVector))
  {
    return fail();
  }
  if (run.Current < run.Steps.size())
  {
    request->Set(continueKey, 1);
    return 1;
  }
  this->FinishOutput(input.Get(), output, mask);
  run.Running = false;
  run.EndRun();
  run.Assembler.Recycle(nullptr); // what this run did not reuse
  request->Remove(continueKey);
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
  os << indent << "UseNumberOfPoints: " << this->UseNumberOfPoints << "\n";
  os << indent << "NumberOfPoints: " << this->NumberOfPoints << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "ParameterSet: " << this->ParameterSet << "\n";
  os << indent << "ParameterFile: " << this->ParameterFile << "\n";
  os << indent << "ModulationScale: " << this->ModulationScale << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "WarmUpLayers: " << this->WarmUpLayers << "\n";
  os << indent << "Jitter: " << this->Jitter << "\n";
  os << indent << "GenerateMask: " << this->GenerateMask << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "UseWorkerThread: " << this->UseWorkerThread << "\n";
  os << indent << "NumberOfSlabs: " << this->NumberOfSlabs << "\n";
  os << indent << "OverlapLayers: " << this->OverlapLayers << "\n";
  os << indent << "PartLayers: " << this->PartLayers << "\n";
  os << indent << "PartVoxels: " << this->PartVoxels << "\n";
}
