// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_volume_headers.h.
#include "bluenoise_volume_headers.h"
#include "bluenoise_options.h"
#include "bluenoise_volume.h"

#include <zlib.h>
#include "vtkType.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <sys/stat.h>
#include <vector>

namespace bluenoise
{
namespace headers
{
namespace
{
// zlib's largest compression ratio (deflate's limit is 1032:1): compressed
// data of n bytes never holds more than this many times n.
const double MaximumCompressionRatio = 1032.0;

std::string Lower(const std::string& s)
{
  return vtksys::SystemTools::LowerCase(s);
}

std::string Trim(const std::string& s)
{
  const size_t a = s.find_first_not_of(" \t\r\n");
  const size_t b = s.find_last_not_of(" \t\r\n");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::vector<std::string> Words(const std::string& s)
{
  std::istringstream in(s);
  std::vector<std::string> words;
  std::string w;
  while (in >> w)
  {
    words.push_back(w);
  }
  return words;
}

std::string Number(double v)
{
  std::ostringstream s;
  s.precision(15);
  s << v;
  return s.str();
}

// The dimensions, spacing and data size every format declares, checked the
// same way: positive whole dimensions, finite positive spacing, and the data
// present in the file (at least `needed` bytes, or for compressed data
// enough bytes to decompress to them).
struct Declared
{
  double Dimensions[3] = { 1, 1, 1 };
  double Spacing[3] = { 1, 1, 1 };
  double Components = 1;
  double BytesPerValue = 1;
  double Available = 0;
  bool Compressed = false;
};

bool CheckDeclared(const Declared& d, Volume& volume, std::string& error)
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
    volume.WholeExtent[2 * i] = 0;
    volume.WholeExtent[2 * i + 1] = static_cast<int>(d.Dimensions[i]) - 1;
  }
  volume.Voxels = static_cast<vtkIdType>(voxels);
  volume.BytesPerVoxel = d.Components * d.BytesPerValue;
  return true;
}

bool DataFileSize(const std::string& path, double offset, double& available, std::string& error)
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

// Bytes a gzip file decompresses to, reading no further than `limit`.
bool GunzippedSize(const std::string& path, double limit, double& size, std::string& error)
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

std::string Directory(const std::string& path)
{
  const std::string dir = vtksys::SystemTools::GetFilenamePath(path);
  return dir.empty() ? std::string(".") : dir;
}

std::string Relative(const std::string& header, const std::string& file)
{
  return vtksys::SystemTools::FileIsFullPath(file) ? file : Directory(header) + "/" + file;
}

// "key<separator>value" lines (NRRD's separator is ": " exactly, as
// vtkNrrdReader reads it; "key:=value" pairs are skipped).
struct TextHeader
{
  std::map<std::string, std::string> Fields;
  size_t Length = 0; // bytes up to and including the last header line
};
}

long long FileSize(const std::string& path)
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

bool ReadHead(const std::string& path, size_t limit, bool gzipped, std::string& head, std::string& error)
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
// NIfTI-1 / NIfTI-2 / Analyze 7.5: the binary header's fields, either byte order,
// read the way VTK's vtkNIFTIImageReader reads them (the version from the magic,
// the data file from the suffix), so that what is checked is what it will trust.
namespace
{
struct NIfTIHeader
{
  double Dim[8] = { 0 };
  double PixDim[8] = { 0 };
  double VoxOffset = 0;
  double BitPix = 0;
  int DataType = 0;
  double DataTypeBytes = 0; // bytes per voxel of the datatype code (0: unknown code)
  size_t HeaderSize = 348;
};

template <typename T>
T Field(const std::string& h, size_t at, bool swap)
{
  T v;
  char bytes[sizeof(T)];
  std::memcpy(bytes, h.data() + at, sizeof(T));
  if (swap)
  {
    std::reverse(bytes, bytes + sizeof(T));
  }
  std::memcpy(&v, bytes, sizeof(T));
  return v;
}

// Bytes per voxel of the datatype codes vtkNIFTIImageReader maps to a VTK
// type (DT_UINT8 = 2, ..., DT_RGBA32 = 2304); 0 for any other code. VTK 9.2's
// RequestInformation looks the code up in its table without a bound, so an
// unknown code reads past the table's end and crashes (found by the volume-
// loader fuzzer): NIfTI's own DT_BINARY, DT_FLOAT128 and DT_COMPLEX256 included.
double NIfTITypeBytes(int code)
{
  static const std::map<int, double> bytes = { { 2, 1 }, { 4, 2 }, { 8, 4 }, { 16, 4 },
    { 32, 8 }, { 64, 8 }, { 128, 3 }, { 256, 1 }, { 512, 2 }, { 768, 4 }, { 1024, 8 },
    { 1280, 8 }, { 1792, 16 }, { 2304, 4 } };
  const auto it = bytes.find(code);
  return it == bytes.end() ? 0.0 : it->second;
}

// The version vtkNIFTIImageReader reads the header as: it looks at the magic
// (NIfTI-2's at byte 4 first, then NIfTI-1's at byte 344), not at sizeof_hdr;
// 0 without a magic (Analyze 7.5), -1 for a NIfTI-2 magic it would misread
// (versions 3 to 9, or the line-ending bytes damaged).
int NIfTIVersion(const std::string& h)
{
  if (h[4] == 'n' && (h[5] == '+' || h[5] == 'i') && h[6] >= '2' && h[6] <= '9' && h[7] == '\0')
  {
    return h[6] == '2' && h.compare(8, 4, "\r\n\032\n") == 0 ? 2 : -1;
  }
  if (h[344] == 'n' && (h[345] == '+' || h[345] == 'i') && h[346] == '1' && h[347] == '\0')
  {
    return 1;
  }
  return 0;
}

// sizeof_hdr must be the size the magic implies, in either byte order; the
// byte order found here is the data's. (VTK takes the byte order from dim[0]
// instead; both agree whenever dim[0] passes its check below.)
bool NIfTIHeaderSize(const std::string& h, int version, bool& swap, std::string& error)
{
  const int32_t size = Field<int32_t>(h, 0, false);
  const int32_t swapped = Field<int32_t>(h, 0, true);
  const int32_t expected = version == 2 ? 540 : 348;
  const int32_t other = version == 2 ? 348 : 540;
  swap = size != expected && swapped == expected;
  if (size == expected || swap)
  {
    return true;
  }
  if (size == other || swapped == other)
  {
    error = "sizeof_hdr is " + std::to_string(other) + " but " +
      (version == 2 ? "the magic says NIfTI-2 (540)"
        : version == 1 ? "the magic says NIfTI-1 (348)"
                       : "without a NIfTI magic it is an Analyze 7.5 header (348)");
  }
  else
  {
    error = "not a NIfTI header (sizeof_hdr is " + std::to_string(size) + ")";
  }
  return false;
}

bool NIfTIFields(const std::string& h, bool two, bool swap, NIfTIHeader& n, std::string& error)
{
  n.HeaderSize = two ? 540 : 348;
  for (int i = 0; i < 8; ++i)
  {
    n.Dim[i] = two ? static_cast<double>(Field<int64_t>(h, 16 + 8 * i, swap))
                   : Field<int16_t>(h, 40 + 2 * i, swap);
    n.PixDim[i] = two ? Field<double>(h, 104 + 8 * i, swap) : Field<float>(h, 76 + 4 * i, swap);
  }
  n.BitPix = two ? Field<int16_t>(h, 14, swap) : Field<int16_t>(h, 72, swap);
  n.DataType = two ? Field<int16_t>(h, 12, swap) : Field<int16_t>(h, 70, swap);
  n.DataTypeBytes = NIfTITypeBytes(n.DataType);
  n.VoxOffset = two ? static_cast<double>(Field<int64_t>(h, 168, swap)) : Field<float>(h, 108, swap);
  if (!(n.Dim[0] >= 1 && n.Dim[0] <= 7))
  {
    error = "dim[0] (the number of dimensions) is " + Number(n.Dim[0]) + ", not in [1, 7]";
    return false;
  }
  if (n.DataTypeBytes == 0.0)
  {
    error = "datatype " + std::to_string(n.DataType) +
      " is not one VTK's NIfTI reader reads (integers of 8 to 64 bits, float32, float64, "
      "complex64, complex128, RGB24, RGBA32)";
    return false;
  }
  if (!(n.BitPix >= 8) || std::fmod(n.BitPix, 8.0) != 0.0)
  {
    error = "bitpix is " + Number(n.BitPix) + " (a multiple of 8 is needed)";
    return false;
  }
  return true;
}

bool ParseNIfTI(const std::string& h, bool singleFile, NIfTIHeader& n, std::string& error)
{
  if (h.size() < 348)
  {
    error = "the file is shorter than a NIfTI header (" + std::to_string(h.size()) + " bytes)";
    return false;
  }
  const int version = NIfTIVersion(h);
  if (version < 0)
  {
    error = "the magic at byte 4 names a NIfTI version other than 1 and 2, or its "
            "line-ending bytes are damaged";
    return false;
  }
  bool swap = false;
  if (!NIfTIHeaderSize(h, version, swap, error))
  {
    return false;
  }
  if (version == 2 && h.size() < 540)
  {
    error = "the file is shorter than a NIfTI-2 header";
    return false;
  }
  if (!NIfTIFields(h, version == 2, swap, n, error))
  {
    return false;
  }
  // In a .nii the data follow the header; a .hdr's are in its .img.
  if (!std::isfinite(n.VoxOffset) || n.VoxOffset < (singleFile ? n.HeaderSize : 0))
  {
    error = "vox_offset is " + Number(n.VoxOffset);
    return false;
  }
  return true;
}

// The .img of a .hdr where vtkNIFTIImageReader looks for it: the same
// compression first (x.hdr: x.img, else x.img.gz; x.hdr.gz: x.img.gz, else
// x.img), in the case of the header's suffix.
std::string NIfTIImageFile(const std::string& path, bool gzipped)
{
  const size_t m = path.size() - (gzipped ? 3 : 0);
  const bool upper = std::isupper(static_cast<unsigned char>(path[m - 3])) != 0;
  const std::string first = path.substr(0, m - 3) + (upper ? "IMG" : "img") + path.substr(m);
  const std::string second = gzipped ? first.substr(0, m) : first + (upper ? ".GZ" : ".gz");
  return FileSize(first) >= 0 ? first : second;
}
}

bool CheckNIfTI(const std::string& path, Volume& volume, std::string& error)
{
  const bool gzipped = Lower(path).size() > 3 && Lower(path).substr(path.size() - 3) == ".gz";
  const std::string bare = Lower(path).substr(0, path.size() - (gzipped ? 3 : 0));
  const bool singleFile = bare.size() < 4 || bare.substr(bare.size() - 4) != ".hdr";
  std::string head;
  NIfTIHeader n;
  if (!ReadHead(path, 540, gzipped, head, error) || !ParseNIfTI(head, singleFile, n, error))
  {
    return false;
  }
  Declared d;
  const int rank = static_cast<int>(n.Dim[0]);
  for (int i = 0; i < 3; ++i)
  {
    d.Dimensions[i] = i < rank ? n.Dim[i + 1] : 1.0;
    // The reader's spacing is pixdim[1..3] whatever the rank, a 0 beyond the
    // rank taken as 1.
    d.Spacing[i] = i >= rank && n.PixDim[i + 1] == 0.0 ? 1.0 : n.PixDim[i + 1];
  }
  // Only the first time point is read; a fifth dimension holds components.
  d.Components = rank >= 5 ? n.Dim[5] : 1.0;
  if (rank >= 4 && !(n.Dim[4] >= 1.0))
  {
    error = "dimension t is " + Number(n.Dim[4]);
    return false;
  }
  // VTK 9.2's reader steps through a row with int byte counts.
  const double row = d.Dimensions[0] * d.Components * n.DataTypeBytes;
  if (row > 2147483647.0)
  {
    error = "a row of the data is " + Number(row) +
      " bytes, more than VTK's NIfTI reader reads (2^31 - 1)";
    return false;
  }
  // The reader allocates by the datatype; a bitpix that says less is not trusted.
  d.BytesPerValue = std::max(n.BitPix / 8.0, n.DataTypeBytes);
  // The data: in the same file after vox_offset, or in the .img of a .hdr.
  const std::string body = singleFile ? path : NIfTIImageFile(path, gzipped);
  const bool bodyGzipped = Lower(body).substr(body.size() - 3) == ".gz";
  if (bodyGzipped)
  {
    const double compressed = static_cast<double>(std::max(0LL, FileSize(body)));
    const double needed = n.VoxOffset +
      d.Dimensions[0] * d.Dimensions[1] * d.Dimensions[2] * d.Components * d.BytesPerValue;
    // A header claiming more than the compressed bytes can hold fails at once.
    double size = 0.0;
    if (needed > compressed * MaximumCompressionRatio + n.VoxOffset)
    {
      d.Compressed = true;
      d.Available = compressed;
      volume.Format = "NIfTI";
      return CheckDeclared(d, volume, error);
    }
    if (!GunzippedSize(body, needed, size, error))
    {
      error = body + ": " + error;
      return false;
    }
    if (n.VoxOffset > size && size > 0.0)
    {
      error = "vox_offset " + Number(n.VoxOffset) + " lies beyond the end of the data (" +
        Number(size) + " bytes decompressed)";
      return false;
    }
    d.Available = std::max(0.0, size - n.VoxOffset);
  }
  else if (!DataFileSize(body, n.VoxOffset, d.Available, error))
  {
    return false;
  }
  volume.Format = "NIfTI";
  return CheckDeclared(d, volume, error);
}

//------------------------------------------------------------------------------
// MetaImage: "Key = Value" lines, ElementDataFile last.
namespace
{
// An element type's size in bytes and VTK type (0, 0 when unknown).
std::pair<double, int> MetaType(const std::string& type)
{
  static const std::map<std::string, std::pair<double, int>> types = {
    { "MET_CHAR", { 1, VTK_SIGNED_CHAR } }, { "MET_UCHAR", { 1, VTK_UNSIGNED_CHAR } },
    { "MET_SHORT", { 2, VTK_SHORT } }, { "MET_USHORT", { 2, VTK_UNSIGNED_SHORT } },
    { "MET_INT", { 4, VTK_INT } }, { "MET_UINT", { 4, VTK_UNSIGNED_INT } },
    { "MET_LONG", { 4, VTK_INT } }, { "MET_ULONG", { 4, VTK_UNSIGNED_INT } },
    { "MET_LONG_LONG", { 8, VTK_LONG_LONG } }, { "MET_ULONG_LONG", { 8, VTK_UNSIGNED_LONG_LONG } },
    { "MET_FLOAT", { 4, VTK_FLOAT } }, { "MET_DOUBLE", { 8, VTK_DOUBLE } } };
  const auto it = types.find(type);
  return it == types.end() ? std::pair<double, int>(0.0, 0) : it->second;
}

bool ParseTextHeader(const std::string& head, const std::string& separator, const std::string& lastKey,
  bool endAtBlankLine, TextHeader& header)
{
  size_t at = 0;
  while (at < head.size())
  {
    size_t end = head.find('\n', at);
    if (end == std::string::npos)
    {
      return false;
    }
    const std::string line = Trim(head.substr(at, end - at));
    header.Length = end + 1;
    at = end + 1;
    if (line.empty() && endAtBlankLine)
    {
      return true;
    }
    const size_t split = line.find(separator);
    if (line.empty() || line[0] == '#' || split == std::string::npos)
    {
      continue;
    }
    const std::string key = Lower(Trim(line.substr(0, split)));
    std::string value = Trim(line.substr(split + separator.size()));
    if (!value.empty() && value[0] == '=')
    {
      continue; // a NRRD key/value pair (key:=value), not a field
    }
    header.Fields[key] = value;
    if (!lastKey.empty() && key == lastKey)
    {
      return true;
    }
  }
  return false;
}

bool Reals(const std::string& text, size_t count, double* values, const char* what,
  std::string& error)
{
  const auto words = Words(text);
  if (words.size() < count)
  {
    error = std::string(what) + " has " + std::to_string(words.size()) + " values, " +
      std::to_string(count) + " needed";
    return false;
  }
  for (size_t i = 0; i < count; ++i)
  {
    if (!ParseReal(words[i], values[i]))
    {
      if (Lower(words[i]) == "nan" || Lower(words[i]).find("inf") != std::string::npos)
      {
        values[i] = std::nan("");
        continue;
      }
      error = std::string(what) + ": '" + words[i] + "' is not a number";
      return false;
    }
  }
  return true;
}

// The data file of a MetaImage header (its own path for LOCAL) and the bytes
// to skip in it before the values.
bool MetaImageDataFile(const std::string& path, TextHeader& header, std::string& data,
  double& skip, std::string& error)
{
  auto& f = header.Fields;
  const std::string file = f["elementdatafile"];
  if (file.empty() || file == "LIST" || file.find('%') != std::string::npos ||
    Words(file).size() != 1)
  {
    error = "ElementDataFile '" + file + "' is not supported (one data file or LOCAL)";
    return false;
  }
  const bool local = Lower(file) == "local";
  data = local ? path : Relative(path, file);
  skip = local ? static_cast<double>(header.Length) : 0.0;
  if (f.count("headersize"))
  {
    double h = 0.0;
    if (!Reals(f["headersize"], 1, &h, "HeaderSize", error) || !(h >= -1.0))
    {
      error = "HeaderSize is '" + f["headersize"] + "'";
      return false;
    }
    skip += std::max(0.0, h);
  }
  return true;
}
}

namespace
{
using Fields = std::map<std::string, std::string>;

// Where and how the values lie in the data file, for reading a slab of them.
bool MetaImageRaw(Fields& f, const std::string& data, double skip,
  const Declared& d, size_t rank, Volume& volume, std::string& error)
{
  RawLayout& raw = volume.Raw;
  raw.DataFile = data;
  // HeaderSize -1: the data are the file's last bytes.
  raw.HeaderBytes = f["headersize"] == "-1"
    ? static_cast<double>(FileSize(data)) - static_cast<double>(volume.Voxels) * volume.BytesPerVoxel
    : skip;
  raw.ScalarType = MetaType(f["elementtype"]).second;
  raw.Components = static_cast<int>(d.Components);
  raw.BigEndian = Lower(f["binarydatabyteordermsb"]) == "true" ||
    Lower(f["elementbyteordermsb"]) == "true";
  const std::string origin =
    f.count("offset") ? f["offset"] : f.count("origin") ? f["origin"] : f["position"];
  if (!origin.empty() && (!Reals(origin, rank, raw.Origin, "Offset", error) ||
                           !std::isfinite(raw.Origin[0] + raw.Origin[1] + raw.Origin[2])))
  {
    error = "Offset '" + origin + "' is not finite";
    return false;
  }
  std::copy(d.Spacing, d.Spacing + 3, raw.Spacing);
  return true;
}
}

bool CheckMetaImage(const std::string& path, Volume& volume, bool& streamable, std::string& error)
{
  std::string head;
  TextHeader header;
  if (!ReadHead(path, 65536, false, head, error))
  {
    return false;
  }
  if (!ParseTextHeader(head, "=", "elementdatafile", false, header))
  {
    error = "no ElementDataFile line in the MetaImage header";
    return false;
  }
  if (head.find('\0') < header.Length)
  {
    error = "the MetaImage header contains a NUL byte";
    return false;
  }
  auto& f = header.Fields;
  double rank = 0;
  if (!Reals(f["ndims"], 1, &rank, "NDims", error) || !(rank >= 1 && rank <= 3))
  {
    error = "NDims is '" + f["ndims"] + "' (1, 2 or 3 supported)";
    return false;
  }
  Declared d;
  const size_t r = static_cast<size_t>(rank);
  const std::string spacing = f.count("elementspacing") ? f["elementspacing"] : f["elementsize"];
  if (Words(f["dimsize"]).size() != r)
  {
    error = "DimSize '" + f["dimsize"] + "' does not have NDims (" + f["ndims"] + ") values";
    return false;
  }
  if (!Reals(f["dimsize"], r, d.Dimensions, "DimSize", error) ||
    (!spacing.empty() && !Reals(spacing, r, d.Spacing, "ElementSpacing", error)))
  {
    return false;
  }
  d.BytesPerValue = MetaType(f["elementtype"]).first;
  if (d.BytesPerValue == 0.0)
  {
    error = "ElementType '" + f["elementtype"] + "' is missing or not supported";
    return false;
  }
  if (f.count("elementnumberofchannels") &&
    !Reals(f["elementnumberofchannels"], 1, &d.Components, "ElementNumberOfChannels", error))
  {
    return false;
  }
  d.Compressed = Lower(f["compresseddata"]) == "true";
  std::string data;
  double skip = 0.0;
  if (!MetaImageDataFile(path, header, data, skip, error) ||
    !DataFileSize(data, skip, d.Available, error))
  {
    return false;
  }
  volume.Format = "MetaImage";
  streamable = !d.Compressed && Lower(f["binarydata"]) != "false";
  return CheckDeclared(d, volume, error) && MetaImageRaw(f, data, skip, d, r, volume, error);
}

//------------------------------------------------------------------------------
// NRRD: "NRRD000x" then "field: value" lines up to a blank line.
namespace
{
double NrrdTypeSize(std::string type)
{
  type = Lower(type);
  if (type.find("int64") != std::string::npos || type.find("long") != std::string::npos)
    return 8;
  if (type.find("int16") != std::string::npos || type.find("short") != std::string::npos)
    return 2;
  if (type.find("int8") != std::string::npos || type.find("char") != std::string::npos)
    return 1;
  if (type.find("int") != std::string::npos || type == "float")
    return 4;
  if (type == "double")
    return 8;
  return 0;
}
}

namespace
{
// The axes (dimension, sizes, spacings) as vtkNrrdReader lays them out.
bool NRRDAxes(Fields& f, Declared& d, std::string& error)
{
  double rank = 0;
  // One axis is not a volume, and VTK 9.2's vtkNrrdReader crashes on it
  // (reading past its buffer; found by the volume-loader fuzzer in CI).
  if (!Reals(f["dimension"], 1, &rank, "dimension", error) || !(rank >= 2 && rank <= 4))
  {
    error = "dimension is '" + f["dimension"] + "' (2 to 4 supported)";
    return false;
  }
  double sizes[4] = { 1, 1, 1, 1 };
  if (Words(f["sizes"]).size() != static_cast<size_t>(rank))
  {
    error = "sizes '" + f["sizes"] + "' does not have dimension (" + f["dimension"] + ") values";
    return false;
  }
  if (!Reals(f["sizes"], static_cast<size_t>(rank), sizes, "sizes", error))
  {
    return false;
  }
  double spacing[4] = { 1, 1, 1, 1 };
  if (f.count("spacings") &&
    !Reals(f["spacings"], static_cast<size_t>(rank), spacing, "spacings", error))
  {
    return false;
  }
  // vtkNrrdReader's guess, followed so that both agree on the layout: the
  // first axis holds the components when there are four axes, when it has
  // at most 9 entries, or when its spacing is 0.
  const int first = rank > 3 || sizes[0] <= 9 || spacing[0] == 0 ? 1 : 0;
  d.Components = first ? sizes[0] : 1.0;
  for (int i = first; i < rank; ++i)
  {
    d.Dimensions[i - first] = sizes[i];
    d.Spacing[i - first] = spacing[i];
  }
  return true;
}

// The values: type and encoding, and the data file (this one after the
// header when none is named) with the bytes it holds after `byte skip`.
bool NRRDData(const std::string& path, Fields& f, const TextHeader& header, bool terminated,
  Declared& d, bool& raw, std::string& error)
{
  d.BytesPerValue = NrrdTypeSize(f["type"]);
  const std::string encoding = Lower(f["encoding"]);
  raw = encoding == "raw";
  if (d.BytesPerValue == 0.0 || (!raw && encoding != "ascii" && encoding != "text" && encoding != "txt"))
  {
    error = "type '" + f["type"] + "' or encoding '" + f["encoding"] +
      "' is not supported (numeric types, raw or ascii encoding)";
    return false;
  }
  if (!raw)
  {
    d.BytesPerValue = 1.0; // at least one character a value
  }
  std::string file = f.count("data file") ? f["data file"] : f["datafile"];
  if (file.find('%') != std::string::npos || Words(file).size() > 1 || file == "LIST")
  {
    error = "data file '" + file + "' is not supported (one data file)";
    return false;
  }
  if (file.empty() && !terminated)
  {
    error = "the NRRD header has no blank line before the data";
    return false;
  }
  double skip = 0.0;
  if (f.count("byte skip") && (!Reals(f["byte skip"], 1, &skip, "byte skip", error) || skip < 0))
  {
    error = "byte skip is '" + f["byte skip"] + "' (>= 0 supported)";
    return false;
  }
  const std::string data = file.empty() ? path : Relative(path, file);
  return DataFileSize(data, skip + (file.empty() ? header.Length : 0), d.Available, error);
}
}

bool CheckNRRD(const std::string& path, Volume& volume, bool& streamable, std::string& error)
{
  std::string head;
  TextHeader header;
  if (!ReadHead(path, 65536, false, head, error))
  {
    return false;
  }
  if (head.compare(0, 7, "NRRD000") != 0)
  {
    error = "no NRRD magic line (NRRD000x)";
    return false;
  }
  const bool terminated = ParseTextHeader(head, ": ", "", true, header);
  // vtkNrrdReader reads the header as a C string: a NUL byte in it made the
  // reader loop for ever (found by the fuzzer).
  if (head.find('\0') < header.Length)
  {
    error = "the NRRD header contains a NUL byte";
    return false;
  }
  Declared d;
  if (!NRRDAxes(header.Fields, d, error) ||
    !NRRDData(path, header.Fields, header, terminated, d, streamable, error))
  {
    return false;
  }
  volume.Format = "NRRD";
  return CheckDeclared(d, volume, error);
}

//------------------------------------------------------------------------------
// VTI: the WholeExtent and Spacing attributes of <ImageData>.
namespace
{
std::string Attribute(const std::string& text, const std::string& name)
{
  const size_t at = text.find(" " + name + "=\"");
  if (at == std::string::npos)
  {
    return std::string();
  }
  const size_t from = at + name.size() + 3;
  const size_t to = text.find('"', from);
  return to == std::string::npos ? std::string() : text.substr(from, to - from);
}

double VTKTypeSize(const std::string& type)
{
  if (type == "Int8" || type == "UInt8" || type == "Char" || type == "String" || type == "Bit")
    return 1;
  if (type == "Int16" || type == "UInt16")
    return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32")
    return 4;
  return 8; // Int64, UInt64, Float64, IdType, and anything else at its largest
}

// What the reader will allocate for every <DataArray> of the file (the XML
// part: up to <AppendedData>): values and bytes, one tuple per voxel unless
// the element says NumberOfTuples. The file is scanned in chunks; a tag is
// parsed once its closing '>' is in the buffer.
bool DeclaredArrays(const std::string& path, double voxels, double& values, double& bytes,
  bool& ascii, std::string& error)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  values = bytes = 0.0;
  ascii = false;
  std::string buffer;
  std::vector<char> chunk(1 << 20);
  while (in)
  {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    buffer.append(chunk.data(), static_cast<size_t>(in.gcount()));
    const size_t appended = buffer.find("<AppendedData");
    size_t at = 0;
    for (size_t tag; (tag = buffer.find("<DataArray", at)) < appended; at = tag + 1)
    {
      const size_t close = buffer.find('>', tag);
      if (close == std::string::npos)
      {
        break;
      }
      const std::string element = buffer.substr(tag, close - tag);
      double components = 1.0, tuples = voxels;
      const std::string c = Attribute(element, "NumberOfComponents");
      const std::string t = Attribute(element, "NumberOfTuples");
      if ((!c.empty() && !ParseReal(c, components)) || (!t.empty() && !ParseReal(t, tuples)) ||
        !(components >= 1.0) || !(tuples >= 0.0))
      {
        error = "a DataArray declares NumberOfComponents '" + c + "', NumberOfTuples '" + t + "'";
        return false;
      }
      values += components * tuples;
      bytes += components * tuples * VTKTypeSize(Attribute(element, "type"));
      ascii = ascii || Attribute(element, "format") == "ascii";
    }
    if (appended != std::string::npos)
    {
      break;
    }
    // Keep an unfinished tag (and a tag name cut by the chunk) for the next round.
    const size_t open = buffer.rfind('<');
    buffer.erase(0, open == std::string::npos || open < at ? buffer.size() : open);
    if (buffer.size() > (1u << 20))
    {
      buffer.clear(); // an endless tag: nothing VTK would read either
    }
  }
  return true;
}
}

// An optional attribute of `count` numbers, all finite when present.
bool FiniteAttribute(
  const std::string& element, const char* name, size_t count, std::string& error)
{
  const std::string text = Attribute(element, name);
  double values[9];
  if (text.empty())
  {
    return true;
  }
  if (!Reals(text, count, values, name, error))
  {
    return false;
  }
  if (!std::all_of(values, values + count, [](double v) { return std::isfinite(v); }))
  {
    error = std::string(name) + " '" + text + "' is not finite";
    return false;
  }
  return true;
}

bool CheckVTI(const std::string& path, Volume& volume, bool& streamable, std::string& error)
{
  std::string head;
  if (!ReadHead(path, 1 << 20, false, head, error))
  {
    return false;
  }
  const size_t image = head.find("<ImageData");
  const size_t close = image == std::string::npos ? image : head.find('>', image);
  if (head.find("<VTKFile") == std::string::npos || close == std::string::npos)
  {
    error = "no <VTKFile> with an <ImageData> element";
    return false;
  }
  const std::string element = head.substr(image, close - image);
  double extent[6];
  Declared d;
  if (!Reals(Attribute(element, "WholeExtent"), 6, extent, "WholeExtent", error))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    if (!(std::abs(extent[2 * i]) < 1.0e9 && std::abs(extent[2 * i + 1]) < 1.0e9))
    {
      error = "WholeExtent '" + Attribute(element, "WholeExtent") + "' is out of range";
      return false;
    }
    d.Dimensions[i] = extent[2 * i + 1] - extent[2 * i] + 1;
  }
  const std::string spacing = Attribute(element, "Spacing");
  if (!spacing.empty() && !Reals(spacing, 3, d.Spacing, "Spacing", error))
  {
    return false;
  }
  if (!FiniteAttribute(element, "Origin", 3, error) ||
    !FiniteAttribute(element, "Direction", 9, error))
  {
    return false;
  }
  // At least one byte a voxel, compressed or not; then what the arrays need.
  d.Compressed = head.find("compressor=\"vtk") != std::string::npos;
  d.Available = static_cast<double>(std::max(1LL, FileSize(path)));
  volume.Format = "VTI";
  streamable = !d.Compressed && head.find("encoding=\"raw\"") != std::string::npos &&
    head.find("format=\"binary\"") == std::string::npos &&
    head.find("format=\"ascii\"") == std::string::npos;
  double values = 0.0, bytes = 0.0;
  bool ascii = false;
  if (!CheckDeclared(d, volume, error) ||
    !DeclaredArrays(path, static_cast<double>(volume.Voxels), values, bytes, ascii, error))
  {
    return false;
  }
  // Uncompressed, every value takes at least one byte of the file, and binary
  // values their size; compressed, the bytes are bounded by zlib's ratio.
  const bool fits = d.Compressed ? bytes <= d.Available * MaximumCompressionRatio
                                 : values <= d.Available && (ascii || bytes <= d.Available);
  if (!fits)
  {
    error = "the arrays declare " + Number(bytes) + " bytes of data but the file has only " +
      Number(d.Available) + " bytes" + (d.Compressed ? " (compressed)" : "");
    return false;
  }
  volume.BytesPerVoxel = volume.Voxels > 0 ? bytes / static_cast<double>(volume.Voxels) : 0.0;
  for (int i = 0; i < 6; ++i)
  {
    volume.WholeExtent[i] = static_cast<int>(extent[i]);
  }
  return true;
}
}
}
