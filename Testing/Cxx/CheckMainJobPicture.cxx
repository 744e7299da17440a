// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// CheckMainJobPicture PNG [MIN_WIDTH MIN_HEIGHT]: exits non-zero unless PNG is
// a readable RGB(A) picture of at least MIN_WIDTH x MIN_HEIGHT (default
// 400 x 300) that is not blank: at least 16 distinct colors, at least 2% of
// the pixels differing from the most frequent (background) color, and at
// least 0.5% of them clearly colored (max - min of R, G, B >= 48; the
// backgrounds and the text are white, gray or black, the points and the
// curves are colored by a color map or in blue, orange and red).
// Used by the MainJob test (RunMainJobTest.cmake) on samples.png and spectrum.png.
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <unordered_map>

int main(int argc, char* argv[])
{
  if (argc != 2 && argc != 4)
  {
    std::fprintf(stderr, "usage: CheckMainJobPicture PNG [MIN_WIDTH MIN_HEIGHT]\n");
    return 2;
  }
  const char* path = argv[1];
  const int minWidth = argc == 4 ? std::atoi(argv[2]) : 400;
  const int minHeight = argc == 4 ? std::atoi(argv[3]) : 300;

  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path))
  {
    std::fprintf(stderr, "%s: not a readable PNG file\n", path);
    return 1;
  }
  reader->SetFileName(path);
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* pixels = image->GetPointData()->GetScalars();
  if (!pixels || pixels->GetNumberOfComponents() < 3 || dims[2] != 1)
  {
    std::fprintf(stderr, "%s: not an RGB(A) picture\n", path);
    return 1;
  }
  if (dims[0] < minWidth || dims[1] < minHeight)
  {
    std::fprintf(stderr, "%s: %d x %d pixels, expected at least %d x %d\n", path, dims[0],
      dims[1], minWidth, minHeight);
    return 1;
  }

  std::unordered_map<std::uint32_t, long long> histogram;
  long long colored = 0;
  const vtkIdType n = pixels->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    std::uint32_t rgb = 0;
    int lo = 255, hi = 0;
    for (int c = 0; c < 3; ++c)
    {
      const int v = static_cast<int>(pixels->GetComponent(i, c)) & 0xff;
      rgb = (rgb << 8) | static_cast<std::uint32_t>(v);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    ++histogram[rgb];
    colored += hi - lo >= 48 ? 1 : 0;
  }
  long long background = 0;
  for (const auto& entry : histogram)
  {
    background = std::max(background, entry.second);
  }
  const double covered = 1.0 - static_cast<double>(background) / static_cast<double>(n);
  const double saturated = static_cast<double>(colored) / static_cast<double>(n);
  std::printf("%s: %d x %d pixels, %zu colors, %.1f%% off the background color, %.2f%% "
              "colored\n",
    path, dims[0], dims[1], histogram.size(), 100.0 * covered, 100.0 * saturated);
  if (histogram.size() < 16 || covered < 0.02 || saturated < 0.005)
  {
    std::fprintf(stderr, "%s: the picture is (nearly) blank\n", path);
    return 1;
  }
  return 0;
}
