// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBlueNoiseSpectrumKernel
 * @brief   The 3D blue-noise spectrum metric of the paper (section 4, Eq. 2-11).
 *
 * Plain C++ (not a vtkObject, not wrapped) so that the sampler tests and the
 * parameter optimizer can call it many thousand times without a pipeline.
 * vtkBlueNoiseSpectrum is the VTK filter around it.
 *
 * Definitions (every quantity below is what Compute() reports):
 *
 * - Signal. b is a point-count volume on an Lx x Ly x Lz grid, x fastest
 *   (index x + Lx * (y + Ly * z)); counts must be finite and non-negative.
 *   N = sum of b is the number of points, V = Lx * Ly * Lz, g = N / V.
 * - Power spectrum. P(f) = |B(f)|^2 / N with B the discrete Fourier transform of
 *   b; the DC term is excluded everywhere. White noise has a mean power of about
 *   1 - g; a single point has power 1 at every frequency.
 * - Frequencies, in cycles per voxel: f = (kx/Lx, ky/Ly, kz/Lz) with every k
 *   folded into [-L/2, L/2).
 * - Radial shells. Lmin = min(Lx, Ly, Lz); a frequency lies on shell
 *   n = floor(Lmin * |f| + 0.5), evaluated in double precision as
 *   sqrt(((kz/Lz)^2 + (ky/Ly)^2) + (kx/Lx)^2) * Lmin (for cubic grids this is
 *   round(|k|), which never ties; on other grids an exact half goes up).
 *   Shell n has frequency n / Lmin. Shells 1 .. nmax are reported, nmax being
 *   the shell of the grid's corner frequency; shell 0 holds only DC and is
 *   left out.
 * - Per shell (Eq. 2-4): RadialPower = mean of P over the shell; Anisotropy =
 *   unbiased sample variance / RadialPower^2 (0 when the shell has fewer than 2
 *   samples or a mean of 0); AnisotropyDB = 10 log10(Anisotropy), floored at
 *   AnisotropyFloorDB (-300 dB) so that an anisotropy of 0 is never -inf;
 *   ShellCount = number of frequencies on the shell over the full spectrum
 *   (both Hermitian halves, as a complex FFT would give). The shell counts add
 *   up to V - 1.
 * - Principal frequency (Eq. 6): f_g = cbrt(g) for g <= 0.5, cbrt(1 - g) above
 *   (0 when g >= 1, which only count volumes can exceed).
 * - Low-frequency ratio (Eq. 7): L = sum of P over 0 < |f| < f_g divided by the
 *   sum of P over all 0 < |f| (|f| itself, not rounded to shells); L = 0 when
 *   there is no power off DC. With h = g (or 1 - g above 0.5), |f| < f_g is
 *   evaluated as |f|^6 < h^2, |f|^2 summed as (fz^2 + fy^2) + fx^2 in double
 *   precision: frequencies exactly on f_g (e.g. |f| = 1/8 for one point in
 *   8^3) are left out, which cbrt's rounding could not guarantee.
 * - Segmented spectra (Eq. 8-10): with the components folded to |fx|, |fy|,
 *   |fz|, SrapsXY is the shell mean of P over frequencies where |fz| is the
 *   largest component, SrapsXZ where |fy| is, SrapsYZ where |fx| is. Ties go to
 *   the lowest axis (x before y before z): |fx| == |fy| >= |fz| lies in SrapsYZ.
 *   Components are compared exactly (|kx| Ly Lz against |ky| Lx Lz and so on).
 *   A shell without a sample in a segment has the value 0 there.
 * - Symmetry (Eq. 11): SymmetryCorrelation C is the mean of the Pearson
 *   correlations of (XY, XZ), (XY, YZ), (XZ, YZ) over the shells
 *   1 .. floor(Lmin / 2) in which all three segments have samples; the
 *   correlation with a constant curve (sum of squared deviations within
 *   (1e-12 * largest |value|)^2 per shell, i.e. zero up to rounding) is 0.
 *   Symmetry S = 1 - C.
 * - Target (Eq. 5): TargetValue T = w L + (1 - w) S, w = Weight (default 0.02).
 * - Realizations. Several volumes on the same grid are averaged: P(f) is the
 *   mean of the realizations' own P(f) (each normalized by its own N); the
 *   shell statistics are computed on that mean; NumberOfPoints is the mean N
 *   and Density = mean N / V.
 *
 * Edge cases: a realization with N = 0 is rejected with an error. When every
 * voxel of every realization holds the same count (g = 1 for a mask) there is
 * no power off DC: Compute() succeeds with Result::Warning set, L = 0, all
 * anisotropies 0, C = 0 and S = 1. No reported value is ever NaN.
 *
 * Cost: per realization, a real-to-complex FFT done as in-cache 2D transforms
 * of the z slabs followed by z transforms over small blocks of columns (FFTW,
 * plans shared per grid shape by the kernels that hold them), then per Compute() one
 * pass over the half spectrum. Slabs, column blocks and the rows of that pass
 * are spread over vtkSMPTools threads (as many as
 * vtkSMPTools::GetEstimatedNumberOfThreads(), e.g. VTK_SMP_MAX_THREADS with
 * the STDThread backend), each running the same single-threaded FFTW plans,
 * and the shell statistics are summed in fixed chunks added in a fixed order:
 * every reported value is the same, to the last bit, whatever the number of
 * threads. BenchmarkSpectrum times it by thread count, with the buffers
 * reused and new (Documentation/Results.md).
 *
 * Memory: the transform buffer, Lz * Ly * 2 (Lx / 2 + 1) doubles (about 8
 * bytes per voxel), which also holds the power of a single realization; from
 * the second realization on, a dense half-spectrum sum of Lz * Ly * (Lx / 2 + 1)
 * doubles (about 4 bytes per voxel) more (BufferBytes() says how much for a
 * grid, before anything is allocated). Buffers of 16 MiB and more are committed in bulk
 * when allocated (on Linux: transparent huge pages where offered, and
 * MADV_POPULATE_WRITE), as faulting them in page by page costs more than the
 * transform on virtual machines. A kernel keeps its buffers across Reset() and
 * SetDimensions() with an unchanged shape; AddSamples() needs 8 bytes per
 * sample besides.
 *
 * Thread safety: distinct kernels may be used from different threads at the
 * same time (plan creation is serialised internally); one kernel must not be
 * used by two threads at once. Other code in the process that calls the FFTW
 * planner directly is not covered by the internal lock.
 */
#ifndef vtkBlueNoiseSpectrumKernel_h
#define vtkBlueNoiseSpectrumKernel_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkBlueNoiseSpectrumKernel
{
public:
  static constexpr double DefaultWeight = 0.02;
  static constexpr double AnisotropyFloorDB = -300.0;

  /// Everything Compute() reports. Per-shell vectors hold shells 1 .. nmax
  /// (entry i is shell i + 1).
  struct Result
  {
    std::vector<double> Frequency;    ///< shell frequency n / Lmin, cycles per voxel
    std::vector<double> RadialPower;  ///< Eq. 2
    std::vector<double> Anisotropy;   ///< Eq. 3-4
    std::vector<double> AnisotropyDB; ///< 10 log10(Anisotropy), floored
    std::vector<double> SrapsXY;      ///< Eq. 8
    std::vector<double> SrapsXZ;      ///< Eq. 9
    std::vector<double> SrapsYZ;      ///< Eq. 10
    std::vector<long long> ShellCount;
    int Dimensions[3] = { 0, 0, 0 };
    int Realizations = 0;
    double NumberOfPoints = 0.0;      ///< mean N over the realizations
    double Density = 0.0;             ///< g
    double PrincipalFrequency = 0.0;  ///< f_g, Eq. 6
    double LowFrequencyRatio = 0.0;   ///< L(g), Eq. 7
    double SymmetryCorrelation = 0.0; ///< C
    double Symmetry = 0.0;            ///< S(g) = 1 - C, Eq. 11
    double TargetValue = 0.0;         ///< T(g), Eq. 5
    std::string Warning;              ///< empty unless the result needs a caveat
  };

  vtkBlueNoiseSpectrumKernel();
  ~vtkBlueNoiseSpectrumKernel();
  vtkBlueNoiseSpectrumKernel(const vtkBlueNoiseSpectrumKernel&) = delete;
  vtkBlueNoiseSpectrumKernel& operator=(const vtkBlueNoiseSpectrumKernel&) = delete;

  /**
   * Set the grid shape (each dimension at least 2) and clear the accumulated
   * realizations. Buffers are kept when the shape does not change. Returns
   * false, with the reason in `error`, for a bad shape; the kernel then has no
   * shape until the next successful call.
   */
  bool SetDimensions(int lx, int ly, int lz, std::string* error = nullptr);

  /**
   * The bytes of the kernel's buffers for an lx * ly * lz grid (see Memory
   * above): the transform, and the half-spectrum sum when several
   * realizations are added. In double, as field-data grids overflow integers.
   */
  static double BufferBytes(int lx, int ly, int lz, bool severalRealizations);
  void GetDimensions(int dims[3]) const;

  /// w of Eq. 5, clamped to [0, 1].
  void SetWeight(double w);
  double GetWeight() const { return this->Weight; }

  /// Forget the accumulated realizations; keep the shape and the buffers.
  void Reset();
  int GetNumberOfRealizations() const { return this->Realizations; }

  /**
   * Add one realization of Lx * Ly * Lz counts, x fastest (a 0/1 mask has one
   * point per set voxel; any value is a count). Returns false and leaves the accumulated state
   * unchanged when no shape is set, N = 0, or a count is negative or not finite.
   */
  bool AddRealization(const unsigned char* mask, std::string* error = nullptr);
  bool AddRealization(const float* counts, std::string* error = nullptr);
  bool AddRealization(const double* counts, std::string* error = nullptr);

  /**
   * Add one realization given as `count` samples: the voxel index of each
   * (x fastest, as above) and its weight (`weights` null: 1 each). Samples on
   * one voxel add up in single precision in the order given, so the result is
   * that of AddRealization(const float*) on a count volume filled in that
   * order, without the volume. Returns false and leaves the accumulated state
   * unchanged for an index outside the grid, a negative or non-finite weight
   * or N = 0.
   */
  bool AddSamples(
    const long long* voxels, const float* weights, std::size_t count, std::string* error = nullptr);

  /// Evaluate the metric on the realizations added so far (false if none).
  bool Compute(Result& out, std::string* error = nullptr) const;

  /**
   * The averaged power spectrum over the full grid with the zero frequency
   * centered: x fastest, Lx * Ly * Lz values, index i on an axis of length L is
   * the frequency (i - floor(L / 2)) / L; the DC value is 0. Returns false (and
   * empties `out`) when no realization has been added.
   */
  bool GetCenteredPowerSpectrum(std::vector<double>& out) const;
  /// The same into caller-owned memory of Lx * Ly * Lz values (untouched on false).
  bool GetCenteredPowerSpectrum(double* out) const;

  /**
   * The same in new memory, committed in bulk like the kernel's own buffers
   * (a gigabyte at 512^3); release it with free() (vtkAbstractArray's
   * VTK_DATA_ARRAY_FREE). Null when no realization has been added or the
   * memory cannot be allocated.
   */
  double* NewCenteredPowerSpectrum() const;

  /**
   * One-call evaluation of a single mask, with a kernel of its own (a loop
   * over many masks of one shape saves the allocations with a kernel kept
   * across Reset() instead).
   */
  static bool Evaluate(const unsigned char* mask, const int dims[3], double weight, Result& out,
    std::string* error = nullptr);

private:
  template <typename T>
  bool AddRealizationTemplate(const T* values, std::string* error);
  // Fills every z slab with fillSlab(z, slab, rowSums, check), checks the counts
  // and transforms them; the power goes where PowerLayout() says.
  template <typename FillSlab>
  bool TransformRealization(FillSlab fillSlab, std::string* error);
  void TransformColumns(double invN);
  void ZeroPower();
  bool MovePowerAside(std::string* error);
  // The accumulated power: its start, and the strides in doubles from one z,
  // one y and one kx to the next.
  const double* PowerLayout(std::size_t strides[3]) const;
  void ReleaseBuffers();

  int Dimensions[3] = { 0, 0, 0 };
  double Weight = DefaultWeight;
  int Realizations = 0;
  int ConstantRealizations = 0; // realizations with no power off DC
  double PointSum = 0.0;        // sum of N over the realizations
  std::size_t HalfSize = 0;     // Lz * Ly * (Lx / 2 + 1)
  std::size_t SlabStride = 0;   // doubles from one z slab of Transform to the next
  // Transform: per z slab, the real input with rows padded to 2 * (Lx / 2 + 1)
  // doubles, transformed in place in x and y, then in z by column blocks; with
  // one realization (PowerInTransform), the power in the real part of each
  // complex slot. PowerSum: the sum over realizations of |B|^2 / N, half
  // spectrum, from the second realization on.
  double* Transform = nullptr;
  double* PowerSum = nullptr;
  bool PowerInTransform = false;
  void* SlabPlan = nullptr;   // fftw_plan, kept alive by Plans
  void* ColumnPlan = nullptr; // fftw_plan, kept alive by Plans
  std::shared_ptr<const void> Plans; // the shape's plans, shared with the kernels of that shape
};

#endif
