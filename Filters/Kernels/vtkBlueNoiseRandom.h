// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBlueNoiseRandom
 * @brief   Seeded PCG32 generator and a symmetric pair hash for the point-set kernels.
 *
 * PCG32 (O'Neill 2014, XSH RR output of a 64-bit LCG) seeded like the
 * reference implementation: any (seed, stream) gives a full-period stream, and
 * the same seed always gives the same numbers on every platform.
 *
 * PairUniform(key, a, b) is a value in [0, 1) that depends only on the key and
 * the unordered pair {a, b} (a 64-bit finaliser applied twice), so a decision
 * taken from it for the pair (a, b) is the same when it is taken for (b, a):
 * vtkPoissonDiskKernel dithers its conflict rule with it.
 */
#ifndef vtkBlueNoiseRandom_h
#define vtkBlueNoiseRandom_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <cstdint>

class VTKFILTERSBLUENOISE_EXPORT vtkBlueNoiseRandom
{
public:
  /// Start the stream `stream` at `seed`.
  void Seed(std::uint64_t seed, std::uint64_t stream);

  /// 32 random bits.
  std::uint32_t Next()
  {
    const std::uint64_t old = this->State;
    this->State = old * 6364136223846793005ULL + this->Increment;
    const auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  /// Uniform in [0, 1) with 24 random bits (every value exact in float).
  float Uniform() { return static_cast<float>(this->Next() >> 8) * (1.0f / 16777216.0f); }

  /// Uniform integer in [0, n), unbiased; n >= 1.
  std::uint64_t Below(std::uint64_t n);

  /// Uniform in [0, 1), a function of the key and of the unordered pair {a, b}.
  static double PairUniform(std::uint64_t key, std::uint64_t a, std::uint64_t b);

private:
  std::uint64_t State = 0;
  std::uint64_t Increment = 1;
};

#endif
