// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_volume_headers.h.
#include "bluenoise_volume_headers.h"
#include "bluenoise_options.h"
#include "bluenoise_volume.h"

#include "vtkBlueNoiseNIfTIReader.h"
#include "vtkBlueNoiseVolumeFileCheck.h"
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
#include <vector>

namespace bluenoise
{
namespace headers
{
namespace
{
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
  return vtkBlueNoiseVolumeFileCheck::Number(v);
}

using Declared = vtkBlueNoiseVolumeFileCheck::Declared;

// The module's check of what a header declares, its result in `volume`.
bool CheckDeclared(const Declared& d, Volume& volume, std::string& error)
{
  vtkBlueNoiseVolumeFileCheck::Checked checked;
  if (!vtkBlueNoiseVolumeFileCheck::CheckDeclared(d, checked, error))
  {
    return false;
  }
  std::copy(checked.WholeExtent, checked.WholeExtent + 6, volume.WholeExtent);
  volume.Voxels = checked.Voxels;
  volume.BytesPerVoxel = checked.BytesPerVoxel;
  return true;
}

bool DataFileSize(const std::string& path, double offset, double& available, std::string& error)
{
  return vtkBlueNoiseVolumeFileCheck::DataFileSize(path, offset, available, error);
}

long long FileSize(const std::string& path)
{
  return vtkBlueNoiseVolumeFileCheck::FileSize(path);
}

bool ReadHead(const std::string& path, size_t limit, bool gzipped, std::string& head, std::string& error)
{
  return vtkBlueNoiseVolumeFileCheck::ReadHead(path, limit, gzipped, head, error);
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

//------------------------------------------------------------------------------
// NIfTI: the module's reader checks its files itself (vtkBlueNoiseNIfTIReader::CheckFile).
bool CheckNIfTI(const std::string& path, Volume& volume, std::string& error)
{
  vtkBlueNoiseVolumeFileCheck::Checked checked;
  if (!vtkBlueNoiseNIfTIReader::CheckFile(path, checked, error))
  {
    return false;
  }
  volume.Format = "NIfTI";
  std::copy(checked.WholeExtent, checked.WholeExtent + 6, volume.WholeExtent);
  volume.Voxels = checked.Voxels;
  volume.BytesPerVoxel = checked.BytesPerVoxel;
  return true;
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
  const bool fits = d.Compressed ? bytes <= d.Available * vtkBlueNoiseVolumeFileCheck::MaximumCompressionRatio
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
