// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Voxels a point ghost array marks as not owned (duplicate or hidden points)
// are not sampled and do not count in the point budget's statistics: a
// volume with such voxels gives the points of the same volume with value 0
// there (density 0, which adds nothing to the budget), for 8-bit, 16-bit,
// float and double values (each type's own counting and filling), one and
// two threads; and the ghost voxels get no point.
#include "SamplerTestUtilities.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <string>

using namespace bluenoise_test;

namespace
{
const int NX = 40, NY = 36, NZ = 30;

bool Ghost(int i, int j, int k)
{
  return (k >= 10 && k < 14) || (i < 3 && j > 30) || (i + j + k) % 17 == 0;
}

// Values of one type in [0, 60], value 0 where `zeroGhosts` and a voxel is a ghost.
template <typename ArrayT>
vtkSmartPointer<vtkImageData> Volume(bool zeroGhosts, bool withGhostArray)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(NX, NY, NZ);
  auto values = vtkSmartPointer<ArrayT>::New();
  values->SetName("values");
  values->SetNumberOfValues(image->GetNumberOfPoints());
  vtkNew<vtkUnsignedCharArray> ghosts;
  ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
  ghosts->SetNumberOfValues(image->GetNumberOfPoints());
  vtkIdType id = 0;
  for (int k = 0; k < NZ; ++k)
  {
    for (int j = 0; j < NY; ++j)
    {
      for (int i = 0; i < NX; ++i, ++id)
      {
        const bool ghost = Ghost(i, j, k);
        const double v = (i * 7 + j * 3 + k * 11) % 61;
        values->SetValue(id, static_cast<typename ArrayT::ValueType>(ghost && zeroGhosts ? 0.0 : v));
        ghosts->SetValue(id, ghost ? vtkDataSetAttributes::DUPLICATEPOINT : 0);
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  if (withGhostArray)
  {
    image->GetPointData()->AddArray(ghosts);
  }
  return image;
}

vtkSmartPointer<vtkPolyData> Sampled(vtkImageData* image)
{
  return Sample(image, [](vtkErrorDiffusionSampler* s) {
    s->SetDensityScale(1.0 / 240.0); // values up to 60: densities up to 1/4
    s->UseNumberOfPointsOn();
    s->SetNumberOfPoints(2000);
  });
}

template <typename ArrayT>
void CheckType(const std::string& type, int threads)
{
  vtkSmartPointer<vtkPolyData> ghosted, zeroed;
  WithThreads(threads, [&] {
    ghosted = Sampled(Volume<ArrayT>(false, true));
    zeroed = Sampled(Volume<ArrayT>(true, false));
  });
  const std::string what = type + ", " + Str(threads) + " thread(s)";
  Check(ghosted->GetNumberOfPoints() >= 1998 && ghosted->GetNumberOfPoints() <= 2002,
    what + ": the budget's 2000 points: " + Str(ghosted->GetNumberOfPoints()));
  Check(SamePoints(ghosted, zeroed),
    what + ": the points of the volume with 0 in the ghost voxels (" +
      Str(ghosted->GetNumberOfPoints()) + " and " + Str(zeroed->GetNumberOfPoints()) + ")");
  int inGhosts = 0;
  for (vtkIdType p = 0; p < ghosted->GetNumberOfPoints(); ++p)
  {
    double x[3];
    ghosted->GetPoint(p, x);
    inGhosts += Ghost(static_cast<int>(x[0]), static_cast<int>(x[1]), static_cast<int>(x[2]));
  }
  Check(inGhosts == 0, what + ": " + Str(inGhosts) + " points in ghost voxels");
}
}

int main()
{
  // Two threads first (see WithThreads).
  for (const int threads : { 2, 1 })
  {
    CheckType<vtkUnsignedCharArray>("uint8", threads);
    CheckType<vtkUnsignedShortArray>("uint16", threads);
    CheckType<vtkFloatArray>("float", threads);
    CheckType<vtkDoubleArray>("double", threads);
  }
  return Summary("TestErrorDiffusionSamplerGhosts");
}
