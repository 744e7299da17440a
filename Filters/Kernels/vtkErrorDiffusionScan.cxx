// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionScan.h"
#include "vtkBlueNoiseDensityClass.h"
#include "vtkBlueNoiseSSE2.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace
{
// In-layer directions (dx, dy) of u and v for the four phases of a cycle:
// each phase is the previous one turned by 90 degrees.
const int PhaseU[4][2] = { { 1, 0 }, { 0, 1 }, { -1, 0 }, { 0, -1 } };
const int PhaseV[4][2] = { { 0, 1 }, { -1, 0 }, { 0, -1 }, { 1, 0 } };

// The row stride of the error buffers: nx rounded up to whole 64-byte lines
// and then to an odd number of them. A scan along y steps by the stride, and
// with a power-of-two stride (nx = 512: 2 kB) its voxels fall into a few
// cache sets and evict each other before the next row reuses them.
vtkIdType ErrorPitch(int nx)
{
  constexpr vtkIdType line = 64 / sizeof(float);
  const vtkIdType lines = (nx + line - 1) / line;
  return (lines % 2 == 0 ? lines + 1 : lines) * line;
}

int PositiveModulo4(int i)
{
  return ((i % 4) + 4) % 4;
}

// A voxel that takes part in the diffusion: 0 < g < 1. Saturated voxels (and
// NaN) have a fixed outcome, so error sent to them would be lost.
inline bool Active(float g)
{
  return g > 0.0f && g < 1.0f;
}

// The parameter table is indexed by the top 17 bits of min(g, 1 - g) as a
// float (sign, exponent and 8 bits of mantissa): 2^-8 relative steps of the
// density from 2^-20 (below which the parameters no longer change) to 0.5.
constexpr int ParameterShift = 15;
std::uint32_t FloatBits(float f)
{
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof(bits));
  return bits;
}
float BitsFloat(std::uint32_t bits)
{
  float f = 0.0f;
  std::memcpy(&f, &bits, sizeof(f));
  return f;
}
const std::uint32_t ParameterBase = FloatBits(0x1p-20f) >> ParameterShift;
const size_t ParameterEntries = (FloatBits(0.5f) >> ParameterShift) - ParameterBase + 1;

size_t ParameterIndex(float minority)
{
  const std::uint32_t key = FloatBits(minority) >> ParameterShift;
  return key <= ParameterBase ? 0 : std::min<size_t>(key - ParameterBase, ParameterEntries - 1);
}

// The density an entry stands for: the middle of its bucket (0.5 for the last).
float ParameterDensity(size_t index)
{
  if (index + 1 == ParameterEntries)
  {
    return 0.5f;
  }
  return BitsFloat(static_cast<std::uint32_t>((index + ParameterBase) << ParameterShift) |
    (1u << (ParameterShift - 1)));
}
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionScan::Generator::Seed(std::uint64_t seed, std::uint64_t stream)
{
  // PCG32 initialization (O'Neill 2014): any seed gives a full-period stream.
  this->State = 0;
  this->Increment = (stream << 1u) | 1u;
  this->Uniform();
  this->State += seed;
  this->Uniform();
}

//------------------------------------------------------------------------------
inline float vtkErrorDiffusionScan::Generator::Uniform()
{
  const std::uint64_t old = this->State;
  this->State = old * 6364136223846793005ULL + this->Increment;
  const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
  const auto rot = static_cast<std::uint32_t>(old >> 59u);
  const std::uint32_t x = (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  // 24 random bits: every value is exact in float, and the result is < 1.
  return static_cast<float>(x >> 8) * (1.0f / 16777216.0f);
}

//------------------------------------------------------------------------------
// The random numbers of a layer depend on the seed and the layer's global
// index only: pieces and slabs of a volume draw what the whole volume would.
void vtkErrorDiffusionScan::SeedLayer(int layer)
{
  const auto z = static_cast<std::uint64_t>(static_cast<std::int64_t>(layer));
  this->Random.Seed(this->Seed, 0x9e3779b97f4a7c15ULL ^ (z * 0xD1B54A32D192ED03ULL));
}

//------------------------------------------------------------------------------
vtkErrorDiffusionScan::vtkErrorDiffusionScan()
  : Table(vtkErrorDiffusionParameterTable::Paper())
{
}

//------------------------------------------------------------------------------
vtkErrorDiffusionScan::~vtkErrorDiffusionScan() = default;

//------------------------------------------------------------------------------
vtkErrorDiffusionScan::LayerScan vtkErrorDiffusionScan::GetLayerScan(
  int nx, int ny, int phase)
{
  return GetLayerScan(nx, ny, phase, nx);
}

//------------------------------------------------------------------------------
vtkErrorDiffusionScan::LayerScan vtkErrorDiffusionScan::GetLayerScan(
  int nx, int ny, int phase, vtkIdType pitch)
{
  phase = PositiveModulo4(phase);
  LayerScan s;
  s.Phase = phase;
  const int* u = PhaseU[phase];
  const int* v = PhaseV[phase];
  const bool rowsAlongX = u[0] != 0;
  s.NU = rowsAlongX ? nx : ny;
  s.NV = rowsAlongX ? ny : nx;
  s.UStride = rowsAlongX ? u[0] : u[1] * pitch;
  s.VStride = rowsAlongX ? v[1] * pitch : v[0];
  // The first voxel is the corner from which both u and v point inwards.
  const int x0 = (u[0] < 0 || v[0] < 0) ? nx - 1 : 0;
  const int y0 = (u[1] < 0 || v[1] < 0) ? ny - 1 : 0;
  s.Start = x0 + pitch * y0;
  return s;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionScan::GetTargetOffsets(const LayerScan& scan, int row, int offsets[6][3])
{
  const int sign = (row % 2 == 0) ? 1 : -1;
  const int du[2] = { sign * PhaseU[scan.Phase][0], sign * PhaseU[scan.Phase][1] };
  const int* dv = PhaseV[scan.Phase];
  const int table[6][3] = {
    { du[0], du[1], 0 },                   // A100
    { -du[0] + dv[0], -du[1] + dv[1], 0 },
    { dv[0], dv[1], 0 },                   // A010
    { -dv[0], -dv[1], 1 },                 // A0-11
    { -du[0], -du[1], 1 },
    { 0, 0, 1 },                           // A001
  };
  std::copy(&table[0][0], &table[0][0] + 18, &offsets[0][0]);
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionScan::Begin(int nx, int ny, int firstLayer)
{
  this->NX = std::max(nx, 0);
  this->NY = std::max(ny, 0);
  this->FirstLayer = firstLayer;
  this->LayersDone = 0;
  this->Carry = 0.0f;
  this->WarmedUp = false;
  this->TestedLayer = nullptr;
  this->ClassedLayer = nullptr;
  this->Pitch = ErrorPitch(this->NX);
  const size_t layer = static_cast<size_t>(this->Pitch) * static_cast<size_t>(this->NY);
  this->Current.assign(layer, 0.0f);
  this->Next.assign(layer, 0.0f);
  // The table or the scale may have changed since the last run.
  this->ParameterTable.assign(ParameterEntries, LevelParameters());
  if (this->Method == METHOD_ERROR_DIFFUSION && !this->UseFixedCharge)
  {
    this->PrepareCharges();
  }
}

//------------------------------------------------------------------------------
// One entry of the parameter table: the parameters of the minority density
// the entry stands for (g <= 0.5; ParametersOf mirrors them above).
vtkErrorDiffusionScan::LevelParameters vtkErrorDiffusionScan::Evaluate(float minority) const
{
  LevelParameters entry;
  const auto params = this->Table.Evaluate(minority);
  std::copy(params.Weights.begin(), params.Weights.end(), entry.Weights);
  const float charge = this->UseFixedCharge ? this->FixedCharge : this->ChargeAt(minority);
  entry.Base = 0.5f - charge;
  entry.Modulation = static_cast<float>(this->ModulationScale) * params.Modulation;
  entry.Valid = true;
  return entry;
}

//------------------------------------------------------------------------------
// Real volumes change g from voxel to voxel; the table spares the
// interpolation of the parameters and the charge, which cost several times
// the rest of a voxel's work.
vtkErrorDiffusionScan::LevelParameters vtkErrorDiffusionScan::ParametersOf(float g)
{
  const bool mirrored = g > 0.5f;
  const float minority = mirrored ? 1.0f - g : g;
  const size_t index = ParameterIndex(minority);
  LevelParameters& entry = this->ParameterTable[index];
  if (!entry.Valid)
  {
    entry = this->Evaluate(ParameterDensity(index));
  }
  LevelParameters p = entry;
  if (mirrored)
  {
    // The mirrored process: t = 0.5 + C(1 - g) - s r m(1 - g).
    p.Base = 1.0f - entry.Base;
    p.Modulation = -entry.Modulation;
  }
  return p;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionScan::ReleaseLayerBuffers()
{
  std::vector<float>().swap(this->Current);
  std::vector<float>().swap(this->Next);
  for (auto* bytes : { &this->Interior, &this->InteriorWork, &this->ClassLow, &this->ClassHigh,
         &this->ClassWork, &this->ClassCurrent, &this->ClassNext })
  {
    std::vector<unsigned char>().swap(*bytes);
  }
  this->ClassedLayer = nullptr;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionScan::SwapLayerBuffers(vtkErrorDiffusionScan& other)
{
  this->Current.swap(other.Current);
  this->Next.swap(other.Next);
  this->Interior.swap(other.Interior);
  this->InteriorWork.swap(other.InteriorWork);
  this->ClassLow.swap(other.ClassLow);
  this->ClassHigh.swap(other.ClassHigh);
  this->ClassWork.swap(other.ClassWork);
  this->ClassCurrent.swap(other.ClassCurrent);
  this->ClassNext.swap(other.ClassNext);
  this->ClassedLayer = other.ClassedLayer = nullptr;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionScan::EndLayer()
{
  std::swap(this->Current, this->Next);
  std::fill(this->Next.begin(), this->Next.end(), 0.0f);
  ++this->LayersDone;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionScan::WarmUp(const float* density, int layers)
{
  if (this->Method != METHOD_ERROR_DIFFUSION || layers <= 0 || this->Current.empty())
  {
    return;
  }
  this->WarmedUp = true;
  const int cycles = (layers + 3) / 4;
  std::vector<unsigned char> discarded(static_cast<size_t>(this->NX) * this->NY);
  const int first = this->FirstLayer + this->LayersDone - 4 * cycles;
  for (int w = 0; w < 4 * cycles; ++w)
  {
    this->ScanLayer(density, density, discarded.data(), first + w);
    std::swap(this->Current, this->Next);
    std::fill(this->Next.begin(), this->Next.end(), 0.0f);
  }
  this->CenterCarriedError(density);
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionScan::CenterCarriedError(const float* density)
{
  double sum = this->Carry;
  size_t active = 0;
  for (int y = 0; y < this->NY; ++y)
  {
    const float* g = density + static_cast<size_t>(this->NX) * y;
    const float* e = this->Current.data() + static_cast<size_t>(this->Pitch) * y;
    for (int x = 0; x < this->NX; ++x)
    {
      sum += e[x];
      active += Active(g[x]) ? 1 : 0;
    }
  }
  this->Carry = 0.0f;
  const float shift = active > 0 ? static_cast<float>(sum / static_cast<double>(active)) : 0.0f;
  for (int y = 0; y < this->NY; ++y)
  {
    const float* g = density + static_cast<size_t>(this->NX) * y;
    float* e = this->Current.data() + static_cast<size_t>(this->Pitch) * y;
    for (int x = 0; x < this->NX; ++x)
    {
      e[x] = Active(g[x]) ? e[x] - shift : 0.0f;
    }
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkErrorDiffusionScan::ProcessLayer(
  const float* density, const float* nextDensity, unsigned char* mask)
{
  if (this->NX == 0 || this->NY == 0)
  {
    return 0;
  }
  if (this->Method == METHOD_WHITE_NOISE)
  {
    this->SeedLayer(this->FirstLayer + this->LayersDone);
    return this->DrawLayerIndependently(density, mask);
  }
  if (this->LayersDone == 0 && !this->WarmedUp)
  {
    this->WarmUp(density, this->WarmUpLayers);
  }
  const vtkIdType count =
    this->ScanLayer(density, nextDensity, mask, this->FirstLayer + this->LayersDone);
  this->EndLayer();
  return count;
}

//------------------------------------------------------------------------------
double vtkErrorDiffusionScan::GetCarriedError() const
{
  double sum = this->Carry;
  for (float e : this->Current)
  {
    sum += e;
  }
  return sum;
}

//------------------------------------------------------------------------------
double vtkErrorDiffusionScan::MeasureReceivedError(const vtkErrorDiffusionParameterTable& table,
  double modulationScale, double g, float charge, int seed)
{
  const double spacing = std::cbrt(1.0 / g); // mean distance between points, in voxels
  const int n = static_cast<int>(48.0 + 4.0 * spacing);
  const int margin = static_cast<int>(std::ceil(1.5 * spacing)) + 2;
  const int settle = 4 * static_cast<int>(std::ceil(2.0 * spacing + 8.0));
  const int measured = settle;
  vtkErrorDiffusionScan probe;
  probe.SetParameters(table);
  probe.SetModulationScale(modulationScale);
  probe.SetSeed(static_cast<std::uint64_t>(seed));
  // The guess at every density, even a negative one (a plain scan never asks
  // a charge curve, which is what the caller calibrates).
  probe.SetFixedCharge(charge);
  probe.SetWarmUpLayers(0);
  probe.Begin(n, n);
  const std::vector<float> density(static_cast<size_t>(n) * n, static_cast<float>(g));
  std::vector<unsigned char> mask(density.size());
  double sum = 0.0;
  long count = 0;
  for (int layer = 0; layer < settle + measured; ++layer)
  {
    probe.ScanLayer<true>(density.data(), density.data(), mask.data(), layer);
    if (layer >= settle)
    {
      for (int y = margin; y < n - margin; ++y)
      {
        for (int x = margin; x < n - margin; ++x)
        {
          sum += probe.Current[x + static_cast<size_t>(probe.Pitch) * y];
          ++count;
        }
      }
    }
    probe.EndLayer();
  }
  return sum / static_cast<double>(count);
}

//------------------------------------------------------------------------------
vtkIdType vtkErrorDiffusionScan::DrawLayerIndependently(
  const float* density, unsigned char* mask)
{
  const vtkIdType n = static_cast<vtkIdType>(this->NX) * this->NY;
  vtkIdType count = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const float g = density[i];
    // g >= 1 and g <= 0 (NaN too) draw no random number, like the scan.
    const unsigned char b = g >= 1.0f ? 1 : ((g > 0.0f && this->Random.Uniform() < g) ? 1 : 0);
    mask[i] = b;
    count += b;
  }
  ++this->LayersDone;
  return count;
}

//------------------------------------------------------------------------------
namespace
{
// The layer's reservoir: error that would go below a bottom face (a voxel
// whose targets in the next layer are all inactive or missing) is shared by
// the active voxels still to come in the layer, each getting share / count
// of the voxels left at the time. Concentrating it on the voxel's own targets
// in the layer instead makes the last layer of a support fire ahead of its
// mass at low densities (the translated threshold is low): about 7 points too
// many on a 256^2 layer at g = 0.01.
struct Reservoir
{
  float Received = 0.0f; // what each of the active voxels to come receives
  vtkIdType Remaining = 0; // active voxels left in the layer after the current one

  // Gives `share` to the voxels to come; false when there are none.
  bool Take(float share)
  {
    if (this->Remaining == 0)
    {
      return false;
    }
    this->Received += share / static_cast<float>(this->Remaining);
    return true;
  }
};

// What FindInterior marks a voxel for: the fast path (ScanRun), or no
// density (not active, below 1), where the scan only clears the mask, a run
// of voxels at a time; 0: the path of the faces (SpreadAtFace).
constexpr unsigned char PathFast = 1;
constexpr unsigned char PathEmpty = 2;

// How many voxels of a row from idx on (step d, `left` of them to the row's
// end) are marked `path` in `interior`.
int RunOf(const unsigned char* interior, vtkIdType idx, vtkIdType d, int left, unsigned char path)
{
  int run = 0;
  while (run < left && interior[idx + run * d] == path)
  {
    ++run;
  }
  return run;
}

// How many voxels of a row from idx on take the fast path: those marked so
// in `interior` when given, else all but the row's last when the row is
// `fast` (away from the faces of a layer whose voxels and successors are
// all active).
int FastRun(const unsigned char* interior, vtkIdType idx, vtkIdType d, int left, bool fast)
{
  if (!interior)
  {
    return fast ? left - 1 : 0;
  }
  return RunOf(interior, idx, d, left, PathFast);
}
}

//------------------------------------------------------------------------------
// The error e of voxel idx at a face of the volume, of the support or of a
// density step: the targets that exist and are active share it in
// proportion to their weights (those of a similar density only, when there
// are such), except that a share for the next layer with no active target
// there goes to the reservoir. Returns the new carry (the share of the next
// voxel scanned).
float vtkErrorDiffusionScan::SpreadAtFace(float e, const float w[6], const bool valid[6],
  const bool similar[6], vtkIdType idx, vtkIdType d, vtkIdType v, void* reservoirPointer)
{
  auto& reservoir = *static_cast<Reservoir*>(reservoirPointer);
  float* cur = this->Current.data();
  float* nxt = this->Next.data();
  const float below = w[TARGET_Z_BACKV] + w[TARGET_Z_BACKU] + w[TARGET_Z];
  const bool anyBelow = valid[TARGET_Z_BACKV] || valid[TARGET_Z_BACKU] || valid[TARGET_Z];
  float local = e; // what the local targets share
  if (!anyBelow && below > 0.0f && reservoir.Take(e * below))
  {
    local = e * (1.0f - below);
  }
  const bool* targets = valid;
  const bool inLayerOnly[6] = { valid[0], valid[1], valid[2], false, false, false };
  if (local != e)
  {
    targets = inLayerOnly;
  }
  bool alike[6];
  bool anyAlike = false;
  for (int t = 0; t < 6; ++t)
  {
    alike[t] = targets[t] && similar[t];
    anyAlike = anyAlike || alike[t];
  }
  if (anyAlike)
  {
    targets = alike; // over a density step only when there is no other way
  }
  float sum = 0.0f;
  for (int t = 0; t < 6; ++t)
  {
    sum += targets[t] ? w[t] : 0.0f;
  }
  if (!(sum > 0.0f))
  {
    return local; // no active target: on to the next voxel scanned
  }
  const float f = local / sum;
  if (targets[TARGET_BACK_V])
  {
    cur[idx - d + v] += f * w[TARGET_BACK_V];
  }
  if (targets[TARGET_V])
  {
    cur[idx + v] += f * w[TARGET_V];
  }
  if (targets[TARGET_Z_BACKV])
  {
    nxt[idx - v] += f * w[TARGET_Z_BACKV];
  }
  if (targets[TARGET_Z_BACKU])
  {
    nxt[idx - d] += f * w[TARGET_Z_BACKU];
  }
  if (targets[TARGET_Z])
  {
    nxt[idx] += f * w[TARGET_Z];
  }
  return targets[TARGET_U] ? f * w[TARGET_U] : 0.0f;
}

//------------------------------------------------------------------------------
// How many voxels of the layer are active, and the lowest and highest of
// their densities (high < low when none is). A branch-free body, so the
// compiler vectorizes it.
vtkErrorDiffusionScan::LayerRange vtkErrorDiffusionScan::RangeOf(const float* g, size_t n)
{
  LayerRange range;
  size_t i = 0;
#if BLUENOISE_SSE2
  // Four at a time (the compiler does not vectorize the comparisons by
  // itself: they may trap); the counts per lane in blocks that fit an int.
  const __m128 zero = _mm_setzero_ps();
  const __m128 one = _mm_set1_ps(1.0f);
  __m128 low = one, high = zero;
  constexpr size_t block = size_t(1) << 20;
  while (i + 4 <= n)
  {
    const size_t end = std::min(n, i + block) & ~size_t(3);
    __m128i count = _mm_setzero_si128();
    for (; i < end; i += 4)
    {
      const __m128 v = _mm_loadu_ps(g + i);
      const __m128 on = _mm_and_ps(_mm_cmpgt_ps(v, zero), _mm_cmplt_ps(v, one));
      low = _mm_min_ps(low, _mm_or_ps(_mm_and_ps(on, v), _mm_andnot_ps(on, one)));
      high = _mm_max_ps(high, _mm_and_ps(on, v));
      count = _mm_sub_epi32(count, _mm_castps_si128(on)); // an active lane is -1
    }
    alignas(16) std::int32_t counts[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(counts), count);
    range.Active += static_cast<vtkIdType>(counts[0]) + counts[1] + counts[2] + counts[3];
  }
  alignas(16) float lows[4], highs[4];
  _mm_store_ps(lows, low);
  _mm_store_ps(highs, high);
  for (int k = 0; k < 4; ++k)
  {
    range.Low = std::min(range.Low, lows[k]);
    range.High = std::max(range.High, highs[k]);
  }
#endif
  for (; i < n; ++i)
  {
    const float v = g[i];
    if (Active(v))
    {
      ++range.Active;
      range.Low = std::min(range.Low, v);
      range.High = std::max(range.High, v);
    }
  }
  return range;
}

//------------------------------------------------------------------------------
// Whether every voxel of the layer and of its successor is active and all
// their densities are similar (the fast path); `active` receives the number
// of active voxels of the layer, and `similar` whether the active densities
// of both are all similar. A layer is tested once, as the successor, and the
// answer reused when it comes up as the current layer (the caller passes the
// same densities).
bool vtkErrorDiffusionScan::TestLayers(
  const float* density, const float* next, vtkIdType& active, bool& similar)
{
  const size_t layerSize = static_cast<size_t>(this->NX) * this->NY;
  const vtkIdType all = static_cast<vtkIdType>(layerSize);
  const LayerRange current = density == this->TestedLayer ? this->Tested : RangeOf(density, layerSize);
  bool allActive = false;
  float low = current.Low, high = current.High;
  if (next)
  {
    const LayerRange following = next == density ? current : RangeOf(next, layerSize);
    this->TestedLayer = next;
    this->Tested = following;
    allActive = current.Active == all && following.Active == all;
    low = std::min(low, following.Low);
    high = std::max(high, following.High);
  }
  similar = high < low || vtkBlueNoiseDensityClass::Similar(low, high);
  active = current.Active;
  return allActive && similar;
}

//------------------------------------------------------------------------------
// The path of each voxel of a layer: PathFast where the 3x3 erosion of
// "active here and in the next layer" holds, with the outside of the layer
// inactive, and with `steps` of "of densities similar to one another" too;
// PathEmpty where there is no density. Byte loops the compiler vectorizes,
// in memory order whatever the orientation of the scan.
const unsigned char* vtkErrorDiffusionScan::FindInterior(
  const float* density, const float* next, bool steps)
{
  const size_t nx = static_cast<size_t>(this->NX), ny = static_cast<size_t>(this->NY);
  const size_t layer = nx * ny;
  this->Interior.assign(layer, 0);
  this->InteriorWork.resize(layer);
  if (nx >= 3 && ny >= 3)
  {
    this->ErodeActive(density, next, steps);
  }
  unsigned char* path = this->Interior.data();
  for (size_t i = 0; i < layer; ++i)
  {
    // Not 0 < g: g <= 0 or NaN, none of them active (ErodeActive's 0).
    path[i] |= static_cast<unsigned char>(!(density[i] > 0.0f)) * PathEmpty;
  }
  return path;
}

//------------------------------------------------------------------------------
// PathFast into Interior (all 0) where FindInterior says.
void vtkErrorDiffusionScan::ErodeActive(const float* density, const float* next, bool steps)
{
  const size_t nx = static_cast<size_t>(this->NX), ny = static_cast<size_t>(this->NY);
  const size_t layer = nx * ny;
  unsigned char* both = this->InteriorWork.data();
  for (size_t i = 0; i < layer; ++i)
  {
    both[i] = static_cast<unsigned char>((density[i] > 0.0f) & (density[i] < 1.0f) &
      (next[i] > 0.0f) & (next[i] < 1.0f));
  }
  unsigned char* rows = this->Interior.data(); // eroded along x
  for (size_t y = 0; y < ny; ++y)
  {
    const unsigned char* k = both + y * nx;
    unsigned char* h = rows + y * nx;
    for (size_t x = 1; x + 1 < nx; ++x)
    {
      h[x] = k[x - 1] & k[x] & k[x + 1];
    }
  }
  unsigned char* eroded = both; // and along y
  std::fill(eroded, eroded + nx, 0);
  std::fill(eroded + (ny - 1) * nx, eroded + layer, 0);
  for (size_t i = nx; i < layer - nx; ++i)
  {
    eroded[i] = rows[i - nx] & rows[i] & rows[i + nx];
  }
  std::swap(this->Interior, this->InteriorWork);
  if (steps)
  {
    this->KeepSimilarInterior(density, next);
  }
}

//------------------------------------------------------------------------------
namespace
{
void ClassesOf(const float* g, size_t n, std::vector<unsigned char>& classes)
{
  classes.resize(n);
  vtkBlueNoiseDensityClass::OfEach(g, n, classes.data());
}
}

//------------------------------------------------------------------------------
// Clears from Interior the voxels whose 3x3 neighborhood in the layer and the
// next holds densities that are not all similar: the lowest and highest
// class of each neighborhood by separable erosions.
void vtkErrorDiffusionScan::KeepSimilarInterior(const float* density, const float* next)
{
  const size_t nx = static_cast<size_t>(this->NX), ny = static_cast<size_t>(this->NY);
  const size_t layer = nx * ny;
  this->ClassLow.resize(layer);
  this->ClassHigh.resize(layer);
  this->ClassWork.resize(layer);
  unsigned char* low = this->ClassLow.data();
  unsigned char* high = this->ClassHigh.data();
  unsigned char* work = this->ClassWork.data();
  // The next layer's classes are kept for its turn as the current one.
  if (this->ClassedLayer != density)
  {
    ClassesOf(density, layer, this->ClassNext);
  }
  std::swap(this->ClassCurrent, this->ClassNext);
  ClassesOf(next, layer, this->ClassNext);
  this->ClassedLayer = next;
  const unsigned char* a = this->ClassCurrent.data();
  const unsigned char* b = this->ClassNext.data();
  for (size_t i = 0; i < layer; ++i)
  {
    low[i] = std::min(a[i], b[i]);
    high[i] = std::max(a[i], b[i]);
  }
  // 3x3 minimum (of the low classes) and maximum (of the high ones): along
  // x into work, then along y back; a loop each, so that they vectorize.
  const auto lower = [](unsigned char a, unsigned char b) { return std::min(a, b); };
  const auto higher = [](unsigned char a, unsigned char b) { return std::max(a, b); };
  const auto erode = [&](unsigned char* values, auto pick) {
    for (size_t y = 0; y < ny; ++y)
    {
      const unsigned char* k = values + y * nx;
      unsigned char* h = work + y * nx;
      h[0] = k[0];
      h[nx - 1] = k[nx - 1];
      for (size_t x = 1; x + 1 < nx; ++x)
      {
        h[x] = pick(pick(k[x - 1], k[x]), k[x + 1]);
      }
    }
    for (size_t i = nx; i + nx < layer; ++i)
    {
      values[i] = pick(pick(work[i - nx], work[i]), work[i + nx]);
    }
  };
  erode(low, lower);
  erode(high, higher);
  unsigned char* interior = this->Interior.data();
  for (size_t i = 0; i < layer; ++i)
  {
    interior[i] &= static_cast<unsigned char>(vtkBlueNoiseDensityClass::Alike(low[i], high[i]));
  }
}

//------------------------------------------------------------------------------
namespace
{
// Whether a voxel of density g fires so seldom (or so nearly always) that a
// branch on the outcome is well predicted: there the branch beats the
// branch-free scan, which waits for the comparison at every voxel; further
// from 0 and 1 the mispredictions cost more than it saves.
inline bool Rare(float g)
{
  constexpr float limit = 0.05f;
  return g < limit || g > 1.0f - limit;
}

// The six targets of voxel idx of a layer (rows v apart, the next voxel of
// the scan d away; next: the following layer, or nullptr) where some lie
// outside the layer or the volume: whether each is active, and whether its
// density is similar to g. The order is that of the weights.
void TargetsAtFace(const float* density, const float* next, vtkIdType idx, vtkIdType d,
  vtkIdType v, bool hasPrevU, bool hasNextU, bool hasPrevRow, bool hasNextRow, float g,
  bool valid[6], bool alike[6])
{
  const bool nextLayer = next != nullptr;
  const float targets[6] = { hasNextU ? density[idx + d] : 0.0f,
    hasPrevU && hasNextRow ? density[idx - d + v] : 0.0f, hasNextRow ? density[idx + v] : 0.0f,
    hasPrevRow && nextLayer ? next[idx - v] : 0.0f, hasPrevU && nextLayer ? next[idx - d] : 0.0f,
    nextLayer ? next[idx] : 0.0f };
  for (int t = 0; t < 6; ++t)
  {
    valid[t] = Active(targets[t]);
    alike[t] = vtkBlueNoiseDensityClass::Similar(g, targets[t]);
  }
}
}

//------------------------------------------------------------------------------
// The scan of n voxels of a row from idx on (error index eidx) whose six
// targets are all active and inside the volume: no test on the targets. The
// generator and what goes from voxel to voxel live in locals: a member would
// be stored and reloaded around every byte stored to the mask, which may
// alias it.
template <bool Record, bool Branchy>
void vtkErrorDiffusionScan::ScanRun(const float* density, unsigned char* mask, vtkIdType idx,
  vtkIdType d, vtkIdType eidx, vtkIdType ed, vtkIdType ev, int n, float received, RunState& state)
{
  float* cur = this->Current.data();
  float* nxt = this->Next.data();
  Generator random = this->Random;
  float carry = state.Carry;
  vtkIdType count = 0;
  for (int p = 0; p < n;)
  {
    // A stretch of voxels of one density: its parameters, in locals the
    // compiler keeps in registers through the stretch.
    const float g = density[idx];
    if (g != state.CachedG)
    {
      state.Level = this->ParametersOf(g);
      state.CachedG = g;
    }
    const float wu = state.Level.Weights[TARGET_U];
    const float wbv = state.Level.Weights[TARGET_BACK_V];
    const float wv = state.Level.Weights[TARGET_V];
    const float wzbv = state.Level.Weights[TARGET_Z_BACKV];
    const float wzbu = state.Level.Weights[TARGET_Z_BACKU];
    const float wz = state.Level.Weights[TARGET_Z];
    const float base = state.Level.Base;
    const float modulation = state.Level.Modulation;
    do
    {
      // g + cur[eidx] (+ the reservoir) is off the critical path.
      const float value = (g + cur[eidx] + received) + carry;
      if (Record)
      {
        cur[eidx] = value - g;
      }
      const float threshold = base + modulation * random.Uniform();
      float e;
      if (Branchy)
      {
        if (value >= threshold)
        {
          mask[idx] = 1;
          ++count;
          e = value - 1.0f;
          carry = value * wu - wu;
        }
        else
        {
          mask[idx] = 0;
          e = value;
          carry = value * wu;
        }
      }
      else
      {
        // Branch-free: near g = 0.5 a branch on the outcome is mispredicted
        // half of the time. value * w - b * w: the product does not wait for
        // the comparison. The same numbers as the branch above.
        const unsigned char b = value >= threshold ? 1 : 0;
        mask[idx] = b;
        count += b;
        e = value - static_cast<float>(b);
        const float taken = value >= threshold ? wu : 0.0f;
        carry = value * wu - taken;
      }
      cur[eidx - ed + ev] += e * wbv;
      cur[eidx + ev] += e * wv;
      nxt[eidx - ev] += e * wzbv;
      nxt[eidx - ed] += e * wzbu;
      nxt[eidx] += e * wz;
      ++p;
      idx += d;
      eidx += ed;
    } while (p < n && density[idx] == g);
  }
  this->Random = random;
  state.Carry = carry;
  state.Count += count;
}

//------------------------------------------------------------------------------
// The voxels' paths (FindInterior) of a layer with inactive voxels or
// density steps, where the fast path still serves the voxels whose
// neighborhood is active and of similar densities (the bulk of any real
// volume's support), with the layer's mask cleared; nullptr for a layer all
// active and alike (or the last one).
const unsigned char* vtkErrorDiffusionScan::LayerPaths(
  const float* density, const float* next, unsigned char* mask, bool allActive, bool similar)
{
  const unsigned char* interior =
    allActive || !next ? nullptr : this->FindInterior(density, next, !similar);
  if (interior)
  {
    // In memory order: the scan skips the voxels of no density, whose mask
    // is 0, and along a column each store would be to a line of its own.
    std::fill(mask, mask + static_cast<size_t>(this->NX) * this->NY, 0);
  }
  if (!interior || similar)
  {
    this->ClassedLayer = nullptr; // the classes kept are of no layer to come
  }
  return interior;
}

//------------------------------------------------------------------------------
// The scan of one layer. Record keeps what each voxel received (for
// MeasureReceivedError) and costs a store per voxel, so it is a template
// flag. Runs of voxels away from the faces of a layer whose voxels and
// successors are all active, and in other layers of voxels whose 3x3
// neighborhood is active in both (FindInterior), go through ScanRun: that is
// the bulk of the work on any large support, and the tests on the targets
// cost a third of the time. The other voxels go through SpreadAtFace.
template <bool Record>
vtkIdType vtkErrorDiffusionScan::ScanLayer(
  const float* density, const float* next, unsigned char* mask, int layer)
{
  Reservoir reservoir;
  bool similar = true;
  const bool allActive = this->TestLayers(density, next, reservoir.Remaining, similar);
  const unsigned char* interior = this->LayerPaths(density, next, mask, allActive, similar);
  const LayerScan s = GetLayerScan(this->NX, this->NY, layer);
  const LayerScan es = GetLayerScan(this->NX, this->NY, layer, this->Pitch);
  this->SeedLayer(layer);
  const vtkIdType V = s.VStride;
  const vtkIdType EV = es.VStride;

  // The share for the next voxel of the scan is the only dependency from one
  // voxel to the next. It also carries, to the next active voxel of the scan,
  // error that has no active target.
  RunState state;
  state.Carry = this->Carry;

  for (int q = 0; q < s.NV; ++q)
  {
    const bool oddRow = (q & 1) != 0;
    const vtkIdType d = oddRow ? -s.UStride : s.UStride;
    vtkIdType idx = s.Start + q * V + (oddRow ? (s.NU - 1) * s.UStride : 0);
    const vtkIdType ed = oddRow ? -es.UStride : es.UStride;
    vtkIdType eidx = es.Start + q * EV + (oddRow ? (es.NU - 1) * es.UStride : 0);
    const bool hasPrevRow = q > 0;
    const bool hasNextRow = q + 1 < s.NV;
    const bool fastRow = hasPrevRow && hasNextRow && allActive;
    for (int p = 0; p < s.NU; ++p, idx += d, eidx += ed)
    {
      const int run = FastRun(interior, idx, d, s.NU - p, fastRow && p > 0);
      if (run > 0)
      {
        if (Rare(density[idx]))
        {
          this->ScanRun<Record, true>(
            density, mask, idx, d, eidx, ed, EV, run, reservoir.Received, state);
        }
        else
        {
          this->ScanRun<Record, false>(
            density, mask, idx, d, eidx, ed, EV, run, reservoir.Received, state);
        }
        reservoir.Remaining -= run;
        p += run - 1;
        idx += (run - 1) * d;
        eidx += (run - 1) * ed;
        continue;
      }
      const int empty = interior ? RunOf(interior, idx, d, s.NU - p, PathEmpty) : 0;
      if (empty > 0) // their mask was cleared above, as their own test would
      {
        p += empty - 1;
        idx += (empty - 1) * d;
        eidx += (empty - 1) * ed;
        continue;
      }
      const float g = density[idx];
      if (!Active(g))
      {
        const unsigned char b = g >= 1.0f ? 1 : 0;
        mask[idx] = b;
        state.Count += b;
        continue;
      }
      if (g != state.CachedG)
      {
        state.Level = this->ParametersOf(g);
        state.CachedG = g;
      }
      // The draw of ScanRun, then the error spread over the targets there are.
      const float value = (g + this->Current[eidx] + reservoir.Received) + state.Carry;
      if (Record)
      {
        this->Current[eidx] = value - g;
      }
      const float threshold =
        state.Level.Base + state.Level.Modulation * this->Random.Uniform();
      const unsigned char b = value >= threshold ? 1 : 0;
      mask[idx] = b;
      state.Count += b;
      const float e = value - static_cast<float>(b);
      --reservoir.Remaining;
      bool valid[6], alike[6];
      TargetsAtFace(density, next, idx, d, V, p > 0, p + 1 < s.NU, hasPrevRow, hasNextRow, g,
        valid, alike);
      state.Carry =
        this->SpreadAtFace(e, state.Level.Weights, valid, alike, eidx, ed, EV, &reservoir);
    }
  }
  this->Carry = state.Carry;
  return state.Count;
}
