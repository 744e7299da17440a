// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseSpectrumKernel.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <fftw3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <type_traits>

namespace
{
// Segment index of a frequency: which component of (|fx|, |fy|, |fz|) is largest.
enum Segment
{
  SegmentYZ = 0, // |fx| largest
  SegmentXZ = 1, // |fy| largest
  SegmentXY = 2  // |fz| largest
};

void SetError(std::string* error, const std::string& message)
{
  if (error)
  {
    *error = message;
  }
}

// Transforms per grid shape: a 2D real-to-complex transform of one z slab
// (in place, rows padded to 2 * (Lx / 2 + 1) doubles) and a batch of
// ColumnBlock 1D transforms along z over a small gathered block. FFTW's one-call
// 3D plan strides through the whole volume for its z pass; at 256^3 with
// FFTW_ESTIMATE that is 4 times slower than transforming z in blocks that stay
// in cache (and as fast as an FFTW_MEASURE plan, without its seconds of planning).
constexpr int ColumnBlock = 8;

struct TransformPlans
{
  fftw_plan Slab = nullptr;
  fftw_plan Columns = nullptr;
};

// FFTW's planner is not thread-safe, so every plan is made (and destroyed) under
// one lock; executing a plan on new arrays is thread-safe. Plans are kept for
// the life of the process: an optimiser evaluates one or two shapes many
// thousand times, and a plan is small next to its buffers. Every buffer comes
// from fftw_malloc and slabs start at multiples of 64 bytes, so all arrays
// share the alignment the plans were made with.
class PlanCache
{
public:
  static PlanCache& Instance()
  {
    static PlanCache cache;
    return cache;
  }

  TransformPlans Get(const int dims[3], double* slab, fftw_complex* columns)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    const std::array<int, 3> key{ { dims[0], dims[1], dims[2] } };
    auto it = this->Plans.find(key);
    if (it != this->Plans.end())
    {
      return it->second;
    }
    // FFTW_ESTIMATE leaves the buffers untouched while planning.
    TransformPlans plans;
    plans.Slab = fftw_plan_dft_r2c_2d(
      dims[1], dims[0], slab, reinterpret_cast<fftw_complex*>(slab), FFTW_ESTIMATE);
    const int n[1] = { dims[2] };
    plans.Columns = fftw_plan_many_dft(1, n, ColumnBlock, columns, nullptr, ColumnBlock, 1, columns,
      nullptr, ColumnBlock, 1, FFTW_FORWARD, FFTW_ESTIMATE);
    if (plans.Slab && plans.Columns)
    {
      this->Plans.emplace(key, plans);
      return plans;
    }
    Destroy(plans);
    return TransformPlans();
  }

  PlanCache(const PlanCache&) = delete;
  PlanCache& operator=(const PlanCache&) = delete;

private:
  PlanCache() = default;
  ~PlanCache()
  {
    for (auto& entry : this->Plans)
    {
      Destroy(entry.second);
    }
  }

  static void Destroy(const TransformPlans& plans)
  {
    if (plans.Slab)
    {
      fftw_destroy_plan(plans.Slab);
    }
    if (plans.Columns)
    {
      fftw_destroy_plan(plans.Columns);
    }
  }

  std::mutex Mutex;
  std::map<std::array<int, 3>, TransformPlans> Plans;
};

// Per-shell sums for one pass over the half spectrum. Counts are integers (a
// sample off the kx = 0 and kx = Lx / 2 planes stands for itself and its
// conjugate mirror, weight 2).
struct ShellSums
{
  double Sum = 0.0;
  double SumSquares = 0.0;
  long long Count = 0;
  double SegmentSum[3] = { 0.0, 0.0, 0.0 };
  long long SegmentCount[3] = { 0, 0, 0 };
};

struct Accumulator
{
  std::vector<ShellSums> Shells;
  double Total = 0.0; // all non-DC power
  double Low = 0.0;   // power with 0 < |f| < f_g
};

// One axis of length L: |k| folded into [-L/2, L/2) and the squared frequency.
struct AxisTable
{
  std::vector<double> Frequency2;   // (|k'| / L)^2
  std::vector<long long> Component; // |k'| times the other two lengths
};

AxisTable MakeAxisTable(int length, int count, long long otherLengths)
{
  AxisTable table;
  table.Frequency2.resize(count);
  table.Component.resize(count);
  for (int k = 0; k < count; ++k)
  {
    const int folded = (2 * k < length) ? k : length - k;
    const double f = static_cast<double>(folded) / length;
    table.Frequency2[k] = f * f;
    table.Component[k] = folded * otherLengths;
  }
  return table;
}

double PrincipalFrequency(double g)
{
  return g <= 0.5 ? std::cbrt(g) : std::cbrt(std::max(0.0, 1.0 - g));
}

// Pearson correlation; 0 when either curve is constant up to rounding, so that
// flat spectra give a defined (if pessimistic) symmetry instead of NaN.
double Correlation(const std::vector<double>& a, const std::vector<double>& b)
{
  const std::size_t n = a.size();
  if (n < 2)
  {
    return 0.0;
  }
  double meanA = 0.0, meanB = 0.0, maxA = 0.0, maxB = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    meanA += a[i];
    meanB += b[i];
    maxA = std::max(maxA, std::abs(a[i]));
    maxB = std::max(maxB, std::abs(b[i]));
  }
  meanA /= n;
  meanB /= n;
  double saa = 0.0, sbb = 0.0, sab = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double da = a[i] - meanA;
    const double db = b[i] - meanB;
    saa += da * da;
    sbb += db * db;
    sab += da * db;
  }
  const double tolA = 1e-12 * maxA;
  const double tolB = 1e-12 * maxB;
  if (saa <= n * tolA * tolA || sbb <= n * tolB * tolB)
  {
    return 0.0;
  }
  return std::max(-1.0, std::min(1.0, sab / std::sqrt(saa * sbb)));
}
}

//------------------------------------------------------------------------------
vtkBlueNoiseSpectrumKernel::vtkBlueNoiseSpectrumKernel() = default;

//------------------------------------------------------------------------------
vtkBlueNoiseSpectrumKernel::~vtkBlueNoiseSpectrumKernel()
{
  this->ReleaseBuffers();
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumKernel::ReleaseBuffers()
{
  fftw_free(this->Transform);
  fftw_free(this->Columns);
  fftw_free(this->PowerSum);
  this->Transform = nullptr;
  this->Columns = nullptr;
  this->PowerSum = nullptr;
  this->SlabPlan = nullptr;
  this->ColumnPlan = nullptr;
  this->SlabStride = 0;
  this->HalfSize = 0;
  std::fill(this->Dimensions, this->Dimensions + 3, 0);
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::SetDimensions(int lx, int ly, int lz, std::string* error)
{
  this->Reset();
  if (this->Transform && lx == this->Dimensions[0] && ly == this->Dimensions[1] &&
    lz == this->Dimensions[2])
  {
    return true;
  }
  this->ReleaseBuffers();
  if (lx < 2 || ly < 2 || lz < 2)
  {
    std::ostringstream msg;
    msg << "grid dimensions " << lx << " x " << ly << " x " << lz
        << " are invalid: every dimension must be at least 2";
    SetError(error, msg.str());
    return false;
  }
  const std::size_t halfX = static_cast<std::size_t>(lx) / 2 + 1;
  // Slabs start at multiples of 8 doubles (64 bytes) to keep one alignment.
  const std::size_t slabStride = (static_cast<std::size_t>(ly) * 2 * halfX + 7) / 8 * 8;
  if (slabStride > std::numeric_limits<std::size_t>::max() / sizeof(double) / 2 / lz)
  {
    SetError(error, "grid dimensions are too large to address");
    return false;
  }
  const std::size_t half = static_cast<std::size_t>(ly) * lz * halfX;
  this->Transform = static_cast<double*>(fftw_malloc(slabStride * lz * sizeof(double)));
  this->Columns = static_cast<double*>(fftw_malloc(2 * ColumnBlock * sizeof(double) * lz));
  this->PowerSum = static_cast<double*>(fftw_malloc(half * sizeof(double)));
  if (!this->Transform || !this->Columns || !this->PowerSum)
  {
    this->ReleaseBuffers();
    std::ostringstream msg;
    msg << "cannot allocate " << (slabStride * lz + half) * sizeof(double) << " bytes for a " << lx
        << " x " << ly << " x " << lz << " spectrum";
    SetError(error, msg.str());
    return false;
  }
  // The last block of a pass transforms some stale lanes; keep them defined.
  std::fill(this->Columns, this->Columns + 2 * ColumnBlock * static_cast<std::size_t>(lz), 0.0);
  const int dims[3] = { lx, ly, lz };
  const TransformPlans plans = PlanCache::Instance().Get(
    dims, this->Transform, reinterpret_cast<fftw_complex*>(this->Columns));
  if (!plans.Slab)
  {
    this->ReleaseBuffers();
    SetError(error, "FFTW could not plan the transform");
    return false;
  }
  this->SlabPlan = plans.Slab;
  this->ColumnPlan = plans.Columns;
  this->SlabStride = slabStride;
  std::copy(dims, dims + 3, this->Dimensions);
  this->HalfSize = half;
  return true;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumKernel::GetDimensions(int dims[3]) const
{
  std::copy(this->Dimensions, this->Dimensions + 3, dims);
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumKernel::SetWeight(double w)
{
  this->Weight = std::isnan(w) ? DefaultWeight : std::max(0.0, std::min(1.0, w));
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumKernel::Reset()
{
  this->Realisations = 0;
  this->ConstantRealisations = 0;
  this->PointSum = 0.0;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::AddRealisation(const unsigned char* mask, std::string* error)
{
  return this->AddRealisationTemplate(mask, error);
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::AddRealisation(const float* counts, std::string* error)
{
  return this->AddRealisationTemplate(counts, error);
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::AddRealisation(const double* counts, std::string* error)
{
  return this->AddRealisationTemplate(counts, error);
}

//------------------------------------------------------------------------------
template <typename T>
bool vtkBlueNoiseSpectrumKernel::AddRealisationTemplate(const T* values, std::string* error)
{
  if (!this->Transform)
  {
    SetError(error, "the grid dimensions are not set");
    return false;
  }
  if (!values)
  {
    SetError(error, "no values given");
    return false;
  }
  const int lx = this->Dimensions[0];
  const int ly = this->Dimensions[1];
  const int lz = this->Dimensions[2];
  const std::size_t padX = 2 * (static_cast<std::size_t>(lx) / 2 + 1);
  const auto slabPlan = static_cast<fftw_plan>(this->SlabPlan);
  const T first = values[0];
  double n = 0.0;
  bool constant = true;
  // Each z slab is filled and transformed in x and y while it is in cache.
  for (int z = 0; z < lz; ++z)
  {
    double* slab = this->Transform + z * this->SlabStride;
    for (int y = 0; y < ly; ++y)
    {
      const T* src = values + (static_cast<std::size_t>(z) * ly + y) * lx;
      double* dst = slab + y * padX;
      double rowSum = 0.0;
      bool rowConstant = true;
      for (int x = 0; x < lx; ++x)
      {
        const double v = static_cast<double>(src[x]);
        if (std::is_floating_point<T>::value &&
          !(v >= 0.0 && v <= std::numeric_limits<double>::max()))
        {
          std::ostringstream msg;
          msg << "the count at voxel (" << x << ", " << y << ", " << z << ") is " << v
              << ": counts must be finite and non-negative";
          SetError(error, msg.str());
          return false;
        }
        dst[x] = v;
        rowSum += v;
        rowConstant &= (src[x] == first);
      }
      n += rowSum;
      constant &= rowConstant;
    }
    fftw_execute_dft_r2c(slabPlan, slab, reinterpret_cast<fftw_complex*>(slab));
  }
  if (n <= 0.0)
  {
    SetError(
      error, "the realisation has no points (N = 0): the spectrum P = |B|^2 / N is undefined");
    return false;
  }

  const bool firstRealisation = (this->Realisations == 0);
  if (constant)
  {
    // A constant volume has no power off DC: the transform would only add
    // rounding noise, so its contribution is exactly zero.
    if (firstRealisation)
    {
      std::fill(this->PowerSum, this->PowerSum + this->HalfSize, 0.0);
    }
    ++this->ConstantRealisations;
  }
  else
  {
    // z transforms over blocks of ColumnBlock (kx, ky) columns gathered from
    // the slabs; the power goes straight from the block to the sum.
    const auto columnPlan = static_cast<fftw_plan>(this->ColumnPlan);
    auto* block = reinterpret_cast<fftw_complex*>(this->Columns);
    const std::size_t columns = this->HalfSize / lz;
    const double invN = 1.0 / n;
    for (std::size_t c0 = 0; c0 < columns; c0 += ColumnBlock)
    {
      const std::size_t width = std::min<std::size_t>(ColumnBlock, columns - c0);
      for (int z = 0; z < lz; ++z)
      {
        const auto* slab =
          reinterpret_cast<const fftw_complex*>(this->Transform + z * this->SlabStride);
        std::memcpy(block + z * ColumnBlock, slab + c0, width * sizeof(fftw_complex));
      }
      fftw_execute_dft(columnPlan, block, block);
      for (int z = 0; z < lz; ++z)
      {
        const fftw_complex* b = block + z * ColumnBlock;
        double* power = this->PowerSum + z * columns + c0;
        for (std::size_t i = 0; i < width; ++i)
        {
          const double p = (b[i][0] * b[i][0] + b[i][1] * b[i][1]) * invN;
          power[i] = firstRealisation ? p : power[i] + p;
        }
      }
    }
  }
  ++this->Realisations;
  this->PointSum += n;
  return true;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::Compute(Result& out, std::string* error) const
{
  if (this->Realisations == 0)
  {
    SetError(error, "no realisation has been added");
    return false;
  }
  const int lx = this->Dimensions[0];
  const int ly = this->Dimensions[1];
  const int lz = this->Dimensions[2];
  const int lmin = std::min(lx, std::min(ly, lz));
  const int halfX = lx / 2 + 1;
  const double voxels = static_cast<double>(lx) * ly * lz;

  const AxisTable ax = MakeAxisTable(lx, halfX, static_cast<long long>(ly) * lz);
  const AxisTable ay = MakeAxisTable(ly, ly, static_cast<long long>(lx) * lz);
  const AxisTable az = MakeAxisTable(lz, lz, static_cast<long long>(lx) * ly);
  // The corner frequency has the largest radius; rounding is monotonic, so no
  // sample can land on a higher shell than the corner's.
  const int maxShell = static_cast<int>(
    std::sqrt(az.Frequency2[lz / 2] + ay.Frequency2[ly / 2] + ax.Frequency2[lx / 2]) * lmin + 0.5);

  const double meanPoints = this->PointSum / this->Realisations;
  const double density = meanPoints / voxels;
  const double fg = PrincipalFrequency(density);
  // |f| < f_g = cbrt(h) is tested as |f|^6 < h^2: cbrt is not correctly
  // rounded (cbrt(2^-9) < 1/8 in glibc), the cubes are exact on dyadic grids.
  const double h = density <= 0.5 ? density : std::max(0.0, 1.0 - density);
  const double h2 = h * h;

  vtkSMPThreadLocal<Accumulator> locals;
  const double* power = this->PowerSum;
  const bool evenX = (lx % 2 == 0);
  // At least 2^18 samples per task: below that, threads cost more than the pass.
  const vtkIdType rows = static_cast<vtkIdType>(ly) * lz;
  const vtkIdType grain = std::max<vtkIdType>(1, (vtkIdType(1) << 18) / halfX);
  vtkSMPTools::For(0, rows, grain, [&](vtkIdType beginRow, vtkIdType endRow) {
    Accumulator& acc = locals.Local();
    if (acc.Shells.empty())
    {
      acc.Shells.resize(maxShell + 1);
    }
    ShellSums* shells = acc.Shells.data();
    double total = 0.0;
    double low = 0.0;
    for (vtkIdType row = beginRow; row < endRow; ++row)
    {
      const int z = static_cast<int>(row / ly);
      const int y = static_cast<int>(row % ly);
      const double yz2 = az.Frequency2[z] + ay.Frequency2[y];
      const long long cy = ay.Component[y];
      const long long cz = az.Component[z];
      const long long cyz = std::max(cy, cz);
      const int rowSegment = (cy >= cz) ? SegmentXZ : SegmentXY;
      const double* p = power + row * halfX;
      for (int x = (row == 0) ? 1 : 0; x < halfX; ++x)
      {
        const double f2 = yz2 + ax.Frequency2[x];
        ShellSums& s = shells[static_cast<int>(std::sqrt(f2) * lmin + 0.5)];
        const int w = (x == 0 || (evenX && x == halfX - 1)) ? 1 : 2;
        const double v = p[x];
        const double wv = w * v;
        s.Sum += wv;
        s.SumSquares += wv * v;
        s.Count += w;
        const int segment = (ax.Component[x] >= cyz) ? SegmentYZ : rowSegment;
        s.SegmentSum[segment] += wv;
        s.SegmentCount[segment] += w;
        total += wv;
        if (f2 * f2 * f2 < h2)
        {
          low += wv;
        }
      }
    }
    acc.Total += total;
    acc.Low += low;
  });

  Accumulator sum;
  sum.Shells.resize(maxShell + 1);
  for (const Accumulator& acc : locals)
  {
    if (acc.Shells.empty())
    {
      continue;
    }
    for (int n = 0; n <= maxShell; ++n)
    {
      ShellSums& d = sum.Shells[n];
      const ShellSums& s = acc.Shells[n];
      d.Sum += s.Sum;
      d.SumSquares += s.SumSquares;
      d.Count += s.Count;
      for (int k = 0; k < 3; ++k)
      {
        d.SegmentSum[k] += s.SegmentSum[k];
        d.SegmentCount[k] += s.SegmentCount[k];
      }
    }
    sum.Total += acc.Total;
    sum.Low += acc.Low;
  }

  // The sums are over the summed power; dividing once here averages it.
  const double invR = 1.0 / this->Realisations;
  const std::size_t nShells = static_cast<std::size_t>(maxShell);
  out.Frequency.resize(nShells);
  out.RadialPower.resize(nShells);
  out.Anisotropy.resize(nShells);
  out.AnisotropyDB.resize(nShells);
  out.SrapsXY.resize(nShells);
  out.SrapsXZ.resize(nShells);
  out.SrapsYZ.resize(nShells);
  out.ShellCount.resize(nShells);
  for (int n = 1; n <= maxShell; ++n)
  {
    const ShellSums& s = sum.Shells[n];
    const std::size_t i = static_cast<std::size_t>(n - 1);
    const double shellSum = s.Sum * invR;
    const double mean = s.Count > 0 ? shellSum / s.Count : 0.0;
    double anisotropy = 0.0;
    if (s.Count >= 2 && mean > 0.0)
    {
      const double variance =
        std::max(0.0, (s.SumSquares * invR * invR - shellSum * mean) / (s.Count - 1));
      anisotropy = variance / (mean * mean);
    }
    out.Frequency[i] = static_cast<double>(n) / lmin;
    out.RadialPower[i] = mean;
    out.Anisotropy[i] = anisotropy;
    out.AnisotropyDB[i] = anisotropy > 0.0
      ? std::max(AnisotropyFloorDB, 10.0 * std::log10(anisotropy))
      : AnisotropyFloorDB;
    const auto segmentMean = [&](int k) {
      return s.SegmentCount[k] > 0 ? s.SegmentSum[k] * invR / s.SegmentCount[k] : 0.0;
    };
    out.SrapsXY[i] = segmentMean(SegmentXY);
    out.SrapsXZ[i] = segmentMean(SegmentXZ);
    out.SrapsYZ[i] = segmentMean(SegmentYZ);
    out.ShellCount[i] = s.Count;
  }

  std::vector<double> xy, xz, yz;
  const int lastCorrelated = std::min(maxShell, lmin / 2);
  for (int n = 1; n <= lastCorrelated; ++n)
  {
    // Up to Lmin / 2 every axis reaches every shell, so no segment is empty
    // there on any grid; the test keeps empty segments out should that change.
    const ShellSums& s = sum.Shells[n];
    if (s.SegmentCount[0] > 0 && s.SegmentCount[1] > 0 && s.SegmentCount[2] > 0)
    {
      xy.push_back(out.SrapsXY[n - 1]);
      xz.push_back(out.SrapsXZ[n - 1]);
      yz.push_back(out.SrapsYZ[n - 1]);
    }
  }
  const double correlation =
    (Correlation(xy, xz) + Correlation(xy, yz) + Correlation(xz, yz)) / 3.0;

  out.Dimensions[0] = lx;
  out.Dimensions[1] = ly;
  out.Dimensions[2] = lz;
  out.Realisations = this->Realisations;
  out.NumberOfPoints = meanPoints;
  out.Density = density;
  out.PrincipalFrequency = fg;
  out.LowFrequencyRatio = sum.Total > 0.0 ? sum.Low / sum.Total : 0.0;
  out.SymmetryCorrelation = correlation;
  out.Symmetry = 1.0 - correlation;
  out.TargetValue = this->Weight * out.LowFrequencyRatio + (1.0 - this->Weight) * out.Symmetry;
  out.Warning.clear();
  if (this->ConstantRealisations == this->Realisations)
  {
    out.Warning = "every voxel holds the same count in every realisation (g = 1 for a mask): "
                  "there is no power off DC, so L = 0, every anisotropy is 0 and S = 1 "
                  "(correlation of constant curves taken as 0)";
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::GetCentredPowerSpectrum(std::vector<double>& out) const
{
  if (this->Realisations == 0)
  {
    out.clear();
    return false;
  }
  out.resize(
    static_cast<std::size_t>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2]);
  return this->GetCentredPowerSpectrum(out.data());
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::GetCentredPowerSpectrum(double* out) const
{
  if (this->Realisations == 0 || !out)
  {
    return false;
  }
  const int lx = this->Dimensions[0];
  const int ly = this->Dimensions[1];
  const int lz = this->Dimensions[2];
  const std::size_t halfX = static_cast<std::size_t>(lx) / 2 + 1;
  const double invR = 1.0 / this->Realisations;
  double* dst = out;
  for (int k = 0; k < lz; ++k)
  {
    const int kz = (k - lz / 2 + lz) % lz;
    for (int j = 0; j < ly; ++j)
    {
      const int ky = (j - ly / 2 + ly) % ly;
      // Frequencies with kx > Lx / 2 are the conjugate mirrors of stored ones.
      const double* direct = this->PowerSum + (static_cast<std::size_t>(kz) * ly + ky) * halfX;
      const double* mirror =
        this->PowerSum + (static_cast<std::size_t>((lz - kz) % lz) * ly + (ly - ky) % ly) * halfX;
      for (int i = 0; i < lx; ++i)
      {
        const int kx = (i - lx / 2 + lx) % lx;
        const double v = (kx <= lx / 2) ? direct[kx] : mirror[lx - kx];
        *dst++ = v * invR;
      }
    }
  }
  out[(static_cast<std::size_t>(lz / 2) * ly + ly / 2) * lx + lx / 2] = 0.0;
  return true;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::Evaluate(
  const unsigned char* mask, const int dims[3], double weight, Result& out, std::string* error)
{
  thread_local vtkBlueNoiseSpectrumKernel kernel;
  if (!kernel.SetDimensions(dims[0], dims[1], dims[2], error))
  {
    return false;
  }
  kernel.SetWeight(weight);
  return kernel.AddRealisation(mask, error) && kernel.Compute(out, error);
}
