// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBlueNoiseRelaxation against its definition (the class comment), both
// rules, written here the plain way: the whole volume in memory, the nearest
// sample and the energies by loops over the box around a voxel. Random
// masks over densities that vary by voxel (within and beyond the move
// tolerance, above 1/4 and 0, whole layers where nothing moves, and similar
// densities with holes of 0), at several volume shapes (rows shorter and
// longer than a word), pushed layer by layer: the relaxed masks must be the
// same bit for bit, and the counts kept (in all, and in each layer
// returned).
#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseDensityClass.h"
#include "vtkBlueNoiseRelaxation.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace bluenoise_test;

namespace
{
using R = vtkBlueNoiseRelaxation;

struct Volume
{
  int N[3];
  std::vector<float> Density;
  std::vector<unsigned char> Mask;
  size_t Index(int x, int y, int z) const { return x + N[0] * (y + static_cast<size_t>(N[1]) * z); }
  bool Inside(int x, int y, int z) const
  {
    return x >= 0 && y >= 0 && z >= 0 && x < N[0] && y < N[1] && z < N[2];
  }
};

// Whether densities a and b are in one region (of the faces rule).
bool InOneRegion(float a, float b)
{
  return std::abs(vtkBlueNoiseDensityClass::Of(a) - vtkBlueNoiseDensityClass::Of(b)) <=
    R::RegionClasses;
}

bool Relaxable(float g)
{
  return g > 0.0f && g <= R::MaximumDensity;
}

// min(cap, squared distance from (x, y, z) to the nearest sample other than
// `except` in the box of half-width `radius` whose density is similar to g).
int Nearest(const Volume& v, int x, int y, int z, int radius, int cap, const int except[3], float g)
{
  int best = cap;
  for (int dz = -radius; dz <= radius; ++dz)
  {
    for (int dy = -radius; dy <= radius; ++dy)
    {
      for (int dx = -radius; dx <= radius; ++dx)
      {
        const int X = x + dx, Y = y + dy, Z = z + dz;
        if (v.Inside(X, Y, Z) && v.Mask[v.Index(X, Y, Z)] &&
          !(X == except[0] && Y == except[1] && Z == except[2]) &&
          vtkBlueNoiseDensityClass::Similar(v.Density[v.Index(X, Y, Z)], g))
        {
          best = std::min(best, dx * dx + dy * dy + dz * dz);
        }
      }
    }
  }
  return best;
}

// Whether the voxels from (x, y, z) + lo f to (x, y, z) + hi f are all in
// the volume, of positive densities in g's region.
bool LineInRegion(const Volume& v, int x, int y, int z, const int f[3], int lo, int hi, float g)
{
  for (int t = lo; t <= hi; ++t)
  {
    const int X = x + t * f[0], Y = y + t * f[1], Z = z + t * f[2];
    if (!v.Inside(X, Y, Z) || !(v.Density[v.Index(X, Y, Z)] > 0.0f) ||
      !InOneRegion(v.Density[v.Index(X, Y, Z)], g))
    {
      return false;
    }
  }
  return true;
}

// One sample's chance to move, as the class comment defines it.
void RelaxSample(Volume& v, std::vector<unsigned char>& moved, int x, int y, int z, std::uint64_t seed)
{
  const float g = v.Density[v.Index(x, y, z)];
  const double spacing = std::cbrt(1.0 / g);
  const double limit = 0.75 * spacing * spacing;
  const int radius =
    static_cast<int>(std::min(std::ceil(0.87 * spacing) + 1.0, double(R::MaximumRadius)));
  const int cap =
    static_cast<int>(std::min(std::ceil(limit), static_cast<double>((radius + 1) * (radius + 1))));
  const int p[3] = { x, y, z };
  const int current = Nearest(v, x, y, z, radius, cap, p, g);
  if (current >= limit)
  {
    return;
  }
  int order[6];
  R::FaceOrder(seed, x, y, z, order);
  int best = current, target = -1;
  for (int face : order)
  {
    const int X = x + R::Faces[face][0], Y = y + R::Faces[face][1], Z = z + R::Faces[face][2];
    if (!v.Inside(X, Y, Z) || v.Mask[v.Index(X, Y, Z)])
    {
      continue;
    }
    const float gc = v.Density[v.Index(X, Y, Z)];
    if (!Relaxable(gc) || std::abs(gc - g) > R::DensityTolerance * g ||
      !LineInRegion(v, x, y, z, R::Faces[face], -radius, radius + 1, g))
    {
      continue;
    }
    const int d = Nearest(v, X, Y, Z, radius, cap, p, g);
    if (d > best)
    {
      best = d;
      target = face;
      if (best >= cap)
      {
        break;
      }
    }
  }
  if (target >= 0)
  {
    const size_t to =
      v.Index(x + R::Faces[target][0], y + R::Faces[target][1], z + R::Faces[target][2]);
    v.Mask[v.Index(x, y, z)] = 0;
    v.Mask[to] = 1;
    moved[to] = 1;
  }
}

// The energy rule's E(c) for the 27 neighbors c of sample p (index k as the
// class comment numbers them), summed as it defines: per layer and row of
// the box around p, each in increasing order, in float.
void Energies(const Volume& v, const int p[3], float g, const float* w, int width, float energy[27])
{
  const int reach = width + 1;
  std::fill(energy, energy + 27, 0.0f);
  for (int dz = -reach; dz <= reach; ++dz)
  {
    float layer[9] = {};
    for (int dy = -reach; dy <= reach; ++dy)
    {
      float row[3] = {};
      for (int dx = -reach; dx <= reach; ++dx)
      {
        const int X = p[0] + dx, Y = p[1] + dy, Z = p[2] + dz;
        if ((dx || dy || dz) && v.Inside(X, Y, Z) && v.Mask[v.Index(X, Y, Z)] &&
          vtkBlueNoiseDensityClass::Similar(v.Density[v.Index(X, Y, Z)], g))
        {
          for (int ex = -1; ex <= 1; ++ex)
          {
            row[ex + 1] += w[dx - ex];
          }
        }
      }
      for (int ey = -1; ey <= 1; ++ey)
      {
        for (int ex = -1; ex <= 1; ++ex)
        {
          layer[3 * (ey + 1) + ex + 1] += w[dy - ey] * row[ex + 1];
        }
      }
    }
    for (int ez = -1; ez <= 1; ++ez)
    {
      for (int k = 0; k < 9; ++k)
      {
        energy[9 * (ez + 1) + k] += w[dz - ez] * layer[k];
      }
    }
  }
}

// One sample's chance to move by the energy rule, as the class comment defines it.
void EnergySample(Volume& v, std::vector<unsigned char>& moved, int x, int y, int z, std::uint64_t seed)
{
  const float g = v.Density[v.Index(x, y, z)];
  float weights[2 * R::MaximumRadius + 3];
  const int width = R::EnergyWeights(g, weights);
  const float* w = weights + R::MaximumRadius + 1;
  const int p[3] = { x, y, z };
  float energy[27];
  Energies(v, p, g, w, width, energy);
  float best = energy[13] * (1.0f - R::EnergyMargin);
  int target = -1;
  const int start = R::EnergyStart(seed, x, y, z);
  for (int n = 0; n < 27; ++n)
  {
    const int k = (start + n) % 27;
    const int d[3] = { k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1 };
    const int X = x + d[0], Y = y + d[1], Z = z + d[2];
    if (k == 13 || !(energy[k] < best) || !v.Inside(X, Y, Z) || v.Mask[v.Index(X, Y, Z)])
    {
      continue;
    }
    const float gc = v.Density[v.Index(X, Y, Z)];
    bool open = Relaxable(gc) && std::abs(gc - g) <= R::DensityTolerance * g;
    for (int axis = 0; axis < 3 && open; ++axis)
    {
      const int f[3] = { axis == 0 ? d[0] : 0, axis == 1 ? d[1] : 0, axis == 2 ? d[2] : 0 };
      open = d[axis] == 0 || LineInRegion(v, x, y, z, f, -width, width + 1, g);
    }
    if (open)
    {
      best = energy[k];
      target = k;
    }
  }
  if (target >= 0)
  {
    const size_t to = v.Index(x + target % 3 - 1, y + target / 3 % 3 - 1, z + target / 9 - 1);
    v.Mask[v.Index(x, y, z)] = 0;
    v.Mask[to] = 1;
    moved[to] = 1;
  }
}

// The reference pass: layer by layer, each layer's samples in the hashed order.
void Relax(Volume& v, std::uint64_t seed, int rule)
{
  std::vector<unsigned char> moved(v.Mask.size(), 0);
  for (int z = 0; z < v.N[2]; ++z)
  {
    std::vector<std::uint64_t> order;
    for (int y = 0; y < v.N[1]; ++y)
    {
      for (int x = 0; x < v.N[0]; ++x)
      {
        const size_t at = v.Index(x, y, z);
        if (v.Mask[at] && !moved[at] && Relaxable(v.Density[at]))
        {
          order.push_back(R::OrderKey(seed, x, y, z) | static_cast<std::uint64_t>(x + v.N[0] * y));
        }
      }
    }
    std::sort(order.begin(), order.end());
    for (std::uint64_t key : order)
    {
      const int i = static_cast<int>(key & 0xFFFFFFFF);
      const int x = i % v.N[0], y = i / v.N[0];
      if (v.Mask[v.Index(x, y, z)] && !moved[v.Index(x, y, z)])
      {
        if (rule == R::RULE_ENERGY)
        {
          EnergySample(v, moved, x, y, z, seed);
        }
        else
        {
          RelaxSample(v, moved, x, y, z, seed);
        }
      }
    }
  }
}

// Densities: a few values per region, some within the tolerance of each other;
// with `bands`, whole layers no sample may move in (0 and 0.3) between them;
// with `holes`, densities of one class only (similar everywhere), with
// regions and single voxels of 0 among them (the support alone ends lines).
Volume Random(int nx, int ny, int nz, std::uint32_t seed, bool bands = false, bool constant = false,
  bool holes = false)
{
  std::mt19937 random(seed);
  Volume v{ { nx, ny, nz }, {}, {} };
  const float levels[] = { 0.0f, 4.0f / 255, 8.0f / 255, 8.05f / 255, 32.0f / 255, 0.25f, 0.3f };
  const float alike[] = { 0.0f, 8.0f / 255, 8.05f / 255, 10.0f / 255, 8.0f / 255, 8.0f / 255, 8.0f / 255 };
  std::uniform_int_distribution<int> pick(0, 6);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  v.Density.resize(static_cast<size_t>(nx) * ny * nz);
  v.Mask.resize(v.Density.size());
  const int block = 5; // regions of 5^3 voxels
  std::vector<float> region(static_cast<size_t>(nx / block + 1) * (ny / block + 1) * (nz / block + 1));
  for (float& g : region)
  {
    g = holes ? alike[pick(random)] : levels[pick(random)];
  }
  for (int z = 0; z < nz; ++z)
  {
    for (int y = 0; y < ny; ++y)
    {
      for (int x = 0; x < nx; ++x)
      {
        const size_t r = x / block + (nx / block + 1) * (y / block + (ny / block + 1) * (z / block));
        const size_t i = v.Index(x, y, z);
        v.Density[i] = constant ? 24.0f / 255
          : holes ? (unit(random) < 0.03f ? 0.0f : region[r])
          : !bands || (z / 4) % 3 == 0 ? region[r]
                                        : (z / 4) % 3 == 1 ? 0.0f : 0.3f;
        v.Mask[i] = unit(random) < 2.0f * std::max(v.Density[i], 0.02f) ? 1 : 0;
        if (holes && !(v.Density[i] > 0.0f))
        {
          v.Mask[i] = 0; // as error diffusion places them (the class comment)
        }
      }
    }
  }
  return v;
}
}

int main()
{
  // Rows shorter and longer than a word, a column, more layers than the ring holds.
  const int shapes[][3] = { { 13, 11, 17 }, { 70, 9, 12 }, { 130, 6, 10 }, { 1, 1, 5 }, { 20, 8, 40 },
    { 24, 22, 30 } };
  // One object for all runs, rules and shapes changing: Begin and SetRule
  // must leave nothing of the run before.
  R relaxation;
  for (const auto& shape : shapes)
  {
    for (std::uint64_t seed : { 1u, 77u, 5u, 9u, 13u, 21u })
    for (int rule : { R::RULE_SPACING, R::RULE_ENERGY })
    {
      // Seed 5: bands of 4 layers that relax, then 4 of 0, then 4 of 0.3.
      // Seed 9: one density everywhere (the faces of the volume alone).
      // Seeds 13 and 21: similar densities with holes of 0.
      Volume v = Random(shape[0], shape[1], shape[2], static_cast<std::uint32_t>(seed + shape[0]),
        seed == 5, seed == 9, seed == 13 || seed == 21);
      const auto count = std::count(v.Mask.begin(), v.Mask.end(), 1);
      const size_t layer = static_cast<size_t>(shape[0]) * shape[1];
      std::vector<unsigned char> relaxed(v.Mask.size(), 2);
      bool countsRight = true; // each layer's Count, its samples after the moves
      relaxation.SetRule(rule);
      relaxation.Begin(shape[0], shape[1], 0, seed);
      auto keep = [&](const std::vector<R::Layer>& layers) {
        for (const auto& l : layers)
        {
          std::copy(l.Mask, l.Mask + layer, relaxed.begin() + l.Z * layer);
          countsRight = countsRight && l.Count == std::count(l.Mask, l.Mask + layer, 1);
        }
      };
      for (int z = 0; z < shape[2]; ++z)
      {
        keep(relaxation.Push(z, &v.Density[z * layer], &v.Mask[z * layer]));
      }
      keep(relaxation.Flush());
      Relax(v, seed, rule);
      const std::string what = Str(shape[0]) + "x" + Str(shape[1]) + "x" + Str(shape[2]) +
        " seed " + Str(seed) + (rule == R::RULE_ENERGY ? " energy" : " spacing") + " (" +
        Str(relaxation.GetNumberOfMoves()) + " moves)";
      Check(relaxed == v.Mask, "the pass moves as its definition does: " + what);
      Check(std::count(relaxed.begin(), relaxed.end(), 1) == count, "the count is kept: " + what);
      Check(countsRight, "each layer comes with its count: " + what);
    }
  }
  return Summary("TestBlueNoiseRelaxationRule");
}
