// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseNIfTIReader.h"

#include "vtkCallbackCommand.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkNIFTIImageHeader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <new>
#include <sstream>
#include <vector>

namespace
{
// An image frame (origin, spacing, direction d, row-major) mapped by the
// 4x4 matrix m: the origin transformed, and each axis j, m d_j spacing_j,
// split into its length (the new spacing) and its direction.
void MapFrame(vtkMatrix4x4* m, const double origin[3], const double spacing[3], const double d[9],
  double mappedOrigin[3], double mappedSpacing[3], double mappedDirection[9])
{
  double point[4] = { origin[0], origin[1], origin[2], 1.0 }, world[4];
  m->MultiplyPoint(point, world);
  std::copy(world, world + 3, mappedOrigin);
  for (int j = 0; j < 3; ++j)
  {
    double column[3] = { 0, 0, 0 };
    for (int i = 0; i < 3; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        column[i] += m->GetElement(i, k) * d[3 * k + j] * spacing[j];
      }
    }
    const double length =
      std::sqrt(column[0] * column[0] + column[1] * column[1] + column[2] * column[2]);
    for (int i = 0; i < 3; ++i)
    {
      mappedDirection[3 * i + j] = length > 0.0 ? column[i] / length : (i == j ? 1.0 : 0.0);
    }
    mappedSpacing[j] = length > 0.0 ? length : spacing[j];
  }
}
}

vtkStandardNewMacro(vtkBlueNoiseNIfTIReader);

using Check = vtkBlueNoiseVolumeFileCheck;

namespace
{
std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && Lower(s.substr(s.size() - suffix.size())) == suffix;
}

std::string Number(double v)
{
  return Check::Number(v);
}

// The error messages of VTK objects (ErrorEvent), collected instead of printed
// while this lives, without VTK's "ERROR: In file, line N\nClass (0x...): " prefix.
class ErrorCollector
{
public:
  explicit ErrorCollector(std::vector<vtkObject*> objects)
    : Objects(std::move(objects))
  {
    this->Command->SetCallback(&ErrorCollector::Record);
    this->Command->SetClientData(this);
    for (vtkObject* object : this->Objects)
    {
      this->Tags.push_back(object->AddObserver(vtkCommand::ErrorEvent, this->Command));
    }
  }
  ~ErrorCollector()
  {
    for (size_t i = 0; i < this->Objects.size(); ++i)
    {
      this->Objects[i]->RemoveObserver(this->Tags[i]);
    }
  }
  ErrorCollector(const ErrorCollector&) = delete;
  ErrorCollector& operator=(const ErrorCollector&) = delete;

  std::vector<std::string> Errors;

private:
  static void Record(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    static_cast<ErrorCollector*>(clientData)->Errors.push_back(
      vtkBlueNoiseVolumeFileCheck::PlainMessage(static_cast<const char*>(callData)));
  }
  std::vector<vtkObject*> Objects;
  std::vector<unsigned long> Tags;
  vtkNew<vtkCallbackCommand> Command;
};

std::string ExtentText(const int* e)
{
  std::ostringstream s;
  s << e[0] << " " << e[1] << " " << e[2] << " " << e[3] << " " << e[4] << " " << e[5];
  return s.str();
}
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
  return Check::FileSize(first) >= 0 ? first : second;
}
}


//------------------------------------------------------------------------------
bool vtkBlueNoiseNIfTIReader::CheckFile(
  const std::string& path, vtkBlueNoiseVolumeFileCheck::Checked& checked, std::string& error)
{
  const bool gzipped = EndsWith(path, ".gz");
  const std::string bare = Lower(path).substr(0, path.size() - (gzipped ? 3 : 0));
  const bool singleFile = !EndsWith(bare, ".hdr");
  std::string head;
  NIfTIHeader n;
  if (Check::FileSize(path) < 0)
  {
    error = std::string("cannot open: ") + std::strerror(errno);
    return false;
  }
  if (!Check::ReadHead(path, 540, gzipped, head, error) || !ParseNIfTI(head, singleFile, n, error))
  {
    return false;
  }
  Check::Declared d;
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
  const bool bodyGzipped = EndsWith(body, ".gz");
  if (bodyGzipped)
  {
    const double compressed = static_cast<double>(std::max(0LL, Check::FileSize(body)));
    const double needed = n.VoxOffset +
      d.Dimensions[0] * d.Dimensions[1] * d.Dimensions[2] * d.Components * d.BytesPerValue;
    // A header claiming more than the compressed bytes can hold fails at once.
    double size = 0.0;
    if (needed > compressed * Check::MaximumCompressionRatio + n.VoxOffset)
    {
      d.Compressed = true;
      d.Available = compressed;
      return Check::CheckDeclared(d, checked, error);
    }
    if (!Check::GunzippedSize(body, needed, size, error))
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
  else if (!Check::DataFileSize(body, n.VoxOffset, d.Available, error))
  {
    return false;
  }
  return Check::CheckDeclared(d, checked, error);
}

//------------------------------------------------------------------------------
int vtkBlueNoiseNIfTIReader::CanReadFile(const char* fileName)
{
  if (!fileName || Check::FileSize(fileName) < 0)
  {
    return 0;
  }
  const std::string path = fileName;
  const bool gzipped = EndsWith(path, ".gz");
  const std::string bare = Lower(path).substr(0, path.size() - (gzipped ? 3 : 0));
  std::string head, error;
  NIfTIHeader n;
  return Check::ReadHead(path, 540, gzipped, head, error) &&
      ParseNIfTI(head, !EndsWith(bare, ".hdr"), n, error)
    ? 1
    : 0;
}

//------------------------------------------------------------------------------
vtkBlueNoiseNIfTIReader::vtkBlueNoiseNIfTIReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkBlueNoiseNIfTIReader::~vtkBlueNoiseNIfTIReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
void vtkBlueNoiseNIfTIReader::Fail(const std::string& message)
{
  this->InformationOK = false;
  vtkErrorMacro(<< (this->FileName ? this->FileName : "(no file name)") << ": " << message);
}

//------------------------------------------------------------------------------
int vtkBlueNoiseNIfTIReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  // Until the file is vouched for, the output is empty.
  static const int empty[6] = { 0, -1, 0, -1, 0, -1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
  this->InformationOK = false;
  this->PendingFrame.clear();
  int extent[6];
  if (!this->ReadHeader(extent))
  {
    return 1;
  }
  const std::string frame = this->ComputeFrame();
  if (!this->FrameIsFinite(frame))
  {
    return 1;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), this->Origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), this->Spacing, 3);
  outInfo->Set(vtkDataObject::DIRECTION(), this->Direction, 9);
  outInfo->Set(vtkAlgorithm::CAN_PRODUCE_SUB_EXTENT(), 1);
  vtkInformation* scalars =
    vtkDataObject::GetActiveFieldInformation(this->Reader->GetOutputInformation(0),
      vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  if (scalars)
  {
    vtkDataObject::SetPointDataActiveScalarInfo(outInfo,
      scalars->Get(vtkDataObject::FIELD_ARRAY_TYPE()),
      scalars->Has(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
        ? scalars->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
        : 1);
  }
  this->PendingFrame = frame;
  this->InformationOK = true;
  return 1;
}

//------------------------------------------------------------------------------
// The header checked against the file (CheckFile), then read by VTK's NIfTI
// reader, which reads it itself: its extent must be the checked one before
// it reads a byte of data.
bool vtkBlueNoiseNIfTIReader::ReadHeader(int extent[6])
{
  if (!this->FileName || !*this->FileName)
  {
    this->Fail("no FileName set");
    return false;
  }
  Check::Checked checked;
  std::string error;
  if (!CheckFile(this->FileName, checked, error))
  {
    this->Fail(error);
    return false;
  }
  this->Reader->SetFileName(this->FileName);
  ErrorCollector messages({ this->Reader, this->Reader->GetExecutive() });
  this->Reader->UpdateInformation();
  vtkInformation* readerInfo = this->Reader->GetOutputInformation(0);
  int read[6] = { 0, -1, 0, -1, 0, -1 };
  if (readerInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    readerInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), read);
  }
  if (!messages.Errors.empty())
  {
    this->Fail(messages.Errors.front());
    return false;
  }
  if (!std::equal(read, read + 6, checked.WholeExtent))
  {
    this->Fail("the NIfTI reader's extent (" + ExtentText(read) + ") differs from the header's (" +
      ExtentText(checked.WholeExtent) + ")");
    return false;
  }
  std::copy(checked.WholeExtent, checked.WholeExtent + 6, extent);
  return true;
}

//------------------------------------------------------------------------------
// Origin, Spacing and Direction: voxel space as VTK's reader gives it, then
// the sform or qform matrix M applied (see the class documentation). Returns
// the frame's name ("voxel", "sform" or "qform").
std::string vtkBlueNoiseNIfTIReader::ComputeFrame()
{
  vtkInformation* readerInfo = this->Reader->GetOutputInformation(0);
  double origin[3] = { 0, 0, 0 }, spacing[3] = { 1, 1, 1 };
  double d[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  if (readerInfo->Has(vtkDataObject::ORIGIN()))
  {
    readerInfo->Get(vtkDataObject::ORIGIN(), origin);
  }
  if (readerInfo->Has(vtkDataObject::SPACING()))
  {
    readerInfo->Get(vtkDataObject::SPACING(), spacing);
  }
  if (readerInfo->Has(vtkDataObject::DIRECTION()))
  {
    readerInfo->Get(vtkDataObject::DIRECTION(), d);
  }
  std::copy(origin, origin + 3, this->Origin);
  std::copy(spacing, spacing + 3, this->Spacing);
  std::copy(d, d + 9, this->Direction);
  vtkNIFTIImageHeader* header = this->Reader->GetNIFTIHeader();
  vtkMatrix4x4* m = nullptr;
  std::string frame = "voxel";
  if (!this->VoxelSpace && header && header->GetSFormCode() > 0 && this->Reader->GetSFormMatrix())
  {
    m = this->Reader->GetSFormMatrix();
    frame = "sform";
  }
  else if (!this->VoxelSpace && header && header->GetQFormCode() > 0 &&
    this->Reader->GetQFormMatrix())
  {
    m = this->Reader->GetQFormMatrix();
    frame = "qform";
  }
  if (m)
  {
    MapFrame(m, origin, spacing, d, this->Origin, this->Spacing, this->Direction);
  }
  return frame;
}

//------------------------------------------------------------------------------
// A matrix can hold NaN or infinity: the points would too.
bool vtkBlueNoiseNIfTIReader::FrameIsFinite(const std::string& frame)
{
  double values[15];
  std::copy(this->Origin, this->Origin + 3, values);
  std::copy(this->Spacing, this->Spacing + 3, values + 3);
  std::copy(this->Direction, this->Direction + 9, values + 6);
  if (std::all_of(values, values + 15, [](double v) { return std::isfinite(v); }))
  {
    return true;
  }
  this->Fail("the volume's origin, spacing or direction is not finite" +
    (frame == "voxel" ? std::string()
                      : " (from the " + frame + " matrix; voxel space ignores it)"));
  return false;
}

//------------------------------------------------------------------------------
int vtkBlueNoiseNIfTIReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!output)
  {
    vtkErrorMacro("the output is not vtkImageData");
    return 0;
  }
  output->Initialize();
  this->Frame.clear();
  if (!this->InformationOK)
  {
    return 1; // reported by RequestInformation: the output stays empty
  }
  // The requested extent (a piece, in parallel), or the whole one.
  int extent[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  }
  if (extent[0] > extent[1] || extent[2] > extent[3] || extent[4] > extent[5])
  {
    return 1; // an empty piece
  }

  ErrorCollector messages({ this->Reader, this->Reader->GetExecutive() });
  std::string failure;
  try
  {
    this->Reader->UpdateExtent(extent);
  }
  catch (const std::bad_alloc&)
  {
    failure = "out of memory while reading";
  }
  vtkImageData* image = this->Reader->GetOutput();
  int got[6] = { 0, -1, 0, -1, 0, -1 };
  if (image)
  {
    image->GetExtent(got);
  }
  if (failure.empty() && !messages.Errors.empty())
  {
    failure = messages.Errors.front();
  }
  else if (failure.empty() && (!image || image->GetNumberOfPoints() == 0))
  {
    failure = "the NIfTI reader produced no voxels";
  }
  else if (failure.empty() && !std::equal(got, got + 6, extent))
  {
    failure = "the NIfTI reader read the extent (" + ExtentText(got) + "), not the requested (" +
      ExtentText(extent) + ")";
  }
  else if (failure.empty() && image->GetPointData()->GetNumberOfArrays() == 0)
  {
    failure = "the volume has no point-data array";
  }
  if (!failure.empty())
  {
    this->Fail(failure);
    this->Reader->GetOutput()->Initialize(); // no copy of a bad read kept
    output->Initialize();
    return 1;
  }

  output->ShallowCopy(image);
  output->SetOrigin(this->Origin);
  output->SetSpacing(this->Spacing);
  output->SetDirectionMatrix(this->Direction);
  vtkNew<vtkStringArray> frame;
  frame->SetName("NIfTIFrame");
  frame->InsertNextValue(this->PendingFrame);
  output->GetFieldData()->AddArray(frame);
  this->Frame = this->PendingFrame;
  return 1;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseNIfTIReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "VoxelSpace: " << this->VoxelSpace << "\n";
  os << indent << "Frame: " << (this->Frame.empty() ? "(none)" : this->Frame) << "\n";
}
