// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionPointAssembler.h"

#include "vtkArrayDispatch.h"
#include "vtkBlueNoiseThreads.h"
#include "vtkCellArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMatrix3x3.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <numeric>
#include <unordered_map>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h> // mmap, madvise
#include <unistd.h>   // sysconf
#endif

namespace
{
// Whether points of a target array can be written by several threads at
// once, each its own range: plain memory, one value per element (not bits).
bool WritableSideBySide(vtkAbstractArray* source, vtkAbstractArray* target)
{
  return vtkDataArray::SafeDownCast(source) && vtkDataArray::SafeDownCast(target) &&
    target->HasStandardMemoryLayout() && target->GetDataType() != VTK_BIT;
}

// dst[dstFirst + p] = src[srcFirst + ids[p]] for p in [0, n), value by value
// (a tuple assignment copies with a memcpy call per tuple).
// to[p] = from[ids[p]], p < n: the gather of one-component values by in-layer ids.
template <typename FromT, typename ToT>
void GatherByIds(FromT from, const vtkIdType* ids, vtkIdType n, ToT to)
{
  for (vtkIdType p = 0; p < n; ++p)
  {
    to[p] = from[ids[p]];
  }
}

struct GatherWorker
{
  template <typename SrcT, typename DstT>
  void operator()(SrcT* src, DstT* dst, const vtkIdType* ids, vtkIdType n, vtkIdType srcFirst,
    vtkIdType dstFirst) const
  {
    const auto in = vtk::DataArrayValueRange(src);
    auto out = vtk::DataArrayValueRange(dst);
    const int nc = src->GetNumberOfComponents();
    if (nc == 1) // scalars, the common case: a plain gather, no product per point
    {
      GatherByIds(in.begin() + srcFirst, ids, n, out.begin() + dstFirst);
      return;
    }
    for (vtkIdType p = 0; p < n; ++p)
    {
      const vtkIdType from = (srcFirst + ids[p]) * nc;
      const vtkIdType to = (dstFirst + p) * nc;
      for (int c = 0; c < nc; ++c)
      {
        out[to + c] = in[from + c];
      }
    }
  }
};

#if defined(__linux__) && defined(MADV_HUGEPAGE)
// Large output arrays live in blocks of their own: mapped memory aligned to
// 2 MB and advised for transparent huge pages (one page fault per 2 MB instead
// of one per 4 kB: most of the cost of fresh memory is page faults). A block
// keeps its capacity when its array is trimmed, so a re-execution that
// recycles the array reuses the pages already there. (Memory from
// posix_memalign, advised in part, could not be regrown in place: glibc's
// realloc then copied the whole array into fresh pages.)
constexpr size_t HugePage = size_t(2) << 20;

size_t RoundUpToHugePage(size_t bytes)
{
  return (bytes + HugePage - 1) / HugePage * HugePage;
}

using BlockPool = vtkErrorDiffusionBlockPool;

struct Block
{
  void* Base;      // of the mapping, HugePage longer than the capacity (for the alignment)
  size_t Capacity; // bytes from the data pointer
  size_t Used;     // bytes that may hold pages: the capacity, or up to the trimmed end
  std::weak_ptr<BlockPool> Pool; // the assembler whose spare the block becomes when freed
};

void Unmap(const Block& block)
{
  munmap(block.Base, block.Capacity + HugePage);
}

// The blocks in use, by data pointer: a pointer not in here is not a block
// (its array may have been reallocated by VTK since, and the address reused).
// Only live blocks are in here, so it is empty whenever no output array is.
// Never destroyed: an output array may be freed after the library's statics.
struct BlockRegistry
{
  std::mutex Mutex;
  std::unordered_map<void*, Block> Blocks;
};
BlockRegistry& Registry()
{
  static auto* registry = new BlockRegistry;
  return *registry;
}

// An assembler's freed blocks, kept as spares for its next run: ParaView
// shallow-copies every output after its filter (vtkPVPostFilter), so a
// re-execution cannot recycle the arrays of the last output, which are freed
// just after it; the next run then writes into pages already there instead of
// faulting in and zeroing fresh ones. Their pages are given back lazily
// (MADV_FREE: the kernel takes them when it needs memory). The pool lives and
// dies with its assembler (its filter): a block freed after that is unmapped,
// and so are the spares a run did not take (ReleaseSpares).
} // anonymous namespace

struct vtkErrorDiffusionBlockPool
{
  std::mutex Mutex;
  std::vector<std::pair<void*, Block>> Spares;
  size_t SpareBytes = 0; // their Used bytes

  ~vtkErrorDiffusionBlockPool() { this->ReleaseSpares(); }

  // A spare block of at least `bytes` (the smallest); null if none.
  void* Take(size_t bytes, Block& block)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    auto best = this->Spares.end();
    for (auto it = this->Spares.begin(); it != this->Spares.end(); ++it)
    {
      if (it->second.Capacity >= bytes &&
        (best == this->Spares.end() || it->second.Capacity < best->second.Capacity))
      {
        best = it;
      }
    }
    if (best == this->Spares.end())
    {
      return nullptr;
    }
    void* data = best->first;
    block = best->second;
    this->SpareBytes -= block.Used;
    this->Spares.erase(best);
    return data;
  }

  // Keeps a freed block unless the spares would exceed a quarter of the
  // machine's memory; then it is unmapped.
  void Keep(void* data, const Block& block)
  {
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      if (this->SpareBytes + block.Used <= MaximumSpareBytes())
      {
#if defined(MADV_FREE)
        madvise(data, block.Used, MADV_FREE);
#endif
        this->Spares.emplace_back(data, block);
        this->SpareBytes += block.Used;
        return;
      }
    }
    Unmap(block);
  }

  void ReleaseSpares()
  {
    std::vector<std::pair<void*, Block>> spares;
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      spares.swap(this->Spares);
      this->SpareBytes = 0;
    }
    for (const auto& spare : spares)
    {
      Unmap(spare.second);
    }
  }

  // A quarter of the machine's memory; none where pages cannot be given back
  // lazily.
  static size_t MaximumSpareBytes()
  {
#if defined(MADV_FREE)
    static const size_t bytes = [] {
      const long pages = sysconf(_SC_PHYS_PAGES);
      const long size = sysconf(_SC_PAGESIZE);
      return pages > 0 && size > 0 ? size_t(pages) * size_t(size) / 4 : 0;
    }();
    return bytes;
#else
    return 0;
#endif
  }
};

namespace
{

// A block of at least `bytes` owned by `pool`, its capacity in `capacity`: a
// spare of the pool, or a fresh mapping.
void* AllocateBlock(const std::shared_ptr<BlockPool>& pool, size_t bytes, size_t& capacity)
{
  Block block;
  void* data = pool->Take(bytes, block);
  if (!data)
  {
    capacity = RoundUpToHugePage(bytes);
    void* base =
      mmap(nullptr, capacity + HugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (base == MAP_FAILED)
    {
      return nullptr;
    }
    data = reinterpret_cast<void*>(RoundUpToHugePage(reinterpret_cast<std::uintptr_t>(base)));
    madvise(data, capacity, MADV_HUGEPAGE); // a hint: failure is harmless
    block = { base, capacity, capacity, pool };
  }
  capacity = block.Capacity;
  block.Used = block.Capacity; // TrimBlock says what is used
  BlockRegistry& registry = Registry();
  std::lock_guard<std::mutex> lock(registry.Mutex);
  registry.Blocks[data] = block;
  return data;
}

// The array free function of blocks: the block goes back to its pool when
// that still exists, else it is unmapped.
void FreeBlock(void* data)
{
  Block block;
  {
    BlockRegistry& registry = Registry();
    std::lock_guard<std::mutex> lock(registry.Mutex);
    const auto it = registry.Blocks.find(data);
    if (it == registry.Blocks.end())
    {
      return;
    }
    block = std::move(it->second);
    registry.Blocks.erase(it);
  }
  if (std::shared_ptr<BlockPool> pool = block.Pool.lock())
  {
    pool->Keep(data, block);
  }
  else
  {
    Unmap(block);
  }
}

// Gives back the block's pages past its first `used` bytes (rounded up to
// huge pages) and returns its capacity; 0 when `data` is not a block.
size_t TrimBlock(void* data, size_t used)
{
  size_t capacity = 0;
  size_t kept = 0;
  {
    BlockRegistry& registry = Registry();
    std::lock_guard<std::mutex> lock(registry.Mutex);
    const auto it = registry.Blocks.find(data);
    if (it == registry.Blocks.end())
    {
      return 0;
    }
    capacity = it->second.Capacity;
    kept = std::min(RoundUpToHugePage(used), capacity);
    it->second.Used = kept;
  }
  if (kept < capacity)
  {
    madvise(static_cast<char*>(data) + kept, capacity - kept, MADV_DONTNEED);
  }
  return capacity;
}

size_t BlockCapacity(void* data)
{
  BlockRegistry& registry = Registry();
  std::lock_guard<std::mutex> lock(registry.Mutex);
  const auto it = registry.Blocks.find(data);
  return it == registry.Blocks.end() ? 0 : it->second.Capacity;
}

// The array's values are `values` values of its block (no copy).
void SetBlock(vtkAbstractArray* array, void* data, vtkIdType values)
{
  array->SetVoidArray(data, values, /*save=*/0, vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(FreeBlock);
}

// A block for arrays of 8 MB and more with VTK's standard memory layout.
bool WantsBlock(vtkAbstractArray* array, size_t bytes)
{
  return bytes >= 4 * HugePage && array->GetDataTypeSize() > 0 &&
    array->HasStandardMemoryLayout() && vtkDataArray::SafeDownCast(array);
}
#else
} // anonymous namespace

struct vtkErrorDiffusionBlockPool // blocks are mapped memory, on Linux only
{
  void ReleaseSpares() {}
};

namespace
{
#endif

// Room for up to `tuples` tuples, uninitialized (the array's count means
// nothing until EnsureTuples sets it). A recycled array keeps its block when
// that is large enough. The room is a hint: where the address space for all
// of it cannot be had, a quarter of it is tried, and so on, and EnsureTuples
// grows the array later. New blocks belong to `pool`.
void ReserveUninitialized(vtkAbstractArray* array, vtkIdType tuples,
  const std::shared_ptr<vtkErrorDiffusionBlockPool>& pool)
{
  (void)pool;
  const int components = std::max(1, array->GetNumberOfComponents());
  const int valueSize = array->GetDataTypeSize();
  for (; tuples > 0; tuples /= 4)
  {
    const vtkIdType values = tuples * components;
    const size_t bytes = static_cast<size_t>(values) * valueSize;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (WantsBlock(array, bytes))
    {
      void* data = array->GetSize() > 0 ? array->GetVoidPointer(0) : nullptr;
      size_t capacity = data ? BlockCapacity(data) : 0;
      if (capacity < bytes)
      {
        data = AllocateBlock(pool, bytes, capacity);
      }
      if (!data)
      {
        continue;
      }
      SetBlock(array, data, static_cast<vtkIdType>(capacity / valueSize));
      return;
    }
#endif
    if (array->GetSize() >= values)
    {
      return; // a recycled array
    }
    try
    {
      if (array->Resize(tuples))
      {
        return;
      }
    }
    catch (const std::bad_alloc&)
    {
      // VTK throws when the allocation fails; try less.
    }
  }
}

// Makes room for `tuples` tuples and sets the count; grows by at least half
// (VTK's Resize of a numeric array more than doubles), so appending layers
// costs amortized O(1) per tuple.
void EnsureTuples(vtkAbstractArray* array, vtkIdType tuples)
{
  const int components = std::max(1, array->GetNumberOfComponents());
  const vtkIdType capacity = array->GetSize() / components;
  if (tuples > capacity)
  {
    array->Resize(std::max(tuples, capacity + capacity / 2));
  }
  array->SetNumberOfTuples(tuples);
}

// For a block array: `tuples` tuples and no room beyond, the block keeping
// its capacity (for the next run that recycles the array) but giving back
// its pages past the values. False for any other array.
bool TrimBlockArray(vtkAbstractArray* array, vtkIdType tuples)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const int components = std::max(1, array->GetNumberOfComponents());
  void* data = array->GetSize() > 0 ? array->GetVoidPointer(0) : nullptr;
  const size_t used = static_cast<size_t>(tuples) * components * array->GetDataTypeSize();
  if (data && TrimBlock(data, used) > 0)
  {
    SetBlock(array, data, tuples * components);
    return true;
  }
#else
  (void)array;
  (void)tuples;
#endif
  return false;
}

// `tuples` tuples and no room beyond (see TrimBlockArray for blocks).
void Trim(vtkAbstractArray* array, vtkIdType tuples)
{
  if (!TrimBlockArray(array, tuples))
  {
    array->SetNumberOfTuples(tuples);
    array->Squeeze();
  }
}

// Uniform offsets in [-0.5, 0.5) for the three axes of one voxel: SplitMix64's
// finalizer over the seed and the voxel, cut into three 21-bit fields (exact
// in float). One hash per point: hashing per axis took half of the points'
// coordinate time at half density.
void JitterOffsets(std::uint64_t seed, int i, int j, int k, double offsets[3])
{
  std::uint64_t z = seed ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) * 0x9E3779B97F4A7C15ULL) ^
    (static_cast<std::uint64_t>(static_cast<std::uint32_t>(j)) * 0xC2B2AE3D27D4EB4FULL) ^
    (static_cast<std::uint64_t>(static_cast<std::uint32_t>(k)) * 0x165667B19E3779F9ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  constexpr std::uint64_t field = (1ULL << 21) - 1;
  for (int a = 0; a < 3; ++a)
  {
    offsets[a] = static_cast<double>((z >> (21 * a + 1)) & field) * (1.0 / 2097152.0) - 0.5;
  }
}

// The world coordinates of the samples of global layer z: ids are in-layer
// indices, rowEnds where each row's ids end. Each row's y and z terms are
// summed once (without jitter): for an axis-aligned grid the result is the
// same as summing per point, origin + spacing * index. Jittered points on an
// axis-aligned grid (Axial: the matrix has no term off its diagonal) take the
// diagonal terms only, three products instead of nine, with the same result.
template <typename T, bool Axial>
void WriteCenters(T* xyz, const double m[16], const int extent[6], int z, const vtkIdType* ids,
  const vtkIdType* rowEnds, int rows, bool jitter, std::uint64_t seed)
{
  const vtkIdType nx = extent[1] - extent[0] + 1;
  vtkIdType p = 0;
  for (int j = 0; j < rows; ++j)
  {
    const int y = extent[2] + static_cast<int>(j);
    const vtkIdType rowStart = static_cast<vtkIdType>(j) * nx;
    double row[3];
    for (int r = 0; r < 3; ++r)
    {
      row[r] = m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3];
    }
    for (; p < rowEnds[j]; ++p)
    {
      const int x = extent[0] + static_cast<int>(ids[p] - rowStart);
      if (!jitter)
      {
        for (int r = 0; r < 3; ++r)
        {
          xyz[3 * p + r] = static_cast<T>(m[4 * r] * x + row[r]);
        }
        continue;
      }
      double d[3];
      JitterOffsets(seed, x, y, z, d);
      const double ijk[3] = { x + d[0], y + d[1], z + d[2] };
      for (int r = 0; r < 3; ++r)
      {
        xyz[3 * p + r] = static_cast<T>(Axial ? m[5 * r] * ijk[r] + m[4 * r + 3]
                                              : m[4 * r] * ijk[0] + m[4 * r + 1] * ijk[1] +
              m[4 * r + 2] * ijk[2] + m[4 * r + 3]);
      }
    }
  }
}

template <typename T>
void WriteCenters(T* xyz, const double m[16], const int extent[6], int z, const vtkIdType* ids,
  const vtkIdType* rowEnds, int rows, bool jitter, std::uint64_t seed)
{
  const bool axial =
    m[1] == 0.0 && m[2] == 0.0 && m[4] == 0.0 && m[6] == 0.0 && m[8] == 0.0 && m[9] == 0.0;
  if (axial)
  {
    WriteCenters<T, true>(xyz, m, extent, z, ids, rowEnds, rows, jitter, seed);
  }
  else
  {
    WriteCenters<T, false>(xyz, m, extent, z, ids, rowEnds, rows, jitter, seed);
  }
}

// The most points an array makes room for at once (address space, see Begin).
constexpr vtkIdType MaximumRoom = vtkIdType(1) << 28;

vtkIdType VoxelCount(const int extent[6])
{
  vtkIdType n = 1;
  for (int a = 0; a < 3; ++a)
  {
    n *= std::max<vtkIdType>(0, extent[2 * a + 1] - extent[2 * a] + 1);
  }
  return n;
}
}

//------------------------------------------------------------------------------
vtkErrorDiffusionPointAssembler::vtkErrorDiffusionPointAssembler()
  : Pool(std::make_shared<vtkErrorDiffusionBlockPool>())
{
}

//------------------------------------------------------------------------------
vtkErrorDiffusionPointAssembler::~vtkErrorDiffusionPointAssembler() = default;

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::Begin(
  vtkImageData* image, const int extent[6], vtkPointData* outPD, int pointsType)
{
  std::copy(extent, extent + 6, this->Extent);
  image->GetExtent(this->SourceExtent);
  vtkImageData::ComputeIndexToPhysicalMatrix(image->GetOrigin(), image->GetSpacing(),
    image->GetDirectionMatrix()->GetData(), this->IndexToPhysical);
  this->Total = 0;
  this->Jitter = false;
  this->OutputPointData = outPD;

  if (pointsType == VTK_DOUBLE)
  {
    this->Coordinates = this->NewOrRecycled<vtkDoubleArray>("points", 3);
  }
  else
  {
    this->Coordinates = this->NewOrRecycled<vtkFloatArray>("points", 3);
  }
  this->Coordinates->SetName("Points");
  this->Densities = this->NewOrRecycled<vtkFloatArray>("array Density", 1);
  this->Densities->SetName("Density");

  this->AddTargets(image->GetPointData(), image->GetNumberOfPoints(), outPD);

  // Room for one point per voxel (up to 2^28) at once: memory is committed
  // only where it is written, so the untouched tail costs address space, not
  // memory, and End() gives it back. Growing from a small array instead would
  // copy the points and fault in every copy.
  const vtkIdType reserve = std::min(VoxelCount(extent), MaximumRoom);
  ReserveUninitialized(this->Coordinates, reserve, this->Pool);
  ReserveUninitialized(this->Densities, reserve, this->Pool);
  for (vtkAbstractArray* target : this->Targets)
  {
    ReserveUninitialized(target, reserve, this->Pool);
  }
  const vtkIdType nx = std::max(0, extent[1] - extent[0] + 1);
  const vtkIdType ny = std::max(0, extent[3] - extent[2] + 1);
  this->LayerIds.resize(static_cast<size_t>(nx * ny) + 1);
  this->LayerRowEnds.resize(static_cast<size_t>(ny));
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::SetJitter(bool jitter, std::uint64_t seed)
{
  this->Jitter = jitter;
  this->JitterSeed = seed;
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionPointAssembler::SetSource(vtkImageData* image, std::string& error)
{
  vtkPointData* inPD = image->GetPointData();
  const vtkIdType points = image->GetNumberOfPoints();
  for (size_t a = 0; a < this->Sources.size(); ++a)
  {
    vtkAbstractArray* source = inPD->GetAbstractArray(this->SourceIndices[a]);
    vtkAbstractArray* first = this->Targets[a];
    const bool sameName = (!source || !source->GetName() || !first->GetName())
      ? (source && source->GetName() == first->GetName())
      : std::strcmp(source->GetName(), first->GetName()) == 0;
    if (!source || !sameName || source->GetDataType() != first->GetDataType() ||
      source->GetNumberOfComponents() != first->GetNumberOfComponents() ||
      source->GetNumberOfTuples() != points)
    {
      error = std::string("the point array '") + (first->GetName() ? first->GetName() : "") +
        "' changed from one slab of the input to the next";
      return false;
    }
    this->Sources[a] = source;
  }
  image->GetExtent(this->SourceExtent);
  return true;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::Reserve(vtkIdType tuples)
{
  EnsureTuples(this->Coordinates, tuples);
  EnsureTuples(this->Densities, tuples);
  for (vtkAbstractArray* target : this->Targets)
  {
    EnsureTuples(target, tuples);
  }
}

//------------------------------------------------------------------------------
// The in-layer indices of the samples, row by row. Branch-free within eight
// voxels (near g = 0.5 a branch per voxel would be mispredicted half of the
// time); eight voxels without a sample are passed over at once (most of them
// at low densities). One slot past the samples is written.
vtkIdType vtkErrorDiffusionPointAssembler::CompactLayer(
  const unsigned char* mask, vtkIdType* ids, vtkIdType* rowEnds) const
{
  const vtkIdType nx = this->Extent[1] - this->Extent[0] + 1;
  const vtkIdType ny = this->Extent[3] - this->Extent[2] + 1;
  vtkIdType n = 0;
  for (vtkIdType j = 0; j < ny; ++j)
  {
    const vtkIdType rowStart = j * nx;
    const unsigned char* bits = mask + rowStart;
    vtkIdType i = 0;
    for (; i + 8 <= nx; i += 8) // a fixed count inside: a third faster than one loop with a test
    {
      std::uint64_t eight;
      std::memcpy(&eight, bits + i, sizeof(eight));
      if (eight == 0)
      {
        continue;
      }
      for (vtkIdType k = i; k < i + 8; ++k)
      {
        ids[n] = rowStart + k;
        n += bits[k];
      }
    }
    for (; i < nx; ++i)
    {
      ids[n] = rowStart + i;
      n += bits[i];
    }
    rowEnds[j] = n;
  }
  return n;
}

//------------------------------------------------------------------------------
vtkErrorDiffusionPointAssembler::HeldLayers::HeldLayers() = default;
vtkErrorDiffusionPointAssembler::HeldLayers::~HeldLayers() = default;

//------------------------------------------------------------------------------
vtkErrorDiffusionPointAssembler::LayerSamples vtkErrorDiffusionPointAssembler::HeldLayers::GetLayer(
  size_t l) const
{
  const Entry& entry = this->Layers[l];
  LayerSamples samples;
  samples.Z = entry.Z;
  samples.Ids = this->Ids->GetPointer(entry.First);
  samples.RowEnds = this->RowEnds.data() + entry.FirstRow;
  samples.Rows = this->Rows;
  samples.Densities = this->Densities->GetPointer(entry.First);
  return samples;
}

//------------------------------------------------------------------------------
vtkIdType vtkErrorDiffusionPointAssembler::HeldLayers::DropLast(vtkIdType n)
{
  n = std::min(std::max<vtkIdType>(n, 0), this->Total);
  this->Total -= n;
  while (!this->Layers.empty() && this->Layers.back().First >= this->Total)
  {
    this->RowEnds.resize(this->Layers.back().FirstRow);
    this->Layers.pop_back();
  }
  if (!this->Layers.empty())
  {
    const vtkIdType keep = this->Total - this->Layers.back().First;
    for (size_t r = this->Layers.back().FirstRow; r < this->RowEnds.size(); ++r)
    {
      this->RowEnds[r] = std::min(this->RowEnds[r], keep);
    }
  }
  return n;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::HeldLayers::Clear()
{
  this->Layers.clear();
  this->RowEnds.clear();
  this->Total = 0;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::HeldLayers::Release()
{
  this->Clear();
  if (this->Ids)
  {
    // A block counts as a spare by what it committed, not by its room.
    TrimBlockArray(this->Ids, this->Peak);
    TrimBlockArray(this->Densities, this->Peak);
  }
  this->Ids = nullptr;
  this->Densities = nullptr;
  this->Peak = 0;
  std::vector<Entry>().swap(this->Layers);
  std::vector<vtkIdType>().swap(this->RowEnds);
}

//------------------------------------------------------------------------------
namespace
{
// Room for `needed` values in `array`, the first `used` kept: a bigger array
// when it has less (by half again at least, or `room`), of the pool's blocks.
template <typename ArrayT>
void HoldRoom(vtkSmartPointer<ArrayT>& array, vtkIdType used, vtkIdType needed, vtkIdType room,
  const std::shared_ptr<vtkErrorDiffusionBlockPool>& pool)
{
  if (array && array->GetSize() >= needed)
  {
    return;
  }
  const vtkIdType size = array ? array->GetSize() : 0;
  auto grown = vtkSmartPointer<ArrayT>::New();
  ReserveUninitialized(grown, std::max({ needed, room, size + size / 2 }), pool);
  if (grown->GetSize() < needed)
  {
    grown->Resize(needed);
  }
  if (used > 0)
  {
    std::copy(array->GetPointer(0), array->GetPointer(0) + used, grown->GetPointer(0));
  }
  array = grown;
}

// The pieces for writing `values` values: with `spread`, enough of them and
// more than one of vtkBlueNoiseThreads::Available() threads, a few a thread
// (so that uneven pieces even out); else one, as starting threads would cost
// more than they save.
vtkIdType PiecesFor(vtkIdType values, bool spread)
{
  constexpr vtkIdType valuesToSpread = vtkIdType(1) << 18;
  if (!spread || values < valuesToSpread)
  {
    return 1;
  }
  const int threads = vtkBlueNoiseThreads::Available();
  return threads > 1 ? 4 * threads : 1;
}

// fn(begin, end) over [0, count) in up to `pieces` consecutive pieces, on the
// threads of vtkBlueNoiseThreads::ForEach when more than one; the pieces must
// be independent.
template <typename Fn>
void ForPieces(vtkIdType count, vtkIdType pieces, Fn&& fn)
{
  pieces = std::min(count, pieces);
  if (pieces <= 1)
  {
    fn(vtkIdType(0), count);
    return;
  }
  vtkBlueNoiseThreads::ForEach(static_cast<int>(pieces), [&](int piece) {
    fn(count * piece / pieces, count * (piece + 1) / pieces);
  });
}
} // anonymous namespace

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::Hold(
  int z, const float* density, const unsigned char* mask, HeldLayers& held) const
{
  const vtkIdType ny = this->Extent[3] - this->Extent[2] + 1;
  const vtkIdType layer = (this->Extent[1] - this->Extent[0] + 1) * ny;
  const vtkIdType first = held.Total;
  const vtkIdType room = std::min(held.Room, MaximumRoom);
  // CompactLayer writes one slot past the samples.
  HoldRoom(held.Ids, first, first + layer + 1, room + 1, this->Pool);
  HoldRoom(held.Densities, first, first + layer, room, this->Pool);
  const size_t firstRow = held.RowEnds.size();
  held.RowEnds.resize(firstRow + static_cast<size_t>(ny));
  held.Rows = static_cast<int>(ny);
  vtkIdType* ids = held.Ids->GetPointer(first);
  const vtkIdType n = this->CompactLayer(mask, ids, &held.RowEnds[firstRow]);
  if (n == 0)
  {
    held.RowEnds.resize(firstRow);
    return;
  }
  GatherByIds(density, ids, n, held.Densities->GetPointer(first));
  held.Layers.push_back({ z, first, firstRow });
  held.Total = first + n;
  held.Peak = std::max(held.Peak, held.Total + 1);
}

//------------------------------------------------------------------------------
vtkIdType vtkErrorDiffusionPointAssembler::Grow(vtkIdType n)
{
  const vtkIdType first = this->Total;
  if (n > 0) // setting an array's count to 0 would free the room Begin reserved
  {
    this->Reserve(first + n);
    this->Total = first + n;
  }
  return first;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::Write(
  const LayerSamples& samples, vtkIdType first, bool others) const
{
  const vtkIdType n = samples.Count();
  if (n <= 0)
  {
    return;
  }
  if (auto* d = vtkDoubleArray::SafeDownCast(this->Coordinates))
  {
    WriteCenters(d->GetPointer(3 * first), this->IndexToPhysical, this->Extent, samples.Z,
      samples.Ids, samples.RowEnds, samples.Rows, this->Jitter, this->JitterSeed);
  }
  else
  {
    WriteCenters(vtkFloatArray::SafeDownCast(this->Coordinates)->GetPointer(3 * first),
      this->IndexToPhysical, this->Extent, samples.Z, samples.Ids, samples.RowEnds, samples.Rows,
      this->Jitter, this->JitterSeed);
  }
  float* densities = this->Densities->GetPointer(first);
  if (samples.Densities)
  {
    std::copy(samples.Densities, samples.Densities + n, densities);
  }
  else
  {
    GatherByIds(samples.LayerDensity, samples.Ids, n, densities);
  }
  this->WriteArrays(samples, first, others ? Arrays::All : Arrays::SideBySide);
}

//------------------------------------------------------------------------------
// Layers are independent (each has its own range of points): with threads to
// spare they are written side by side, a few consecutive layers a task, and
// the arrays that cannot be written so follow on this thread.
void vtkErrorDiffusionPointAssembler::WriteHeld(
  const HeldLayers& held, vtkIdType first, bool spread) const
{
  const size_t layers = held.GetNumberOfLayers();
  std::vector<vtkIdType> firsts(layers + 1, first);
  for (size_t l = 0; l < layers; ++l)
  {
    firsts[l + 1] = firsts[l] + held.GetLayer(l).Count();
  }
  const vtkIdType pieces = PiecesFor(held.GetNumberOfPoints(), spread);
  const bool apart = pieces > 1;
  ForPieces(static_cast<vtkIdType>(layers), pieces, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType l = begin; l < end; ++l)
    {
      this->Write(held.GetLayer(static_cast<size_t>(l)), firsts[l], !apart);
    }
  });
  for (size_t l = 0; apart && this->HasOtherArrays() && l < layers; ++l)
  {
    this->WriteOthers(held.GetLayer(l), firsts[l]);
  }
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::WriteOthers(const LayerSamples& samples, vtkIdType first) const
{
  this->WriteArrays(samples, first, Arrays::Others);
}

//------------------------------------------------------------------------------
// The carried arrays' values of the samples, as points [first, first + n):
// those of the arrays writable side by side, of the others, or of all.
void vtkErrorDiffusionPointAssembler::WriteArrays(
  const LayerSamples& samples, vtkIdType first, Arrays which) const
{
  // The layer's first voxel in the source image (full x and y extent).
  const vtkIdType layerSize = static_cast<vtkIdType>(this->SourceExtent[1] - this->SourceExtent[0] + 1) *
    (this->SourceExtent[3] - this->SourceExtent[2] + 1);
  const vtkIdType layerFirst = static_cast<vtkIdType>(samples.Z - this->SourceExtent[4]) * layerSize;
  const vtkIdType* ids = samples.Ids;
  const vtkIdType n = samples.Count();
  for (size_t a = 0; a < this->Targets.size(); ++a)
  {
    vtkAbstractArray* source = this->Sources[a];
    vtkAbstractArray* target = this->Targets[a];
    const bool sideBySide = WritableSideBySide(source, target);
    if ((which == Arrays::SideBySide && !sideBySide) || (which == Arrays::Others && sideBySide))
    {
      continue;
    }
    auto* sourceData = vtkDataArray::SafeDownCast(source);
    auto* targetData = vtkDataArray::SafeDownCast(target);
    if (sourceData && targetData)
    {
      using Dispatcher = vtkArrayDispatch::Dispatch2SameValueType;
      GatherWorker worker;
      if (!Dispatcher::Execute(sourceData, targetData, worker, ids, n, layerFirst, first))
      {
        worker(sourceData, targetData, ids, n, layerFirst, first);
      }
      continue;
    }
    for (vtkIdType p = 0; p < n; ++p) // strings and other non-numeric arrays
    {
      target->SetTuple(first + p, layerFirst + ids[p], source);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionPointAssembler::HasOtherArrays() const
{
  for (size_t a = 0; a < this->Targets.size(); ++a)
  {
    if (!WritableSideBySide(this->Sources[a], this->Targets[a]))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::AddLayer(
  int z, const float* density, const unsigned char* mask, vtkIdType count)
{
  if (count <= 0)
  {
    return;
  }
  LayerSamples samples; // in place: LayerIds has room for a whole layer
  samples.Z = z;
  samples.Ids = this->LayerIds.data();
  samples.RowEnds = this->LayerRowEnds.data();
  samples.Rows = static_cast<int>(this->LayerRowEnds.size());
  samples.LayerDensity = density;
  this->CompactLayer(mask, this->LayerIds.data(), this->LayerRowEnds.data());
  this->Write(samples, this->Grow(samples.Count()), true);
}

//------------------------------------------------------------------------------
vtkIdType vtkErrorDiffusionPointAssembler::RemoveLast(vtkIdType n)
{
  // The arrays keep their tuples until End trims them to the total: shrinking
  // them here would free a block array's memory through VTK (to nothing, when
  // all go), which End's trim gives back its own way.
  n = std::min(std::max<vtkIdType>(n, 0), this->Total);
  this->Total -= n;
  return n;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPoints> vtkErrorDiffusionPointAssembler::End()
{
  Trim(this->Coordinates, this->Total);
  Trim(this->Densities, this->Total);
  for (vtkAbstractArray* target : this->Targets)
  {
    Trim(target, this->Total);
  }
  // Recycled arrays were written through pointers: their time stamps must
  // say so (cached ranges, renderers' buffers).
  this->Coordinates->Modified();
  this->Densities->Modified();
  for (vtkAbstractArray* target : this->Targets)
  {
    target->Modified();
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(this->Coordinates);
  if (this->OutputPointData)
  {
    this->OutputPointData->AddArray(this->Densities);
  }
  this->Sources.clear();
  this->Targets.clear();
  this->OutputPointData = nullptr;
  // The output holds the arrays alone (see Recycle).
  this->Coordinates = nullptr;
  this->Densities = nullptr;
  return points;
}

//------------------------------------------------------------------------------
// Every image array with one tuple per point gets a copy of the same kind,
// keeping the attribute roles; arrays are paired by position, so unnamed
// arrays are carried too.
void vtkErrorDiffusionPointAssembler::AddTargets(
  vtkPointData* inPD, vtkIdType points, vtkPointData* outPD)
{
  this->Sources.clear();
  this->Targets.clear();
  this->SourceIndices.clear();
  this->Skipped.clear();
  for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* source = inPD->GetAbstractArray(a);
    if (!source || (source->GetName() && std::strcmp(source->GetName(), "Density") == 0))
    {
      continue;
    }
    if (source->GetNumberOfTuples() != points || source->GetNumberOfComponents() < 1)
    {
      this->Skipped.emplace_back(source->GetName() ? source->GetName() : "(unnamed)");
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> target = this->TargetFor(source);
    const int index = outPD->AddArray(target);
    for (int role = 0; role < vtkDataSetAttributes::NUM_ATTRIBUTES; ++role)
    {
      if (inPD->GetAbstractAttribute(role) == source)
      {
        outPD->SetActiveAttribute(index, role);
      }
    }
    this->Sources.push_back(source);
    this->Targets.push_back(target);
    this->SourceIndices.push_back(a);
  }
}

//------------------------------------------------------------------------------
// An empty array like `source` for its samples: a recycled one of the same
// kind, unless either carries component names or information (the copy could
// keep stale ones), or a new one.
vtkSmartPointer<vtkAbstractArray> vtkErrorDiffusionPointAssembler::TargetFor(
  vtkAbstractArray* source)
{
  vtkSmartPointer<vtkAbstractArray> target;
  if (source->GetName() && !source->HasAComponentName() && !source->HasInformation())
  {
    target = this->TakeRecycled(std::string("array ") + source->GetName(),
      source->GetClassName(), source->GetNumberOfComponents());
  }
  if (!target || target->HasAComponentName() || target->HasInformation())
  {
    target = vtkSmartPointer<vtkAbstractArray>::Take(source->NewInstance());
  }
  target->SetName(source->GetName());
  target->SetNumberOfComponents(source->GetNumberOfComponents());
  target->CopyComponentNames(source);
  if (source->HasInformation())
  {
    target->CopyInformation(source->GetInformation(), /*deep=*/1);
  }
  return target;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionPointAssembler::Recycle(vtkPolyData* previous)
{
  if (!previous)
  {
    this->Pool->ReleaseSpares(); // what the run did not take
    this->Recycled.clear();      // spares for the next run
    return;
  }
  this->Recycled.clear();
  // Held by `previous` alone: the container by it, the array by the container.
  const auto keep = [this](vtkObject* container, vtkAbstractArray* array, const std::string& role) {
    if (container && container->GetReferenceCount() == 1 && array &&
      array->GetReferenceCount() == 1)
    {
      this->Recycled.push_back({ role, array });
    }
  };
  if (vtkPoints* points = previous->GetPoints())
  {
    keep(points, points->GetData(), "points");
  }
  vtkPointData* pd = previous->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = pd->GetAbstractArray(a);
    if (array && array->GetName())
    {
      keep(pd, array, std::string("array ") + array->GetName());
    }
  }
  if (vtkCellArray* verts = previous->GetVerts())
  {
    keep(verts, verts->GetOffsetsArray(), "vertex offsets");
    keep(verts, verts->GetConnectivityArray(), "vertex connectivity");
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkAbstractArray> vtkErrorDiffusionPointAssembler::TakeRecycled(
  const std::string& role, const char* className, int components)
{
  for (auto it = this->Recycled.begin(); it != this->Recycled.end(); ++it)
  {
    if (it->Role == role &&
      (!className || std::strcmp(it->Array->GetClassName(), className) == 0) &&
      it->Array->GetNumberOfComponents() == components)
    {
      vtkSmartPointer<vtkAbstractArray> array = it->Array;
      this->Recycled.erase(it);
      return array;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
template <typename ArrayT>
vtkSmartPointer<ArrayT> vtkErrorDiffusionPointAssembler::NewOrRecycled(
  const std::string& role, int components)
{
  // The filter's own arrays: of their class when of their role.
  vtkSmartPointer<ArrayT> array = ArrayT::SafeDownCast(this->TakeRecycled(role, nullptr, components));
  if (!array)
  {
    array = vtkSmartPointer<ArrayT>::New();
    array->SetNumberOfComponents(components);
    return array;
  }
  if (array->HasInformation())
  {
    array->GetInformation()->Clear(); // cached ranges of the old values
  }
  return array;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkCellArray> vtkErrorDiffusionPointAssembler::MakeVertices(vtkIdType n)
{
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  auto fill = [this, n, &verts](auto offsets, auto connectivity) {
    using ValueT = typename std::remove_reference<decltype(*offsets->GetPointer(0))>::type;
    ReserveUninitialized(offsets, n + 1, this->Pool);
    ReserveUninitialized(connectivity, n, this->Pool);
    offsets->SetNumberOfTuples(n + 1); // SetNumberOfValues would reallocate a larger array
    connectivity->SetNumberOfTuples(n);
    ValueT* offset = offsets->GetPointer(0);
    ValueT* point = connectivity->GetPointer(0);
    offset[n] = static_cast<ValueT>(n);
    ForPieces(n, PiecesFor(n, true), [offset, point](vtkIdType begin, vtkIdType end) {
      std::iota(offset + begin, offset + end, static_cast<ValueT>(begin));
      std::iota(point + begin, point + end, static_cast<ValueT>(begin));
    });
    Trim(offsets, n + 1); // a recycled array may be larger
    Trim(connectivity, n);
    offsets->Modified();
    connectivity->Modified();
    verts->SetData(offsets, connectivity);
  };
  if (n < VTK_TYPE_INT32_MAX)
  {
    fill(this->NewOrRecycled<vtkTypeInt32Array>("vertex offsets", 1),
      this->NewOrRecycled<vtkTypeInt32Array>("vertex connectivity", 1));
  }
  else
  {
    fill(this->NewOrRecycled<vtkTypeInt64Array>("vertex offsets", 1),
      this->NewOrRecycled<vtkTypeInt64Array>("vertex connectivity", 1));
  }
  this->Recycled.clear(); // the last user of a run's recycled arrays
  return verts;
}
