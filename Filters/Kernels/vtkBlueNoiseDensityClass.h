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
 * layers.
 */
#ifndef vtkBlueNoiseDensityClass_h
#define vtkBlueNoiseDensityClass_h

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

  /// Whether densities of these classes are similar.
  static bool Alike(int a, int b) { return a - b <= SimilarClasses && b - a <= SimilarClasses; }

  /// Whether the two densities are similar.
  static bool Similar(float a, float b) { return Alike(Of(a), Of(b)); }
};

#endif
