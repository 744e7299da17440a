// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The scan and error-filter geometry the kernel runs: every voxel of a layer
// visited once, serpentine rows, a 90 degree turn per layer over a cycle of
// four, the paper's offsets in the first layer, and no error ever sent to a
// voxel that has already been processed.
#include "BlueNoiseTestUtilities.h"
#include "vtkErrorDiffusionKernel.h"

#include <vector>

using namespace bluenoise_test;

namespace
{
struct Visit
{
  int X, Y;
};

// The voxels of one layer in the order the kernel scans them.
std::vector<Visit> ScanOrder(int nx, int ny, const vtkErrorDiffusionKernel::LayerScan& s)
{
  std::vector<Visit> order;
  for (int q = 0; q < s.NV; ++q)
  {
    for (int p = 0; p < s.NU; ++p)
    {
      const vtkIdType idx =
        s.Start + q * s.VStride + ((q % 2 == 0) ? p : (s.NU - 1 - p)) * s.UStride;
      order.push_back({ static_cast<int>(idx % nx), static_cast<int>(idx / nx) });
    }
  }
  (void)ny;
  return order;
}
}

int main()
{
  // Layer-1 offsets are the paper's (Fig. 4): A100, A-110, A010, A0-11, A-101, A001.
  {
    const auto s = vtkErrorDiffusionKernel::GetLayerScan(5, 4, 0);
    int offsets[6][3];
    vtkErrorDiffusionKernel::GetTargetOffsets(s, 0, offsets);
    const int paper[6][3] = { { 1, 0, 0 }, { -1, 1, 0 }, { 0, 1, 0 }, { 0, -1, 1 }, { -1, 0, 1 },
      { 0, 0, 1 } };
    bool same = true;
    for (int t = 0; t < 6; ++t)
    {
      for (int c = 0; c < 3; ++c)
      {
        same = same && offsets[t][c] == paper[t][c];
      }
    }
    Check(same, "first-layer offsets are the paper's");
  }

  for (const auto& dims : { std::pair<int, int>{ 7, 5 }, { 4, 9 }, { 1, 6 }, { 6, 1 }, { 8, 8 } })
  {
    const int nx = dims.first;
    const int ny = dims.second;
    std::vector<int> firstU(4, 0), firstV(4, 0);
    for (int phase = 0; phase < 4; ++phase)
    {
      const std::string where = Str(nx) + "x" + Str(ny) + " phase " + Str(phase);
      const auto s = vtkErrorDiffusionKernel::GetLayerScan(nx, ny, phase);
      Check(s.Phase == phase && vtkErrorDiffusionKernel::GetLayerScan(nx, ny, phase + 4).Start == s.Start,
        where + ": phase repeats every 4 layers");
      const auto order = ScanOrder(nx, ny, s);
      // Each voxel once.
      std::vector<int> rank(static_cast<size_t>(nx) * ny, -1);
      bool inside = true;
      for (size_t r = 0; r < order.size(); ++r)
      {
        const Visit& v = order[r];
        inside = inside && v.X >= 0 && v.X < nx && v.Y >= 0 && v.Y < ny &&
          rank[v.X + static_cast<size_t>(nx) * v.Y] == -1;
        if (inside)
        {
          rank[v.X + static_cast<size_t>(nx) * v.Y] = static_cast<int>(r);
        }
      }
      Check(inside && order.size() == rank.size(), where + ": every voxel exactly once");
      // Serpentine: consecutive voxels are neighbors.
      bool adjacent = true;
      for (size_t r = 1; r < order.size(); ++r)
      {
        adjacent = adjacent &&
          std::abs(order[r].X - order[r - 1].X) + std::abs(order[r].Y - order[r - 1].Y) == 1;
      }
      Check(adjacent, where + ": serpentine (consecutive voxels adjacent)");
      // No error flows back: same-layer targets come later in the scan.
      bool forward = true;
      for (size_t r = 0; r < order.size(); ++r)
      {
        const int q = static_cast<int>(r) / s.NU;
        int offsets[6][3];
        vtkErrorDiffusionKernel::GetTargetOffsets(s, q, offsets);
        for (int t = 0; t < 6; ++t)
        {
          const int x = order[r].X + offsets[t][0];
          const int y = order[r].Y + offsets[t][1];
          if (offsets[t][2] == 1 || x < 0 || y < 0 || x >= nx || y >= ny)
          {
            continue; // next layer, or outside (handled as a face)
          }
          forward = forward && rank[x + static_cast<size_t>(nx) * y] > static_cast<int>(r);
        }
        // Next-layer targets have |dx|, |dy| <= 1 and dz == 1 only.
        for (int t = 3; t < 6; ++t)
        {
          forward = forward && offsets[t][2] == 1;
        }
      }
      Check(forward, where + ": no error reaches an already processed voxel");
      int offsets[6][3];
      vtkErrorDiffusionKernel::GetTargetOffsets(s, 0, offsets);
      firstU[phase] = offsets[0][0] + 2 * offsets[0][1];
      firstV[phase] = offsets[2][0] + 2 * offsets[2][1];
    }
    // The scan direction turns by 90 degrees per layer: u_{k+1} = R90 u_k.
    auto turn = [](int code) {
      const int x = (code == 1) - (code == -1);
      const int y = (code == 2) - (code == -2);
      return -y + 2 * x; // (x, y) -> (-y, x)
    };
    bool turns = true;
    for (int phase = 0; phase < 4; ++phase)
    {
      turns = turns && firstU[(phase + 1) % 4] == turn(firstU[phase]) &&
        firstV[(phase + 1) % 4] == turn(firstV[phase]);
    }
    Check(turns, Str(nx) + "x" + Str(ny) + ": each layer turns the scan by 90 degrees");
  }
  return Summary("TestErrorDiffusionScanGeometry");
}
