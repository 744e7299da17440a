// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// World coordinates: with a non-trivial origin, spacing and direction matrix
// (and an extent that does not start at 0), every point sits on the center of
// a sampled voxel; the field data records the sampling grid. Jittered
// points move inside their voxels by the same offsets (in index space) on a
// rotated grid as on an axis-aligned one.
#include "SamplerTestUtilities.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkPoints.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace bluenoise_test;

int main()
{
  auto image = MakeVolume(20, 16, 12, [](int i, int j, int) { return 0.02f * (1 + (i + j) % 10); });
  image->SetExtent(-5, 14, 3, 18, 10, 21); // same 20 x 16 x 12 voxels
  image->SetOrigin(10.0, -3.5, 7.25);
  image->SetSpacing(0.5, 1.25, 2.0);
  vtkNew<vtkTransform> rotation;
  rotation->RotateWXYZ(33.0, 1.0, 2.0, 0.5);
  vtkNew<vtkMatrix3x3> direction;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      direction->SetElement(r, c, rotation->GetMatrix()->GetElement(r, c));
    }
  }
  image->SetDirectionMatrix(direction);

  for (int precision : { vtkAlgorithm::SINGLE_PRECISION, vtkAlgorithm::DOUBLE_PRECISION })
  {
    vtkNew<vtkErrorDiffusionSampler> sampler;
    sampler->SetInputData(image);
    sampler->SetDensityMappingToIdentity();
    sampler->SetOutputPointsPrecision(precision);
    sampler->GenerateMaskOn();
    sampler->Update();
    vtkPolyData* out = sampler->GetOutput();
    vtkImageData* mask = sampler->GetMaskOutput();
    const vtkIdType n = out->GetNumberOfPoints();
    Check(n > 100, "samples drawn: " + Str(n));
    Check(out->GetNumberOfVerts() == n, "one vertex cell per point");
    Check(out->GetPoints()->GetDataType() ==
        (precision == vtkAlgorithm::DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT),
      "point precision");
    const double tol = precision == vtkAlgorithm::DOUBLE_PRECISION ? 1e-9 : 1e-4;

    std::set<vtkIdType> seen;
    int offCentre = 0;
    int notInMask = 0;
    for (vtkIdType p = 0; p < n; ++p)
    {
      double x[3];
      out->GetPoint(p, x);
      double ijk[3];
      image->TransformPhysicalPointToContinuousIndex(x, ijk);
      int index[3];
      for (int c = 0; c < 3; ++c)
      {
        index[c] = static_cast<int>(std::lround(ijk[c]));
        if (std::abs(ijk[c] - index[c]) > tol)
        {
          ++offCentre;
        }
      }
      double center[3];
      image->TransformIndexToPhysicalPoint(index, center);
      if (std::sqrt(vtkMath::Distance2BetweenPoints(center, x)) > tol * 10)
      {
        ++offCentre;
      }
      const vtkIdType id = image->ComputePointId(index);
      if (id < 0 || mask->GetPointData()->GetScalars()->GetComponent(id, 0) != 1.0)
      {
        ++notInMask;
      }
      seen.insert(id);
    }
    Check(offCentre == 0, Str(offCentre) + " points off a voxel center");
    Check(notInMask == 0, Str(notInMask) + " points not on a masked voxel");
    Check(static_cast<vtkIdType>(seen.size()) == n, "no voxel sampled twice");

    // The mask has the input's geometry.
    int e[6];
    mask->GetExtent(e);
    Check(e[0] == -5 && e[1] == 14 && e[4] == 10 && e[5] == 21, "mask extent");
    Check(mask->GetSpacing()[1] == 1.25 && mask->GetOrigin()[2] == 7.25 &&
        mask->GetDirectionMatrix()->GetElement(0, 1) == direction->GetElement(0, 1),
      "mask geometry");

    // Field data: the sampling grid.
    vtkFieldData* fd = out->GetFieldData();
    auto* origin = vtkDoubleArray::SafeDownCast(fd->GetArray("SamplingGridOrigin"));
    auto* spacing = vtkDoubleArray::SafeDownCast(fd->GetArray("SamplingGridSpacing"));
    auto* extent = vtkIntArray::SafeDownCast(fd->GetArray("SamplingGridExtent"));
    auto* dir = vtkDoubleArray::SafeDownCast(fd->GetArray("SamplingGridDirection"));
    Check(origin && spacing && extent && dir, "sampling grid field data present");
    if (origin && spacing && extent && dir)
    {
      Check(origin->GetComponent(0, 0) == 10.0 && origin->GetComponent(0, 1) == -3.5 &&
          spacing->GetComponent(0, 2) == 2.0 && extent->GetNumberOfComponents() == 6 &&
          extent->GetValue(0) == -5 && extent->GetValue(3) == 18 && extent->GetValue(5) == 21 &&
          dir->GetNumberOfComponents() == 9 &&
          dir->GetComponent(0, 5) == direction->GetElement(1, 2),
        "sampling grid values");
    }
  }

  // Jitter: the offset of each point from its voxel center, in index space,
  // on the rotated grid and on the same grid axis-aligned.
  vtkNew<vtkImageData> aligned;
  aligned->DeepCopy(image);
  vtkNew<vtkMatrix3x3> identity;
  aligned->SetDirectionMatrix(identity);
  std::vector<std::vector<double>> offsets;
  for (vtkImageData* grid : { image.GetPointer(), aligned.GetPointer() })
  {
    std::vector<double> gridOffsets;
    vtkNew<vtkErrorDiffusionSampler> centers, jittered;
    for (vtkErrorDiffusionSampler* sampler : { centers.GetPointer(), jittered.GetPointer() })
    {
      sampler->SetInputData(grid);
      sampler->SetDensityMappingToIdentity();
      sampler->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
      sampler->SetUseNumberOfPoints(false); // the densities as they are
      sampler->SetJitter(sampler == jittered.GetPointer());
      sampler->Update();
    }
    const vtkIdType n = centers->GetOutput()->GetNumberOfPoints();
    Check(jittered->GetOutput()->GetNumberOfPoints() == n, "jitter keeps the points");
    double largest = 0.0;
    for (vtkIdType p = 0; p < n && jittered->GetOutput()->GetNumberOfPoints() == n; ++p)
    {
      double a[3], b[3], ia[3], ib[3];
      centers->GetOutput()->GetPoint(p, a);
      jittered->GetOutput()->GetPoint(p, b);
      grid->TransformPhysicalPointToContinuousIndex(a, ia);
      grid->TransformPhysicalPointToContinuousIndex(b, ib);
      for (int c = 0; c < 3; ++c)
      {
        gridOffsets.push_back(ib[c] - ia[c]);
        largest = std::max(largest, std::abs(ib[c] - ia[c]));
      }
    }
    Check(largest > 0.45 && largest <= 0.5 + 1e-9,
      "jittered points within half a voxel of their centers, up to " + Str(largest));
    offsets.push_back(gridOffsets);
  }
  double apart = offsets[0].size() == offsets[1].size() ? 0.0 : 1.0;
  for (size_t i = 0; i < offsets[0].size() && i < offsets[1].size(); ++i)
  {
    apart = std::max(apart, std::abs(offsets[0][i] - offsets[1][i]));
  }
  Check(apart < 1e-9, "the same jitter on the rotated grid and the axis-aligned one: " + Str(apart));
  return Summary("TestErrorDiffusionSamplerGeometry");
}
