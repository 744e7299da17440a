// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Pieces: the sampler samples whatever extent the pipeline hands it. Two
// pieces of an analytic source are sampled separately; every point of a piece
// lies in that piece's extent, the field data records that extent, and the
// two counts add up to about the whole volume's (piece faces are volume faces
// for the error, so only about the count is checked).
#include "SamplerTestUtilities.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"
#include "vtkRTAnalyticSource.h"

#include <algorithm>
#include <cmath>

using namespace bluenoise_test;

int main()
{
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(0, 47, 0, 47, 0, 47);
  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputConnection(source->GetOutputPort());
  sampler->UseNumberOfPointsOff();
  sampler->SetDensityScale(0.3);
  // One mapping for every piece: the array's own range would be each piece's.
  sampler->UseCustomScalarRangeOn();
  sampler->SetScalarRange(37.0, 277.0);

  sampler->UpdatePiece(0, 1, 0);
  const vtkIdType whole = sampler->GetOutput()->GetNumberOfPoints();
  vtkIdType sum = 0;
  for (int piece = 0; piece < 2; ++piece)
  {
    sampler->UpdatePiece(piece, 2, 0);
    vtkPolyData* out = sampler->GetOutput();
    auto* extent =
      vtkIntArray::SafeDownCast(out->GetFieldData()->GetArray("SamplingGridExtent"));
    if (!Check(extent != nullptr, "piece " + Str(piece) + ": sampling grid recorded"))
    {
      continue;
    }
    int e[6];
    for (int c = 0; c < 6; ++c)
    {
      e[c] = extent->GetValue(c);
    }
    const vtkIdType voxels = static_cast<vtkIdType>(e[1] - e[0] + 1) * (e[3] - e[2] + 1) * (e[5] - e[4] + 1);
    Check(voxels < 48 * 48 * 48 && voxels > 0, "piece " + Str(piece) + " is a part of the volume");
    int outside = 0;
    for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
    {
      const double* x = out->GetPoint(p); // unit spacing, origin 0 (Wavelet: origin at 0 for this extent)
      for (int c = 0; c < 3; ++c)
      {
        outside += (x[c] < e[2 * c] - 1e-6 || x[c] > e[2 * c + 1] + 1e-6) ? 1 : 0;
      }
    }
    Check(outside == 0, "piece " + Str(piece) + ": " + Str(outside) + " points outside its extent");
    sum += out->GetNumberOfPoints();
  }
  source->UpdatePiece(0, 1, 0);
  vtkDataArray* values = source->GetOutput()->GetPointData()->GetScalars();
  double expected = 0.0;
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    expected += std::min(1.0, std::max(0.0, 0.3 * (values->GetComponent(i, 0) - 37.0) / 240.0));
  }
  std::cout << "expected " << expected << ", whole " << whole << " points, pieces " << sum
            << std::endl;
  Check(whole > 1000 && std::abs(whole - expected) < 0.03 * expected, "whole count");
  Check(std::abs(sum - expected) < 0.03 * expected, "pieces add up to the expected count");
  return Summary("TestErrorDiffusionSamplerPieces");
}
