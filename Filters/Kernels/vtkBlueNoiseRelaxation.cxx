// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseRelaxation.h"
#include "vtkBlueNoiseDensityClass.h"
#include "vtkBlueNoiseSSE2.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace
{
// At least 2 * MaximumRadius + 3 layers (the window around the layer being
// relaxed and the layer just released); a power of two, for the index.
constexpr int RingSize = 32;
static_assert(RingSize >= 2 * vtkBlueNoiseRelaxation::MaximumRadius + 3, "ring too small");

// The layers not yet final (the one being relaxed, the one below it and the
// MaximumRadius above it) keep their densities and masks: these take 6 bytes a
// voxel, 25 MiB a layer of 2048^2, against 1/8 byte for the bits. With one
// more, what Push returns stays through the next Push (the header's promise):
// Push(z) overwrites layer z - PlaneCount, which Push(z - 2) released at the
// latest (it relaxed layer z - 2 - MaximumRadius).
constexpr int PlaneCount = vtkBlueNoiseRelaxation::MaximumRadius + 3;

// Zero rows above and below a layer's bits: a search reaches past the edges
// without a test per row.
constexpr int PadRows = vtkBlueNoiseRelaxation::MaximumRadius + 1;

// Nearest visits every shell where there are at most this many (from about
// 4/255 up), the nearest first and no further than it must where more.
constexpr size_t EveryShell = 12;

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

// Bit i for byte i != 0, of n <= 64 bytes; eight at a time: the high bit of
// each byte set when the byte is not 0, then the eight high bits gathered
// into the top byte by one multiplication (little-endian loads).
std::uint64_t PackBits(const unsigned char* bytes, int n)
{
  constexpr std::uint64_t low7 = 0x7F7F7F7F7F7F7F7FULL;
  constexpr std::uint64_t high = 0x8080808080808080ULL;
  constexpr std::uint64_t gather = 0x0102040810204080ULL;
  std::uint64_t bits = 0;
  int i = 0;
  for (; i + 8 <= n; i += 8)
  {
    std::uint64_t v;
    std::memcpy(&v, bytes + i, 8);
    const std::uint64_t nonzero = (((v & low7) + low7) | v) & high;
    bits |= (((nonzero >> 7) * gather) >> 56) << i;
  }
  for (; i < n; ++i)
  {
    bits |= static_cast<std::uint64_t>(bytes[i] != 0) << i;
  }
  return bits;
}

// Bit k set when classes[k] is Alike `cls`, for k < 16 n (n <= 4). Sixteen
// at a time with SSE2: |c - cls| from two saturated differences, compared
// with SimilarClasses by a third.
std::uint64_t AlikeBits(const unsigned char* classes, int cls, int n)
{
  std::uint64_t alike = 0;
#if BLUENOISE_SSE2
  const __m128i c = _mm_set1_epi8(static_cast<char>(cls));
  const __m128i most = _mm_set1_epi8(static_cast<char>(vtkBlueNoiseDensityClass::SimilarClasses));
  for (int i = 0; i < 16 * n; i += 16)
  {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(classes + i));
    const __m128i apart = _mm_or_si128(_mm_subs_epu8(v, c), _mm_subs_epu8(c, v));
    const __m128i near = _mm_cmpeq_epi8(_mm_subs_epu8(apart, most), _mm_setzero_si128());
    alike |= static_cast<std::uint64_t>(static_cast<unsigned>(_mm_movemask_epi8(near)) & 0xFFFFu)
      << i;
  }
#else
  for (int k = 0; k < 16 * n; ++k)
  {
    alike |= static_cast<std::uint64_t>(vtkBlueNoiseDensityClass::Alike(classes[k], cls)) << k;
  }
#endif
  return alike;
}

// Whether all n > 0 densities equal the first (as floats do). A block at a
// time, without a branch per density, so that the test vectorizes.
bool Uniform(const float* g, size_t n)
{
  const float first = g[0];
  constexpr size_t block = 256;
  for (size_t i = 0; i < n; i += block)
  {
    const size_t end = std::min(n, i + block);
    int same = 1;
    for (size_t k = i; k < end; ++k)
    {
      same &= g[k] == first;
    }
    if (!same)
    {
      return false;
    }
  }
  return true;
}

// low[i] = min(low[i], lower[i]) and high[i] = max(high[i], higher[i]), i < n.
void LowerAndHigher(unsigned char* __restrict low, unsigned char* __restrict high,
  const unsigned char* __restrict lower, const unsigned char* __restrict higher, size_t n)
{
  for (size_t i = 0; i < n; ++i)
  {
    low[i] = std::min(low[i], lower[i]);
    high[i] = std::max(high[i], higher[i]);
  }
}

// Four floats added and multiplied lane by lane, each lane rounded as a
// float would be (with SSE2 where there is, else a loop).
struct Lanes4
{
#if BLUENOISE_SSE2
  __m128 V;
  static Lanes4 Zero() { return { _mm_setzero_ps() }; }
  static Lanes4 Load(const float* p) { return { _mm_loadu_ps(p) }; }
  static Lanes4 All(float x) { return { _mm_set1_ps(x) }; }
  Lanes4 operator+(const Lanes4& o) const { return { _mm_add_ps(this->V, o.V) }; }
  Lanes4 operator*(const Lanes4& o) const { return { _mm_mul_ps(this->V, o.V) }; }
  void Store(float* p) const { _mm_storeu_ps(p, this->V); }
#else
  float V[4];
  static Lanes4 Zero() { return { { 0.0f, 0.0f, 0.0f, 0.0f } }; }
  static Lanes4 Load(const float* p) { return { { p[0], p[1], p[2], p[3] } }; }
  static Lanes4 All(float x) { return { { x, x, x, x } }; }
  Lanes4 operator+(const Lanes4& o) const
  {
    return { { V[0] + o.V[0], V[1] + o.V[1], V[2] + o.V[2], V[3] + o.V[3] } };
  }
  Lanes4 operator*(const Lanes4& o) const
  {
    return { { V[0] * o.V[0], V[1] * o.V[1], V[2] * o.V[2], V[3] * o.V[3] } };
  }
  void Store(float* p) const { std::copy(this->V, this->V + 4, p); }
#endif
};

inline bool Relaxable(float g)
{
  return g > 0.0f && g <= vtkBlueNoiseRelaxation::MaximumDensity;
}

// Whether any of the n densities is Relaxable: most layers at densities above
// 1/4 have none, and every value is read. Sixteen at a time with SSE2 (the
// compiler does not vectorize the comparisons by itself: they may trap).
bool AnyRelaxable(const float* g, size_t n)
{
  size_t i = 0;
#if BLUENOISE_SSE2
  const __m128 zero = _mm_setzero_ps();
  const __m128 most = _mm_set1_ps(vtkBlueNoiseRelaxation::MaximumDensity);
  for (; i + 16 <= n; i += 16)
  {
    __m128 any = _mm_setzero_ps();
    for (size_t k = i; k < i + 16; k += 4)
    {
      const __m128 four = _mm_loadu_ps(g + k);
      any = _mm_or_ps(any, _mm_and_ps(_mm_cmpgt_ps(four, zero), _mm_cmple_ps(four, most)));
    }
    if (_mm_movemask_ps(any) != 0)
    {
      return true;
    }
  }
#endif
  return std::any_of(g + i, g + n, Relaxable);
}
}

//------------------------------------------------------------------------------
std::uint64_t vtkBlueNoiseRelaxation::OrderKey(std::uint64_t seed, int x, int y, int z)
{
  return Hash(seed, x, y, z) & ~std::uint64_t(0xFFFFFFFF);
}

//------------------------------------------------------------------------------
// Fisher-Yates on the bits of another hash.
void vtkBlueNoiseRelaxation::FaceOrder(std::uint64_t seed, int x, int y, int z, int order[6])
{
  std::uint64_t h = Hash(seed ^ 0x5DEECE66DULL, x, y, z);
  for (int k = 0; k < 6; ++k)
  {
    order[k] = k;
  }
  for (int k = 5; k > 0; --k, h /= 6)
  {
    std::swap(order[k], order[h % static_cast<std::uint64_t>(k + 1)]);
  }
}

//------------------------------------------------------------------------------
void vtkBlueNoiseRelaxation::SetRule(int rule)
{
  const int chosen = rule == RULE_ENERGY ? RULE_ENERGY : RULE_SPACING;
  if (chosen != this->Rule)
  {
    this->Rule = chosen;
    for (Roots& roots : this->RootCache) // made by the other rule
    {
      roots.Density = -1.0f;
    }
    this->LastDensity = -1.0f;
  }
}

//------------------------------------------------------------------------------
int vtkBlueNoiseRelaxation::EnergyStart(std::uint64_t seed, int x, int y, int z)
{
  return static_cast<int>(Hash(seed ^ 0x5DEECE66DULL, x, y, z) % 27);
}

//------------------------------------------------------------------------------
void vtkBlueNoiseRelaxation::Begin(
  int nx, int ny, int firstZ, std::uint64_t seed, int firstMovable)
{
  this->NX = std::max(nx, 0);
  this->NY = std::max(ny, 0);
  // A zero word on either side of a row: the window reads 32 voxels to
  // either side of a sample, and up to one word past the last.
  this->WordsPerRow = (this->NX + 63) / 64 + 2;
  this->First = firstZ;
  this->Last = firstZ - 1;
  this->Relaxed = firstZ;
  this->Movable = firstMovable;
  this->Finalized = firstZ;
  this->Seed = seed;
  this->Moves = 0;
  this->LastDensity = -1.0f;
  const size_t layer = static_cast<size_t>(this->NX) * this->NY;
  const size_t words = static_cast<size_t>(this->WordsPerRow) * (this->NY + 2 * PadRows);
  this->NoSamples.assign(words, 0);
  this->Ring.resize(RingSize);
  for (Slot& slot : this->Ring)
  {
    slot.Z = firstZ - RingSize - 1;
    slot.Bits.assign(words, 0);
  }
  // The planes are made by the first layer that needs them (Push): a run
  // whose first layers are context (a part side by side with the one below
  // it) holds none while it scans them.
  this->Planes.resize(PlaneCount);
  for (Plane& plane : this->Planes)
  {
    plane.Z = firstZ - RingSize - 1;
    if (plane.Density.size() != layer)
    {
      plane = Plane();
    }
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
// The words of row y (-PadRows <= y < NY + PadRows) of a layer's bits; the
// word before the first is there (zero).
inline const std::uint64_t* vtkBlueNoiseRelaxation::Row(const std::uint64_t* bits, int y) const
{
  return bits + this->RowStart(y);
}

inline std::ptrdiff_t vtkBlueNoiseRelaxation::RowStart(int y) const
{
  return static_cast<std::ptrdiff_t>(y + PadRows) * this->WordsPerRow + 1;
}

//------------------------------------------------------------------------------
inline void vtkBlueNoiseRelaxation::Set(int x, int y, int z, bool sample)
{
  Slot* slot = this->Find(z);
  std::uint64_t& word =
    const_cast<std::uint64_t*>(this->Row(slot->Bits.data(), y))[x >> 6];
  const std::uint64_t bit = std::uint64_t(1) << (x & 63);
  word = sample ? (word | bit) : (word & ~bit);
  Plane* plane = this->FindPlane(z);
  plane->Mask[x + static_cast<size_t>(this->NX) * y] = sample ? 1 : 0;
  plane->Count += sample ? 1 : -1; // a move empties a sample's voxel and fills an empty one
}

//------------------------------------------------------------------------------
// The limit, search radius and cap of density g, and the rows searched
// (real volumes repeat densities: the roots and rows are kept while g is).
void vtkBlueNoiseRelaxation::SetDensity(float g)
{
  if (g == this->LastDensity)
  {
    return;
  }
  this->LastDensity = g;
  // Where neighboring samples differ in density (a volume of steps) the
  // root changes from one sample to the next: the last roots are kept, in
  // a table indexed by a hash of the density's bits.
  std::uint32_t bits;
  std::memcpy(&bits, &g, sizeof(bits));
  this->Current = (bits * 0x9E3779B1u) >> (32 - RootCacheBits);
  Roots& roots = this->RootCache[this->Current];
  if (roots.Density != g)
  {
    roots.Density = g;
    if (this->Rule == RULE_ENERGY)
    {
      // The box of the energy, and the window it reads: its rows to Radius + 1.
      roots.Radius = EnergyWeights(g, roots.Weights);
      roots.Cap = 0;
    }
    else
    {
      const double spacing = std::cbrt(1.0 / g);
      roots.Limit = 0.75 * spacing * spacing;
      // Clamped before the conversion to int: tiny densities have a huge spacing.
      roots.Radius = static_cast<int>(
        std::min(std::ceil(0.87 * spacing) + 1.0, static_cast<double>(MaximumRadius)));
      // Only whether a sample is nearer than the limit matters, and nothing
      // beyond the radius can be found.
      roots.Cap = static_cast<int>(std::min(
        std::ceil(roots.Limit), static_cast<double>((roots.Radius + 1) * (roots.Radius + 1))));
    }
    // Each pair of radius and cap gets its rows once.
    RowSet& rows = this->RowSets[static_cast<size_t>(roots.Radius * RowSetCaps + roots.Cap)];
    if (rows.Loaded.empty())
    {
      rows = MakeRows(roots.Radius, roots.Cap);
    }
  }
  this->Limit = roots.Limit;
  this->Radius = roots.Radius;
  this->Cap = roots.Cap;
}

//------------------------------------------------------------------------------
int vtkBlueNoiseRelaxation::EnergyWeights(float g, float weights[2 * MaximumRadius + 3])
{
  const double sigma = EnergySigma * std::cbrt(1.0 / g);
  // Clamped before the conversion to int: tiny densities have a huge spacing.
  const int width = static_cast<int>(
    std::max(1.0, std::min(std::ceil(EnergyBox * sigma), static_cast<double>(MaximumEnergyWidth))));
  for (int d = -MaximumRadius - 1; d <= MaximumRadius + 1; ++d)
  {
    weights[d + MaximumRadius + 1] = std::abs(d) <= width
      ? static_cast<float>(std::exp(-d * d / (2.0 * sigma * sigma)))
      : 0.0f;
  }
  return width;
}

//------------------------------------------------------------------------------
// The rows searched around a sample and its face neighbors, for a search
// radius and cap.
vtkBlueNoiseRelaxation::RowSet vtkBlueNoiseRelaxation::MakeRows(int radius, int cap)
{
  RowSet set;
  if (cap == 0) // the energy rule's: every row within radius + 1, no shells
  {
    for (int dz = -radius - 1; dz <= radius + 1; ++dz)
    {
      set.Loaded.push_back({ dz, -radius - 1, radius + 1 });
    }
    return set;
  }
  const auto searched = [&](int dz, int dy) {
    return std::abs(dz) <= radius && std::abs(dy) <= radius && dz * dz + dy * dy < cap;
  };
  const auto add = [](std::vector<RowRun>& runs, int dz, int dy) {
    if (!runs.empty() && runs.back().DZ == dz && runs.back().High == dy - 1)
    {
      ++runs.back().High;
    }
    else
    {
      runs.push_back({ dz, dy, dy });
    }
  };
  std::vector<std::pair<int, int>> rows; // squared distance and cell of the searched rows
  for (int dz = -radius - 1; dz <= radius + 1; ++dz)
  {
    for (int dy = -radius - 1; dy <= radius + 1; ++dy)
    {
      if (searched(dz, dy))
      {
        rows.emplace_back(dz * dz + dy * dy, dz * Span + dy);
      }
      if (searched(dz, dy) || searched(dz - 1, dy) || searched(dz + 1, dy) ||
        searched(dz, dy - 1) || searched(dz, dy + 1))
      {
        add(set.Loaded, dz, dy);
      }
    }
  }
  std::stable_sort(rows.begin(), rows.end(),
    [](const std::pair<int, int>& a, const std::pair<int, int>& b) { return a.first < b.first; });
  // The rows at one distance are one row turned by quarter turns about the
  // center (the search is symmetric): four of each, but for the center's own
  // row, repeated here so that every shell has four.
  for (size_t k = 0; k < rows.size();)
  {
    const size_t n = rows[k].first == 0 ? 1 : 4;
    Shell shell{ rows[k].first, {} };
    for (size_t i = 0; i < 4; ++i)
    {
      shell.Cells[i] = rows[k + i % n].second;
    }
    set.Shells.push_back(shell);
    k += n;
  }
  return set;
}

//------------------------------------------------------------------------------
// Copies the rows the current density's rule reads around sample (x, y)
// (CurrentRows().Loaded) of the layers in Layers into the window, without
// the sample itself (it is not its own neighbor): bit k of a row is voxel
// x - 32 + k (zero outside the volume).
void vtkBlueNoiseRelaxation::LoadAround(int x, int y)
{
  const int start = x - 32; // from -32: the word before the first is zero
  const int shift = start & 63;
  const std::ptrdiff_t word = this->RowStart(y) + (start >> 6);
  const std::ptrdiff_t stride = this->WordsPerRow;
  for (const RowRun& run : this->CurrentRows().Loaded)
  {
    const std::uint64_t* words = this->Layers[run.DZ + Reach] + word + run.Low * stride;
    std::uint64_t* cell = this->Window + (run.DZ + Reach) * Span + run.Low + Reach;
    for (int n = run.High - run.Low; n >= 0; --n, words += stride, ++cell)
    {
      // The second word's part in two shifts: one by 64 - shift would be
      // undefined for shift = 0.
      *cell = (words[0] >> shift) | ((words[1] << 1) << (63 - shift));
    }
  }
  this->Window[Reach * Span + Reach] &= ~(std::uint64_t(1) << 32);
}

//------------------------------------------------------------------------------
// The classes of a layer's densities (DensityClass) into `slot`: the lowest
// and highest of the positive ones per word and in all, and each voxel's
// when they differ. A layer of one density (the test is cheap) is done at
// once; the others in loops the compiler vectorizes.
void vtkBlueNoiseRelaxation::Classify(Slot& slot, const float* density)
{
  const size_t layer = static_cast<size_t>(this->NX) * this->NY;
  if (layer == 0 || Uniform(density, layer))
  {
    const int c = layer == 0 ? 0 : vtkBlueNoiseDensityClass::Of(density[0]);
    slot.Low = c == 0 ? 255 : c;
    slot.High = c;
    slot.WordLow.assign(slot.Bits.size(), static_cast<unsigned char>(slot.Low));
    slot.WordHigh.assign(slot.Bits.size(), static_cast<unsigned char>(slot.High));
    std::vector<unsigned char>().swap(slot.Classes);
    slot.Full = c != 0;
    slot.Support.assign(slot.Full ? 0 : slot.Bits.size(), 0);
    return;
  }
  this->ClassScratch.resize(layer);
  unsigned char* classes = this->ClassScratch.data();
  vtkBlueNoiseDensityClass::OfEach(density, layer, classes);
  slot.WordLow.assign(slot.Bits.size(), 255);
  slot.WordHigh.assign(slot.Bits.size(), 0);
  slot.Full = std::all_of(classes, classes + layer, [](unsigned char c) { return c != 0; });
  slot.Support.assign(slot.Full ? 0 : slot.Bits.size(), 0);
  int low = 255, high = 0;
  for (int y = 0; y < this->NY; ++y)
  {
    const unsigned char* row = classes + static_cast<size_t>(y) * this->NX;
    for (int x0 = 0; x0 < this->NX; x0 += 64)
    {
      const int x1 = std::min(this->NX, x0 + 64);
      // The lowest positive class as 1 + the lowest of c - 1 in bytes,
      // where 0 wraps to 255: no branch on c.
      unsigned char below = 255, hi = 0;
      for (int x = x0; x < x1; ++x)
      {
        const unsigned char c = row[x];
        below = std::min(below, static_cast<unsigned char>(c - 1));
        hi = std::max(hi, c);
      }
      const std::ptrdiff_t word = this->RowStart(y) + (x0 >> 6);
      if (!slot.Full)
      {
        slot.Support[word] = PackBits(row + x0, x1 - x0);
      }
      slot.WordLow[word] = static_cast<unsigned char>(hi ? below + 1 : 255);
      slot.WordHigh[word] = hi;
      low = std::min<int>(low, slot.WordLow[word]);
      high = std::max<int>(high, hi);
    }
  }
  slot.Low = low;
  slot.High = high;
  if (low < high)
  {
    slot.Classes.swap(this->ClassScratch); // the slot's old buffer is the next scratch
  }
  else
  {
    std::vector<unsigned char>().swap(slot.Classes); // one class: no copy kept
  }
}

//------------------------------------------------------------------------------
// Whether the layer relaxed has samples of dissimilar densities within
// reach of one another (Mixed), or of densities of more than one region
// (RegionMixed); if so, per row and word the lowest and highest class within
// Reach rows and layers (MixedLow, MixedHigh).
void vtkBlueNoiseRelaxation::FindMixed()
{
  int low = 255, high = 0;
  bool full = true;
  for (const Slot* slot : this->Slots)
  {
    if (slot)
    {
      low = std::min(low, slot->Low);
      high = std::max(high, slot->High);
    }
    full = full && (!slot || slot->Full);
  }
  this->Mixed = low <= high && !vtkBlueNoiseDensityClass::Alike(low, high);
  this->RegionMixed = low <= high && !Within(low, high, RegionClasses);
  this->Whole = full && !this->RegionMixed;
  if (!this->Mixed && !this->RegionMixed)
  {
    return;
  }
  // Byte loops over raw pointers, innermost along the words: stores through
  // the vectors' own would be reloads of their data at every byte (a char
  // may alias anything), and no loop would vectorize.
  const size_t words = this->NoSamples.size();
  this->MixedLayersLow.assign(words, 255); // over the layers
  this->MixedLayersHigh.assign(words, 0);
  unsigned char* low1 = this->MixedLayersLow.data();
  unsigned char* high1 = this->MixedLayersHigh.data();
  for (const Slot* slot : this->Slots)
  {
    if (slot)
    {
      LowerAndHigher(low1, high1, slot->WordLow.data(), slot->WordHigh.data(), words);
    }
  }
  this->MixedLow.assign(words, 255);
  this->MixedHigh.assign(words, 0);
  unsigned char* rowLow = this->MixedLow.data();
  unsigned char* rowHigh = this->MixedHigh.data();
  const std::ptrdiff_t stride = this->WordsPerRow;
  for (int y = 0; y < this->NY; ++y) // and over the rows
  {
    const std::ptrdiff_t start = this->RowStart(y) - 1;
    for (int dy = -Reach; dy <= Reach; ++dy)
    {
      const std::ptrdiff_t from = start + dy * stride;
      LowerAndHigher(rowLow + start, rowHigh + start, low1 + from, high1 + from, stride);
    }
  }
}

//------------------------------------------------------------------------------
// Whether a sample of class `cls` at (x, y) of the layer relaxed may have
// densities whose classes differ from its own by more than `classes` within
// reach.
inline bool vtkBlueNoiseRelaxation::MixedAround(int x, int y, int cls, int classes) const
{
  const std::ptrdiff_t row = this->RowStart(y);
  const std::ptrdiff_t a = row + ((x - Reach) >> 6), b = row + ((x + Reach) >> 6);
  const int lo = std::min(this->MixedLow[a], this->MixedLow[b]);
  const int hi = std::max(this->MixedHigh[a], this->MixedHigh[b]);
  return !Within(lo, cls, classes) || !Within(hi, cls, classes);
}

//------------------------------------------------------------------------------
// For a sample of class `cls` at (x, y): whether all positive densities
// within reach are similar to its own (`counted`: KeepSimilar has nothing to
// clear) and in its region (`region`: only the support ends a line).
inline void vtkBlueNoiseRelaxation::Alikeness(int x, int y, int cls, bool& counted, bool& region) const
{
  counted = !this->Mixed || !this->MixedAround(x, y, cls, vtkBlueNoiseDensityClass::SimilarClasses);
  region = !this->RegionMixed || !this->MixedAround(x, y, cls, RegionClasses);
}

//------------------------------------------------------------------------------
// Clears from the window's `runs` of rows around (x, y) the samples whose
// class is dissimilar to `cls`, and those beyond the search along x (Radius
// + 1, where Nearest puts its sentinel).
void vtkBlueNoiseRelaxation::KeepSimilar(const std::vector<RowRun>& runs, int x, int y, int cls)
{
  const int span = this->Radius + 1;
  const std::uint64_t reach = ((std::uint64_t(1) << (2 * span + 1)) - 1) << (32 - span);
  // The classes read: of voxels x - 8 ... x + 7, or x - 16 ... x + 15 for
  // the widest searches (bits 32 - span ... 32 + span are all that are kept).
  static_assert(MaximumRadius + 1 <= 16, "a search wider than the classes read");
  const int blocks = span <= 8 ? 1 : 2;
  const int from = 32 - 8 * blocks;
  for (const RowRun& run : runs)
  {
    const Slot* slot = this->Slots[run.DZ + Reach];
    std::uint64_t* cell = this->Window + (run.DZ + Reach) * Span + run.Low + Reach;
    for (int dy = run.Low; dy <= run.High; ++dy, ++cell)
    {
      std::uint64_t bits = *cell & reach;
      if (!slot || slot->Classes.empty())
      {
        *cell = slot && vtkBlueNoiseDensityClass::Alike(slot->Low, cls) ? bits : 0;
        continue;
      }
      if (!bits)
      {
        continue;
      }
      const std::ptrdiff_t first = static_cast<std::ptrdiff_t>(y + dy) * this->NX + (x - 32);
      if (first + from >= 0 &&
        first + from + 16 * blocks <= static_cast<std::ptrdiff_t>(slot->Classes.size()))
      {
        *cell = bits & (AlikeBits(slot->Classes.data() + first + from, cls, blocks) << from);
        continue;
      }
      for (std::uint64_t left = bits; left; left &= left - 1) // near the layer's ends
      {
        const int k = __builtin_ctzll(left);
        if (!vtkBlueNoiseDensityClass::Alike(slot->Classes[first + k], cls))
        {
          bits &= ~(std::uint64_t(1) << k);
        }
      }
      *cell = bits;
    }
  }
}

//------------------------------------------------------------------------------
// The squared distance from the voxel at offset (fx, fy, fz) of the window's
// center to the nearest sample in the window within Radius along each axis,
// or Cap when none is nearer; where there are many shells of rows (below),
// as soon as one at `enough` or nearer is found, that one (any answer of
// `enough` or less means the same to the callers). The four rows of a shell
// are at the same distance: the nearest sample in any of them is the nearest
// in their union, the nearer of its first set bits on either side of the
// voxel (a sentinel bit at Radius + 1 stands for none). Few shells (at the
// densities that cost most) are all visited, as a stop after one or another
// is a branch no predictor learns; many are visited nearest first, and no
// further once they cannot hold anything nearer than the best so far.
int vtkBlueNoiseRelaxation::Nearest(int fx, int fy, int fz, int enough) const
{
  const int center = 32 + fx;
  const std::uint64_t right = std::uint64_t(1) << (this->Radius + 1);
  const std::uint64_t left = std::uint64_t(1) << (62 - this->Radius);
  const std::uint64_t* window = this->Window + (fz + Reach) * Span + fy + Reach;
  const auto distance = [&](const Shell& shell) {
    const int* cell = shell.Cells;
    const std::uint64_t bits = window[cell[0]] | window[cell[1]] | window[cell[2]] | window[cell[3]];
    const int dx = std::min(
      __builtin_ctzll((bits >> center) | right), __builtin_clzll((bits << (63 - center)) | left));
    return dx * dx + shell.Squared;
  };
  int best = this->Cap;
  const std::vector<Shell>& shells = this->CurrentRows().Shells;
  const bool every = shells.size() <= EveryShell;
  for (const Shell& shell : shells)
  {
    if (!every && (shell.Squared >= best || best <= enough))
    {
      break;
    }
    best = std::min(best, distance(shell));
  }
  return best;
}

//------------------------------------------------------------------------------
// Bit f set when face neighbor f of (x, y) in the window's layer is no place
// to move to: outside the volume, in a layer that is final, or a sample.
inline unsigned vtkBlueNoiseRelaxation::BlockedFaces(int x, int y) const
{
  const std::uint64_t* center = this->Window + Reach * Span + Reach;
  const auto bit = [](std::uint64_t row, int k) { return static_cast<unsigned>((row >> k) & 1); };
  // Faces in the order of the table Faces: +x, -x, +y, -y, +z, -z.
  const unsigned occupied = bit(center[0], 33) | bit(center[0], 31) << 1 | bit(center[1], 32) << 2 |
    bit(center[-1], 32) << 3 | bit(center[Span], 32) << 4 | bit(center[-Span], 32) << 5;
  const unsigned outside = static_cast<unsigned>(x + 1 >= this->NX) |
    static_cast<unsigned>(x == 0) << 1 | static_cast<unsigned>(y + 1 >= this->NY) << 2 |
    static_cast<unsigned>(y == 0) << 3 | static_cast<unsigned>(!this->Densities[2]) << 4 |
    static_cast<unsigned>(!this->Densities[0]) << 5;
  return occupied | outside;
}

//------------------------------------------------------------------------------
// Whether voxel (x, y), in the volume, is of positive density in the layer
// of `slot`.
inline bool vtkBlueNoiseRelaxation::Supported(const Slot* slot, int x, int y) const
{
  return slot->Full || ((this->Row(slot->Support.data(), y)[x >> 6] >> (x & 63)) & 1);
}

//------------------------------------------------------------------------------
// Whether voxel (x, y) of layer z + dz (z the layer relaxed, |dz| <= Reach)
// is in the region of class `cls`: in the volume (in the run's layers), of
// positive density, of a class alike.
inline bool vtkBlueNoiseRelaxation::InRegion(int x, int y, int dz, int cls) const
{
  const Slot* slot = this->Slots[dz + Reach];
  if (!slot || x < 0 || y < 0 || x >= this->NX || y >= this->NY)
  {
    return false;
  }
  if (!this->Supported(slot, x, y))
  {
    return false;
  }
  const int c = slot->Classes.empty() ? slot->Low : slot->Classes[x + static_cast<size_t>(this->NX) * y];
  return Within(c, cls, RegionClasses);
}

//------------------------------------------------------------------------------
// Whether the voxels along face f's axis within Radius of sample (x, y) of
// the layer relaxed and of its neighbor there (Radius + 1 on the face's side,
// Radius on the other) are all in the region of class `cls`. Where every
// voxel of positive density within Reach is of a class alike (`alike`), only
// the volume, the run's layers and the densities' support can end the line:
// LineSupported reads those a word or a bit at a time.
bool vtkBlueNoiseRelaxation::LineInRegion(int x, int y, int face, int cls, bool alike) const
{
  if (alike)
  {
    return this->LineSupported(x, y, face);
  }
  const int* f = Faces[face];
  const int r = this->Radius;
  for (int t = -r; t <= r + 1; ++t)
  {
    if (!this->InRegion(x + t * f[0], y + t * f[1], t * f[2], cls))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// LineInRegion without the classes: the line in the volume (in the run's
// layers) and of positive densities only.
bool vtkBlueNoiseRelaxation::LineSupported(int x, int y, int face) const
{
  const int* f = Faces[face];
  const int axis = f[0] != 0 ? 0 : (f[1] != 0 ? 1 : 2);
  const int sign = f[axis];
  const int r = this->Radius;
  // The line's ends along its axis, from the sample (0 at the sample).
  const int low = sign > 0 ? -r : -r - 1;
  const int high = sign > 0 ? r + 1 : r;
  const Slot* center = this->Slots[Reach];
  if (axis == 2)
  {
    for (int dz = low; dz <= high; ++dz)
    {
      const Slot* slot = this->Slots[dz + Reach];
      if (!slot || !this->Supported(slot, x, y))
      {
        return false;
      }
    }
    return true;
  }
  if (axis == 1)
  {
    if (y + low < 0 || y + high >= this->NY)
    {
      return false;
    }
    for (int dy = low; dy <= high; ++dy)
    {
      if (!this->Supported(center, x, y + dy))
      {
        return false;
      }
    }
    return true;
  }
  const int from = x + low, to = x + high;
  if (from < 0 || to >= this->NX)
  {
    return false;
  }
  if (center->Full)
  {
    return true;
  }
  const std::uint64_t* row = this->Row(center->Support.data(), y);
  for (int w = from >> 6; w <= to >> 6; ++w) // the bits from..to, a word at a time
  {
    const int first = std::max(from, 64 * w) - 64 * w;
    const int last = std::min(to, 64 * w + 63) - 64 * w;
    const std::uint64_t mask = (~std::uint64_t(0) >> (63 - last)) & (~std::uint64_t(0) << first);
    if ((row[w] & mask) != mask)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Bit f set when the line of face f (LineInRegion) leaves the region, where
// the layers in reach are whole (Whole): only the volume's faces along x and
// y and the run's layers (consecutive: the two ends tell) can end it.
inline unsigned vtkBlueNoiseRelaxation::BandFaces(int x, int y) const
{
  const int r = this->Radius;
  // The line from p - r to p + r + 1 (towards +) or p - r - 1 to p + r (-).
  const auto up = [r](int p, int n) { return static_cast<unsigned>(p - r < 0 || p + r + 1 >= n); };
  const auto down = [r](int p, int n) { return static_cast<unsigned>(p - r - 1 < 0 || p + r >= n); };
  const Slot* const* s = this->Slots + Reach;
  const unsigned zUp = !s[-r] || !s[r + 1];
  const unsigned zDown = !s[-r - 1] || !s[r];
  // Faces in the order of the table Faces: +x, -x, +y, -y, +z, -z.
  return up(x, this->NX) | down(x, this->NX) << 1 | up(y, this->NY) << 2 |
    down(y, this->NY) << 3 | zUp << 4 | zDown << 5;
}

//------------------------------------------------------------------------------
// Bit f set when face neighbor f has a sample other than this one at squared
// distance `reach` (1 or 2) or less: it cannot be farther from the others than
// this sample is when its nearest other sample is at `reach` or more. Most
// candidates are like that at densities above 1/8, where a neighborhood
// search each cost most of the pass. (For reach 2 the rows one away in both y
// and z are in the window: the sample's own search reads them at such
// densities.)
inline unsigned vtkBlueNoiseRelaxation::CrowdedFaces(int reach) const
{
  unsigned crowded = 0;
  for (int face = 0; face < 6; ++face)
  {
    const int* f = Faces[face];
    const std::uint64_t* c = this->Window + (f[2] + Reach) * Span + f[1] + Reach;
    const int bit = 32 + f[0];
    const std::uint64_t across = c[1] | c[-1] | c[Span] | c[-Span];
    std::uint64_t near = ((c[0] >> (bit - 1)) & 5) | ((across >> bit) & 1); // distance 1
    if (reach >= 2)
    {
      const std::uint64_t diagonal = c[Span + 1] | c[Span - 1] | c[1 - Span] | c[-1 - Span];
      near |= ((across >> (bit - 1)) & 5) | ((diagonal >> bit) & 1); // distance sqrt(2)
    }
    crowded |= static_cast<unsigned>(near != 0) << face;
  }
  return crowded;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseRelaxation::RelaxSample(int x, int y, int z, float g)
{
  this->SetDensity(g);
  if (this->Rule == RULE_ENERGY)
  {
    this->MoveByEnergy(x, y, z, g);
  }
  else
  {
    this->MoveBySpacing(x, y, z, g);
  }
}

//------------------------------------------------------------------------------
// The sample at (x, y, z) moves by the voxel (dx, dy, dz), once for all.
void vtkBlueNoiseRelaxation::Move(int x, int y, int z, int dx, int dy, int dz)
{
  const int X = x + dx, Y = y + dy, Z = z + dz;
  this->Set(x, y, z, false);
  this->Set(X, Y, Z, true);
  this->FindPlane(Z)->Moved[X + static_cast<size_t>(this->NX) * Y] = 1;
  ++this->Moves;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseRelaxation::MoveBySpacing(int x, int y, int z, float g)
{
  const std::vector<RowRun>& loaded = this->CurrentRows().Loaded;
  this->LoadAround(x, y);
  int current = this->Nearest(0, 0, 0, -1);
  if (current >= this->Limit)
  {
    return; // with samples of other densities in view: without them too
  }
  const int cls = vtkBlueNoiseDensityClass::Of(g); // of its region
  // Where densities are mixed, the samples of other densities leave the
  // window. None of them fills a voxel the sample may move to: that voxel's
  // density is within DensityTolerance of the sample's, so of a similar class.
  bool alike, region;
  this->Alikeness(x, y, cls, alike, region);
  if (!alike)
  {
    this->KeepSimilar(loaded, x, y, cls);
    current = this->Nearest(0, 0, 0, -1);
    if (current >= this->Limit)
    {
      return;
    }
  }
  // Only to a voxel of nearly the same density: along a density gradient a
  // rule by distance moves samples one way more than the other (with a
  // tolerance of 1/8: 3 % fewer points in the sparse end slab of a ramp).
  int best = current;
  int target = -1;
  const unsigned open = ~(this->BlockedFaces(x, y) | this->CrowdedFaces(std::min(current, 2)) |
                          (this->Whole ? this->BandFaces(x, y) : 0u)) & 0x3Fu;
  if (!open)
  {
    return; // often so where samples are dense
  }
  // The order matters only among two or more open faces: one alone is
  // asked without drawing it.
  int order[6];
  const int faces = (open & (open - 1)) == 0 ? 1 : 6;
  if (faces == 1)
  {
    order[0] = __builtin_ctz(open);
  }
  else
  {
    FaceOrder(this->Seed, x, y, z, order);
  }
  for (int k = 0; k < faces; ++k)
  {
    const int face = order[k];
    if (!((open >> face) & 1))
    {
      continue;
    }
    const int* f = Faces[face];
    const int X = x + f[0], Y = y + f[1];
    const float* density = this->Densities[f[2] + 1];
    const float gc = density[X + static_cast<size_t>(this->NX) * Y];
    if (!Relaxable(gc) || std::abs(gc - g) > DensityTolerance * g ||
      (!this->Whole && !this->LineInRegion(x, y, face, cls, region)))
    {
      continue;
    }
    // A candidate with a sample as near as the best so far cannot win.
    const int d = this->Nearest(f[0], f[1], f[2], best);
    if (d > best)
    {
      best = d;
      target = face;
      if (best >= this->Cap)
      {
        break;
      }
    }
  }
  if (target >= 0)
  {
    this->Move(x, y, z, Faces[target][0], Faces[target][1], Faces[target][2]);
  }
}

//------------------------------------------------------------------------------
// The energy at the window's center and its 26 neighbors, at index (dz + 1)
// 9 + (dy + 1) 3 + dx + 1 for the neighbor (dx, dy, dz): over the samples
// in the window within Radius + 1 of the center along each axis, the sum of
// w(dx') w(dy') w(dz') (Weights; (dx', dy', dz') a sample's offset from the
// neighbor), in float, in the order the header gives.
void vtkBlueNoiseRelaxation::Energies(float energy[27]) const
{
  const int reach = this->Radius + 1;
  // w[d], |d| <= MaximumRadius + 1; even, so a row's sample at sx adds to the
  // neighbors dx = -1, 0, 1 the four weights from w[-sx - 1] on (the fourth,
  // of no neighbor, is carried along for four lanes at a time).
  const float* w = this->RootCache[this->Current].Weights + MaximumRadius + 1;
  const std::uint64_t keep = ((std::uint64_t(1) << (2 * reach + 1)) - 1) << (32 - reach);
  Lanes4 sums[3][3]; // by dz + 1, dy + 1; lanes by dx + 1
  std::fill(&sums[0][0], &sums[0][0] + 9, Lanes4::Zero());
  for (int dz = -reach; dz <= reach; ++dz)
  {
    // The rows of the layer with samples within reach, found without a
    // branch per row (most rows have none, and which ones is not
    // predictable), then visited in order.
    const std::uint64_t* rows = this->Window + (dz + Reach) * Span + Reach;
    std::uint32_t full = 0; // bit dy + reach
    for (int dy = -reach; dy <= reach; ++dy)
    {
      full |= static_cast<std::uint32_t>((rows[dy] & keep) != 0) << (dy + reach);
    }
    if (!full)
    {
      continue;
    }
    Lanes4 layer[3] = { Lanes4::Zero(), Lanes4::Zero(), Lanes4::Zero() }; // by dy + 1
    for (; full; full &= full - 1)
    {
      const int dy = __builtin_ctz(full) - reach;
      Lanes4 row = Lanes4::Zero(); // over the row's samples
      for (std::uint64_t bits = rows[dy] & keep; bits; bits &= bits - 1)
      {
        row = row + Lanes4::Load(w - (__builtin_ctzll(bits) - 32) - 1);
      }
      for (int ey = 0; ey < 3; ++ey)
      {
        layer[ey] = layer[ey] + Lanes4::All(w[dy - ey + 1]) * row;
      }
    }
    for (int ez = 0; ez < 3; ++ez)
    {
      const Lanes4 wz = Lanes4::All(w[dz - ez + 1]);
      for (int ey = 0; ey < 3; ++ey)
      {
        sums[ez][ey] = sums[ez][ey] + wz * layer[ey];
      }
    }
  }
  for (int ez = 0; ez < 3; ++ez)
  {
    for (int ey = 0; ey < 3; ++ey)
    {
      float lanes[4];
      sums[ez][ey].Store(lanes);
      std::copy(lanes, lanes + 3, energy + 9 * ez + 3 * ey);
    }
  }
}

//------------------------------------------------------------------------------
void vtkBlueNoiseRelaxation::MoveByEnergy(int x, int y, int z, float g)
{
  this->LoadAround(x, y);
  const int cls = vtkBlueNoiseDensityClass::Of(g);
  bool alike, region;
  this->Alikeness(x, y, cls, alike, region);
  if (!alike)
  {
    this->KeepSimilar(this->CurrentRows().Loaded, x, y, cls);
  }
  float energy[27];
  this->Energies(energy);
  // The neighbors below (1 - EnergyMargin) E(p) (a move must lower the
  // energy by more than the sums' rounding), the lowest first and among
  // equals the first in the order from `start`: the first one the sample may
  // move to is its target. Each lowest is found without a branch on the
  // energies, which come in no order a branch could learn.
  const float limit = energy[13] * (1.0f - EnergyMargin);
  const int start = EnergyStart(this->Seed, x, y, z);
  unsigned left = ((1u << 27) - 1) & ~(1u << 13);
  // The faces' rule, asked as needed; where the layers in reach are whole,
  // at once from the band's faces.
  FaceLines open;
  if (this->Whole)
  {
    open.Known = 0x3F;
    open.Open = ~this->BandFaces(x, y) & 0x3Fu;
  }
  for (;;)
  {
    int target = -1;
    float low = limit;
    for (int n = 0; n < 27; ++n)
    {
      const int k = start + n < 27 ? start + n : start + n - 27;
      const bool lower = ((left >> k) & 1) && energy[k] < low;
      low = lower ? energy[k] : low;
      target = lower ? k : target;
    }
    if (target < 0)
    {
      return;
    }
    const int d[3] = { target % 3 - 1, target / 3 % 3 - 1, target / 9 - 1 };
    if (this->EnergyTargetOpen(x, y, g, d, cls, region, open))
    {
      this->Move(x, y, z, d[0], d[1], d[2]);
      return;
    }
    left &= ~(1u << target);
  }
}

//------------------------------------------------------------------------------
// Whether the sample at (x, y) of the layer relaxed, of density g and class
// `cls`, may move by d: into the volume, a layer not final, an empty voxel
// of a density within DensityTolerance, and along each axis d has open by
// the faces' rule (what `open` has not asked yet, asked and kept there).
bool vtkBlueNoiseRelaxation::EnergyTargetOpen(
  int x, int y, float g, const int d[3], int cls, bool region, FaceLines& open) const
{
  const int X = x + d[0], Y = y + d[1];
  const float* density = this->Densities[d[2] + 1];
  if (X < 0 || Y < 0 || X >= this->NX || Y >= this->NY || !density ||
    ((this->Window[(d[2] + Reach) * Span + d[1] + Reach] >> (32 + d[0])) & 1))
  {
    return false; // outside the volume, in a final layer, or a sample
  }
  const float gc = density[X + static_cast<size_t>(this->NX) * Y];
  if (!Relaxable(gc) || std::abs(gc - g) > DensityTolerance * g)
  {
    return false;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    if (d[axis] != 0)
    {
      const int face = 2 * axis + (d[axis] < 0 ? 1 : 0);
      if (!((open.Known >> face) & 1))
      {
        open.Known |= 1u << face;
        open.Open |= static_cast<unsigned>(this->LineInRegion(x, y, face, cls, region)) << face;
      }
      if (!((open.Open >> face) & 1))
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// Asks the cache for what RelaxLayer and RelaxSample will read around voxel
// (x, y) of the layer being relaxed (`plane`): the densities of 11 layers do
// not fit in the second level cache of 2 MiB at 256^2 voxels a layer.
void vtkBlueNoiseRelaxation::Prefetch(int x, int y, const Plane& plane)
{
  const int reach = 2; // the rows of the nearest neighbors at the densities that cost most
  const std::ptrdiff_t word = this->RowStart(y) + (x >> 6);
  for (int dz = -reach; dz <= reach; ++dz)
  {
    for (int dy = -reach; dy <= reach; ++dy)
    {
      __builtin_prefetch(this->Layers[dz + Reach] + word + dy * this->WordsPerRow);
    }
  }
  const size_t i = x + static_cast<size_t>(this->NX) * y;
  for (const float* density : this->Densities) // the candidates' densities
  {
    if (density)
    {
      __builtin_prefetch(density + i);
    }
  }
  __builtin_prefetch(plane.Density.data() + (y > 0 ? i - this->NX : i));
  __builtin_prefetch(plane.Density.data() + (y + 1 < this->NY ? i + this->NX : i));
  __builtin_prefetch(plane.Mask.data() + i);
  __builtin_prefetch(plane.Moved.data() + i);
}

//------------------------------------------------------------------------------
// Order by the keys' high 32 bits, ties in the order given: a least
// significant digit radix sort, a byte a pass.
void vtkBlueNoiseRelaxation::SortOrder()
{
  const size_t n = this->Order.size();
  size_t counts[4][257] = {};
  for (const std::uint64_t key : this->Order)
  {
    for (int pass = 0; pass < 4; ++pass)
    {
      ++counts[pass][((key >> (32 + 8 * pass)) & 0xFF) + 1];
    }
  }
  this->Scratch.resize(n);
  for (int pass = 0; pass < 4; ++pass)
  {
    size_t* start = counts[pass];
    for (int b = 0; b < 256; ++b)
    {
      start[b + 1] += start[b];
    }
    for (const std::uint64_t key : this->Order)
    {
      this->Scratch[start[(key >> (32 + 8 * pass)) & 0xFF]++] = key;
    }
    this->Order.swap(this->Scratch);
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
  for (int dz = -Reach; dz <= Reach; ++dz)
  {
    const Slot* near = this->Find(z + dz);
    this->Layers[dz + Reach] = near ? near->Bits.data() : this->NoSamples.data();
    this->Slots[dz + Reach] = near;
  }
  this->FindMixed();
  for (int dz = -1; dz <= 1; ++dz) // where samples may move to
  {
    const Plane* near = z + dz >= this->Finalized ? this->FindPlane(z + dz) : nullptr;
    this->Densities[dz + 1] = near ? near->Density.data() : nullptr;
  }
  const int words = (this->NX + 63) / 64;
  for (int y = 0; y < this->NY; ++y) // the samples, through the bits
  {
    const std::uint64_t* row = this->Row(slot->Bits.data(), y);
    for (int w = 0; w < words; ++w)
    {
      for (std::uint64_t bits = row[w]; bits; bits &= bits - 1)
      {
        const int x = 64 * w + __builtin_ctzll(bits);
        const size_t i = x + static_cast<size_t>(this->NX) * y;
        if (!plane->Moved[i] && Relaxable(plane->Density[i]))
        {
          this->Order.push_back(OrderKey(this->Seed, x, y, z) | i);
        }
      }
    }
  }
  this->SortOrder();
  const auto nx = static_cast<std::uint32_t>(this->NX);
  const size_t ahead = 4; // samples: far enough for the rows to arrive
  for (size_t k = 0; k < this->Order.size(); ++k)
  {
    if (k + ahead < this->Order.size())
    {
      const auto i = static_cast<std::uint32_t>(this->Order[k + ahead]);
      this->Prefetch(static_cast<int>(i % nx), static_cast<int>(i / nx), *plane);
    }
    const auto i = static_cast<std::uint32_t>(this->Order[k]);
    // An earlier move may have taken this sample away, or put one here.
    if (plane->Mask[i] && !plane->Moved[i])
    {
      this->RelaxSample(static_cast<int>(i % nx), static_cast<int>(i / nx), z, plane->Density[i]);
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
  layer.Count = plane->Count;
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
  const size_t layer = static_cast<size_t>(this->NX) * this->NY;
  slot.Relaxable = z >= this->Movable && AnyRelaxable(density, layer);
  std::fill(slot.Bits.begin(), slot.Bits.end(), 0);
  vtkIdType count = 0;
  for (int y = 0; y < this->NY; ++y)
  {
    const unsigned char* row = mask + static_cast<size_t>(y) * this->NX;
    auto* words = const_cast<std::uint64_t*>(this->Row(slot.Bits.data(), y));
    for (int x0 = 0; x0 < this->NX; x0 += 64)
    {
      words[x0 >> 6] = PackBits(row + x0, std::min(64, this->NX - x0));
      count += __builtin_popcountll(words[x0 >> 6]);
    }
  }
  this->Classify(slot, density);
  if (!slot.Relaxable && this->Relaxed == z && this->Finalized == z)
  {
    // No layer before it waits, and no sample moves into or out of it: it is
    // final as it came (densities above 1/4, or none), without a copy.
    this->Relaxed = this->Finalized = z + 1;
    this->Done.push_back({ z, density, mask, count, true });
    return this->Done;
  }
  Plane& plane = this->Planes[static_cast<size_t>(z - this->First) % PlaneCount];
  if (plane.Density.size() != layer)
  {
    plane.Density.resize(layer);
    plane.Mask.resize(layer);
    plane.Moved.resize(layer);
  }
  plane.Z = z;
  plane.Count = count;
  std::copy(density, density + layer, plane.Density.begin());
  std::copy(mask, mask + layer, plane.Mask.begin());
  std::fill(plane.Moved.begin(), plane.Moved.end(), 0);
  this->RelaxReady();
  return this->Done;
}

//------------------------------------------------------------------------------
// Relaxes the layers whose neighbors are all in (a layer no sample may move in
// needs none), and returns those that became final: the one below each layer
// relaxed, and a layer no sample may move in as soon as all before it are.
void vtkBlueNoiseRelaxation::RelaxReady()
{
  for (; this->Relaxed <= this->Last; ++this->Relaxed)
  {
    const bool relaxable = this->Find(this->Relaxed)->Relaxable;
    if (relaxable && this->Relaxed + MaximumRadius > this->Last)
    {
      break;
    }
    this->RelaxLayer(this->Relaxed);
    if (this->Relaxed - 1 >= this->Finalized)
    {
      this->Release(this->Relaxed - 1);
    }
    if (!relaxable && this->Relaxed == this->Finalized)
    {
      this->Release(this->Relaxed);
    }
  }
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
