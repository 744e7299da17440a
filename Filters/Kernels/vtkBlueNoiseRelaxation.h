// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBlueNoiseRelaxation
 * @brief   One sweep of local moves that spreads clustered samples of a voxel
 *          point set, layer by layer, without changing their number.
 *
 * Error diffusion places its points well on the whole but leaves pairs closer
 * than the blue-noise spacing now and then; that is most of what it has more
 * than a Poisson-disk set below the principal frequency. This pass moves each
 * such point by one voxel, to where it is farthest from its neighbors (the
 * distance rule, the default; the energy rule, below, moves every point to
 * where its neighbors repel it least):
 *
 * For every sample p of a layer whose density g(p) is in (0, 1/4] (above, the
 * moves lower L(g) still but raise S(g): at g = 0.35, 0.00036 to 0.00065 on
 * a 128^3 cube), in an order given by a hash of the seed and the voxel (each
 * sample once; one that moved is not moved again): with s = g(p)^(-1/3) the mean spacing of
 * samples at that density and d(v) the distance from voxel v to the nearest
 * other sample of a similar density (below) within the search radius
 * w = min(ceil(0.87 s) + 1, 8) voxels
 * (w + 1 when there is none), if d(p)^2 < 0.75 s^2, p moves to the one of its
 * six face neighbors c that is empty, has 0 < g(c) <= 1/4 and
 * |g(c) - g(p)| <= g(p) / 64, lies in the layers given (between the first
 * and the last), is not across a face of p's region (below), and has the
 * largest d(c), provided d(c) > d(p) (the first in
 * a hashed order among equals). Allowed to a voxel of another density,
 * samples drift: out of a dense region into a sparse one next to it (a third
 * more points in the 16 layers below a step from g = 0.2 to 0.02), and,
 * along a gradient, one way more than the other (3 % on a ramp with a
 * tolerance of 1/8). Moves to
 * the 6 face neighbors keep the spectrum isotropic (moves to the 26
 * neighbors reach a lower L(g) but add up to 0.8 dB of anisotropy).
 *
 * Similar densities: vtkBlueNoiseDensityClass::Similar, within a factor of
 * about 4. The samples of a region next to a much denser one do not see the
 * denser one's samples (nor the other way round): counted, they crowd the
 * region's samples near the boundary, which all move away from it and leave
 * a skin, empty at the boundary and too full a few voxels in, that shows in
 * the region's spectrum (up to 2 dB of anisotropy at 4/255 next to ten
 * times the density). A smooth gradient changes the density by far less
 * than that factor over a search.
 *
 * Faces: p's region is the voxels of the volume (of the run's layers) of
 * positive densities whose classes are within RegionClasses of g(p)'s (a
 * factor of about 1.09). A move to face neighbor c needs the
 * voxels along that face's axis within w of p and of c (2w + 2 of them) to
 * be in the region. Near a face of the region (of the volume, of the
 * support, or of a step to other densities) samples so move only along the
 * face: a search there reaches past it and finds nothing, and samples let
 * to move towards the face or away from it drift to it (on a cube at
 * 24/255, a skin 1.3 times as dense in the face layer and 0.7 times in the
 * next one, 0.8 dB of anisotropy). The region is narrower than the similar
 * densities: where the density steps within their factor, the samples
 * across (counted) push p away from the step, and a region reaching across
 * it let samples drift away, emptying the layers along the step (with both
 * rules; with the energy rule, anisotropy in a region of constant density
 * inside a varying one). A run's first and last layers are faces; with
 * context layers below the first movable one, that one is not.
 *
 * The energy rule (SetRule(RULE_ENERGY)) moves samples by what the whole
 * neighborhood says, not the nearest sample alone: the same samples, order,
 * once-only moves, similar densities and faces as above, but with sigma = EnergySigma s, W = ceil(EnergyBox sigma) (at least 1, at most
 * MaximumEnergyWidth) and w the weights of EnergyWeights, every such sample
 * p moves to the neighbor c of its 26 (face, edge and corner; empty, 0 <
 * g(c) <= 1/4, |g(c) - g(p)| <= g(p) / 64, in the layers given, and, along
 * each axis c differs from p in, open by the faces rule with w = W) of the
 * lowest energy E(c), provided E(c) < (1 - EnergyMargin) E(p), the first in
 * the order k = (EnergyStart + n) mod 27, n = 0 ... 26, among equals, where
 * neighbor k is at (k mod 3 - 1, floor(k / 3) mod 3 - 1, floor(k / 9) - 1)
 * from p (k = 13 is p). E(c) is the Gaussian energy of the other samples of
 * a similar density around c, truncated to the box of half width W:
 *   E(c) = sum over dz of w(dz - ez) (sum over dy of w(dy - ey) (sum over
 *          dx of w(dx - ex))),
 * (dx, dy, dz) the offsets from p of those samples, from -(W + 1) to W + 1
 * each, (ex, ey, ez) = c - p, every sum in float in increasing order, the
 * innermost starting from 0.0f. Moves to the 26 neighbors add no anisotropy
 * here (the energy does not favor the axes as the distance rule's do), and
 * two passes of it (one pass's output pushed into the next) take L(g) below
 * weighted sample elimination's on constant cubes; a pass costs several
 * times the distance rule's (Testing/QualityReport.md has the figures).
 *
 * On constant cubes it lowers L(g) below both the plain scan's and a
 * continuous Poisson-disk set's of the same count, lowers S(g) and leaves the
 * anisotropy as it was (Testing/QualityReport.md has the figures).
 *
 * Samples are at voxels of positive density, as error diffusion places them:
 * one at a density of 0 never moves, and the searches count it only where
 * every positive density within reach is similar to the searching sample's.
 *
 * Streaming: Push() one layer after another (densities and mask, x fastest);
 * once the layers from z - 1 to z + w are in, layer z is relaxed (its samples
 * may move into z - 1, z or z + 1) and layer z - 1 becomes final: Push
 * returns the final layers, and Flush() the rest after the last one. A layer
 * with no density in (0, 1/4] is final once the layers before it are (no
 * sample moves into or out of it); pushed then, it is returned as it came,
 * its buffers the caller's (Borrowed). The buffers of a layer that is not
 * borrowed stay as they are through the next Push too, and are reused by the
 * one after: a caller may hand them to another thread for a while. Memory:
 * the densities, masks and move flags (6 bytes a voxel) of the MaximumRadius
 * + 3 layers not yet final, made by the first layer that is not context, and
 * the masks as bits of 32 layers, with their density classes per word of
 * bits and, for a layer of more than one density, per voxel (a byte), and,
 * for a layer with voxels of no density, which have one (a bit).
 *
 * The searches: the rows of bits around a sample (those its search and its
 * face neighbors' read) are copied into a window, 64 voxels wide, once per
 * sample, and the nearest sample in a row is found from the bit counts on
 * either side of the voxel, without a loop over the row's samples; the rows
 * at one distance from the voxel's, four at a time, are searched as one.
 * Where every density within reach of a sample is similar to its own, the
 * lines of the faces' rule are read from the bits of the densities' support.
 */
#ifndef vtkBlueNoiseRelaxation_h
#define vtkBlueNoiseRelaxation_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <cstddef>
#include <cstdint>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkBlueNoiseRelaxation
{
public:
  /// A layer the pass is done with: its (relaxed) mask and its densities.
  struct Layer
  {
    int Z = 0;
    const float* Density = nullptr;
    const unsigned char* Mask = nullptr;
    vtkIdType Count = 0;           ///< samples in the layer
    bool Borrowed = false;         ///< the buffers given to Push: the caller's
  };

  static constexpr int MaximumRadius = 8;
  /// The rules by which a sample moves (SetRule).
  enum Rules
  {
    RULE_SPACING = 0, ///< away from its nearest neighbor, when too near (above)
    RULE_ENERGY = 1   ///< to where its Gaussian energy is lowest (below)
  };
  /// The energy rule's widest box: half width MaximumRadius - 1.
  static constexpr int MaximumEnergyWidth = MaximumRadius - 1;
  static constexpr float MaximumDensity = 0.25f;
  /// How far a move may change the density, relative to it.
  static constexpr float DensityTolerance = 1.0f / 64.0f;

  /// The face neighbors, in the order FaceOrder permutes: +x, -x, +y, -y, +z, -z.
  static constexpr int Faces[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
    { 0, 0, 1 }, { 0, 0, -1 } };

  /**
   * The hashed order of a layer's samples: by OrderKey(seed, x, y, z) | i,
   * i = x + nx y the index in the layer (the key's low 32 bits are 0).
   */
  static std::uint64_t OrderKey(std::uint64_t seed, int x, int y, int z);

  /// The order in which the faces (indices into Faces) of sample (x, y, z) are tried.
  static void FaceOrder(std::uint64_t seed, int x, int y, int z, int order[6]);

  /**
   * Start a run over layers of nx * ny voxels, the first one being z. The
   * layers below firstMovable (when it is above firstZ) are context: the
   * searches see their samples, but none moves into or out of them, and Push
   * returns each as final at once (Borrowed). A part of a volume whose
   * layers below are sampled apart relaxes its first layers with those below
   * in view, as a run over the whole volume would.
   */
  void Begin(int nx, int ny, int firstZ, std::uint64_t seed, int firstMovable = VTK_INT_MIN);

  /**
   * Add the next layer (global index z = the previous one + 1). Returns the
   * layers that became final (the list valid until the next call of Push or
   * Flush; the buffers of a layer not Borrowed until the call after that).
   */
  const std::vector<Layer>& Push(int z, const float* density, const unsigned char* mask);

  /// After the last layer: relax what is left and return every other layer.
  const std::vector<Layer>& Flush();

  /**
   * The rule, before Begin: RULE_SPACING (the default) or RULE_ENERGY.
   * Anything else is RULE_SPACING.
   */
  void SetRule(int rule);
  int GetRule() const { return this->Rule; }

  /**
   * The energy rule's box half width W and weights for density g:
   * weights[d + MaximumRadius + 1] = exp(-d^2 / (2 sigma^2)) for |d| <= W,
   * 0 for W < |d| <= MaximumRadius + 1 (sigma = EnergySigma s).
   */
  static int EnergyWeights(float g, float weights[2 * MaximumRadius + 3]);
  /// sigma over the mean spacing s = g^(-1/3); W = ceil(EnergyBox sigma).
  static constexpr double EnergySigma = 0.3;
  static constexpr double EnergyBox = 2.5;
  /// A move lowers the energy to below (1 - EnergyMargin) times the sample's.
  static constexpr float EnergyMargin = 1.0e-6f;

  /**
   * A sample's region for the faces rule: densities whose classes
   * (vtkBlueNoiseDensityClass) differ from its own by at most this many.
   */
  static constexpr int RegionClasses = 2;

  /// Where the energy rule's order of the neighbors of sample (x, y, z) starts: 0 ... 26.
  static int EnergyStart(std::uint64_t seed, int x, int y, int z);

  /// Samples moved so far.
  vtkIdType GetNumberOfMoves() const { return this->Moves; }

private:
  struct Slot // what the searches read, for the layers around the one relaxed
  {
    int Z = 0;
    std::vector<std::uint64_t> Bits; // the mask, rows padded to whole words, zero rows around
    bool Relaxable = false;          // some density of the layer is in (0, 1/4]
    // The classes (vtkBlueNoiseDensityClass) of the voxels of positive
    // density: their lowest and highest, per word of Bits (Low > High where
    // none) and in the layer; each voxel's only when they differ (else empty).
    std::vector<unsigned char> WordLow, WordHigh;
    int Low = 255, High = 0;
    std::vector<unsigned char> Classes;
    // Whether every voxel has a positive density; if not, which do, as Bits.
    bool Full = true;
    std::vector<std::uint64_t> Support;
  };
  struct Plane // what can still change, for the layers not yet final
  {
    int Z = 0;
    std::vector<float> Density;
    std::vector<unsigned char> Mask;
    std::vector<unsigned char> Moved; // samples that moved here: they move no more
    vtkIdType Count = 0;              // samples in Mask
  };
  struct RowRun // rows dy = Low ... High of layer dz from the one searched around
  {
    int DZ;
    int Low;
    int High;
  };
  struct Shell // four rows at one distance (dz^2 + dy^2 = Squared) from the center's
  {
    int Squared;
    int Cells[4]; // their places in Window from the center's: dz Span + dy
  };

  Slot* Find(int z);
  Plane* FindPlane(int z);
  const std::uint64_t* Row(const std::uint64_t* bits, int y) const;
  std::ptrdiff_t RowStart(int y) const;
  void Set(int x, int y, int z, bool sample);
  void SetDensity(float g);
  struct RowSet // what the searches read for one radius and cap
  {
    std::vector<RowRun> Loaded; // the rows around a sample and its face neighbors
    std::vector<Shell> Shells;  // the rows within the radius and nearer than the cap, nearest first
  };
  static RowSet MakeRows(int radius, int cap);
  void LoadAround(int x, int y);
  void Classify(Slot& slot, const float* density);
  bool MixedAround(int x, int y, int cls, int classes) const;
  void Alikeness(int x, int y, int cls, bool& counted, bool& region) const;
  void FindMixed();
  void KeepSimilar(const std::vector<RowRun>& runs, int x, int y, int cls);
  int Nearest(int fx, int fy, int fz, int enough) const;
  unsigned BlockedFaces(int x, int y) const;
  unsigned CrowdedFaces(int reach) const;
  bool Supported(const Slot* slot, int x, int y) const;
  bool InRegion(int x, int y, int dz, int cls) const;
  bool LineInRegion(int x, int y, int face, int cls, bool alike) const;
  bool LineSupported(int x, int y, int face) const;
  unsigned BandFaces(int x, int y) const;
  void SortOrder();
  void RelaxLayer(int z);
  void Prefetch(int x, int y, const Plane& plane);
  void RelaxSample(int x, int y, int z, float g);
  void MoveBySpacing(int x, int y, int z, float g);
  void MoveByEnergy(int x, int y, int z, float g);
  void Energies(float energy[27]) const;
  struct FaceLines // which faces' lines were asked (Known), and which are open
  {
    unsigned Known = 0;
    unsigned Open = 0;
  };
  bool EnergyTargetOpen(int x, int y, float g, const int d[3], int cls, bool region, FaceLines& open) const;
  void Move(int x, int y, int z, int dx, int dy, int dz);
  void Release(int z);
  void RelaxReady();

  int NX = 0;
  int NY = 0;
  int WordsPerRow = 0;
  int First = 0;     // first layer of the run
  int Last = -1;     // last layer pushed
  int Relaxed = 0;   // layers below this one are relaxed
  int Movable = 0;   // layers below this one are context
  int Finalized = 0; // layers below this one were returned
  std::uint64_t Seed = 0;
  vtkIdType Moves = 0;
  float LastDensity = -1.0f; // the density Limit, Radius, Cap and the rows are for
  double Limit = 0.0;         // the squared distance below which a sample moves
  int Radius = 1;             // of the box searched around a voxel
  int Cap = 1;                // distances are counted up to this one (squared)
  int Rule = RULE_SPACING;
  static bool Within(int a, int b, int classes) { return a - b <= classes && b - a <= classes; }
  struct Roots // Limit, Radius and Cap of a density (and the energy rule's Weights)
  {
    float Density = -1.0f;
    double Limit = 0.0;
    int Radius = 1;
    int Cap = 1;
    // EnergyWeights', and one more, 0: the energy's rows carry a fourth lane
    // of no neighbor, which reads one past w(MaximumRadius + 1) at the
    // widest box.
    float Weights[2 * MaximumRadius + 4] = {};
  };
  static constexpr int RootCacheBits = 6;
  Roots RootCache[1 << RootCacheBits];
  unsigned Current = 0; // the entry of LastDensity (its Weights for the energy rule)
  // The row sets by radius and cap (at radius * RowSetCaps + cap), made as
  // they come up (SetDensity); the energy rule's at cap 0 (the spacing
  // rule's caps are at least 2).
  static constexpr int RowSetCaps = (MaximumRadius + 1) * (MaximumRadius + 1) + 1;
  std::vector<RowSet> RowSets = std::vector<RowSet>((MaximumRadius + 1) * RowSetCaps);
  const RowSet& CurrentRows() const
  {
    return this->RowSets[static_cast<size_t>(this->Radius * RowSetCaps + this->Cap)];
  }
  // The bits around the sample being relaxed: rows dz, dy in [-Reach, Reach]
  // (Reach = MaximumRadius + 1), each 64 voxels wide, the sample's x at bit 32.
  static constexpr int Reach = MaximumRadius + 1;
  static constexpr int Span = 2 * Reach + 1;
  std::uint64_t Window[Span * Span];
  const std::uint64_t* Layers[Span]; // the bits of layers z - Reach ... z + Reach
  const float* Densities[3] = {};     // of layers z - 1, z, z + 1 where samples may move
  const Slot* Slots[Span] = {};       // of layers z - Reach ... z + Reach (nullptr: none)
  // Where the layer relaxed has samples of dissimilar densities within reach:
  // per row and word, the lowest and highest class over the words within
  // Reach rows and layers (Mixed false: nowhere, and these are not made).
  bool Mixed = false;
  bool RegionMixed = false; // the same by RegionClasses
  // The run's layers within Reach of the one relaxed are of positive
  // densities only, all alike: regions end only at the faces along x and y
  // and at the run's first and last layers.
  bool Whole = false;
  std::vector<unsigned char> MixedLow, MixedHigh;
  std::vector<unsigned char> MixedLayersLow, MixedLayersHigh; // over the layers only
  std::vector<Slot> Ring;
  std::vector<Plane> Planes;
  std::vector<std::uint64_t> NoSamples; // the bits of a layer outside the ring
  std::vector<Layer> Done;
  std::vector<unsigned char> ClassScratch; // a layer's classes, kept by its slot when mixed
  std::vector<std::uint64_t> Order; // hash and index of a layer's samples
  std::vector<std::uint64_t> Scratch; // for sorting Order
};

#endif
