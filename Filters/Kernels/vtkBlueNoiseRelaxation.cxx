// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseRelaxation.h"

#include <algorithm>
#include <cmath>

namespace
{
// At least 2 * MaximumRadius + 3 layers (the window around the layer being
// relaxed and the layer just released); a power of two, for the index.
constexpr int RingSize = 32;
static_assert(RingSize >= 2 * vtkBlueNoiseRelaxation::MaximumRadius + 3, "ring too small");

// The layers not yet final (the one being relaxed, the one below it and the
// MaximumRadius above it) keep their densities and masks: these take 6 bytes a
// voxel, 25 MiB a layer of 2048^2, against 1/8 byte for the bits.
constexpr int PlaneCount = vtkBlueNoiseRelaxation::MaximumRadius + 3;

// Zero rows above and below a layer's bits: a search reaches past the edges
// without a test per row.
constexpr int PadRows = vtkBlueNoiseRelaxation::MaximumRadius + 1;

// SplitMix64's finalizer over the seed and a voxel.
std::uint64_t Hash(std::uint64_t seed, int x, int y, int z)
{
  std::uint64_t h = seed ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) * 0x9E3779B97F4A7C15ULL) ^
    (static_cast<std::uint64_t>(static_cast<std::uint32_t>(y)) * 0xC2B2AE3D27D4EB4FULL) ^
    (static_cast<std::uint64_t>(static_cast<std::uint32_t>(z)) * 0x165667B19E3779F9ULL);
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ULL;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBULL;
  return h ^ (h >> 31);
}

// Bit i for byte i != 0, of n <= 64 bytes; eight at a time, branch-free, for
// the compiler to vectorize.
std::uint64_t PackBits(const unsigned char* bytes, int n)
{
  std::uint64_t bits = 0;
  int i = 0;
  for (; i + 8 <= n; i += 8)
  {
    unsigned int byte = 0;
    for (int k = 0; k < 8; ++k)
    {
      byte |= static_cast<unsigned int>(bytes[i + k] != 0) << k;
    }
    bits |= static_cast<std::uint64_t>(byte) << i;
  }
  for (; i < n; ++i)
  {
    bits |= static_cast<std::uint64_t>(bytes[i] != 0) << i;
  }
  return bits;
}

// How far a move may change the density, relative to it.
constexpr float DensityTolerance = 1.0f / 64.0f;

inline bool Relaxable(float g)
{
  return g > 0.0f && g <= vtkBlueNoiseRelaxation::MaximumDensity;
}

// Offsets searched outwards: 0, -1, 1, -2, 2, ...
int Outward(int i)
{
  return (i & 1) ? -((i + 1) / 2) : i / 2;
}

const int Faces[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 },
  { 0, 0, -1 } };
}

//------------------------------------------------------------------------------
void vtkBlueNoiseRelaxation::Begin(int nx, int ny, int firstZ, std::uint64_t seed)
{
  this->NX = std::max(nx, 0);
  this->NY = std::max(ny, 0);
  this->WordsPerRow = (this->NX + 63) / 64 + 1; // a spare word: reads may run one past
  this->First = firstZ;
  this->Last = firstZ - 1;
  this->Relaxed = firstZ;
  this->Finalized = firstZ;
  this->Seed = seed;
  this->Moves = 0;
  const size_t layer = static_cast<size_t>(this->NX) * this->NY;
  const size_t words = static_cast<size_t>(this->WordsPerRow) * (this->NY + 2 * PadRows);
  this->NoSamples.assign(words, 0);
  this->Ring.resize(RingSize);
  for (Slot& slot : this->Ring)
  {
    slot.Z = firstZ - RingSize - 1;
    slot.Bits.assign(words, 0);
  }
  this->Planes.resize(PlaneCount);
  for (Plane& plane : this->Planes)
  {
    plane.Z = firstZ - RingSize - 1;
    plane.Density.resize(layer);
    plane.Mask.resize(layer);
    plane.Moved.resize(layer);
  }
}

//------------------------------------------------------------------------------
// Layers already final are still read (as neighbors) while in the ring;
// only the layers from Finalized on can change.
inline vtkBlueNoiseRelaxation::Slot* vtkBlueNoiseRelaxation::Find(int z)
{
  if (z < this->First || z > this->Last)
  {
    return nullptr;
  }
  Slot& slot = this->Ring[static_cast<size_t>(z - this->First) & (RingSize - 1)];
  return slot.Z == z ? &slot : nullptr;
}

//------------------------------------------------------------------------------
// Densities and masks: only for the layers that are not final yet.
inline vtkBlueNoiseRelaxation::Plane* vtkBlueNoiseRelaxation::FindPlane(int z)
{
  if (z < this->First || z > this->Last)
  {
    return nullptr;
  }
  Plane& plane = this->Planes[static_cast<size_t>(z - this->First) % PlaneCount];
  return plane.Z == z ? &plane : nullptr;
}

//------------------------------------------------------------------------------
// The words of row y (-PadRows <= y < NY + PadRows) of a layer's bits.
inline const std::uint64_t* vtkBlueNoiseRelaxation::Row(const std::uint64_t* bits, int y) const
{
  return bits + static_cast<std::ptrdiff_t>(y + PadRows) * this->WordsPerRow;
}

//------------------------------------------------------------------------------
inline bool vtkBlueNoiseRelaxation::Sample(int x, int y, int z)
{
  const Slot* slot = this->Find(z);
  return slot && (this->Row(slot->Bits.data(), y)[x >> 6] >> (x & 63)) & 1;
}

//------------------------------------------------------------------------------
inline float vtkBlueNoiseRelaxation::DensityAt(int x, int y, int z)
{
  const Plane* plane = this->FindPlane(z);
  return plane ? plane->Density[x + static_cast<size_t>(this->NX) * y] : 0.0f;
}

//------------------------------------------------------------------------------
inline void vtkBlueNoiseRelaxation::Set(int x, int y, int z, bool sample)
{
  Slot* slot = this->Find(z);
  std::uint64_t& word =
    const_cast<std::uint64_t*>(this->Row(slot->Bits.data(), y))[x >> 6];
  const std::uint64_t bit = std::uint64_t(1) << (x & 63);
  word = sample ? (word | bit) : (word & ~bit);
  this->FindPlane(z)->Mask[x + static_cast<size_t>(this->NX) * y] = sample ? 1 : 0;
}

//------------------------------------------------------------------------------
// The rows (dz, dy) within `radius`, nearest first, for NearestSquared.
void vtkBlueNoiseRelaxation::SetRadius(int radius)
{
  if (radius == this->Radius && !this->Rows.empty())
  {
    return;
  }
  this->Radius = radius;
  this->Rows.clear();
  for (int dz = -radius; dz <= radius; ++dz)
  {
    for (int dy = -radius; dy <= radius; ++dy)
    {
      this->Rows.push_back({ dz, dy, dz * dz + dy * dy });
    }
  }
  std::stable_sort(this->Rows.begin(), this->Rows.end(),
    [](const RowOffset& a, const RowOffset& b) { return a.Squared < b.Squared; });
}

//------------------------------------------------------------------------------
// The squared distance from (x, y, z) to the nearest sample other than the
// `except` voxel within Radius along each axis, or `best` when none is
// nearer than that; as soon as one is found at `enough` or nearer, that one.
// Rows are visited nearest first, and no further once they cannot hold
// anything nearer than the best so far.
int vtkBlueNoiseRelaxation::NearestSquared(
  int x, int y, int z, int best, int enough, int exceptX, int exceptY, int exceptZ)
{
  const int radius = this->Radius;
  // Only the layers that can hold a sample nearer than `best`.
  int reach = 0;
  while (reach < radius && (reach + 1) * (reach + 1) < best)
  {
    ++reach;
  }
  const std::uint64_t* layers[2 * MaximumRadius + 1];
  for (int dz = -reach; dz <= reach; ++dz)
  {
    const Slot* slot = this->Find(z + dz);
    layers[dz + radius] = slot ? slot->Bits.data() : this->NoSamples.data();
  }
  const int x0 = std::max(0, x - radius);
  const int x1 = std::min(this->NX - 1, x + radius);
  const int shift = x0 & 63;
  const std::uint64_t width = (std::uint64_t(1) << (x1 - x0 + 1)) - 1;
  for (const RowOffset& row : this->Rows)
  {
    if (row.Squared >= best)
    {
      break;
    }
    const int Y = y + row.DY;
    // The bits x0..x1 of the row: at most 17, in at most two words.
    const std::uint64_t* words = this->Row(layers[row.DZ + radius], Y) + (x0 >> 6);
    std::uint64_t bits = words[0] >> shift;
    if (shift)
    {
      bits |= words[1] << (64 - shift);
    }
    for (bits &= width; bits; bits &= bits - 1)
    {
      const int X = x0 + __builtin_ctzll(bits);
      if (X == exceptX && Y == exceptY && z + row.DZ == exceptZ)
      {
        continue;
      }
      const int d = (X - x) * (X - x) + row.Squared;
      if (d < best)
      {
        best = d;
        this->Nearest[0] = X - x;
        this->Nearest[1] = row.DY;
        this->Nearest[2] = row.DZ;
      }
      if (best <= enough)
      {
        return best;
      }
    }
  }
  return best;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseRelaxation::RelaxSample(int x, int y, int z, float g)
{
  if (g != this->LastDensity) // real volumes repeat densities: spare the roots
  {
    const double spacing = std::cbrt(1.0 / g);
    this->Limit = 0.75 * spacing * spacing;
    // Clamped before the conversion to int: tiny densities have a huge spacing.
    this->SetRadius(static_cast<int>(
      std::min(std::ceil(0.87 * spacing) + 1.0, static_cast<double>(MaximumRadius))));
    this->LastDensity = g;
  }
  // Only whether p has a sample nearer than the limit matters here (nothing
  // beyond the search radius can be found).
  const int cap = static_cast<int>(std::min(
    std::ceil(this->Limit), static_cast<double>((this->Radius + 1) * (this->Radius + 1))));
  const int current = this->NearestSquared(x, y, z, cap, -1, x, y, z);
  if (current >= this->Limit)
  {
    return;
  }
  // A face f towards that nearest sample v (f . v >= 1) comes nearer to it
  // (|v - f|^2 = |v|^2 - 2 f . v + 1 < |v|^2): it cannot win.
  const int toward[3] = { this->Nearest[0], this->Nearest[1], this->Nearest[2] };
  // The six faces in a hashed order (Fisher-Yates on the hash's bits).
  std::uint64_t h = Hash(this->Seed ^ 0x5DEECE66DULL, x, y, z);
  int order[6] = { 0, 1, 2, 3, 4, 5 };
  for (int k = 5; k > 0; --k, h /= 6)
  {
    std::swap(order[k], order[h % static_cast<std::uint64_t>(k + 1)]);
  }
  // Only to a voxel of nearly the same density: along a density gradient a
  // rule by distance moves samples one way more than the other (with a
  // tolerance of 1/8: 3 % fewer points in the sparse end slab of a ramp).
  int best = current;
  int target = -1;
  for (const int face : order)
  {
    const int* f = Faces[face];
    // That sample is at |v - f|^2 from the candidate: no farther can it be.
    const int bound = std::min(
      cap, current - 2 * (f[0] * toward[0] + f[1] * toward[1] + f[2] * toward[2]) + 1);
    if (bound <= best)
    {
      continue;
    }
    const int X = x + f[0], Y = y + f[1], Z = z + f[2];
    if (X < 0 || X >= this->NX || Y < 0 || Y >= this->NY || Z < this->Finalized ||
      !this->FindPlane(Z) || this->Sample(X, Y, Z))
    {
      continue;
    }
    const float gc = this->DensityAt(X, Y, Z);
    if (!Relaxable(gc) || std::abs(gc - g) > DensityTolerance * g)
    {
      continue;
    }
    // A candidate with a sample as near as the best so far cannot win.
    const int d = this->NearestSquared(X, Y, Z, bound, best, x, y, z);
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
    const int X = x + Faces[target][0], Y = y + Faces[target][1], Z = z + Faces[target][2];
    this->Set(x, y, z, false);
    this->Set(X, Y, Z, true);
    this->FindPlane(Z)->Moved[X + static_cast<size_t>(this->NX) * Y] = 1; // once is all
    ++this->Moves;
  }
}

//------------------------------------------------------------------------------
// Asks the cache for what RelaxSample will read around voxel i of layer z.
void vtkBlueNoiseRelaxation::Prefetch(size_t i, int z)
{
  const int x = static_cast<int>(i % this->NX), y = static_cast<int>(i / this->NX);
  const int reach = 2; // the rows of the nearest neighbors at the densities that cost most
  for (int dz = -reach; dz <= reach; ++dz)
  {
    const Slot* slot = this->Find(z + dz);
    if (!slot)
    {
      continue;
    }
    for (int dy = -reach; dy <= reach; ++dy)
    {
      __builtin_prefetch(this->Row(slot->Bits.data(), y + dy) + (x >> 6));
    }
    const Plane* plane = dz >= -1 && dz <= 1 ? this->FindPlane(z + dz) : nullptr;
    if (plane)
    {
      __builtin_prefetch(plane->Density.data() + i);
    }
  }
}

//------------------------------------------------------------------------------
// The samples of layer z, in the hashed order, each given its chance to move.
void vtkBlueNoiseRelaxation::RelaxLayer(int z)
{
  const Slot* slot = this->Find(z);
  Plane* plane = this->FindPlane(z);
  this->Order.clear();
  if (!slot->Relaxable)
  {
    return; // no sample may move in this layer, and none into it
  }
  for (int y = 0; y < this->NY; ++y) // the samples, through the bits
  {
    const std::uint64_t* words = this->Row(slot->Bits.data(), y);
    for (int w = 0; w < this->WordsPerRow; ++w)
    {
      for (std::uint64_t bits = words[w]; bits; bits &= bits - 1)
      {
        const int x = 64 * w + __builtin_ctzll(bits);
        const size_t i = x + static_cast<size_t>(this->NX) * y;
        if (!plane->Moved[i] && Relaxable(plane->Density[i]))
        {
          this->Order.push_back((Hash(this->Seed, x, y, z) & ~std::uint64_t(0xFFFFFFFF)) | i);
        }
      }
    }
  }
  std::sort(this->Order.begin(), this->Order.end());
  const size_t ahead = 4; // samples: far enough for the rows to arrive
  for (size_t k = 0; k < this->Order.size(); ++k)
  {
    if (k + ahead < this->Order.size())
    {
      this->Prefetch(this->Order[k + ahead] & 0xFFFFFFFF, z);
    }
    const size_t i = this->Order[k] & 0xFFFFFFFF;
    // An earlier move may have taken this sample away, or put one here.
    if (plane->Mask[i] && !plane->Moved[i])
    {
      this->RelaxSample(
        static_cast<int>(i % this->NX), static_cast<int>(i / this->NX), z, plane->Density[i]);
    }
  }
}

//------------------------------------------------------------------------------
// Layer z is final: no sample will move into or out of it any more.
void vtkBlueNoiseRelaxation::Release(int z)
{
  Plane* plane = this->FindPlane(z);
  Layer layer;
  layer.Z = z;
  layer.Density = plane->Density.data();
  layer.Mask = plane->Mask.data();
  layer.Count = std::count(plane->Mask.begin(), plane->Mask.end(), 1);
  this->Done.push_back(layer);
  this->Finalized = z + 1;
}

//------------------------------------------------------------------------------
const std::vector<vtkBlueNoiseRelaxation::Layer>& vtkBlueNoiseRelaxation::Push(
  int z, const float* density, const unsigned char* mask)
{
  this->Done.clear();
  this->Last = z;
  Slot& slot = this->Ring[static_cast<size_t>(z - this->First) & (RingSize - 1)];
  slot.Z = z;
  Plane& plane = this->Planes[static_cast<size_t>(z - this->First) % PlaneCount];
  plane.Z = z;
  const size_t layer = plane.Mask.size();
  std::copy(density, density + layer, plane.Density.begin());
  slot.Relaxable = std::any_of(density, density + layer, Relaxable);
  std::copy(mask, mask + layer, plane.Mask.begin());
  std::fill(plane.Moved.begin(), plane.Moved.end(), 0);
  std::fill(slot.Bits.begin(), slot.Bits.end(), 0);
  for (int y = 0; y < this->NY; ++y)
  {
    const unsigned char* row = mask + static_cast<size_t>(y) * this->NX;
    auto* words = const_cast<std::uint64_t*>(this->Row(slot.Bits.data(), y));
    for (int x0 = 0; x0 < this->NX; x0 += 64)
    {
      words[x0 >> 6] = PackBits(row + x0, std::min(64, this->NX - x0));
    }
  }
  for (; this->Relaxed + MaximumRadius <= this->Last; ++this->Relaxed)
  {
    this->RelaxLayer(this->Relaxed);
    if (this->Relaxed - 1 >= this->Finalized)
    {
      this->Release(this->Relaxed - 1);
    }
  }
  return this->Done;
}

//------------------------------------------------------------------------------
const std::vector<vtkBlueNoiseRelaxation::Layer>& vtkBlueNoiseRelaxation::Flush()
{
  this->Done.clear();
  for (; this->Relaxed <= this->Last; ++this->Relaxed)
  {
    this->RelaxLayer(this->Relaxed);
  }
  for (int z = this->Finalized; z <= this->Last; ++z)
  {
    this->Release(z);
  }
  return this->Done;
}
