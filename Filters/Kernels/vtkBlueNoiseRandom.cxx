// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseRandom.h"

#include <utility>

namespace
{
// The 64-bit finaliser of MurmurHash3: every input bit flips each output bit
// with probability close to 1/2.
std::uint64_t Mix(std::uint64_t x)
{
  x ^= x >> 33u;
  x *= 0xff51afd7ed558ccdULL;
  x ^= x >> 33u;
  x *= 0xc4ceb9fe1a85ec53ULL;
  x ^= x >> 33u;
  return x;
}
}

//------------------------------------------------------------------------------
void vtkBlueNoiseRandom::Seed(std::uint64_t seed, std::uint64_t stream)
{
  this->State = 0;
  this->Increment = (stream << 1u) | 1u;
  this->Next();
  this->State += seed;
  this->Next();
}

//------------------------------------------------------------------------------
std::uint64_t vtkBlueNoiseRandom::Below(std::uint64_t n)
{
  if (n <= 1)
  {
    return 0;
  }
  // Rejection of the top partial block of 2^32 (or 2^64) values keeps every
  // residue equally likely.
  if (n <= 0xffffffffULL)
  {
    const auto n32 = static_cast<std::uint32_t>(n);
    const std::uint32_t limit = (0u - n32) % n32; // 2^32 mod n
    std::uint32_t x;
    do
    {
      x = this->Next();
    } while (x < limit);
    return x % n32;
  }
  const std::uint64_t limit = (0ULL - n) % n; // 2^64 mod n
  std::uint64_t x;
  do
  {
    x = (static_cast<std::uint64_t>(this->Next()) << 32u) | this->Next();
  } while (x < limit);
  return x % n;
}

//------------------------------------------------------------------------------
double vtkBlueNoiseRandom::PairUniform(std::uint64_t key, std::uint64_t a, std::uint64_t b)
{
  if (a > b)
  {
    std::swap(a, b);
  }
  const std::uint64_t h = Mix(Mix(key ^ (a * 0x9e3779b97f4a7c15ULL)) ^ b);
  return static_cast<double>(h >> 11u) * (1.0 / 9007199254740992.0); // 53 bits
}
