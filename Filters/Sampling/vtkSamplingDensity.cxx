// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSamplingDensity.h"

#include "vtkArrayDispatch.h"
#include "vtkBlueNoiseSSE2.h"
#include "vtkBlueNoiseThreads.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSetAttributes.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTypeTraits.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

namespace
{
constexpr unsigned char NotOwned =
  vtkDataSetAttributes::DUPLICATEPOINT | vtkDataSetAttributes::HIDDENPOINT;

// g = clamp(scale * (a x + b)) to [0, 1], NaN to 0; scale may be +inf (a
// budget out of reach: every voxel of positive density drawn).
struct DensityMap
{
  double A;
  double B;
  double Scale;

  float operator()(double x) const
  {
    const double g = this->Scale * (this->A * x + this->B);
    if (!(g > 0.0)) // NaN too
    {
      return 0.0f;
    }
    return g >= 1.0 ? 1.0f : static_cast<float>(g);
  }

#if BLUENOISE_SSE2
  // Two values at once, with the same results: max passes its second
  // operand (0) on NaN and on equal zeros, min passes 1 unless g < 1. (The
  // compiler does not vectorize the branches above by itself: the
  // comparisons may trap.)
  __m128d operator()(__m128d x) const
  {
    const __m128d g = _mm_mul_pd(_mm_set1_pd(this->Scale),
      _mm_add_pd(_mm_mul_pd(_mm_set1_pd(this->A), x), _mm_set1_pd(this->B)));
    return _mm_min_pd(_mm_max_pd(g, _mm_setzero_pd()), _mm_set1_pd(1.0));
  }
#endif
};

// The value of one tuple: a component, or the magnitude for component -1.
template <typename TupleT>
double TupleValue(const TupleT& tuple, int component)
{
  if (component >= 0)
  {
    return static_cast<double>(tuple[component]);
  }
  double sum = 0.0;
  for (const auto c : tuple)
  {
    sum += static_cast<double>(c) * static_cast<double>(c);
  }
  return std::sqrt(sum);
}

// Counts of 8- or 16-bit values: CountLanes(T) tables of Values(T) counts,
// laid one after the other (8-bit values in four interleaved tables:
// consecutive equal values, a background, would otherwise each wait for the
// increment before).
template <typename T>
constexpr size_t Values()
{
  return static_cast<size_t>(1) << (8 * sizeof(T));
}
template <typename T>
constexpr size_t CountLanes()
{
  return sizeof(T) == 1 ? 4 : 1;
}
template <typename T>
constexpr int ValueOffset() // added to a value to index its count
{
  return std::is_signed<T>::value ? -static_cast<int>(std::numeric_limits<T>::min()) : 0;
}

// How many of the floats from `begin` on (before `end`) have the bits `run`,
// four at a time: stops at the first four that do not all have them. (Plain
// loads and compares: one implementation for every target, which compilers
// turn into vector compares where there are some.)
inline vtkIdType RunLength(const float* values, vtkIdType begin, vtkIdType end, std::uint32_t run)
{
  vtkIdType t = begin;
  for (; t + 4 <= end; t += 4)
  {
    std::uint32_t four[4];
    std::memcpy(four, values + t, sizeof(four));
    if ((four[0] ^ run) | (four[1] ^ run) | (four[2] ^ run) | (four[3] ^ run))
    {
      break;
    }
  }
  return t - begin;
}

// Whether the sixteen bytes at `bytes` all equal `value`: two 64-bit words
// against the value in every byte.
inline bool SixteenEqual(const void* bytes, unsigned char value)
{
  std::uint64_t words[2];
  std::memcpy(words, bytes, sizeof(words));
  const std::uint64_t all = 0x0101010101010101ULL * value;
  return ((words[0] ^ all) | (words[1] ^ all)) == 0;
}

// Counts 8-bit values [0, n) into `table` (CountLanes x Values counts) and,
// with Fill, writes their densities (`density`, by value index) to `out`, in
// one pass: sixteen equal values (backgrounds, flat regions) at once, their
// count held until the value changes.
template <typename T, bool Fill>
void CountBytes(const T* values, vtkIdType n, std::uint64_t* table,
  const float* density = nullptr, float* out = nullptr)
{
  static_assert(sizeof(T) == 1 && CountLanes<T>() == 4, "four tables of 8-bit values");
  const auto index = [](T v) { return static_cast<size_t>(static_cast<int>(v) + ValueOffset<T>()); };
  vtkIdType t = 0;
  size_t lane = 0;
  size_t run = 0;         // the value of the held count
  std::uint64_t held = 0; // sixteens of `run` not yet in the table
  for (; t + 16 <= n; t += 16)
  {
    const size_t v = index(values[t]);
    if (SixteenEqual(values + t, static_cast<unsigned char>(values[t])))
    {
      if constexpr (Fill)
      {
        std::fill_n(out + t, 16, density[v]);
      }
      if (v != run)
      {
        table[run] += held;
        run = v;
        held = 0;
      }
      held += 16;
      continue;
    }
    for (int k = 0; k < 16; ++k, lane = (lane + 1) & 3)
    {
      const size_t u = index(values[t + k]);
      if constexpr (Fill)
      {
        out[t + k] = density[u];
      }
      ++table[lane * Values<T>() + u];
    }
  }
  table[run] += held;
  for (; t < n; ++t, lane = (lane + 1) & 3)
  {
    const size_t u = index(values[t]);
    if constexpr (Fill)
    {
      out[t] = density[u];
    }
    ++table[lane * Values<T>() + u];
  }
}

// Adds the values of one component over tuples [begin, end) to `table`
// (CountLanes x Values counts), ghosts skipped.
template <typename T, typename RangeT>
void CountComponent(const RangeT& all, int nc, int component, vtkIdType begin, vtkIdType end,
  const unsigned char* ghosts, std::uint64_t* table)
{
  constexpr size_t lanes = CountLanes<T>();
  const auto index = [&](vtkIdType t) {
    return static_cast<size_t>(static_cast<int>(all[t * nc + component]) + ValueOffset<T>());
  };
  vtkIdType t = begin;
  if constexpr (sizeof(T) == 1 && std::is_pointer<decltype(all.begin())>::value)
  {
    if (!ghosts && nc == 1)
    {
      CountBytes<T, false>(all.begin() + begin, end - begin, table);
      return;
    }
  }
  if (!ghosts)
  {
    for (; t + static_cast<vtkIdType>(lanes) <= end; t += lanes)
    {
      for (size_t l = 0; l < lanes; ++l)
      {
        ++table[l * Values<T>() + index(t + l)];
      }
    }
  }
  for (; t < end; ++t)
  {
    table[index(t)] += (ghosts && (ghosts[t] & NotOwned)) ? 0u : 1u;
  }
}

// The count of value index v over the lanes of `table`.
template <typename T>
std::uint64_t CountOf(const std::vector<std::uint64_t>& table, size_t v)
{
  std::uint64_t n = 0;
  for (size_t l = 0; l < CountLanes<T>(); ++l)
  {
    n += table[l * Values<T>() + v];
  }
  return n;
}

void AddRun(vtkSamplingBudget::FloatTally& tally, std::uint32_t bits, std::uint64_t length)
{
  if (length > 0)
  {
    float x = 0.0f;
    std::memcpy(&x, &bits, sizeof(x));
    tally.Add(x, length);
  }
}

// Small integer types are counted per value first: exact, and a fraction of
// the cost of bucketing every value.
template <typename T>
constexpr bool IsSmallInteger()
{
  return std::is_integral<T>::value && sizeof(T) <= 2;
}

struct StatisticsWorker
{
  vtkSamplingDensity::SpareTallies* Spares = nullptr;

  template <typename ArrayT>
  void operator()(ArrayT* array, vtkIdType begin, vtkIdType end, int component,
    const unsigned char* ghosts, vtkPiecewiseFunction* function, vtkSamplingBudget& out) const
  {
    using T = vtk::GetAPIType<ArrayT>;
    if constexpr (IsSmallInteger<T>())
    {
      if (component >= 0)
      {
        this->CountValues(array, begin, end, component, ghosts, function, out);
        return;
      }
    }
    if constexpr (std::is_same<T, float>::value)
    {
      if (component >= 0 && !function)
      {
        this->TallyFloats(array, begin, end, component, ghosts, out);
        return;
      }
    }
    if (function) // not known to be safe from several threads
    {
      this->AddTuples(array, begin, end, component, ghosts, function, out);
      return;
    }
    vtkSMPThreadLocal<vtkSamplingBudget> local;
    vtkSMPTools::For(begin, end, 65536, [&](vtkIdType first, vtkIdType last) {
      this->AddTuples(array, first, last, component, ghosts, nullptr, local.Local());
    });
    for (auto& partial : local)
    {
      out.Merge(partial);
    }
  }

  template <typename ArrayT>
  void AddTuples(ArrayT* array, vtkIdType first, vtkIdType last, int component,
    const unsigned char* ghosts, vtkPiecewiseFunction* function, vtkSamplingBudget& out) const
  {
    vtkIdType t = first;
    for (const auto tuple : vtk::DataArrayTupleRange(array, first, last))
    {
      if (!(ghosts && (ghosts[t] & NotOwned)))
      {
        double x = TupleValue(tuple, component);
        if (function && !std::isnan(x))
        {
          x = function->GetValue(x);
        }
        out.Add(x);
      }
      ++t;
    }
  }

  // A float component: tallied by its bits (vtkSamplingBudget::FloatTally).
  template <typename ArrayT>
  void TallyFloats(ArrayT* array, vtkIdType begin, vtkIdType end, int component,
    const unsigned char* ghosts, vtkSamplingBudget& out) const
  {
    vtkSMPThreadLocal<vtkSamplingBudget::FloatTally*> local(nullptr);
    const auto all = vtk::DataArrayValueRange(array);
    const int nc = array->GetNumberOfComponents();
    const bool contiguous = !ghosts && nc == 1; // the values one after the other
    vtkSMPTools::For(begin, end, 65536, [&](vtkIdType first, vtkIdType last) {
      vtkSamplingBudget::FloatTally*& mine = local.Local();
      if (!mine)
      {
        mine = this->Spares->Take().release();
      }
      vtkSamplingBudget::FloatTally& tally = *mine;
      // Runs of equal values (by their bits) counted at once.
      std::uint32_t run = 0;
      std::uint64_t length = 0;
      for (vtkIdType t = first; t < last; ++t)
      {
        if (!(ghosts && (ghosts[t] & NotOwned)))
        {
          const float x = all[t * nc + component];
          std::uint32_t bits = 0;
          std::memcpy(&bits, &x, sizeof(bits));
          if (bits != run || length == 0)
          {
            AddRun(tally, run, length);
            run = bits;
            length = 0;
          }
          ++length;
          if constexpr (std::is_pointer<decltype(all.begin())>::value)
          {
            if (length >= 2 && contiguous) // a run: the rest of it at once
            {
              const vtkIdType more = RunLength(all.begin(), t + 1, last, run);
              length += static_cast<std::uint64_t>(more);
              t += more;
            }
          }
        }
      }
      AddRun(tally, run, length);
    });
    for (vtkSamplingBudget::FloatTally* tally : local)
    {
      if (tally)
      {
        out.Merge(*tally);
        this->Spares->Give(std::unique_ptr<vtkSamplingBudget::FloatTally>(tally));
      }
    }
  }

  template <typename ArrayT>
  void CountValues(ArrayT* array, vtkIdType begin, vtkIdType end, int component,
    const unsigned char* ghosts, vtkPiecewiseFunction* function, vtkSamplingBudget& out) const
  {
    using T = vtk::GetAPIType<ArrayT>;
    using Table = std::vector<std::uint64_t>;
    vtkSMPThreadLocal<Table> local;
    const auto all = vtk::DataArrayValueRange(array);
    const int nc = array->GetNumberOfComponents();
    vtkSMPTools::For(begin, end, 65536, [&](vtkIdType first, vtkIdType last) {
      Table& table = local.Local();
      table.resize(CountLanes<T>() * Values<T>(), 0);
      CountComponent<T>(all, nc, component, first, last, ghosts, table.data());
    });
    std::vector<std::uint64_t> total(Values<T>(), 0);
    for (const Table& table : local)
    {
      for (size_t v = 0; v < Values<T>(); ++v)
      {
        total[v] += CountOf<T>(table, v);
      }
    }
    for (size_t i = 0; i < Values<T>(); ++i)
    {
      if (total[i] > 0)
      {
        const double v = static_cast<double>(static_cast<int>(i) - ValueOffset<T>());
        out.Add(function ? function->GetValue(v) : v, static_cast<double>(total[i]));
      }
    }
  }

};

struct FillWorker
{
  vtkSamplingDensity::ValueTable& Table;

  template <typename ArrayT>
  void operator()(ArrayT* array, vtkIdType begin, vtkIdType end, int component,
    const unsigned char* ghosts, vtkPiecewiseFunction* function, double scale,
    const vtkSamplingBudget::Mapping& map, float* out, double& sum) const
  {
    const DensityMap density{ map.A, map.B, scale };
    using T = vtk::GetAPIType<ArrayT>;
    if constexpr (IsSmallInteger<T>())
    {
      if (component >= 0 && !function)
      {
        sum = this->FillByTable(array, begin, end, component, ghosts, map, scale, density, out);
        return;
      }
    }
    if (component >= 0 && !function)
    {
      sum = FillComponent(array, begin, end, component, ghosts, density, out);
      return;
    }
    double total = 0.0;
    vtkIdType i = 0;
    for (const auto tuple : vtk::DataArrayTupleRange(array, begin, end))
    {
      double x = TupleValue(tuple, component);
      if (function && !std::isnan(x))
      {
        x = function->GetValue(x);
      }
      const float g = (ghosts && (ghosts[begin + i] & NotOwned)) ? 0.0f : density(x);
      out[i++] = g;
      total += g;
    }
    sum = total;
  }

  // One component, mapped value by value; the sum in four lanes (one would
  // chain every addition to the one before).
  template <typename ArrayT>
  static double FillComponent(ArrayT* array, vtkIdType begin, vtkIdType end, int component,
    const unsigned char* ghosts, const DensityMap& density, float* out)
  {
    if (!ghosts && array->GetNumberOfComponents() == 1)
    {
      return FillScalars(array, begin, end, density, out);
    }
    const auto all = vtk::DataArrayValueRange(array);
    const int nc = array->GetNumberOfComponents();
    const auto one = [&](vtkIdType t) {
      const bool owned = !(ghosts && (ghosts[t] & NotOwned));
      const float g = owned ? density(static_cast<double>(all[t * nc + component])) : 0.0f;
      out[t - begin] = g;
      return g;
    };
    double lanes[4] = { 0.0, 0.0, 0.0, 0.0 };
    vtkIdType t = begin;
    for (; t + 4 <= end; t += 4)
    {
      lanes[0] += one(t);
      lanes[1] += one(t + 1);
      lanes[2] += one(t + 2);
      lanes[3] += one(t + 3);
    }
    for (; t < end; ++t)
    {
      lanes[(t - begin) & 3] += one(t);
    }
    return (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
  }

  // FillComponent for one component without ghosts, the common case: the
  // same lanes, two values at a time where SSE2 is.
  template <typename ArrayT>
  static double FillScalars(
    ArrayT* array, vtkIdType begin, vtkIdType end, const DensityMap& density, float* out)
  {
    const auto values = vtk::DataArrayValueRange<1>(array, begin, end);
    const vtkIdType n = end - begin;
    double lanes[4] = { 0.0, 0.0, 0.0, 0.0 };
    vtkIdType i = 0;
#if BLUENOISE_SSE2
    const auto pair = [&](vtkIdType k) {
      return _mm_cvtpd_ps(density(
        _mm_set_pd(static_cast<double>(values[k + 1]), static_cast<double>(values[k]))));
    };
    __m128d low = _mm_setzero_pd();  // lanes 0 and 1
    __m128d high = _mm_setzero_pd(); // lanes 2 and 3
    for (; i + 4 <= n; i += 4)
    {
      const __m128 g = _mm_movelh_ps(pair(i), pair(i + 2));
      _mm_storeu_ps(out + i, g);
      low = _mm_add_pd(low, _mm_cvtps_pd(g));
      high = _mm_add_pd(high, _mm_cvtps_pd(_mm_movehl_ps(g, g)));
    }
    _mm_storeu_pd(lanes, low);
    _mm_storeu_pd(lanes + 2, high);
#endif
    for (; i < n; ++i)
    {
      const float g = density(static_cast<double>(values[i]));
      out[i] = g;
      lanes[i & 3] += g;
    }
    return (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
  }

  // 8- and 16-bit values through a table of their densities: a load per
  // voxel instead of the mapping, and the sum from the counts per value.
  template <typename ArrayT>
  double FillByTable(ArrayT* array, vtkIdType begin, vtkIdType end, int component,
    const unsigned char* ghosts, const vtkSamplingBudget::Mapping& map, double scale,
    const DensityMap& density, float* out) const
  {
    using T = vtk::GetAPIType<ArrayT>;
    constexpr int offset = std::is_signed<T>::value ? -static_cast<int>(std::numeric_limits<T>::min()) : 0;
    constexpr size_t values = static_cast<size_t>(1) << (8 * sizeof(T));
    // A table pays off only for layers much larger than itself (16-bit
    // values on layers under 512^2 voxels are mapped directly).
    if (static_cast<size_t>(end - begin) < 4 * values)
    {
      double total = 0.0;
      const auto all = vtk::DataArrayValueRange(array);
      const int nc = array->GetNumberOfComponents();
      for (vtkIdType t = begin; t < end; ++t)
      {
        const float g = (ghosts && (ghosts[t] & NotOwned)) ? 0.0f : density(all[t * nc + component]);
        out[t - begin] = g;
        total += g;
      }
      return total;
    }
    vtkSamplingDensity::ValueTable& cache = this->Table;
    constexpr int type = vtkTypeTraits<T>::VTK_TYPE_ID;
    if (cache.Type != type || cache.A != map.A || cache.B != map.B || cache.Scale != scale)
    {
      cache.Density.resize(values);
      for (size_t v = 0; v < values; ++v)
      {
        cache.Density[v] = density(static_cast<double>(static_cast<int>(v) - offset));
      }
      cache.Type = type;
      cache.A = map.A;
      cache.B = map.B;
      cache.Scale = scale;
    }
    const std::vector<float>& table = cache.Density;
    const auto all = vtk::DataArrayValueRange(array);
    const int nc = array->GetNumberOfComponents();
    // The sum from the counts per value (exact).
    std::vector<std::uint64_t>& counts = cache.Counts;
    counts.assign(CountLanes<T>() * values, 0);
    if constexpr (sizeof(T) == 1 && std::is_pointer<decltype(all.begin())>::value)
    {
      if (!ghosts && nc == 1) // the common case, in one pass
      {
        CountBytes<T, true>(all.begin() + begin, end - begin, counts.data(), table.data(), out);
        return SumOfCounts<T>(counts, table);
      }
    }
    for (vtkIdType t = begin; t < end; ++t)
    {
      const int v = static_cast<int>(all[t * nc + component]) + offset;
      out[t - begin] = (ghosts && (ghosts[t] & NotOwned)) ? 0.0f : table[v];
    }
    CountComponent<T>(all, nc, component, begin, end, ghosts, counts.data());
    return SumOfCounts<T>(counts, table);
  }

  // The densities' sum from the counts per value.
  template <typename T>
  static double SumOfCounts(const std::vector<std::uint64_t>& counts, const std::vector<float>& table)
  {
    double total = 0.0;
    for (size_t v = 0; v < Values<T>(); ++v)
    {
      total += static_cast<double>(CountOf<T>(counts, v)) * table[v];
    }
    return total;
  }
};
}

//------------------------------------------------------------------------------
void vtkSamplingDensity::SetMapping(int mode, int component, vtkPiecewiseFunction* function)
{
  this->Mode = mode;
  this->Component = component;
  this->Function = mode == TRANSFER_FUNCTION ? function : nullptr;
  this->RangeSet = false;
  this->Map = vtkSamplingBudget::Mapping();
  this->Scale = 1.0;
}

//------------------------------------------------------------------------------
void vtkSamplingDensity::SetRange(double low, double high)
{
  this->Range[0] = low;
  this->Range[1] = high;
  this->RangeSet = true;
}

//------------------------------------------------------------------------------
void vtkSamplingDensity::GetRange(double range[2]) const
{
  range[0] = this->Range[0];
  range[1] = this->Range[1];
}

//------------------------------------------------------------------------------
bool vtkSamplingDensity::NeedsStatistics(bool budget) const
{
  return budget || (this->Mode == SCALAR_RANGE && !this->RangeSet);
}

//------------------------------------------------------------------------------
void vtkSamplingDensity::CollectStatistics(vtkDataArray* array, vtkIdType begin, vtkIdType end,
  const unsigned char* ghosts, vtkSamplingBudget& statistics, int threads) const
{
  // A part must be worth a thread and a histogram of its own (2 MiB).
  const vtkIdType parts = std::min<vtkIdType>(threads, (end - begin) / (vtkIdType(1) << 18));
  if (parts > 1 && !this->Function)
  {
    std::vector<vtkSamplingBudget> partial(static_cast<size_t>(parts - 1));
    const auto bound = [&](vtkIdType k) { return begin + (end - begin) * k / parts; };
    vtkBlueNoiseThreads::Split(static_cast<int>(parts), [&](int k) {
      this->CollectStatistics(
        array, bound(k), bound(k + 1), ghosts, k == 0 ? statistics : partial[k - 1], 1);
    });
    for (const vtkSamplingBudget& part : partial)
    {
      statistics.Merge(part);
    }
    return;
  }
  StatisticsWorker worker;
  worker.Spares = this->Spares.get();
  if (!vtkArrayDispatch::Dispatch::Execute(
        array, worker, begin, end, this->Component, ghosts, this->Function, statistics))
  {
    worker(array, begin, end, this->Component, ghosts, this->Function, statistics);
  }
}

//------------------------------------------------------------------------------
std::unique_ptr<vtkSamplingBudget::FloatTally> vtkSamplingDensity::SpareTallies::Take()
{
  std::unique_ptr<vtkSamplingBudget::FloatTally> tally;
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    if (!this->Tallies.empty())
    {
      tally = std::move(this->Tallies.back());
      this->Tallies.pop_back();
    }
  }
  if (!tally)
  {
    return std::unique_ptr<vtkSamplingBudget::FloatTally>(new vtkSamplingBudget::FloatTally);
  }
  tally->Reset();
  return tally;
}

//------------------------------------------------------------------------------
void vtkSamplingDensity::SpareTallies::Give(std::unique_ptr<vtkSamplingBudget::FloatTally> tally)
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  if (this->Tallies.size() < 16) // more threads than that are rare: the rest go
  {
    this->Tallies.push_back(std::move(tally));
  }
}

//------------------------------------------------------------------------------
vtkSamplingDensity::Outcome vtkSamplingDensity::Finish(
  const vtkSamplingBudget* statistics, const Budget& budget)
{
  Outcome outcome;
  outcome.Note = this->FixLinearMap(statistics);
  if (!budget.ByPoints)
  {
    this->Scale = budget.Value;
    return outcome;
  }
  if (!statistics)
  {
    this->Scale = 0.0; // nothing counted: no density can be scaled to the points
    return outcome;
  }
  const auto solution = statistics->Solve(budget.Value, this->Map);
  this->Scale = solution.Scale;
  outcome.OutOfReach = solution.OutOfReach;
  outcome.Reachable = solution.Reachable;
  return outcome;
}

//------------------------------------------------------------------------------
// The linear map of SCALAR_RANGE from the set range, or else the statistics'
// finite range; the identity for the other mappings. Returns a note or nullptr.
const char* vtkSamplingDensity::FixLinearMap(const vtkSamplingBudget* statistics)
{
  this->Map = vtkSamplingBudget::Mapping();
  if (this->Mode != SCALAR_RANGE)
  {
    return nullptr;
  }
  if (!this->RangeSet)
  {
    double range[2] = { 0.0, 0.0 };
    if (!statistics || !statistics->GetRange(range))
    {
      this->Map.A = 0.0; // no finite value: nothing to sample
      this->Map.B = 0.0;
      return nullptr;
    }
    this->Range[0] = range[0];
    this->Range[1] = range[1];
  }
  if (!(this->Range[1] > this->Range[0]))
  {
    // A single value is the top of its own range: uniform density.
    this->Map.A = 0.0;
    this->Map.B = 1.0;
    return "the scalar range has zero width: every voxel gets the same density";
  }
  // Halved first, so that hi - lo cannot overflow (a range of +-1e308).
  const double width = 0.5 * this->Range[1] - 0.5 * this->Range[0];
  this->Map.A = 0.5 / width;
  this->Map.B = -0.5 * this->Range[0] / width;
  return nullptr;
}

//------------------------------------------------------------------------------
double vtkSamplingDensity::Fill(vtkDataArray* array, vtkIdType begin, vtkIdType end,
  const unsigned char* ghosts, float* out, ValueTable& table) const
{
  FillWorker worker{ table };
  double sum = 0.0;
  if (!vtkArrayDispatch::Dispatch::Execute(array, worker, begin, end, this->Component, ghosts,
        this->Function, this->Scale, this->Map, out, sum))
  {
    worker(array, begin, end, this->Component, ghosts, this->Function, this->Scale, this->Map,
      out, sum);
  }
  return sum;
}
