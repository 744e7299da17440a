// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseVolumeFileCheck.h"

#include "vtk_zlib.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <vector>

//------------------------------------------------------------------------------
std::string vtkBlueNoiseVolumeFileCheck::Number(double v)
{
  std::ostringstream s;
  s.precision(15);
  s << v;
  return s.str();
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseVolumeFileCheck::CheckDeclared(
  const Declared& d, Checked& checked, std::string& error)
{
  static const char* const axis[3] = { "x", "y", "z" };
  double voxels = 1.0;
  for (int i = 0; i < 3; ++i)
  {
    if (!(d.Dimensions[i] >= 1.0) || d.Dimensions[i] != std::floor(d.Dimensions[i]) ||
      d.Dimensions[i] > 2147483647.0)
    {
      error = std::string("dimension ") + axis[i] + " is " + Number(d.Dimensions[i]) +
        " (must be a whole number >= 1)";
      return false;
    }
    if (!std::isfinite(d.Spacing[i]) || !(d.Spacing[i] > 0.0))
    {
      error = std::string("spacing ") + axis[i] + " is " + Number(d.Spacing[i]) +
        " (must be finite and > 0)";
      return false;
    }
    voxels *= d.Dimensions[i];
  }
  if (!(d.Components >= 1.0 && d.Components <= 4096.0))
  {
    error = "the number of components is " + Number(d.Components);
    return false;
  }
  const double needed = voxels * d.Components * d.BytesPerValue;
  const double holds = d.Available * (d.Compressed ? MaximumCompressionRatio : 1.0);
  if (!(needed <= holds))
  {
    error = "the header declares " + Number(d.Dimensions[0]) + " x " + Number(d.Dimensions[1]) +
      " x " + Number(d.Dimensions[2]) + " voxels (" + Number(needed) + " bytes of data) but " +
      (d.Compressed ? "the compressed data has only " : "the data has only ") +
      Number(d.Available) + " bytes";
    return false;
  }
  if (voxels > 9.0e18)
  {
    error = "too many voxels: " + Number(voxels);
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    checked.WholeExtent[2 * i] = 0;
    checked.WholeExtent[2 * i + 1] = static_cast<int>(d.Dimensions[i]) - 1;
  }
  checked.Voxels = static_cast<vtkIdType>(voxels);
  checked.BytesPerVoxel = d.Components * d.BytesPerValue;
  return true;
}

//------------------------------------------------------------------------------
long long vtkBlueNoiseVolumeFileCheck::FileSize(const std::string& path)
{
  struct stat info;
  if (stat(path.c_str(), &info) != 0)
  {
    return -1;
  }
  if (!S_ISREG(info.st_mode))
  {
    errno = EISDIR;
    return -1;
  }
  return static_cast<long long>(info.st_size);
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseVolumeFileCheck::ReadHead(
  const std::string& path, size_t limit, bool gzipped, std::string& head, std::string& error)
{
  head.assign(limit, '\0');
  if (gzipped)
  {
    gzFile file = gzopen(path.c_str(), "rb");
    if (!file)
    {
      error = std::string("cannot open: ") + std::strerror(errno);
      return false;
    }
    const int n = gzread(file, &head[0], static_cast<unsigned>(limit));
    gzclose(file);
    if (n < 0)
    {
      error = "corrupt gzip data";
      return false;
    }
    head.resize(static_cast<size_t>(n));
    return true;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  in.read(&head[0], static_cast<std::streamsize>(limit));
  head.resize(static_cast<size_t>(in.gcount()));
  return true;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseVolumeFileCheck::GunzippedSize(
  const std::string& path, double limit, double& size, std::string& error)
{
  gzFile file = gzopen(path.c_str(), "rb");
  if (!file)
  {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  std::vector<char> buffer(1 << 20);
  size = 0.0;
  while (size < limit)
  {
    const int n = gzread(file, buffer.data(), static_cast<unsigned>(buffer.size()));
    if (n < 0)
    {
      int code = 0;
      error = std::string("corrupt gzip data: ") + gzerror(file, &code);
      gzclose(file);
      return false;
    }
    if (n == 0)
    {
      break;
    }
    size += n;
  }
  gzclose(file);
  return true;
}

//------------------------------------------------------------------------------
bool vtkBlueNoiseVolumeFileCheck::DataFileSize(
  const std::string& path, double offset, double& available, std::string& error)
{
  const long long size = FileSize(path);
  if (size < 0)
  {
    error = "cannot open the data file " + path + ": " + std::strerror(errno);
    return false;
  }
  if (offset > static_cast<double>(size))
  {
    error = "the data starts at byte " + Number(offset) + ", beyond the end of " + path + " (" +
      std::to_string(size) + " bytes)";
    return false;
  }
  available = static_cast<double>(size) - offset;
  return true;
}

//------------------------------------------------------------------------------
std::string vtkBlueNoiseVolumeFileCheck::PlainMessage(const char* message)
{
  std::string text = message ? message : "";
  const size_t line = text.find(", line ");
  const size_t newline = line == std::string::npos ? line : text.find('\n', line);
  if (newline != std::string::npos)
  {
    const size_t close = text.find("): ", newline);
    text = text.substr(close == std::string::npos ? newline + 1 : close + 3);
  }
  const size_t first = text.find_first_not_of(" \t\r\n");
  const size_t last = text.find_last_not_of(" \t\r\n");
  text = first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  return text.empty() ? std::string("unknown error") : text;
}
