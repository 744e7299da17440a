// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseSpectrumKernel.h"

#include "vtkSMPTools.h"

#include <fftw3.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <type_traits>

#if defined(__linux__)
#include <sys/mman.h>
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23 // Linux 5.14; older kernels answer EINVAL
#endif
#endif

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

// At least 2^18 values per task: below that, threads cost more than they
// save (a 64^3 grid runs on the calling thread).
constexpr vtkIdType ValuesPerTask = vtkIdType(1) << 18;

vtkIdType SlabGrain(int lx, int ly)
{
  return std::max<vtkIdType>(1, ValuesPerTask / (static_cast<vtkIdType>(lx) * ly));
}

//------------------------------------------------------------------------------
// The buffers of a large grid are committed in bulk before the transform
// writes them: faulting them in page by page as the first write reaches them
// costs more than the transform on virtual machines that trap every fault,
// and transparent huge pages cut the number of pages by 512 where the system
// offers them. Small buffers (an optimizer's grids) are left to the usual
// first touch. The memory comes from posix_memalign, so free() releases it;
// either alignment satisfies FFTW.
constexpr std::size_t LargeBytes = std::size_t(1) << 24;     // 16 MiB
constexpr std::size_t LargeAlignment = std::size_t(1) << 21; // 2 MiB: huge pages
constexpr std::size_t SmallAlignment = 64;
constexpr std::size_t CommitChunk = std::size_t(1) << 26; // 64 MiB per task

// False when the system has not the memory: with overcommit an allocation
// succeeds whatever its size, and writing it is what fails (the process is
// killed), so the commit is where a grid too large for the memory is found.
bool CommitPages(char* begin, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise(begin, bytes, MADV_HUGEPAGE); // advice only: a failure changes nothing
#endif
#if defined(__linux__)
  const vtkIdType chunks = static_cast<vtkIdType>((bytes + CommitChunk - 1) / CommitChunk);
  std::atomic<bool> committed(true);
  vtkSMPTools::For(0, chunks, 1,
    [&](vtkIdType first, vtkIdType last)
    {
      for (vtkIdType c = first; c < last && committed.load(std::memory_order_relaxed); ++c)
      {
        char* chunk = begin + c * CommitChunk;
        const std::size_t size =
          std::min(CommitChunk, bytes - static_cast<std::size_t>(c) * CommitChunk);
        if (madvise(chunk, size, MADV_POPULATE_WRITE) == 0)
        {
          continue;
        }
        if (errno == ENOMEM || errno == EFAULT)
        {
          committed = false; // the pages cannot be had
        }
        else
        {
          std::memset(chunk, 0, size); // EINVAL (before Linux 5.14): first touch, in parallel
        }
      }
    });
  return committed.load();
#else
  (void)begin;
  (void)bytes;
  return true;
#endif
}

double* AllocateLarge(std::size_t count)
{
  const std::size_t bytes = count * sizeof(double);
  const bool large = bytes >= LargeBytes;
  void* memory = nullptr;
  if (posix_memalign(&memory, large ? LargeAlignment : SmallAlignment, bytes) != 0)
  {
    return nullptr;
  }
  if (large && !CommitPages(static_cast<char*>(memory), bytes))
  {
    std::free(memory);
    return nullptr;
  }
  return static_cast<double*>(memory);
}

//------------------------------------------------------------------------------
// Transforms per grid shape: a 2D real-to-complex transform of one z slab
// (in place, rows padded to 2 * (Lx / 2 + 1) doubles) and a batch of
// ColumnBlock 1D transforms along z over a small gathered block. FFTW's one-call
// 3D plan strides through the whole volume for its z pass, out of cache;
// slabs and in-cache column blocks take a fraction of its time on one core
// (BenchmarkSpectrum compares the two). Slabs and
// blocks are independent, so they are spread over vtkSMPTools threads, every
// one executing the same single-threaded plans: the result does not depend on
// the number of threads.
constexpr int ColumnBlock = 8;

struct TransformPlans
{
  fftw_plan Slab = nullptr;
  fftw_plan Columns = nullptr;
};

// FFTW's planner is not thread-safe, so every plan is made (and destroyed) under
// one lock; executing a plan on new arrays is thread-safe. The plans of a
// shape are shared by the kernels that hold them (an optimizer's kernel keeps
// one shape for many thousand transforms) and destroyed with the last holder:
// the process keeps no plan. Plans are made on arrays aligned like every
// array they later run on (slabs start at multiples of 64 bytes of 2 MiB
// aligned buffers, column blocks come from fftw_malloc).
class PlanRegistry
{
public:
  static std::shared_ptr<const TransformPlans> Get(const int dims[3], double* slab)
  {
    State& state = Instance();
    std::lock_guard<std::mutex> lock(state.Mutex);
    const std::array<int, 3> key{ { dims[0], dims[1], dims[2] } };
    auto it = state.Plans.find(key);
    if (it != state.Plans.end())
    {
      // An expired entry's release is waiting for the lock: it is replaced.
      if (auto plans = it->second.Owned.lock())
      {
        return plans;
      }
    }
    // FFTW_ESTIMATE leaves the arrays untouched while planning.
    auto* plans = new TransformPlans;
    plans->Slab = fftw_plan_dft_r2c_2d(
      dims[1], dims[0], slab, reinterpret_cast<fftw_complex*>(slab), FFTW_ESTIMATE);
    auto* columns = static_cast<fftw_complex*>(
      fftw_malloc(sizeof(fftw_complex) * ColumnBlock * static_cast<std::size_t>(dims[2])));
    const int n[1] = { dims[2] };
    plans->Columns = columns ? fftw_plan_many_dft(1, n, ColumnBlock, columns, nullptr, ColumnBlock,
                                 1, columns, nullptr, ColumnBlock, 1, FFTW_FORWARD, FFTW_ESTIMATE)
                             : nullptr;
    fftw_free(columns);
    if (!plans->Slab || !plans->Columns)
    {
      Destroy(plans);
      return nullptr;
    }
    std::shared_ptr<const TransformPlans> held(plans, [key](const TransformPlans* p) {
      State& registry = Instance();
      std::lock_guard<std::mutex> released(registry.Mutex);
      auto entry = registry.Plans.find(key);
      if (entry != registry.Plans.end() && entry->second.Plans == p)
      {
        registry.Plans.erase(entry);
      }
      Destroy(p);
    });
    state.Plans[key] = { plans, held };
    return held;
  }

private:
  struct Entry
  {
    const TransformPlans* Plans;
    std::weak_ptr<const TransformPlans> Owned;
  };
  struct State
  {
    std::mutex Mutex;
    std::map<std::array<int, 3>, Entry> Plans;
  };

  // Never destroyed: a kernel may be released by another library's static
  // object after this one's statics are gone.
  static State& Instance()
  {
    static State* state = new State;
    return *state;
  }

  static void Destroy(const TransformPlans* plans) // with the lock held
  {
    if (plans->Slab)
    {
      fftw_destroy_plan(plans->Slab);
    }
    if (plans->Columns)
    {
      fftw_destroy_plan(plans->Columns);
    }
    delete plans;
  }
};

// One task's block of ColumnBlock columns along z, allocated on first use.
// The last block of a pass transforms some stale lanes, so the block starts
// zeroed to keep them defined.
class ColumnScratch
{
public:
  ColumnScratch() = default;
  ~ColumnScratch() { fftw_free(this->Block); }
  ColumnScratch(const ColumnScratch&) = delete;
  ColumnScratch& operator=(const ColumnScratch&) = delete;

  fftw_complex* Get(int lz)
  {
    if (!this->Block)
    {
      const std::size_t n = static_cast<std::size_t>(ColumnBlock) * lz;
      this->Block = static_cast<fftw_complex*>(fftw_malloc(n * sizeof(fftw_complex)));
      if (this->Block)
      {
        std::fill(&this->Block[0][0], &this->Block[0][0] + 2 * n, 0.0);
      }
    }
    return this->Block;
  }

private:
  fftw_complex* Block = nullptr;
};

// What the fill of one z slab found: the row sums (in the order the old
// sequential pass added them, so that N is the same to the last bit), the
// value range (equal ends: a constant volume) and the first invalid count.
struct SlabCheck
{
  double Min = std::numeric_limits<double>::infinity();
  double Max = -std::numeric_limits<double>::infinity();
  bool Invalid = false;
  int BadX = 0;
  int BadY = 0;
  double BadValue = 0.0;
};

// Fills one padded slab row from x-fastest values and checks them; returns
// the row sum as the sequence of double additions in x order (for a mask the
// partial sums are whole numbers, so an integer sum is the same number).
template <typename T>
double FillRow(const T* src, int lx, double* dst, int y, SlabCheck& check)
{
  if constexpr (std::is_integral<T>::value)
  {
    static_assert(std::is_unsigned<T>::value, "counts of an integral type are unsigned");
    unsigned long long sum = 0;
    T low = src[0];
    T high = src[0];
    for (int x = 0; x < lx; ++x)
    {
      const T v = src[x];
      dst[x] = static_cast<double>(v);
      sum += v;
      low = std::min(low, v);
      high = std::max(high, v);
    }
    check.Min = std::min(check.Min, static_cast<double>(low));
    check.Max = std::max(check.Max, static_cast<double>(high));
    return static_cast<double>(sum);
  }
  else
  {
    double sum = 0.0;
    double low = check.Min;
    double high = check.Max;
    bool valid = true;
    for (int x = 0; x < lx; ++x)
    {
      const double v = static_cast<double>(src[x]);
      dst[x] = v;
      sum += v;
      low = std::min(low, v);
      high = std::max(high, v);
      valid &= (v >= 0.0) & (v <= std::numeric_limits<double>::max());
    }
    check.Min = low;
    check.Max = high;
    for (int x = 0; !valid && !check.Invalid && x < lx; ++x)
    {
      if (!(dst[x] >= 0.0 && dst[x] <= std::numeric_limits<double>::max()))
      {
        check.Invalid = true;
        check.BadX = x;
        check.BadY = y;
        check.BadValue = dst[x];
      }
    }
    return sum;
  }
}

//------------------------------------------------------------------------------
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

  void Add(const ShellSums& s)
  {
    this->Sum += s.Sum;
    this->SumSquares += s.SumSquares;
    this->Count += s.Count;
    for (int k = 0; k < 3; ++k)
    {
      this->SegmentSum[k] += s.SegmentSum[k];
      this->SegmentCount[k] += s.SegmentCount[k];
    }
  }
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

// The frequency lattice of the half spectrum, as Compute() walks it.
struct ShellGeometry
{
  int Lx = 0, Ly = 0, Lz = 0, Lmin = 0, HalfX = 0, MaxShell = 0;
  AxisTable X, Y, Z;

  explicit ShellGeometry(const int dims[3])
    : Lx(dims[0])
    , Ly(dims[1])
    , Lz(dims[2])
    , Lmin(std::min(dims[0], std::min(dims[1], dims[2])))
    , HalfX(dims[0] / 2 + 1)
    , X(MakeAxisTable(dims[0], dims[0] / 2 + 1, static_cast<long long>(dims[1]) * dims[2]))
    , Y(MakeAxisTable(dims[1], dims[1], static_cast<long long>(dims[0]) * dims[2]))
    , Z(MakeAxisTable(dims[2], dims[2], static_cast<long long>(dims[0]) * dims[1]))
  {
    // The corner frequency has the largest radius; rounding is monotonic, so no
    // sample can land on a higher shell than the corner's.
    this->MaxShell =
      static_cast<int>(std::sqrt(this->Z.Frequency2[this->Lz / 2] +
                         this->Y.Frequency2[this->Ly / 2] + this->X.Frequency2[this->Lx / 2]) *
          this->Lmin +
        0.5);
  }
};

// Where the accumulated power is: with one realization, in place in the
// transform buffer (the real part of each complex slot); from the second on,
// in the dense PowerSum buffer.
struct PowerView
{
  const double* Base = nullptr;
  std::size_t SlabStride = 0; // doubles from one z to the next
  std::size_t RowStride = 0;  // doubles from one y to the next
  std::size_t Step = 1;       // doubles from one kx to the next

  PowerView(const double* base, const std::size_t strides[3])
    : Base(base)
    , SlabStride(strides[0])
    , RowStride(strides[1])
    , Step(strides[2])
  {
  }

  const double* Row(int y, int z) const
  {
    return this->Base + z * this->SlabStride + y * this->RowStride;
  }
};

// The rows (y, z) of the half spectrum are summed in a fixed number of
// contiguous chunks whose partial sums are added in chunk order, so the
// result is the same whatever the number of threads.
constexpr vtkIdType ShellChunks = 64;

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

void SumShellRows(const ShellGeometry& g, const PowerView& power, double h2, vtkIdType beginRow,
  vtkIdType endRow, Accumulator& acc)
{
  acc.Shells.assign(static_cast<std::size_t>(g.MaxShell) + 1, ShellSums());
  ShellSums* shells = acc.Shells.data();
  const bool evenX = (g.Lx % 2 == 0);
  double total = 0.0;
  double low = 0.0;
  for (vtkIdType row = beginRow; row < endRow; ++row)
  {
    const int z = static_cast<int>(row / g.Ly);
    const int y = static_cast<int>(row % g.Ly);
    const double yz2 = g.Z.Frequency2[z] + g.Y.Frequency2[y];
    const long long cy = g.Y.Component[y];
    const long long cz = g.Z.Component[z];
    const long long cyz = std::max(cy, cz);
    const int rowSegment = (cy >= cz) ? SegmentXZ : SegmentXY;
    const double* p = power.Row(y, z);
    const std::size_t step = power.Step;
    for (int x = (row == 0) ? 1 : 0; x < g.HalfX; ++x)
    {
      const double f2 = yz2 + g.X.Frequency2[x];
      ShellSums& s = shells[static_cast<int>(std::sqrt(f2) * g.Lmin + 0.5)];
      const int w = (x == 0 || (evenX && x == g.HalfX - 1)) ? 1 : 2;
      const double v = p[x * step];
      const double wv = w * v;
      s.Sum += wv;
      s.SumSquares += wv * v;
      s.Count += w;
      const int segment = (g.X.Component[x] >= cyz) ? SegmentYZ : rowSegment;
      s.SegmentSum[segment] += wv;
      s.SegmentCount[segment] += w;
      total += wv;
      if (f2 * f2 * f2 < h2)
      {
        low += wv;
      }
    }
  }
  acc.Total = total;
  acc.Low = low;
}

Accumulator SumShells(const ShellGeometry& g, const PowerView& power, double h2)
{
  const vtkIdType rows = static_cast<vtkIdType>(g.Ly) * g.Lz;
  const vtkIdType chunks = std::min(rows, ShellChunks);
  std::vector<Accumulator> partial(static_cast<std::size_t>(chunks));
  // At least 2^18 samples per task: below that, threads cost more than the pass.
  const vtkIdType grain = std::max<vtkIdType>(1, ((vtkIdType(1) << 18) / g.HalfX) * chunks / rows);
  vtkSMPTools::For(0, chunks, grain,
    [&](vtkIdType c0, vtkIdType c1)
    {
      for (vtkIdType c = c0; c < c1; ++c)
      {
        SumShellRows(g, power, h2, rows * c / chunks, rows * (c + 1) / chunks, partial[c]);
      }
    });
  Accumulator sum;
  sum.Shells.resize(static_cast<std::size_t>(g.MaxShell) + 1);
  for (const Accumulator& acc : partial)
  {
    for (int n = 0; n <= g.MaxShell; ++n)
    {
      sum.Shells[n].Add(acc.Shells[n]);
    }
    sum.Total += acc.Total;
    sum.Low += acc.Low;
  }
  return sum;
}

void FillShells(const Accumulator& sum, const ShellGeometry& g, int realizations,
  vtkBlueNoiseSpectrumKernel::Result& out)
{
  constexpr double floorDB = vtkBlueNoiseSpectrumKernel::AnisotropyFloorDB;
  // The sums are over the summed power; dividing once here averages it.
  const double invR = 1.0 / realizations;
  const std::size_t nShells = static_cast<std::size_t>(g.MaxShell);
  for (auto* column : { &out.Frequency, &out.RadialPower, &out.Anisotropy, &out.AnisotropyDB,
         &out.SrapsXY, &out.SrapsXZ, &out.SrapsYZ })
  {
    column->resize(nShells);
  }
  out.ShellCount.resize(nShells);
  for (int n = 1; n <= g.MaxShell; ++n)
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
    out.Frequency[i] = static_cast<double>(n) / g.Lmin;
    out.RadialPower[i] = mean;
    out.Anisotropy[i] = anisotropy;
    out.AnisotropyDB[i] =
      anisotropy > 0.0 ? std::max(floorDB, 10.0 * std::log10(anisotropy)) : floorDB;
    const auto segmentMean = [&](int k)
    { return s.SegmentCount[k] > 0 ? s.SegmentSum[k] * invR / s.SegmentCount[k] : 0.0; };
    out.SrapsXY[i] = segmentMean(SegmentXY);
    out.SrapsXZ[i] = segmentMean(SegmentXZ);
    out.SrapsYZ[i] = segmentMean(SegmentYZ);
    out.ShellCount[i] = s.Count;
  }
}

double SymmetryCorrelation(
  const Accumulator& sum, const ShellGeometry& g, const vtkBlueNoiseSpectrumKernel::Result& out)
{
  std::vector<double> xy, xz, yz;
  const int lastCorrelated = std::min(g.MaxShell, g.Lmin / 2);
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
  return (Correlation(xy, xz) + Correlation(xy, yz) + Correlation(xz, yz)) / 3.0;
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
  std::free(this->Transform);
  std::free(this->PowerSum);
  this->Transform = nullptr;
  this->PowerSum = nullptr;
  this->PowerInTransform = false;
  this->SlabPlan = nullptr;
  this->ColumnPlan = nullptr;
  this->Plans = nullptr;
  this->SlabStride = 0;
  this->HalfSize = 0;
  std::fill(this->Dimensions, this->Dimensions + 3, 0);
}

//------------------------------------------------------------------------------
double vtkBlueNoiseSpectrumKernel::BufferBytes(int lx, int ly, int lz, bool severalRealizations)
{
  const double half = static_cast<double>(lz) * ly * (lx / 2 + 1) * sizeof(double);
  return (severalRealizations ? 3.0 : 2.0) * half;
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
  this->Transform = AllocateLarge(slabStride * lz);
  if (!this->Transform)
  {
    std::ostringstream msg;
    msg << "cannot allocate " << slabStride * lz * sizeof(double) << " bytes for a " << lx << " x "
        << ly << " x " << lz << " spectrum";
    SetError(error, msg.str());
    return false;
  }
  const int dims[3] = { lx, ly, lz };
  auto plans = PlanRegistry::Get(dims, this->Transform);
  if (!plans)
  {
    this->ReleaseBuffers();
    SetError(error, "FFTW could not plan the transform");
    return false;
  }
  this->SlabPlan = plans->Slab;
  this->ColumnPlan = plans->Columns;
  this->Plans = std::move(plans);
  this->SlabStride = slabStride;
  std::copy(dims, dims + 3, this->Dimensions);
  this->HalfSize = static_cast<std::size_t>(ly) * lz * halfX;
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
  this->Realizations = 0;
  this->ConstantRealizations = 0;
  this->PointSum = 0.0;
  this->PowerInTransform = false;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::AddRealization(const unsigned char* mask, std::string* error)
{
  return this->AddRealizationTemplate(mask, error);
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::AddRealization(const float* counts, std::string* error)
{
  return this->AddRealizationTemplate(counts, error);
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::AddRealization(const double* counts, std::string* error)
{
  return this->AddRealizationTemplate(counts, error);
}

//------------------------------------------------------------------------------
template <typename T>
bool vtkBlueNoiseSpectrumKernel::AddRealizationTemplate(const T* values, std::string* error)
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
  return this->TransformRealization(
    [values, lx, ly](int z, double* slab, double* rowSums, SlabCheck& check)
    {
      const std::size_t padX = 2 * (static_cast<std::size_t>(lx) / 2 + 1);
      for (int y = 0; y < ly; ++y)
      {
        const T* src = values + (static_cast<std::size_t>(z) * ly + y) * lx;
        rowSums[y] = FillRow(src, lx, slab + y * padX, y, check);
      }
    },
    error);
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::AddSamples(
  const long long* voxels, const float* weights, std::size_t count, std::string* error)
{
  if (!this->Transform)
  {
    SetError(error, "the grid dimensions are not set");
    return false;
  }
  if (count > 0 && !voxels)
  {
    SetError(error, "no voxel indices given");
    return false;
  }
  // The samples of each z slab, in the order given: a stable counting sort.
  const int lx = this->Dimensions[0];
  const int ly = this->Dimensions[1];
  const int lz = this->Dimensions[2];
  const long long slabSize = static_cast<long long>(lx) * ly;
  std::vector<std::size_t> first(static_cast<std::size_t>(lz) + 1, 0);
  for (std::size_t i = 0; i < count; ++i)
  {
    const float w = weights ? weights[i] : 1.0f;
    if (voxels[i] < 0 || voxels[i] >= slabSize * lz || !(w >= 0.0f && std::isfinite(w)))
    {
      std::ostringstream msg;
      msg << "sample " << i << " (voxel " << voxels[i] << ", weight " << w
          << ") is outside the grid or has a weight that is negative or not finite";
      SetError(error, msg.str());
      return false;
    }
    ++first[static_cast<std::size_t>(voxels[i] / slabSize) + 1];
  }
  for (int z = 0; z < lz; ++z)
  {
    first[z + 1] += first[z];
  }
  std::vector<std::size_t> order(count);
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for (std::size_t i = 0; i < count; ++i)
  {
    order[next[static_cast<std::size_t>(voxels[i] / slabSize)]++] = i;
  }
  // Samples on one voxel add up in single precision, in the order given: the
  // values a float count volume filled in that order would hold.
  return this->TransformRealization(
    [&](int z, double* slab, double* rowSums, SlabCheck& check)
    {
      const std::size_t padX = 2 * (static_cast<std::size_t>(lx) / 2 + 1);
      for (int y = 0; y < ly; ++y)
      {
        std::fill(slab + y * padX, slab + y * padX + lx, 0.0);
      }
      for (std::size_t s = first[z]; s < first[z + 1]; ++s)
      {
        const std::size_t i = order[s];
        const long long inSlab = voxels[i] - z * slabSize;
        double& slot = slab[(inSlab / lx) * padX + inSlab % lx];
        slot = static_cast<double>(static_cast<float>(slot) + (weights ? weights[i] : 1.0f));
      }
      for (int y = 0; y < ly; ++y)
      {
        rowSums[y] = FillRow(slab + y * padX, lx, slab + y * padX, y, check);
      }
    },
    error);
}

//------------------------------------------------------------------------------
template <typename FillSlab>
bool vtkBlueNoiseSpectrumKernel::TransformRealization(FillSlab fillSlab, std::string* error)
{
  // The first realization's power is in the transform buffer: move it aside
  // before this one overwrites it (and so that a rejected one changes nothing).
  if (this->PowerInTransform && !this->MovePowerAside(error))
  {
    return false;
  }
  const int lx = this->Dimensions[0];
  const int ly = this->Dimensions[1];
  const int lz = this->Dimensions[2];
  const auto slabPlan = static_cast<fftw_plan>(this->SlabPlan);
  std::vector<double> rowSums(static_cast<std::size_t>(ly) * lz);
  std::vector<SlabCheck> checks(static_cast<std::size_t>(lz));
  // Each z slab is filled and transformed in x and y while it is in cache.
  vtkSMPTools::For(0, lz, SlabGrain(lx, ly),
    [&](vtkIdType z0, vtkIdType z1)
    {
      for (vtkIdType z = z0; z < z1; ++z)
      {
        double* slab = this->Transform + z * this->SlabStride;
        fillSlab(static_cast<int>(z), slab, rowSums.data() + z * ly, checks[z]);
        if (!checks[z].Invalid)
        {
          fftw_execute_dft_r2c(slabPlan, slab, reinterpret_cast<fftw_complex*>(slab));
        }
      }
    });
  double n = 0.0;
  for (double rowSum : rowSums)
  {
    n += rowSum;
  }
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (int z = 0; z < lz; ++z)
  {
    const SlabCheck& c = checks[z];
    if (c.Invalid)
    {
      std::ostringstream msg;
      msg << "the count at voxel (" << c.BadX << ", " << c.BadY << ", " << z << ") is "
          << c.BadValue << ": counts must be finite and non-negative";
      SetError(error, msg.str());
      return false;
    }
    low = std::min(low, c.Min);
    high = std::max(high, c.Max);
  }
  if (n <= 0.0)
  {
    SetError(
      error, "the realization has no points (N = 0): the spectrum P = |B|^2 / N is undefined");
    return false;
  }
  if (low == high)
  {
    // A constant volume has no power off DC: the transform would only add
    // rounding noise, so its contribution is exactly zero.
    if (this->Realizations == 0)
    {
      this->ZeroPower();
    }
    ++this->ConstantRealizations;
  }
  else
  {
    this->TransformColumns(1.0 / n);
  }
  this->PowerInTransform = (this->Realizations == 0);
  ++this->Realizations;
  this->PointSum += n;
  return true;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumKernel::TransformColumns(double invN)
{
  // z transforms over blocks of ColumnBlock (kx, ky) columns gathered from the
  // slabs; the power goes straight from the block to where it is kept.
  const int lz = this->Dimensions[2];
  const auto columnPlan = static_cast<fftw_plan>(this->ColumnPlan);
  const std::size_t columns = this->HalfSize / lz;
  const vtkIdType blocks = static_cast<vtkIdType>((columns + ColumnBlock - 1) / ColumnBlock);
  const bool first = (this->Realizations == 0);
  // A block per task, not a vtkSMPThreadLocal one per thread: a task covers
  // about ValuesPerTask values, so its one block costs little, and GCC 14
  // reported a false -Wstringop-overflow in the thread-local's constructor
  // (VTK's Sequential backend) inlined here.
  const vtkIdType grain = std::max<vtkIdType>(1, ValuesPerTask / (ColumnBlock * lz));
  vtkSMPTools::For(0, blocks, grain,
    [&](vtkIdType b0, vtkIdType b1)
    {
      ColumnScratch scratch;
      fftw_complex* block = scratch.Get(lz);
      for (vtkIdType b = b0; b < b1; ++b)
      {
        const std::size_t c0 = static_cast<std::size_t>(b) * ColumnBlock;
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
          const fftw_complex* v = block + z * ColumnBlock;
          if (first)
          {
            // The real part of each slot of this block: its columns are read.
            double* power = this->Transform + z * this->SlabStride + 2 * c0;
            for (std::size_t i = 0; i < width; ++i)
            {
              power[2 * i] = (v[i][0] * v[i][0] + v[i][1] * v[i][1]) * invN;
            }
          }
          else
          {
            double* power = this->PowerSum + z * columns + c0;
            for (std::size_t i = 0; i < width; ++i)
            {
              power[i] += (v[i][0] * v[i][0] + v[i][1] * v[i][1]) * invN;
            }
          }
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkBlueNoiseSpectrumKernel::ZeroPower()
{
  const int lx = this->Dimensions[0];
  const int ly = this->Dimensions[1];
  vtkSMPTools::For(0, this->Dimensions[2], SlabGrain(lx, ly),
    [&](vtkIdType z0, vtkIdType z1)
    {
      std::fill(
        this->Transform + z0 * this->SlabStride, this->Transform + z1 * this->SlabStride, 0.0);
    });
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::MovePowerAside(std::string* error)
{
  if (!this->PowerSum)
  {
    this->PowerSum = AllocateLarge(this->HalfSize);
    if (!this->PowerSum)
    {
      std::ostringstream msg;
      msg << "cannot allocate " << this->HalfSize * sizeof(double)
          << " bytes to average realizations";
      SetError(error, msg.str());
      return false;
    }
  }
  const int lx = this->Dimensions[0];
  const int ly = this->Dimensions[1];
  const std::size_t halfX = static_cast<std::size_t>(lx) / 2 + 1;
  std::size_t strides[3];
  const PowerView from(this->PowerLayout(strides), strides);
  vtkSMPTools::For(0, this->Dimensions[2], SlabGrain(lx, ly),
    [&](vtkIdType z0, vtkIdType z1)
    {
      for (vtkIdType z = z0; z < z1; ++z)
      {
        for (int y = 0; y < ly; ++y)
        {
          const double* src = from.Row(y, static_cast<int>(z));
          double* dst = this->PowerSum + (static_cast<std::size_t>(z) * ly + y) * halfX;
          for (std::size_t x = 0; x < halfX; ++x)
          {
            dst[x] = src[2 * x];
          }
        }
      }
    });
  this->PowerInTransform = false;
  return true;
}

//------------------------------------------------------------------------------
const double* vtkBlueNoiseSpectrumKernel::PowerLayout(std::size_t strides[3]) const
{
  const std::size_t halfX = static_cast<std::size_t>(this->Dimensions[0]) / 2 + 1;
  if (this->PowerInTransform)
  {
    strides[0] = this->SlabStride;
    strides[1] = 2 * halfX;
    strides[2] = 2;
    return this->Transform;
  }
  strides[0] = static_cast<std::size_t>(this->Dimensions[1]) * halfX;
  strides[1] = halfX;
  strides[2] = 1;
  return this->PowerSum;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::Compute(Result& out, std::string* error) const
{
  if (this->Realizations == 0)
  {
    SetError(error, "no realization has been added");
    return false;
  }
  const ShellGeometry geometry(this->Dimensions);
  const double voxels =
    static_cast<double>(geometry.Lx) * static_cast<double>(geometry.Ly) * geometry.Lz;
  const double meanPoints = this->PointSum / this->Realizations;
  const double density = meanPoints / voxels;
  // |f| < f_g = cbrt(h) is tested as |f|^6 < h^2: cbrt is not correctly
  // rounded (cbrt(2^-9) < 1/8 in glibc), the cubes are exact on dyadic grids.
  const double h = density <= 0.5 ? density : std::max(0.0, 1.0 - density);
  std::size_t strides[3];
  const PowerView power(this->PowerLayout(strides), strides);
  const Accumulator sum = SumShells(geometry, power, h * h);

  FillShells(sum, geometry, this->Realizations, out);
  const double correlation = SymmetryCorrelation(sum, geometry, out);
  std::copy(this->Dimensions, this->Dimensions + 3, out.Dimensions);
  out.Realizations = this->Realizations;
  out.NumberOfPoints = meanPoints;
  out.Density = density;
  out.PrincipalFrequency = PrincipalFrequency(density);
  out.LowFrequencyRatio = sum.Total > 0.0 ? sum.Low / sum.Total : 0.0;
  out.SymmetryCorrelation = correlation;
  out.Symmetry = 1.0 - correlation;
  out.TargetValue = this->Weight * out.LowFrequencyRatio + (1.0 - this->Weight) * out.Symmetry;
  out.Warning.clear();
  if (this->ConstantRealizations == this->Realizations)
  {
    out.Warning = "every voxel holds the same count in every realization (g = 1 for a mask): "
                  "there is no power off DC, so L = 0, every anisotropy is 0 and S = 1 "
                  "(correlation of constant curves taken as 0)";
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::GetCenteredPowerSpectrum(std::vector<double>& out) const
{
  if (this->Realizations == 0)
  {
    out.clear();
    return false;
  }
  out.resize(
    static_cast<std::size_t>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2]);
  return this->GetCenteredPowerSpectrum(out.data());
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::GetCenteredPowerSpectrum(double* out) const
{
  if (this->Realizations == 0 || !out)
  {
    return false;
  }
  const int lx = this->Dimensions[0];
  const int ly = this->Dimensions[1];
  const int lz = this->Dimensions[2];
  const double invR = 1.0 / this->Realizations;
  std::size_t strides[3];
  const PowerView power(this->PowerLayout(strides), strides);
  const std::size_t step = power.Step;
  vtkSMPTools::For(0, lz, SlabGrain(lx, ly),
    [&](vtkIdType k0, vtkIdType k1)
    {
      double* dst = out + static_cast<std::size_t>(k0) * ly * lx;
      for (vtkIdType k = k0; k < k1; ++k)
      {
        const int kz = static_cast<int>((k - lz / 2 + lz) % lz);
        for (int j = 0; j < ly; ++j)
        {
          const int ky = (j - ly / 2 + ly) % ly;
          // Frequencies with kx > Lx / 2 are the conjugate mirrors of stored
          // ones. Index i holds kx = i - floor(Lx / 2), folded into [0, Lx).
          const double* direct = power.Row(ky, kz);
          const double* mirror = power.Row((ly - ky) % ly, (lz - kz) % lz);
          for (int kx = lx - lx / 2; kx < lx; ++kx)
          {
            *dst++ = (kx <= lx / 2 ? direct[kx * step] : mirror[(lx - kx) * step]) * invR;
          }
          for (int kx = 0; kx < lx - lx / 2; ++kx)
          {
            *dst++ = direct[kx * step] * invR;
          }
        }
      }
    });
  out[(static_cast<std::size_t>(lz / 2) * ly + ly / 2) * lx + lx / 2] = 0.0;
  return true;
}

//------------------------------------------------------------------------------
double* vtkBlueNoiseSpectrumKernel::NewCenteredPowerSpectrum() const
{
  if (this->Realizations == 0)
  {
    return nullptr;
  }
  double* out = AllocateLarge(
    static_cast<std::size_t>(this->Dimensions[0]) * this->Dimensions[1] * this->Dimensions[2]);
  if (out)
  {
    this->GetCenteredPowerSpectrum(out);
  }
  return out;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseSpectrumKernel::Evaluate(
  const unsigned char* mask, const int dims[3], double weight, Result& out, std::string* error)
{
  vtkBlueNoiseSpectrumKernel kernel;
  if (!kernel.SetDimensions(dims[0], dims[1], dims[2], error))
  {
    return false;
  }
  kernel.SetWeight(weight);
  return kernel.AddRealization(mask, error) && kernel.Compute(out, error);
}
