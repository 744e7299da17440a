// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The baseline of every speed ratio: the tightest simple single-threaded loop
// of the paper's scan (TightScan), shared by the benchmark programs and the
// library that pvpython_update_pipeline.py loads to run it in its own process.
#ifndef BlueNoiseTightScan_h
#define BlueNoiseTightScan_h

#include "vtkErrorDiffusionKernel.h"
#include "vtkErrorDiffusionParameterTable.h"
#include "vtkType.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <vector>

namespace BlueNoiseTight
{
// PCG32, as the paper's implementations use a plain generator.
struct Pcg32
{
  std::uint64_t State = 0x853c49e6748fea9bULL;
  float Uniform()
  {
    const std::uint64_t old = this->State;
    this->State = old * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto x = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto r = static_cast<std::uint32_t>(old >> 59u);
    return static_cast<float>(((x >> r) | (x << ((32u - r) & 31u))) >> 8) * (1.0f / 16777216.0f);
  }
};

// The baseline: the tightest simple single-threaded loop of the paper's scan.
// It does: layers along z, the serpentine of each layer turned by 90 degrees
// per layer (the kernel's GetLayerScan), the threshold 0.5 +- s r m(g) with
// s = 0.5 and r from PCG32, the error to the six targets of Table 1 with the
// level's weights looked up when the density changes (a constant cube has
// one; for 8-bit input from a table of the 256 values' weights, made once),
// the binary volume b as output; densities g = clamp(scale * value), from a
// 256-entry table for 8-bit input. It does not: renormalize the weights at
// the faces (the error buffers are padded by one voxel, and what lands in
// the padding is dropped), divide or take a modulo per voxel, warm up,
// translate the threshold by a charge, keep counts exact, treat empty or
// full voxels apart, or make points. What the filter does beyond it is what
// a ratio against it prices.
template <typename T>
inline vtkIdType TightScan(const T* values, int n, double scale, unsigned char* b)
{
  const auto table = vtkErrorDiffusionParameterTable::Paper();
  const vtkIdType pitch = n + 2; // the error buffers: one voxel of padding all round
  const size_t layer = static_cast<size_t>(n) * n;
  std::vector<float> current(static_cast<size_t>(pitch) * pitch, 0.0f);
  std::vector<float> next(current.size(), 0.0f);
  float lut[256];
  vtkErrorDiffusionParameterTable::Parameters byValue[256];
  for (int v = 0; v < 256; ++v)
  {
    lut[v] = static_cast<float>(std::min(1.0, std::max(0.0, scale * v)));
    byValue[v] = table.Evaluate(lut[v]);
  }
  const auto density = [&](T value) {
    if (sizeof(T) == 1)
    {
      return lut[static_cast<unsigned char>(value)];
    }
    return std::min(1.0f, std::max(0.0f, static_cast<float>(scale) * static_cast<float>(value)));
  };
  const auto padded = [n, pitch](vtkIdType stride) { // a stride of the unpadded layer
    return stride == 1 || stride == -1 ? stride : stride / n * pitch;
  };
  Pcg32 random;
  vtkIdType count = 0;
  float lastG = -1.0f;
  float w[6] = { 0, 0, 0, 0, 0, 0 };
  float m = 0.0f;
  for (int z = 0; z < n; ++z)
  {
    const auto scan = vtkErrorDiffusionKernel::GetLayerScan(n, n, z);
    const vtkIdType pu = padded(scan.UStride), pv = padded(scan.VStride);
    const vtkIdType pstart = (scan.Start % n + 1) + pitch * (scan.Start / n + 1);
    vtkIdType d[2][6]; // the targets' padded offsets on even and odd rows
    for (int parity = 0; parity < 2; ++parity)
    {
      int offsets[6][3];
      vtkErrorDiffusionKernel::GetTargetOffsets(scan, parity, offsets);
      for (int t = 0; t < 6; ++t)
      {
        d[parity][t] = offsets[t][0] + pitch * offsets[t][1];
      }
    }
    const T* in = values + z * layer;
    unsigned char* out = b + z * layer;
    for (int q = 0; q < scan.NV; ++q)
    {
      const bool odd = (q & 1) != 0;
      const vtkIdType step = odd ? -scan.UStride : scan.UStride;
      const vtkIdType pstep = odd ? -pu : pu;
      vtkIdType idx = scan.Start + q * scan.VStride + (odd ? (scan.NU - 1) * scan.UStride : 0);
      vtkIdType pidx = pstart + q * pv + (odd ? (scan.NU - 1) * pu : 0);
      const vtkIdType* o = d[odd ? 1 : 0];
      for (int u = 0; u < scan.NU; ++u, idx += step, pidx += pstep)
      {
        const float g = density(in[idx]);
        if (g != lastG)
        {
          const auto p = sizeof(T) == 1 ? byValue[static_cast<unsigned char>(in[idx])] : table.Evaluate(g);
          std::copy(p.Weights.begin(), p.Weights.end(), w);
          m = 0.5f * p.Modulation;
          lastG = g;
        }
        const float r = random.Uniform() * m;
        const float threshold = g <= 0.5f ? 0.5f + r : 0.5f - r;
        const float value = g + current[pidx];
        const unsigned char bit = value >= threshold ? 1 : 0;
        out[idx] = bit;
        count += bit;
        const float e = value - bit;
        current[pidx + o[0]] += e * w[0];
        current[pidx + o[1]] += e * w[1];
        current[pidx + o[2]] += e * w[2];
        next[pidx + o[3]] += e * w[3];
        next[pidx + o[4]] += e * w[4];
        next[pidx + o[5]] += e * w[5];
      }
    }
    std::swap(current, next);
    std::fill(next.begin(), next.end(), 0.0f);
  }
  return count;
}

// The fastest of three TightScans, in seconds; `points` the samples of the
// last. The binary volume b (n^3 values) is the caller's, so that a caller
// timing it beside other work allocates it once.
template <typename T>
inline double FastestSeconds(const T* values, int n, double scale, unsigned char* b, vtkIdType& points)
{
  double best = 1e30;
  for (int i = 0; i < 3; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    points = TightScan(values, n, scale, b);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}
} // namespace BlueNoiseTight

#endif
