// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBlueNoiseVolumeFileCheck
 * @brief   Checks of a volume file's header against the real size of its data.
 *
 * Files are distrusted: before a reader allocates anything, what a header
 * declares (dimensions, spacing, components, bytes per value) is checked
 * here against the bytes the file really holds. Dimensions must be whole and
 * >= 1, spacing finite and > 0, and the data present: at least the declared
 * bytes, or, compressed, enough bytes to decompress to them (zlib's largest
 * ratio, 1032:1, bounds what n compressed bytes can hold). So time and memory
 * follow the file's real size, whatever its header claims.
 *
 * Plain C++ (static functions, no VTK pipeline), shared by the module's
 * readers (vtkBlueNoiseNIfTIReader) and the programs' header checks
 * (Apps/Common/bluenoise_volume_headers.cxx). Failures are a message in
 * `error`, naming the problem (not the file: callers add it).
 */
#ifndef vtkBlueNoiseVolumeFileCheck_h
#define vtkBlueNoiseVolumeFileCheck_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <cstddef> // for size_t
#include <string>  // for std::string

class VTKFILTERSBLUENOISE_EXPORT vtkBlueNoiseVolumeFileCheck
{
public:
  /// zlib's largest compression ratio (deflate's limit is 1032:1): compressed
  /// data of n bytes never holds more than this many times n.
  static constexpr double MaximumCompressionRatio = 1032.0;

  /// What a header declares, to be checked by CheckDeclared.
  struct Declared
  {
    double Dimensions[3] = { 1, 1, 1 };
    double Spacing[3] = { 1, 1, 1 };
    double Components = 1;
    double BytesPerValue = 1;
    /// Bytes of data the file holds (compressed bytes when Compressed).
    double Available = 0;
    bool Compressed = false;
  };

  /// What a successful check vouches for.
  struct Checked
  {
    int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
    vtkIdType Voxels = 0;
    /// Bytes of one voxel over all declared values (a lower bound).
    double BytesPerVoxel = 0.0;
  };

  /// Positive whole dimensions, finite positive spacing, 1 to 4096
  /// components, and the declared bytes present; fills `checked` (extent from 0).
  static bool CheckDeclared(const Declared& declared, Checked& checked, std::string& error);

  /// Size of a file in bytes, -1 when it cannot be read or is not a regular file (errno set).
  static long long FileSize(const std::string& path);

  /// At most `limit` bytes from the start of `path` (gunzipped when `gzipped`).
  static bool ReadHead(
    const std::string& path, size_t limit, bool gzipped, std::string& head, std::string& error);

  /// Bytes a gzip file decompresses to, reading no further than `limit` bytes of it.
  static bool GunzippedSize(
    const std::string& path, double limit, double& size, std::string& error);

  /// The bytes of `path` after `offset` (an error when the offset lies beyond its end).
  static bool DataFileSize(
    const std::string& path, double offset, double& available, std::string& error);

  /// A number for messages (15 significant digits).
  static std::string Number(double value);

  /**
   * The text of a VTK error or warning event without what the macros put
   * before it ("<kind>: In <file>, line <n>\n<Class> (<address>): "), trimmed;
   * "unknown error" when nothing is left.
   */
  static std::string PlainMessage(const char* message);
};

#endif
