// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the spectrum tests: random volumes, a mask's voxels as
// points with the sampler's grid field data, tolerant comparison, a NaN sweep
// over a kernel result and the filter's table read back as a result.
#ifndef TestBlueNoiseSpectrumUtilities_h
#define TestBlueNoiseSpectrumUtilities_h

#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace spectrum_test
{
using bluenoise_test::Check;
using bluenoise_test::Str;
using Result = vtkBlueNoiseSpectrumKernel::Result;

inline std::size_t Voxels(const int dims[3])
{
  return static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
}

// Bernoulli(g) per voxel.
inline std::vector<unsigned char> RandomMask(const int dims[3], double g, std::mt19937& rng)
{
  std::bernoulli_distribution draw(g);
  std::vector<unsigned char> mask(Voxels(dims));
  for (auto& m : mask)
  {
    m = draw(rng) ? 1 : 0;
  }
  return mask;
}

// Non-integer counts in [0, 3).
inline std::vector<double> RandomCounts(const int dims[3], std::mt19937& rng)
{
  std::uniform_real_distribution<double> draw(0.0, 3.0);
  std::vector<double> counts(Voxels(dims));
  for (auto& c : counts)
  {
    c = draw(rng);
  }
  return counts;
}

// The set voxels of an x-fastest mask on a dims grid as points, voxel (i, j, k)
// at position(i, j, k, x).
template <typename Position>
vtkSmartPointer<vtkPolyData> MaskPoints(
  const std::vector<unsigned char>& mask, const int dims[3], Position position)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  std::size_t v = 0;
  for (int k = 0; k < dims[2]; ++k)
  {
    for (int j = 0; j < dims[1]; ++j)
    {
      for (int i = 0; i < dims[0]; ++i, ++v)
      {
        if (mask[v])
        {
          double x[3];
          position(i, j, k, x);
          points->InsertNextPoint(x);
        }
      }
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  return data;
}

// The sampler's field data: SamplingGridOrigin, SamplingGridSpacing,
// SamplingGridExtent and, unless null, SamplingGridDirection (row major).
inline void AddSamplingGrid(vtkPolyData* data, const double origin[3], const double spacing[3],
  const int extent[6], const double* direction = nullptr)
{
  const auto add = [data](vtkDataArray* array, const char* name, int n, const double* v)
  {
    array->SetName(name);
    array->SetNumberOfComponents(n);
    array->SetNumberOfTuples(1);
    for (int i = 0; i < n; ++i)
    {
      array->SetComponent(0, i, v[i]);
    }
    data->GetFieldData()->AddArray(array);
  };
  const double wholeExtent[6] = { double(extent[0]), double(extent[1]), double(extent[2]),
    double(extent[3]), double(extent[4]), double(extent[5]) };
  add(vtkNew<vtkDoubleArray>(), "SamplingGridOrigin", 3, origin);
  add(vtkNew<vtkDoubleArray>(), "SamplingGridSpacing", 3, spacing);
  add(vtkNew<vtkIntArray>(), "SamplingGridExtent", 6, wholeExtent);
  if (direction)
  {
    add(vtkNew<vtkDoubleArray>(), "SamplingGridDirection", 9, direction);
  }
}

// |a - b| <= rel * max(1, |a|, |b|).
inline bool Close(double a, double b, double rel)
{
  return std::abs(a - b) <= rel * std::max(1.0, std::max(std::abs(a), std::abs(b)));
}

inline bool CheckClose(double a, double b, double rel, const std::string& what)
{
  return Check(Close(a, b, rel), what + ": " + Str(a) + " vs " + Str(b));
}

inline bool AllFinite(const std::vector<double>& v)
{
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

inline bool CheckFinite(const Result& r, const std::string& what)
{
  const bool ok = AllFinite(r.Frequency) && AllFinite(r.RadialPower) && AllFinite(r.Anisotropy) &&
    AllFinite(r.AnisotropyDB) && AllFinite(r.SrapsXY) && AllFinite(r.SrapsXZ) &&
    AllFinite(r.SrapsYZ) && std::isfinite(r.NumberOfPoints) && std::isfinite(r.Density) &&
    std::isfinite(r.PrincipalFrequency) && std::isfinite(r.LowFrequencyRatio) &&
    std::isfinite(r.SymmetryCorrelation) && std::isfinite(r.Symmetry) &&
    std::isfinite(r.TargetValue);
  return Check(ok, what + ": a reported value is not finite");
}

inline long long TotalCount(const Result& r)
{
  long long total = 0;
  for (long long c : r.ShellCount)
  {
    total += c;
  }
  return total;
}

// The filter's table (columns and field data) as a kernel result; false with
// a failed check when a column or field array is missing.
inline bool ResultFromTable(vtkTable* table, Result& r)
{
  const auto column = [table](const char* name, std::vector<double>& values)
  {
    vtkDataArray* array = vtkDataArray::SafeDownCast(table->GetColumnByName(name));
    if (!Check(array != nullptr, std::string("the table has no column ") + name))
    {
      return false;
    }
    values.resize(static_cast<std::size_t>(array->GetNumberOfTuples()));
    for (std::size_t i = 0; i < values.size(); ++i)
    {
      values[i] = array->GetComponent(static_cast<vtkIdType>(i), 0);
    }
    return true;
  };
  const auto field = [table](const char* name, double& value)
  {
    vtkDataArray* array = table->GetFieldData()->GetArray(name);
    if (!Check(array != nullptr && array->GetNumberOfTuples() == 1,
          std::string("the table has no field array ") + name))
    {
      return false;
    }
    value = array->GetComponent(0, 0);
    return true;
  };
  std::vector<double> counts;
  double realizations = 0.0;
  const bool ok = column("Frequency", r.Frequency) && column("RadialPower", r.RadialPower) &&
    column("Anisotropy", r.Anisotropy) && column("AnisotropyDB", r.AnisotropyDB) &&
    column("SRAPS_XY", r.SrapsXY) && column("SRAPS_XZ", r.SrapsXZ) &&
    column("SRAPS_YZ", r.SrapsYZ) && column("ShellCount", counts) &&
    field("NumberOfPoints", r.NumberOfPoints) && field("Density", r.Density) &&
    field("PrincipalFrequency", r.PrincipalFrequency) &&
    field("LowFrequencyRatio", r.LowFrequencyRatio) &&
    field("SymmetryCorrelation", r.SymmetryCorrelation) && field("Symmetry", r.Symmetry) &&
    field("TargetValue", r.TargetValue) && field("Realizations", realizations);
  r.ShellCount.assign(counts.begin(), counts.end());
  r.Realizations = static_cast<int>(realizations);
  return ok;
}

// Every per-shell and scalar value of two results, to `rel`.
inline void CheckSameResult(const Result& a, const Result& b, double rel, const std::string& what)
{
  if (!Check(a.RadialPower.size() == b.RadialPower.size(),
        what + ": shell counts differ (" + Str(a.RadialPower.size()) + " vs " +
          Str(b.RadialPower.size()) + ")"))
  {
    return;
  }
  for (std::size_t i = 0; i < a.RadialPower.size(); ++i)
  {
    const std::string shell = what + " shell " + Str(i + 1);
    CheckClose(a.Frequency[i], b.Frequency[i], rel, shell + " Frequency");
    CheckClose(a.RadialPower[i], b.RadialPower[i], rel, shell + " RadialPower");
    CheckClose(a.Anisotropy[i], b.Anisotropy[i], rel, shell + " Anisotropy");
    CheckClose(a.SrapsXY[i], b.SrapsXY[i], rel, shell + " SrapsXY");
    CheckClose(a.SrapsXZ[i], b.SrapsXZ[i], rel, shell + " SrapsXZ");
    CheckClose(a.SrapsYZ[i], b.SrapsYZ[i], rel, shell + " SrapsYZ");
    Check(a.ShellCount[i] == b.ShellCount[i],
      shell + " ShellCount " + Str(a.ShellCount[i]) + " vs " + Str(b.ShellCount[i]));
  }
  CheckClose(a.NumberOfPoints, b.NumberOfPoints, rel, what + " NumberOfPoints");
  CheckClose(a.Density, b.Density, rel, what + " Density");
  CheckClose(a.PrincipalFrequency, b.PrincipalFrequency, rel, what + " PrincipalFrequency");
  CheckClose(a.LowFrequencyRatio, b.LowFrequencyRatio, rel, what + " LowFrequencyRatio");
  CheckClose(a.SymmetryCorrelation, b.SymmetryCorrelation, rel, what + " SymmetryCorrelation");
  CheckClose(a.Symmetry, b.Symmetry, rel, what + " Symmetry");
  CheckClose(a.TargetValue, b.TargetValue, rel, what + " TargetValue");
  Check(a.Realizations == b.Realizations,
    what + " Realizations " + Str(a.Realizations) + " vs " + Str(b.Realizations));
}
}

#endif
