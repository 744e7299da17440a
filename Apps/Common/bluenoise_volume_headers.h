// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The header checks behind bluenoise_volume.h, one function per format. Each
// parses the header itself (no VTK reader, no allocation beyond the header
// text) and compares what it declares with the real size of the data, with
// the module's vtkBlueNoiseVolumeFileCheck; NIfTI files are checked by the
// module's reader itself (vtkBlueNoiseNIfTIReader::CheckFile).
#ifndef bluenoise_volume_headers_h
#define bluenoise_volume_headers_h

#include <string>

namespace bluenoise
{
struct Volume;
namespace headers
{
bool CheckNIfTI(const std::string& path, Volume& volume, std::string& error);
bool CheckMetaImage(const std::string& path, Volume& volume, bool& streamable, std::string& error);
bool CheckNRRD(const std::string& path, Volume& volume, bool& streamable, std::string& error);
bool CheckVTI(const std::string& path, Volume& volume, bool& streamable, std::string& error);
}
}

#endif
