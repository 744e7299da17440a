// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBlueNoiseDensityClass
 * @brief   Whether two densities are alike: a class per density, its base-2
 *          logarithm in sixteenths.
 *
 * Where a volume's density steps (a region next to one several times denser
 * or sparser), the error-diffusion scan keeps each side's error to that side
 * (vtkErrorDiffusionScan) and the relaxation lets each side's samples ignore
 * the other's (vtkBlueNoiseRelaxation). Both ask this class whether two
 * densities are similar: their classes differ by SimilarClasses or less, a
 * factor of about 4 (3.6 to 4.5, as the class is a logarithm in steps).
 *
 * The class of g > 0 is the float's exponent and its first four mantissa bits,
 * from 2^-14 (class 1, and below) to 2^2 (255, and above); that of g <= 0 or
 * NaN is 0. Bit operations only: the scan and the relaxation classify whole
 * layers (OfEach).
 */
#ifndef vtkBlueNoiseDensityClass_h
#define vtkBlueNoiseDensityClass_h

#include "vtkBlueNoiseSSE2.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

class vtkBlueNoiseDensityClass
{
public:
  /// Densities whose classes differ by more than this are not similar.
  static constexpr int SimilarClasses = 32;

  /// The class of a density.
  static int Of(float g)
  {
    std::uint32_t bits;
    std::memcpy(&bits, &g, sizeof(bits));
    return OfBits(bits);
  }

  /// The class of the density whose float has these bits.
  static int OfBits(std::uint32_t bits)
  {
    // Without a branch, so that loops over densities vectorize. Positive,
    // NaN excluded: the bits less one are below infinity's.
    const bool positive = bits - 1u < 0x7F800000u;
    const int c = static_cast<int>(bits >> 19) - (113 << 4); // 2^-14: exponent 113
    const int clamped = c < 1 ? 1 : (c > 255 ? 255 : c);
    return positive ? clamped : 0;
  }

  /**
   * classes[i] = Of(g[i]) for i < n. Sixteen at a time with SSE2 (the
   * compiler leaves the plain loop scalar): OfBits on four lanes of 32 bits,
   * the clamp by saturation as they are packed into bytes.
   */
  static void OfEach(const float* g, size_t n, unsigned char* classes)
  {
    size_t i = 0;
#if BLUENOISE_SSE2
    const __m128i one = _mm_set1_epi32(1);
    const __m128i none = _mm_set1_epi32(-1);
    const __m128i infinity = _mm_set1_epi32(0x7F800000);
    const __m128i base = _mm_set1_epi32(113 << 4);
    const __m128i lowest = _mm_set1_epi16(1);
    // Four classes as 32-bit lanes (any value where the density is not
    // positive) and the lanes of the positive ones (all bits set).
    const auto four = [&](const float* p, __m128i& positive) {
      const __m128i bits = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
      const __m128i less = _mm_sub_epi32(bits, one); // signed: 0 ... infinity - 1 when positive
      positive = _mm_and_si128(_mm_cmpgt_epi32(less, none), _mm_cmplt_epi32(less, infinity));
      return _mm_sub_epi32(_mm_srli_epi32(bits, 19), base);
    };
    for (; i + 16 <= n; i += 16)
    {
      __m128i p0, p1, p2, p3;
      const __m128i c0 = four(g + i, p0), c1 = four(g + i + 4, p1);
      const __m128i c2 = four(g + i + 8, p2), c3 = four(g + i + 12, p3);
      // Positive densities' classes fit 16 bits; below 1 up to 1, above 255
      // down to it as the words become bytes.
      const __m128i low = _mm_max_epi16(_mm_packs_epi32(c0, c1), lowest);
      const __m128i high = _mm_max_epi16(_mm_packs_epi32(c2, c3), lowest);
      const __m128i mask =
        _mm_packs_epi16(_mm_packs_epi32(p0, p1), _mm_packs_epi32(p2, p3));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(classes + i),
        _mm_and_si128(_mm_packus_epi16(low, high), mask));
    }
#endif
    for (; i < n; ++i)
    {
      std::uint32_t bits;
      std::memcpy(&bits, g + i, sizeof(bits));
      classes[i] = static_cast<unsigned char>(OfBits(bits));
    }
  }

  /// Whether densities of these classes are similar.
  static bool Alike(int a, int b) { return a - b <= SimilarClasses && b - a <= SimilarClasses; }

  /// Whether the two densities are similar.
  static bool Similar(float a, float b) { return Alike(Of(a), Of(b)); }
};

#endif
