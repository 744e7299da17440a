// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The header checks behind bluenoise_volume.h, one function per format. Each
// parses the header itself (no VTK reader, no allocation beyond the header
// text) and compares what it declares with the real size of the data.
#ifndef bluenoise_volume_headers_h
#define bluenoise_volume_headers_h

#include <string>

namespace bluenoise
{
struct Volume;
namespace headers
{
/// Size of a file in bytes, -1 when it cannot be read (errno set).
long long FileSize(const std::string& path);
/// At most `limit` bytes from the start of `path` (gunzipped when `gzipped`).
bool ReadHead(const std::string& path, size_t limit, bool gzipped, std::string& head, std::string& error);

bool CheckNIfTI(const std::string& path, Volume& volume, std::string& error);
bool CheckMetaImage(const std::string& path, Volume& volume, bool& streamable, std::string& error);
bool CheckNRRD(const std::string& path, Volume& volume, bool& streamable, std::string& error);
bool CheckVTI(const std::string& path, Volume& volume, bool& streamable, std::string& error);
}
}

#endif
