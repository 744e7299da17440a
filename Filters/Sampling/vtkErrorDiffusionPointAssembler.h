// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionPointAssembler
 * @brief   Builds a sampler's output points, layer by layer, from the sample
 *          masks of an image's layers.
 *
 * For the samples of each layer (the voxels whose mask is 1) it appends the
 * voxel center in world coordinates (the image's origin, spacing and
 * direction matrix), optionally moved by a jitter, the density the sample was
 * drawn with (float array `Density`) and the tuple of every point-data array
 * of the image (numeric arrays through vtkArrayDispatch, others tuple by
 * tuple).
 *
 * Jitter: with SetJitter(true, seed) each point moves from its voxel center
 * by an offset uniform in [-0.5, 0.5) voxel along each index axis, a hash of
 * the seed and the voxel's global (i, j, k) index: the same voxel gets the
 * same offset whatever the slab, piece or thread that samples it. The point
 * stays inside its voxel, so binning it to the nearest grid point (as
 * vtkBlueNoiseSpectrum does) recovers the voxel.
 *
 * The image may come in slabs (streaming): SetSource() gives the image that
 * holds the next layers; its extent may exceed the layers sampled from it.
 * Every slab must have the arrays the first one had (same names, types and
 * components). Arrays whose number of tuples is not the image's number of
 * points are not carried (GetSkippedArrays()).
 *
 * Memory: the output arrays reserve one point per voxel of the sampled extent
 * (up to 2^28) up front, so they never grow by copying; only what is written
 * is committed, and End() trims them to size. On Linux, arrays of 8 MB and
 * more live in mapped blocks of their own, 2 MB aligned and advised for
 * transparent huge pages (most of the cost of fresh memory is page faults);
 * a block keeps its capacity through End() (its pages past the points are
 * given back), so the next run that recycles the array neither copies nor
 * faults in what it had. A block freed while its assembler lives is kept
 * for the assembler's next run (ParaView frees the last output's arrays
 * only after the next run has started: see Recycle); the spares a run does
 * not take are unmapped when it ends, and all of them with the assembler, so
 * no memory outlives the filter that owns the assembler.
 *
 * Layers must come in z order, each once. The image and its arrays are only
 * read, so another thread may read them at the same time.
 */
#ifndef vtkErrorDiffusionPointAssembler_h
#define vtkErrorDiffusionPointAssembler_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkSmartPointer.h"           // for members
#include "vtkType.h"                   // for vtkIdType

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class vtkAbstractArray;
class vtkCellArray;
class vtkDataArray;
class vtkFloatArray;
class vtkIdTypeArray;
class vtkImageData;
class vtkPointData;
class vtkPoints;
class vtkPolyData;
struct vtkErrorDiffusionBlockPool;

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionPointAssembler
{
public:
  vtkErrorDiffusionPointAssembler();
  ~vtkErrorDiffusionPointAssembler();
  vtkErrorDiffusionPointAssembler(const vtkErrorDiffusionPointAssembler&) = delete;
  vtkErrorDiffusionPointAssembler& operator=(const vtkErrorDiffusionPointAssembler&) = delete;

  /**
   * Starts the points of the layers of `extent` (x and y must be the image's
   * full x and y extent). `image` gives the geometry and the arrays; outPD
   * receives (CopyAllocate) every array of the image's point data with one
   * tuple per voxel, except one named `Density`, which End() replaces by the
   * densities. pointsType: VTK_FLOAT or VTK_DOUBLE.
   */
  void Begin(vtkImageData* image, const int extent[6], vtkPointData* outPD, int pointsType);

  /// Jitter the points (see the class comment). Call after Begin.
  void SetJitter(bool jitter, std::uint64_t seed);

  /**
   * The image the next layers are read from (the one given to Begin until
   * this is called). Returns false, with the reason, when its arrays do not
   * match the first image's.
   */
  bool SetSource(vtkImageData* image, std::string& error);

  /**
   * Appends the samples of global layer z: density and mask hold one value
   * per voxel of the layer, x fastest; count is the number of ones in mask.
   */
  void AddLayer(int z, const float* density, const unsigned char* mask, vtkIdType count);

  /// Points appended so far.
  vtkIdType GetNumberOfPoints() const { return this->Total; }

  /**
   * The samples of one layer, compacted: their in-layer indices, row by row,
   * and the densities they were drawn with. A view of memory it does not own.
   */
  struct LayerSamples
  {
    int Z = 0;                           ///< global layer
    const vtkIdType* Ids = nullptr;      ///< in-layer indices of the samples, row by row
    const vtkIdType* RowEnds = nullptr;  ///< where each row's samples end in Ids
    int Rows = 0;                        ///< the layer's rows
    const float* Densities = nullptr;    ///< the density each sample was drawn with,
    const float* LayerDensity = nullptr; ///< or (Densities null) the layer's, by in-layer index
    vtkIdType Count() const { return this->Rows > 0 ? this->RowEnds[this->Rows - 1] : 0; }
  };

  /**
   * Layers held back to be written later: AddLayer in two halves (Hold, then
   * Grow and Write), so that layers sampled on other threads are compacted
   * there and written in order into room taken on one thread. The samples of
   * all the layers lie one after another in arrays of the assembler's
   * blocks, 2 MB pages (fresh memory of 4 kB pages costs a page fault per
   * page, more than the compaction itself); Release gives them to its
   * spares, so the next store of the run writes into memory already
   * committed.
   */
  class VTKFILTERSBLUENOISE_EXPORT HeldLayers
  {
  public:
    HeldLayers();
    ~HeldLayers();
    HeldLayers(const HeldLayers&) = delete;
    HeldLayers& operator=(const HeldLayers&) = delete;

    size_t GetNumberOfLayers() const { return this->Layers.size(); }
    LayerSamples GetLayer(size_t l) const;
    vtkIdType GetNumberOfPoints() const { return this->Total; }
    /// Drops the last n samples (at most all); returns how many went.
    vtkIdType DropLast(vtkIdType n);
    /**
     * The points to make room for at the first Hold (up to 2^28): address
     * space, as the output's arrays take (memory is committed only where
     * written).
     */
    void SetRoom(vtkIdType points) { this->Room = points; }
    /// No layers; the memory stays for the next ones.
    void Clear();
    /// No layers and no memory (its blocks become the assembler's spares).
    void Release();

  private:
    friend class vtkErrorDiffusionPointAssembler;
    struct Entry
    {
      int Z;
      vtkIdType First; // its first sample in Ids and Densities
      size_t FirstRow; // its first row end in RowEnds
    };
    std::vector<Entry> Layers;
    std::vector<vtkIdType> RowEnds; // each from its layer's first sample
    vtkSmartPointer<vtkIdTypeArray> Ids;
    vtkSmartPointer<vtkFloatArray> Densities;
    int Rows = 0;
    vtkIdType Total = 0;
    vtkIdType Room = 0;
    vtkIdType Peak = 0; // the most points held in the arrays: what they committed
  };

  /**
   * Compacts the samples of global layer z (as AddLayer takes them) after
   * those `held` has. Reads nothing that changes while layers are added: any
   * thread may call it, one at a time for one `held`.
   */
  void Hold(int z, const float* density, const unsigned char* mask, HeldLayers& held) const;

  /// Room for n more points after those appended; returns the first one's index.
  vtkIdType Grow(vtkIdType n);

  /**
   * Writes compacted samples as points [first, first + Count()) (room from
   * Grow). Writes only there: threads may write disjoint ranges at the same
   * time, but then without the arrays whose values share memory or are not
   * plain numbers (bits, strings: others false), which WriteOthers writes
   * afterwards on one thread.
   */
  void Write(const LayerSamples& samples, vtkIdType first, bool others) const;
  void WriteOthers(const LayerSamples& samples, vtkIdType first) const;
  /**
   * Writes every layer `held` has, one after another, as points from `first`
   * on (room from Grow), as Write with others true does. With `spread`, a
   * large count of points is written on up to vtkBlueNoiseThreads::Available()
   * threads: for a caller whose other threads are idle.
   */
  void WriteHeld(const HeldLayers& held, vtkIdType first, bool spread) const;
  /// Whether an array is carried that Write leaves to WriteOthers.
  bool HasOtherArrays() const;

  /// Drops the last n points appended (at most all); returns how many went.
  vtkIdType RemoveLast(vtkIdType n);

  /// Names of the image arrays that were not carried (wrong number of tuples).
  const std::vector<std::string>& GetSkippedArrays() const { return this->Skipped; }

  /**
   * Trims the arrays to the number of points, adds `Density` to the point
   * data given to Begin() and returns the points.
   */
  vtkSmartPointer<vtkPoints> End();

  /**
   * One vertex cell per point, for n points (32-bit storage when it fits,
   * to halve the memory), filled on up to vtkBlueNoiseThreads::Available()
   * threads. Does not depend on a Begin() or End().
   */
  vtkSmartPointer<vtkCellArray> MakeVertices(vtkIdType n);

  /**
   * Keeps the arrays of an earlier output that nothing else holds (its
   * points, point arrays and vertices: each held by that output alone), so
   * that Begin() and MakeVertices() grow them in place instead of
   * allocating: a re-execution writes into memory already committed, where
   * fresh memory costs the kernel's zeroing of every page (as much as the
   * scan itself). Call before emptying `previous`; what is not used by the
   * next Begin() and MakeVertices() is released. Recycle(nullptr) ends a
   * run: the kept arrays are released, and the spare blocks the run did not
   * take are unmapped.
   */
  void Recycle(vtkPolyData* previous);

private:
  void AddTargets(vtkPointData* inPD, vtkIdType points, vtkPointData* outPD);
  vtkSmartPointer<vtkAbstractArray> TargetFor(vtkAbstractArray* source);
  void Reserve(vtkIdType tuples);
  vtkIdType CompactLayer(const unsigned char* mask, vtkIdType* ids, vtkIdType* rowEnds) const;
  enum class Arrays
  {
    SideBySide,
    Others,
    All
  };
  void WriteArrays(const LayerSamples& samples, vtkIdType first, Arrays which) const;

  int Extent[6] = { 0, -1, 0, -1, 0, -1 };       // sampled
  int SourceExtent[6] = { 0, -1, 0, -1, 0, -1 }; // of the image the arrays come from
  double IndexToPhysical[16];
  bool Jitter = false;
  std::uint64_t JitterSeed = 0;
  vtkIdType Total = 0;
  vtkPointData* OutputPointData = nullptr;
  vtkSmartPointer<vtkDataArray> Coordinates;
  vtkSmartPointer<vtkFloatArray> Densities;
  std::vector<vtkAbstractArray*> Sources; // image arrays, read at the sampled voxels
  std::vector<vtkAbstractArray*> Targets; // their copies in the output
  std::vector<int> SourceIndices;         // where each source is in the image's point data
  std::vector<std::string> Skipped;
  // Arrays of an earlier output until used or released, by role: "points",
  // "vertex offsets", "vertex connectivity", or "array " and the name.
  struct Kept
  {
    std::string Role;
    vtkSmartPointer<vtkAbstractArray> Array;
  };
  std::vector<Kept> Recycled;
  // The kept array of a role, of class className (any when null).
  vtkSmartPointer<vtkAbstractArray> TakeRecycled(
    const std::string& role, const char* className, int components);
  template <typename ArrayT>
  vtkSmartPointer<ArrayT> NewOrRecycled(const std::string& role, int components);
  // AddLayer's layer, compacted in place.
  std::vector<vtkIdType> LayerIds;
  std::vector<vtkIdType> LayerRowEnds;
  // This assembler's blocks freed by their arrays, kept for its next run.
  std::shared_ptr<vtkErrorDiffusionBlockPool> Pool;
};

#endif
