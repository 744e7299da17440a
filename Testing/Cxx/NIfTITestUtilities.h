// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Small NIfTI-1 files written by the reader tests themselves: a 348-byte
// header (the fields the tests set, in the machine's byte order), 4 bytes of
// extension flags, and int16 voxels, plain (.nii) or gzipped (.nii.gz).
#ifndef NIfTITestUtilities_h
#define NIfTITestUtilities_h

#include "vtk_zlib.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace bluenoise_test
{
struct NIfTIFile
{
  int Dims[3] = { 5, 4, 3 };
  float PixDim[3] = { 1.5f, 2.0f, 2.5f };
  float QFac = 1.0f; // pixdim[0]
  short QFormCode = 0;
  short SFormCode = 0;
  float Quatern[3] = { 0, 0, 0 }; // b, c, d
  float QOffset[3] = { 0, 0, 0 };
  float SRow[3][4] = { { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 } };
  int SizeOfHeader = 348;

  /// The value of file voxel (i, j, k).
  static int16_t Value(int i, int j, int k) { return static_cast<int16_t>(i + 10 * j + 100 * k); }

  std::string Bytes() const
  {
    std::string h(352, '\0');
    auto put = [&h](size_t at, const void* v, size_t n) { std::memcpy(&h[at], v, n); };
    const int32_t size = this->SizeOfHeader;
    put(0, &size, 4);
    const int16_t dim[8] = { 3, static_cast<int16_t>(this->Dims[0]),
      static_cast<int16_t>(this->Dims[1]), static_cast<int16_t>(this->Dims[2]), 1, 1, 1, 1 };
    put(40, dim, sizeof(dim));
    const int16_t datatype = 4, bitpix = 16; // DT_INT16
    put(70, &datatype, 2);
    put(72, &bitpix, 2);
    const float pixdim[8] = { this->QFac, this->PixDim[0], this->PixDim[1], this->PixDim[2], 1, 1,
      1, 1 };
    put(76, pixdim, sizeof(pixdim));
    const float voxOffset = 352.0f, slope = 1.0f;
    put(108, &voxOffset, 4);
    put(112, &slope, 4);
    put(252, &this->QFormCode, 2);
    put(254, &this->SFormCode, 2);
    put(256, this->Quatern, 12);
    put(268, this->QOffset, 12);
    put(280, this->SRow, 48);
    put(344, "n+1\0", 4);
    for (int k = 0; k < this->Dims[2]; ++k)
    {
      for (int j = 0; j < this->Dims[1]; ++j)
      {
        for (int i = 0; i < this->Dims[0]; ++i)
        {
          const int16_t v = Value(i, j, k);
          h.append(reinterpret_cast<const char*>(&v), 2);
        }
      }
    }
    return h;
  }
};

/// Writes `bytes` to `path`, gzipped when the name ends in .gz.
inline bool WriteFile(const std::string& path, const std::string& bytes)
{
  if (path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0)
  {
    gzFile file = gzopen(path.c_str(), "wb");
    if (!file)
    {
      return false;
    }
    const int n = gzwrite(file, bytes.data(), static_cast<unsigned>(bytes.size()));
    return gzclose(file) == Z_OK && n == static_cast<int>(bytes.size());
  }
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    return false;
  }
  const size_t n = std::fwrite(bytes.data(), 1, bytes.size(), file);
  return std::fclose(file) == 0 && n == bytes.size();
}

/// The bytes of a file ("" when it cannot be read).
inline std::string ReadFile(const std::string& path)
{
  std::string bytes;
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file)
  {
    return bytes;
  }
  char buffer[65536];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof(buffer), file)) > 0)
  {
    bytes.append(buffer, n);
  }
  std::fclose(file);
  return bytes;
}
}

#endif
