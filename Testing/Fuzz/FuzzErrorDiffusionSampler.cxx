// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: vtkErrorDiffusionSampler on a random small image (up to
// 16^3 voxels, 24 a side, any numeric type, 1 to 4 components, NaN and
// infinities, odd geometry, extra arrays of the wrong length) with random
// properties (all five methods, the three density mappings, budget or scale,
// jitter, slabs, pieces, seed, parameter sets including a custom file of
// random text).
//
// ModulationScale comes from a fixed set (0, 0.25, ..., 2) but for one input
// in 64, which takes any value: the error diffusion calibrates a charge curve
// per (parameter table, scale) pair, seconds per curve under ASan and the
// fuzzer's instrumentation, and vtkErrorDiffusionChargeCurve keeps the 64
// pairs used last. LLVMFuzzerInitialize calibrates the 27 curves of the
// built-in tables at the set's scales once (they then stay in that cache):
// calibrations on demand were 84 % of the fuzzer's time and cut its rate to
// 18 inputs/s. The rare arbitrary scale and the custom tables still calibrate
// on demand, so that path is fuzzed too.
//
// The promises checked: no crash and no sanitizer report; an update that
// reports an error leaves both outputs empty; one that does not gives at most
// one point per voxel of its piece, each with a density in [0, 1]; and the
// same filter then samples a good volume correctly.
#include "FuzzUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkErrorDiffusionChargeCurve.h"
#include "vtkErrorDiffusionParameterTable.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

using namespace bluenoise_fuzz;

namespace
{
constexpr double FixedScales[] = { 0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0 };

constexpr int ScalarTypes[] = { VTK_CHAR, VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT,
  VTK_UNSIGNED_SHORT, VTK_INT, VTK_UNSIGNED_INT, VTK_LONG_LONG, VTK_UNSIGNED_LONG_LONG,
  VTK_ID_TYPE, VTK_FLOAT, VTK_DOUBLE };

// The fill loops below run once per value: they go without coverage
// instrumentation (their branches say nothing of the filter), and the uniform
// draw is written out as libstdc++'s uniform_real_distribution<double> makes
// it from a 32-bit generator (generate_canonical: two draws, a sum, a
// division): the same values bit for bit, without the long double log it
// takes per call (a third of the time the image took).
__attribute__((no_sanitize("coverage"))) void FillRandomBytes(
  std::mt19937& random, unsigned char* bytes, size_t size)
{
  for (size_t i = 0; i < size; ++i)
  {
    bytes[i] = static_cast<unsigned char>(random());
  }
}

__attribute__((no_sanitize("coverage"))) void FillUniform(
  std::mt19937& random, vtkDataArray* array, double lo, double hi)
{
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    double sum = static_cast<double>(random());
    sum += static_cast<double>(random()) * 0x1p32;
    double unit = sum * 0x1p-64;
    if (unit >= 1.0)
    {
      unit = std::nextafter(1.0, 0.0);
    }
    array->SetVariantValue(i, vtkVariant(unit * (hi - lo) + lo));
  }
}

/// An array of `tuples` tuples filled by one of a few patterns, with special
/// floating-point values sprinkled in for the floating types.
vtkSmartPointer<vtkDataArray> MakeArray(FuzzedDataProvider& fdp, const char* name, vtkIdType tuples)
{
  const int type = fdp.PickValueInArray(ScalarTypes);
  auto array = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
  array->SetName(name);
  array->SetNumberOfComponents(fdp.ConsumeIntegralInRange<int>(1, 4));
  array->SetNumberOfTuples(tuples);
  auto* bytes = static_cast<unsigned char*>(array->GetVoidPointer(0));
  const size_t size = static_cast<size_t>(array->GetNumberOfValues()) * array->GetDataTypeSize();
  std::mt19937 random(fdp.ConsumeIntegral<uint32_t>());
  switch (fdp.ConsumeIntegralInRange<int>(0, 3))
  {
    case 0: // raw bytes from the input, repeated
    {
      std::vector<uint8_t> chunk = fdp.ConsumeBytes<uint8_t>(fdp.ConsumeIntegralInRange<size_t>(1, 64));
      for (size_t i = 0; i < size && !chunk.empty(); ++i)
      {
        bytes[i] = chunk[i % chunk.size()];
      }
      break;
    }
    case 1: // random bytes
      FillRandomBytes(random, bytes, size);
      break;
    default: // one value, or values in a range, through the array's own conversion
    {
      const double lo = fdp.ConsumeFloatingPointInRange<double>(-300.0, 300.0);
      const double width = fdp.ConsumeFloatingPointInRange<double>(0.0, 300.0);
      FillUniform(random, array, lo, lo + width);
      break;
    }
  }
  if (type == VTK_FLOAT || type == VTK_DOUBLE)
  {
    const int specials = fdp.ConsumeIntegralInRange<int>(0, 4);
    for (int s = 0; s < specials && array->GetNumberOfValues() > 0; ++s)
    {
      const vtkIdType at = fdp.ConsumeIntegralInRange<vtkIdType>(0, array->GetNumberOfValues() - 1);
      const double v = PickDouble(fdp, -1.0, 2.0);
      if (type == VTK_FLOAT)
      {
        // Out-of-range doubles become infinities, as a file's float would be.
        const float f = std::isfinite(v) && std::fabs(v) > 3e38 ? std::copysign(INFINITY, v)
                                                               : static_cast<float>(v);
        static_cast<float*>(array->GetVoidPointer(0))[at] = f;
      }
      else
      {
        static_cast<double*>(array->GetVoidPointer(0))[at] = v;
      }
    }
  }
  return array;
}

vtkSmartPointer<vtkImageData> MakeImage(FuzzedDataProvider& fdp, int maxVoxels)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  int dims[3];
  int voxels = 1;
  for (int& d : dims)
  {
    d = fdp.ConsumeIntegralInRange<int>(1, 24);
    while (voxels * d > maxVoxels && d > 1)
    {
      d /= 2;
    }
    voxels *= d;
  }
  const int shift = fdp.ConsumeIntegralInRange<int>(-3, 3);
  image->SetExtent(shift, shift + dims[0] - 1, 0, dims[1] - 1, -shift, -shift + dims[2] - 1);
  if (fdp.ConsumeBool())
  {
    image->SetOrigin(PickDouble(fdp, -10, 10), PickDouble(fdp, -10, 10), PickDouble(fdp, -10, 10));
    image->SetSpacing(PickDouble(fdp, 0, 3), PickDouble(fdp, 0, 3), PickDouble(fdp, 0, 3));
  }
  if (fdp.ConsumeBool())
  {
    vtkNew<vtkMatrix3x3> direction;
    for (int i = 0; i < 9; ++i)
    {
      direction->SetElement(i / 3, i % 3, PickDouble(fdp, -1, 1));
    }
    image->SetDirectionMatrix(direction);
  }
  const vtkIdType points = image->GetNumberOfPoints();
  image->GetPointData()->SetScalars(MakeArray(fdp, "density", points));
  if (fdp.ConsumeBool()) // a second array, perhaps of the wrong length
  {
    const vtkIdType tuples =
      fdp.ConsumeBool() ? points : fdp.ConsumeIntegralInRange<vtkIdType>(0, points + 2);
    image->GetPointData()->AddArray(MakeArray(fdp, "other", tuples));
  }
  if (fdp.ConsumeBool())
  {
    vtkNew<vtkStringArray> names;
    names->SetName("names");
    names->SetNumberOfValues(fdp.ConsumeBool() ? points : fdp.ConsumeIntegralInRange<int>(0, 3));
    image->GetPointData()->AddArray(names);
  }
  if (fdp.ConsumeBool())
  {
    image->GetCellData()->AddArray(MakeArray(fdp, "cells", image->GetNumberOfCells()));
  }
  return image;
}

/// The parameter file of PARAMETERS_CUSTOM: random text, or no file at all.
std::string ParameterFile(FuzzedDataProvider& fdp)
{
  if (fdp.ConsumeIntegralInRange<int>(0, 3) == 0)
  {
    return "/nonexistent/bluenoise-fuzz-parameters.txt";
  }
  static const std::string path =
    "/tmp/bluenoise-fuzz-parameters-" + std::to_string(getpid()) + ".txt";
  std::ofstream(path, std::ios::binary) << fdp.ConsumeRandomLengthString(512);
  return path;
}

void Configure(FuzzedDataProvider& fdp, vtkErrorDiffusionSampler* sampler)
{
  const char* arrays[] = { "density", "other", "names", "cells", "missing" };
  switch (fdp.ConsumeIntegralInRange<int>(0, 2))
  {
    case 0:
      break; // the active scalars
    case 1:
      sampler->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, fdp.PickValueInArray(arrays));
      break;
    default:
      sampler->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_CELLS, fdp.PickValueInArray(arrays));
  }
  sampler->SetComponent(fdp.ConsumeIntegralInRange<int>(-2, 4));
  sampler->SetDensityMapping(fdp.ConsumeIntegralInRange<int>(-1, 3));
  sampler->SetUseCustomScalarRange(fdp.ConsumeBool());
  sampler->SetScalarRange(PickDouble(fdp, -300, 300), PickDouble(fdp, -300, 300));
  if (fdp.ConsumeBool())
  {
    vtkNew<vtkPiecewiseFunction> function;
    const int nodes = fdp.ConsumeIntegralInRange<int>(0, 5);
    for (int i = 0; i < nodes; ++i)
    {
      function->AddPoint(PickDouble(fdp, -300, 300), PickDouble(fdp, -0.5, 1.5));
    }
    sampler->SetTransferFunction(function);
  }
  sampler->SetUseNumberOfPoints(fdp.ConsumeBool());
  sampler->SetNumberOfPoints(fdp.ConsumeBool() ? fdp.ConsumeIntegralInRange<vtkIdType>(-5, 20000)
                                               : fdp.ConsumeIntegral<vtkIdType>());
  sampler->SetDensityScale(PickDouble(fdp, 0, 4));
  sampler->SetParameterSet(fdp.ConsumeIntegralInRange<int>(-1, 4));
  if (sampler->GetParameterSet() == vtkErrorDiffusionSampler::PARAMETERS_CUSTOM)
  {
    sampler->SetParameterFile(ParameterFile(fdp).c_str());
  }
  // A fixed set of scales, rarely another (see the file comment).
  sampler->SetModulationScale(fdp.ConsumeIntegralInRange<int>(0, 63) == 0
      ? PickDouble(fdp, 0, 2)
      : fdp.PickValueInArray(FixedScales));
  sampler->SetSeed(fdp.ConsumeIntegral<int>());
  sampler->SetWarmUpLayers(fdp.ConsumeIntegralInRange<int>(-1, 8));
  sampler->SetJitter(fdp.ConsumeBool());
  sampler->SetGenerateMask(fdp.ConsumeBool());
  sampler->SetOutputPointsPrecision(fdp.ConsumeIntegralInRange<int>(-1, 3));
  sampler->SetUseWorkerThread(fdp.ConsumeBool());
  sampler->SetNumberOfSlabs(fdp.ConsumeIntegralInRange<int>(0, 9));
  sampler->SetOverlapLayers(fdp.ConsumeIntegralInRange<int>(-1, 8));
  // Parts of a few layers and voxels, so that small volumes are cut too.
  sampler->SetPartLayers(fdp.ConsumeIntegralInRange<int>(0, 16));
  sampler->SetPartVoxels(fdp.ConsumeIntegralInRange<vtkIdType>(0, 8192));
}

/// The promises of an update that reported no error.
void CheckResult(vtkErrorDiffusionSampler* sampler, vtkIdType voxels)
{
  vtkPolyData* points = sampler->GetOutput();
  Require(points->GetNumberOfPoints() <= voxels, "at most one point per voxel");
  if (points->GetNumberOfPoints() == 0)
  {
    return;
  }
  vtkDataArray* density = points->GetPointData()->GetArray("Density");
  Require(density && density->GetNumberOfTuples() == points->GetNumberOfPoints(),
    "a Density value per point");
  for (vtkIdType i = 0; i < density->GetNumberOfTuples(); ++i)
  {
    const double g = density->GetTuple1(i);
    Require(g >= 0.0 && g <= 1.0, "densities in [0, 1]", std::to_string(g));
  }
}

/// The same filter, reset, samples a good volume: 20 points from 6^3 voxels
/// of 8-bit values 3 on the range [0, 10] (density 0.3). (Float values drew
/// fresh float tallies, 1.5 MiB per statistics thread faulted in page by page
/// under ASan, for 70 % of the fuzzer's time; the 8-bit counts cost next to
/// nothing. The float tallies' reuse is still fuzzed, from one statistics
/// step to the next of an update in several slabs, and
/// TestErrorDiffusionSamplerSoak reuses them across 150 updates.)
void CheckGoodUpdate(vtkErrorDiffusionSampler* sampler, MessageObserver* observer)
{
  auto good = vtkSmartPointer<vtkImageData>::New();
  good->SetDimensions(6, 6, 6);
  vtkNew<vtkUnsignedCharArray> values;
  values->SetName("good");
  values->SetNumberOfValues(good->GetNumberOfPoints());
  values->Fill(3);
  good->GetPointData()->SetScalars(values);
  sampler->SetInputData(good);
  sampler->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  sampler->SetMethod(vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION);
  sampler->SetComponent(0);
  sampler->SetDensityMapping(vtkErrorDiffusionSampler::DENSITY_SCALAR_RANGE);
  sampler->SetUseCustomScalarRange(true);
  sampler->SetScalarRange(0.0, 10.0);
  sampler->SetTransferFunction(nullptr);
  sampler->SetDensityScale(1.0);
  sampler->SetUseNumberOfPoints(true);
  sampler->SetNumberOfPoints(20);
  sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_PAPER);
  sampler->SetModulationScale(1.0);
  sampler->SetNumberOfSlabs(1);
  observer->Reset();
  sampler->UpdatePiece(0, 1, 0);
  const vtkIdType n = sampler->GetOutput()->GetNumberOfPoints();
  Require(observer->NumberOfErrors == 0, "the next good update reports no error", observer->Errors);
  if (n < 19 || n > 21)
  {
    sampler->Print(std::cerr);
    Require(false, "the next good update draws its 20 points", std::to_string(n));
  }
}
}

/// Calibrates the charge curves of the built-in tables at the fixed scales,
/// held for the whole run: the samplers' kernels find them (Get).
extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  static std::vector<std::shared_ptr<vtkErrorDiffusionChargeCurve>> held;
  for (const auto& table : { vtkErrorDiffusionParameterTable::Paper(),
         vtkErrorDiffusionParameterTable::Fixed(), vtkErrorDiffusionParameterTable::Optimized() })
  {
    for (double scale : FixedScales)
    {
      held.push_back(vtkErrorDiffusionChargeCurve::Get(table, scale));
      held.back()->GetCharges();
    }
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  Quiet();
  FuzzedDataProvider fdp(data, size);
  vtkNew<vtkErrorDiffusionSampler> sampler;
  vtkNew<MessageObserver> observer;
  observer->Watch(sampler);

  // Volumes of at most 16^3 voxels (24 a side), 8^3 for the point-set
  // methods, which cost far more per voxel: the rate is what finds bugs, and
  // slabs, pieces, overlap and warm-up layers are all reached at that size.
  const int method = fdp.ConsumeIntegralInRange<int>(-1, 5);
  const bool slowMethod = method == vtkErrorDiffusionSampler::METHOD_POISSON_DISK ||
    method == vtkErrorDiffusionSampler::METHOD_SAMPLE_ELIMINATION;
  auto image = MakeImage(fdp, slowMethod ? 8 * 8 * 8 : 16 * 16 * 16);
  sampler->SetInputData(image);
  sampler->SetMethod(method);
  Configure(fdp, sampler);
  const int pieces = fdp.ConsumeBool() ? 1 : fdp.ConsumeIntegralInRange<int>(1, 4);
  const int piece = fdp.ConsumeIntegralInRange<int>(0, pieces - 1);
  if (std::getenv("BLUENOISE_FUZZ_PRINT")) // to reproduce a finding by hand
  {
    sampler->Print(std::cerr);
    std::cerr << "piece " << piece << " of " << pieces << "\n";
    image->Print(std::cerr);
  }
  sampler->UpdatePiece(piece, pieces, 0);

  if (observer->NumberOfErrors > 0)
  {
    Require(sampler->GetOutput()->GetNumberOfPoints() == 0, "an error leaves no points",
      observer->Errors);
    Require(sampler->GetMaskOutput()->GetNumberOfPoints() == 0, "an error leaves no mask",
      observer->Errors);
  }
  else
  {
    CheckResult(sampler, image->GetNumberOfPoints());
  }
  CheckGoodUpdate(sampler, observer);
  return 0;
}
