// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBlueNoiseDensityClass against its definition (the class comment), and
// OfEach, the layers' classifier, against Of: at the boundaries of the
// classes, the floats that are not positive numbers (0, -0, negatives, NaN
// of either sign, infinities, subnormals), and random bit patterns, at every
// length and alignment of the run (its vector part and its tail).
#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseDensityClass.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace bluenoise_test;

namespace
{
using C = vtkBlueNoiseDensityClass;

float FromBits(std::uint32_t bits)
{
  float f;
  std::memcpy(&f, &bits, sizeof(f));
  return f;
}

// The definition, written out: g = 2^e (1 + f) has the class 16 (e + 14) +
// floor(16 f), clamped to [1, 255]; 0 for what is not a positive number.
int Definition(float g)
{
  if (!(g > 0.0f))
  {
    return 0;
  }
  if (std::isinf(g))
  {
    return 255;
  }
  int exponent;
  const double mantissa = std::frexp(static_cast<double>(g), &exponent); // [0.5, 1)
  const long c = 16L * (exponent - 1 + 14) + static_cast<long>(std::floor((2.0 * mantissa - 1.0) * 16.0));
  return static_cast<int>(std::min(255L, std::max(1L, c)));
}

std::vector<float> Specials()
{
  std::vector<float> values = { 0.0f, -0.0f, -1.0f, -1.0e-30f, 1.0f, 0.25f, 0.5f, 2.0f, 4.0f,
    3.99f, 4.01f, 1.0e30f, std::numeric_limits<float>::infinity(),
    -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
    -std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::denorm_min(),
    std::numeric_limits<float>::min(), std::ldexp(1.0f, -14), std::ldexp(1.0f, -15),
    std::nextafter(std::ldexp(1.0f, -14), 0.0f), FromBits(0x7F800001u), FromBits(0xFFFFFFFFu),
    FromBits(0x80000001u), FromBits(0x7F7FFFFFu) };
  for (int e = -16; e <= 3; ++e) // every class boundary between
  {
    for (int m = 0; m < 16; ++m)
    {
      const float edge = std::ldexp(1.0f + m / 16.0f, e);
      values.push_back(edge);
      values.push_back(std::nextafter(edge, 0.0f));
      values.push_back(std::nextafter(edge, 10.0f));
    }
  }
  return values;
}
}

int main()
{
  Check(C::Of(std::ldexp(1.0f, -14)) == 1 && C::Of(0.25f) == 192,
    "classes of 2^-14 and of 1/4");
  const std::vector<float> specials = Specials();
  int wrong = 0;
  for (const float g : specials)
  {
    wrong += C::Of(g) != Definition(g);
  }
  Check(wrong == 0, "Of() by its definition at special values and class boundaries");

  // OfEach = Of, element by element, whatever the length and alignment.
  std::mt19937 random(29);
  std::vector<float> values(4096);
  for (size_t i = 0; i < values.size(); ++i)
  {
    values[i] = i < specials.size() ? specials[i]
      : (i % 3 == 0 ? FromBits(static_cast<std::uint32_t>(random()))
                    : std::ldexp(std::generate_canonical<float, 24>(random), -static_cast<int>(random() % 20)));
  }
  std::shuffle(values.begin(), values.end(), random);
  std::vector<unsigned char> classes(values.size() + 1);
  int mismatches = 0;
  for (size_t start = 0; start < 17; ++start)
  {
    for (size_t n = 0; start + n <= values.size(); n += n < 40 ? 1 : 997)
    {
      classes.assign(classes.size(), 77);
      C::OfEach(values.data() + start, n, classes.data());
      for (size_t i = 0; i < n; ++i)
      {
        mismatches += classes[i] != C::Of(values[start + i]);
      }
      mismatches += classes[n] != 77; // nothing written past the end
    }
  }
  Check(mismatches == 0, "OfEach() = Of() at every length and alignment");
  return Summary("TestBlueNoiseDensityClass");
}
