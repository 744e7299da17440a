// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionKernel.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <mutex>
#include <sstream>

namespace
{
// In-layer directions (dx, dy) of u and v for the four phases of a cycle:
// each phase is the previous one turned by 90 degrees.
const int PhaseU[4][2] = { { 1, 0 }, { 0, 1 }, { -1, 0 }, { 0, -1 } };
const int PhaseV[4][2] = { { 0, 1 }, { -1, 0 }, { 0, -1 }, { 1, 0 } };

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

// Calibrated charges per (table, modulation scale): calibration costs a few
// milliseconds, a sampler may run many times with the same parameters.
std::mutex ChargeCacheMutex;
std::map<std::string, std::vector<float>> ChargeCache;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionKernel::Generator::Seed(std::uint64_t seed, std::uint64_t stream)
{
  // PCG32 initialisation (O'Neill 2014): any seed gives a full-period stream.
  this->State = 0;
  this->Increment = (stream << 1u) | 1u;
  this->Uniform();
  this->State += seed;
  this->Uniform();
}

//------------------------------------------------------------------------------
inline float vtkErrorDiffusionKernel::Generator::Uniform()
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
vtkErrorDiffusionKernel::vtkErrorDiffusionKernel()
  : Table(vtkErrorDiffusionParameterTable::Paper())
{
}

//------------------------------------------------------------------------------
vtkErrorDiffusionKernel::LayerScan vtkErrorDiffusionKernel::GetLayerScan(
  int nx, int ny, int phase)
{
  phase = PositiveModulo4(phase);
  LayerScan s;
  s.Phase = phase;
  const int* u = PhaseU[phase];
  const int* v = PhaseV[phase];
  const bool rowsAlongX = u[0] != 0;
  s.NU = rowsAlongX ? nx : ny;
  s.NV = rowsAlongX ? ny : nx;
  s.UStride = rowsAlongX ? u[0] : static_cast<vtkIdType>(u[1]) * nx;
  s.VStride = rowsAlongX ? static_cast<vtkIdType>(v[1]) * nx : v[0];
  // The first voxel is the corner from which both u and v point inwards.
  const int x0 = (u[0] < 0 || v[0] < 0) ? nx - 1 : 0;
  const int y0 = (u[1] < 0 || v[1] < 0) ? ny - 1 : 0;
  s.Start = x0 + static_cast<vtkIdType>(nx) * y0;
  return s;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionKernel::GetTargetOffsets(const LayerScan& scan, int row, int offsets[6][3])
{
  const int sign = (row % 2 == 0) ? 1 : -1;
  const int du[2] = { sign * PhaseU[scan.Phase][0], sign * PhaseU[scan.Phase][1] };
  const int* dv = PhaseV[scan.Phase];
  const int table[6][3] = {
    { du[0], du[1], 0 },                 // A100
    { -du[0] + dv[0], -du[1] + dv[1], 0 },
    { dv[0], dv[1], 0 },                 // A010
    { -dv[0], -dv[1], 1 },               // A0-11
    { -du[0], -du[1], 1 },
    { 0, 0, 1 },                         // A001
  };
  std::copy(&table[0][0], &table[0][0] + 18, &offsets[0][0]);
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionKernel::Begin(int nx, int ny, int nz, int firstLayer)
{
  this->NX = std::max(nx, 0);
  this->NY = std::max(ny, 0);
  this->NZ = std::max(nz, 0);
  this->FirstLayer = firstLayer;
  this->LayersDone = 0;
  this->TestedLayer = nullptr;
  this->ParameterCache.fill(LevelParameters()); // the table or the scale may have changed
  const size_t layer = static_cast<size_t>(this->NX) * static_cast<size_t>(this->NY);
  this->Current.assign(layer, 0.0f);
  this->Next.assign(layer, 0.0f);
  this->Random.Seed(this->Seed, 0x9e3779b97f4a7c15ULL);
  this->KeyLevels.clear();
  for (const auto& key : this->Table.GetKeys())
  {
    this->KeyLevels.push_back(static_cast<float>(key.Level));
  }
  if (this->BoundaryMode == BOUNDARY_STEADY_STATE && this->Method == METHOD_ERROR_DIFFUSION)
  {
    this->KeyCharges = GetSteadyStateCharges(this->Table, this->ModulationScale);
  }
  else
  {
    this->KeyCharges.assign(this->KeyLevels.size(), 0.0f);
  }
}

//------------------------------------------------------------------------------
std::vector<float> vtkErrorDiffusionKernel::GetSteadyStateCharges(
  const vtkErrorDiffusionParameterTable& table, double modulationScale)
{
  std::ostringstream key;
  table.Write(key);
  key << "scale " << modulationScale;
  {
    std::lock_guard<std::mutex> lock(ChargeCacheMutex);
    auto found = ChargeCache.find(key.str());
    if (found != ChargeCache.end())
    {
      return found->second;
    }
  }
  // For each key density: run the uncompensated process on a constant box
  // long enough to reach its steady state, then average the error each voxel
  // receives (what the scan holds when it reaches it) away from the faces.
  const int n = 24;
  const int settle = 64;
  const int measured = 64;
  const int margin = 3;
  std::vector<float> charges;
  for (const auto& k : table.GetKeys())
  {
    vtkErrorDiffusionKernel probe;
    probe.SetParameters(table);
    probe.SetModulationScale(modulationScale);
    probe.SetBoundaryMode(BOUNDARY_RENORMALIZE); // zero charge, no warm-up
    probe.SetSeed(12345);
    probe.Begin(n, n, settle + measured + 1);
    const std::vector<float> density(static_cast<size_t>(n) * n, static_cast<float>(k.Level / 255.0));
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
            sum += probe.Current[x + static_cast<size_t>(n) * y];
            ++count;
          }
        }
      }
      std::swap(probe.Current, probe.Next);
      std::fill(probe.Next.begin(), probe.Next.end(), 0.0f);
    }
    charges.push_back(static_cast<float>(sum / count));
  }
  std::lock_guard<std::mutex> lock(ChargeCacheMutex);
  if (ChargeCache.size() >= 1024)
  {
    ChargeCache.clear(); // a parameter search makes a new table per candidate
  }
  ChargeCache[key.str()] = charges;
  return charges;
}

//------------------------------------------------------------------------------
float vtkErrorDiffusionKernel::ChargeAt(float g) const
{
  const float level = 255.0f * (g > 0.5f ? 1.0f - g : g);
  const size_t n = this->KeyLevels.size();
  if (n == 0)
  {
    return 0.0f;
  }
  if (level <= this->KeyLevels.front())
  {
    return this->KeyCharges.front();
  }
  if (level >= this->KeyLevels.back())
  {
    return this->KeyCharges.back();
  }
  const size_t i =
    std::upper_bound(this->KeyLevels.begin(), this->KeyLevels.end(), level) - this->KeyLevels.begin();
  const float t = (level - this->KeyLevels[i - 1]) / (this->KeyLevels[i] - this->KeyLevels[i - 1]);
  return this->KeyCharges[i - 1] + t * (this->KeyCharges[i] - this->KeyCharges[i - 1]);
}

//------------------------------------------------------------------------------
vtkIdType vtkErrorDiffusionKernel::ProcessLayer(
  const float* density, const float* nextDensity, unsigned char* mask)
{
  if (this->NX == 0 || this->NY == 0)
  {
    return 0;
  }
  if (this->Method == METHOD_WHITE_NOISE)
  {
    return this->DrawLayerIndependently(density, mask);
  }
  const bool steady = this->BoundaryMode == BOUNDARY_STEADY_STATE;
  if (this->LayersDone == 0 && steady && this->WarmUpLayers > 0)
  {
    // Whole cycles, so layer 0 keeps its phase. The virtual layers repeat the
    // first layer, so each one's successor has the first layer's densities.
    const int warmUp = 4 * ((this->WarmUpLayers + 3) / 4);
    std::vector<unsigned char> discarded(this->Current.size());
    for (int w = 0; w < warmUp; ++w)
    {
      this->ScanLayer(density, density, discarded.data(), this->FirstLayer - warmUp + w);
      std::swap(this->Current, this->Next);
      std::fill(this->Next.begin(), this->Next.end(), 0.0f);
    }
  }
  // Past the last layer the steady-state mode lets the error leave through an
  // open layer whose voxels all take error; the paper's keeps it in the layer.
  const float* next = nextDensity;
  if (this->LayersDone + 1 >= this->NZ)
  {
    next = nullptr;
    if (steady)
    {
      this->OpenLayer.resize(this->Current.size(), 0.5f);
      next = this->OpenLayer.data();
    }
  }
  const vtkIdType count =
    this->ScanLayer(density, next, mask, this->FirstLayer + this->LayersDone);
  std::swap(this->Current, this->Next);
  std::fill(this->Next.begin(), this->Next.end(), 0.0f);
  ++this->LayersDone;
  return count;
}

//------------------------------------------------------------------------------
vtkIdType vtkErrorDiffusionKernel::DrawLayerIndependently(
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
// True when no voxel of the layer is saturated or empty. Fixed-size blocks
// with a branch-free body, so the compiler vectorises them; the test still
// stops at the first block with an inactive voxel.
bool AllActive(const float* g, size_t n)
{
  constexpr size_t block = 256;
  size_t i = 0;
  for (; i + block <= n; i += block)
  {
    int inactive = 0;
    for (size_t j = 0; j < block; ++j)
    {
      inactive |= static_cast<int>(!(g[i + j] > 0.0f)) | static_cast<int>(!(g[i + j] < 1.0f));
    }
    if (inactive)
    {
      return false;
    }
  }
  for (; i < n; ++i)
  {
    if (!Active(g[i]))
    {
      return false;
    }
  }
  return true;
}
}

//------------------------------------------------------------------------------
// Real volumes change g from voxel to voxel but hold few distinct values (an
// 8-bit MRI has at most 256): a small direct-mapped cache keyed by the bits
// of g spares most table interpolations, which cost several times the rest
// of a voxel's work.
const vtkErrorDiffusionKernel::LevelParameters& vtkErrorDiffusionKernel::ParametersOf(float g)
{
  std::uint32_t bits = 0;
  std::memcpy(&bits, &g, sizeof(bits));
  LevelParameters& entry = this->ParameterCache[(bits * 2654435761u) >> 24];
  if (entry.G != g)
  {
    const auto params = this->Table.Evaluate(g);
    std::copy(params.Weights.begin(), params.Weights.end(), entry.Weights);
    const float charge = this->ChargeAt(g);
    entry.Base = g <= 0.5f ? 0.5f - charge : 0.5f + charge;
    const float scale = static_cast<float>(this->ModulationScale);
    entry.Modulation = (g <= 0.5f ? scale : -scale) * params.Modulation;
    entry.G = g;
  }
  return entry;
}

//------------------------------------------------------------------------------
// The scan of one layer. Record keeps what each voxel received (for
// GetSteadyStateCharges) and costs a store per voxel, so it is a template
// flag. Rows away from the faces of a layer whose voxels and successors are
// all active take a path without any test on the targets: that is the bulk
// of the work on any large support, and the tests cost a third of the time.
template <bool Record>
vtkIdType vtkErrorDiffusionKernel::ScanLayer(
  const float* density, const float* next, unsigned char* mask, int layer)
{
  const bool nextLayerExists = next != nullptr;
  const size_t layerSize = static_cast<size_t>(this->NX) * this->NY;
  // A layer is tested once, as the successor, and the answer reused when it
  // comes up as the current layer (the caller passes the same densities).
  bool currentActive = false;
  if (density == this->TestedLayer)
  {
    currentActive = this->TestedLayerActive;
  }
  else
  {
    currentActive = AllActive(density, layerSize);
  }
  bool nextActive = false;
  if (nextLayerExists)
  {
    nextActive = next == density ? currentActive : AllActive(next, layerSize);
    this->TestedLayer = next;
    this->TestedLayerActive = nextActive;
  }
  const bool allActive = currentActive && nextActive;
  const LayerScan s = GetLayerScan(this->NX, this->NY, layer);
  float* cur = this->Current.data();
  float* nxt = this->Next.data();
  const vtkIdType V = s.VStride;

  float cachedG = -1.0f;
  float w[6] = { 0, 0, 0, 0, 0, 0 };
  float base = 0.5f;       // 0.5 - C(g) below g = 0.5, 0.5 + C(1 - g) above
  float modulation = 0.0f; // s * m(g), negative above g = 0.5 (the mirrored process)
  vtkIdType count = 0;

  for (int q = 0; q < s.NV; ++q)
  {
    const bool oddRow = (q & 1) != 0;
    const vtkIdType d = oddRow ? -s.UStride : s.UStride;
    vtkIdType idx = s.Start + q * V + (oddRow ? (s.NU - 1) * s.UStride : 0);
    const bool hasPrevRow = q > 0;
    const bool hasNextRow = q + 1 < s.NV;
    const bool fullRow = hasPrevRow && hasNextRow && nextLayerExists;
    const bool fastRow = fullRow && allActive;
    // The share for the next voxel of the row stays in a register: it is the
    // only dependency from one voxel to the next.
    float carry = 0.0f;
    for (int p = 0; p < s.NU; ++p, idx += d)
    {
      const float g = density[idx];
      const bool hasPrevU = p > 0;
      const bool hasNextU = p + 1 < s.NU;
      const bool fast = fastRow && hasPrevU && hasNextU;
      if (!fast && !Active(g))
      {
        const unsigned char b = g >= 1.0f ? 1 : 0;
        mask[idx] = b;
        count += b;
        carry = 0.0f;
        continue;
      }
      if (g != cachedG)
      {
        const LevelParameters& p = this->ParametersOf(g);
        std::copy(p.Weights, p.Weights + 6, w);
        base = p.Base;
        modulation = p.Modulation;
        cachedG = g;
      }
      const float value = (g + cur[idx]) + carry; // g + cur[idx] is off the critical path
      if (Record)
      {
        cur[idx] = value - g;
      }
      const float threshold = base + modulation * this->Random.Uniform();
      // Branch-free: near g = 0.5 a branch on the outcome is mispredicted
      // half of the time.
      const unsigned char b = value >= threshold ? 1 : 0;
      mask[idx] = b;
      count += b;
      const float e = value - static_cast<float>(b);

      if (fast)
      {
        // value * w - b * w: the product does not wait for the comparison.
        const float taken = value >= threshold ? w[TARGET_U] : 0.0f;
        carry = value * w[TARGET_U] - taken;
        cur[idx - d + V] += e * w[TARGET_BACK_V];
        cur[idx + V] += e * w[TARGET_V];
        nxt[idx - V] += e * w[TARGET_Z_BACKV];
        nxt[idx - d] += e * w[TARGET_Z_BACKU];
        nxt[idx] += e * w[TARGET_Z];
        continue;
      }
      // A face of the volume or of the support (saturated voxels around): the
      // targets that exist and are active share the error in proportion to
      // their weights.
      const bool valid[6] = { hasNextU && Active(density[idx + d]),
        hasPrevU && hasNextRow && Active(density[idx - d + V]),
        hasNextRow && Active(density[idx + V]),
        hasPrevRow && nextLayerExists && Active(next[idx - V]),
        hasPrevU && nextLayerExists && Active(next[idx - d]),
        nextLayerExists && Active(next[idx]) };
      float sum = 0.0f;
      for (int t = 0; t < 6; ++t)
      {
        sum += valid[t] ? w[t] : 0.0f;
      }
      carry = 0.0f;
      if (!(sum > 0.0f))
      {
        continue; // no active target: the error has nowhere to go
      }
      const float f = e / sum;
      if (valid[TARGET_U])
      {
        carry = f * w[TARGET_U];
      }
      if (valid[TARGET_BACK_V])
      {
        cur[idx - d + V] += f * w[TARGET_BACK_V];
      }
      if (valid[TARGET_V])
      {
        cur[idx + V] += f * w[TARGET_V];
      }
      if (valid[TARGET_Z_BACKV])
      {
        nxt[idx - V] += f * w[TARGET_Z_BACKV];
      }
      if (valid[TARGET_Z_BACKU])
      {
        nxt[idx - d] += f * w[TARGET_Z_BACKU];
      }
      if (valid[TARGET_Z])
      {
        nxt[idx] += f * w[TARGET_Z];
      }
    }
  }
  return count;
}
