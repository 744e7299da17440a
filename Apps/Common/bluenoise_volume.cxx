// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_volume.h.
#include "bluenoise_volume.h"
#include "bluenoise_messages.h"
#include "bluenoise_raw_reader.h"
#include "bluenoise_volume_headers.h"
#include "bluenoise_xml_reader.h"

#include "vtkBlueNoiseNIfTIReader.h"
#include "vtkBlueNoiseVolumeFileCheck.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkMatrix3x3.h"
#include "vtkMetaImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkPointData.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <new>
#include <sstream>

namespace bluenoise
{
namespace
{
bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
    vtksys::SystemTools::LowerCase(s.substr(s.size() - suffix.size())) == suffix;
}

// A raw MetaImage's voxels through a reader of sub-extents (bluenoise_raw_reader.h).
vtkSmartPointer<vtkAlgorithm> NewRawReader(const Volume& volume)
{
  const RawLayout& raw = volume.Raw;
  auto r = NewRawImageReader();
  r->SetFileName(raw.DataFile.c_str());
  r->SetFileDimensionality(3);
  r->SetDataScalarType(raw.ScalarType);
  r->SetNumberOfScalarComponents(raw.Components);
  r->SetDataExtent(const_cast<int*>(volume.WholeExtent));
  r->SetDataSpacing(const_cast<double*>(raw.Spacing));
  r->SetDataOrigin(const_cast<double*>(raw.Origin));
  r->SetHeaderSize(static_cast<unsigned long>(raw.HeaderBytes));
  r->FileLowerLeftOn(); // rows stored first to last, as MetaImage does
  if (raw.BigEndian)
  {
    r->SetDataByteOrderToBigEndian();
  }
  else
  {
    r->SetDataByteOrderToLittleEndian();
  }
  return r;
}

vtkSmartPointer<vtkAlgorithm> NewReader(const std::string& path, const VolumeOptions& options)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  if (EndsWith(path, ".vti"))
  {
    auto r = NewXMLImageDataReader();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (EndsWith(path, ".nii") || EndsWith(path, ".nii.gz") || EndsWith(path, ".hdr"))
  {
    // The module's reader: the same checks, and the sform / qform world frame.
    auto r = vtkSmartPointer<vtkBlueNoiseNIfTIReader>::New();
    r->SetFileName(path.c_str());
    r->SetVoxelSpace(options.VoxelSpace);
    reader = r;
  }
  else if (EndsWith(path, ".nrrd") || EndsWith(path, ".nhdr"))
  {
    auto r = vtkSmartPointer<vtkNrrdReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (EndsWith(path, ".mhd") || EndsWith(path, ".mha"))
  {
    auto r = vtkSmartPointer<vtkMetaImageReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  return reader;
}

// A message of the module's NIfTI reader without the file name it starts
// with (the callers name the file themselves); others as they are.
std::string WithoutFileName(vtkAlgorithm* reader, const std::string& message)
{
  auto nifti = vtkBlueNoiseNIfTIReader::SafeDownCast(reader);
  const std::string name = nifti && nifti->GetFileName() ? nifti->GetFileName() + std::string(": ") : "";
  return !name.empty() && message.compare(0, name.size(), name) == 0 ? message.substr(name.size())
                                                                     : message;
}

// Runs the reader on `extent` (or its whole extent), catching its errors and
// failed allocations.
bool RunReader(vtkAlgorithm* reader, const int* extent, std::string& error)
{
  VTKMessages messages;
  messages.Attach(reader);
  std::string failure;
  try
  {
    if (extent)
    {
      reader->UpdateExtent(extent);
    }
    else
    {
      reader->Update();
    }
  }
  catch (const std::bad_alloc&)
  {
    failure = "out of memory while reading";
  }
  if (failure.empty() && !messages.Errors.empty())
  {
    failure = WithoutFileName(reader, messages.Errors.front());
  }
  error = failure;
  return failure.empty();
}

// The reader's whole extent is the one the header check vouched for (slabs
// are requested from it).
bool SameExtent(vtkAlgorithm* reader, const Volume& volume, std::string& error)
{
  VTKMessages messages;
  messages.Attach(reader);
  reader->UpdateInformation();
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  vtkInformation* info = reader->GetOutputInformation(0);
  if (info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  }
  if (vtkBlueNoiseNIfTIReader::SafeDownCast(reader) && !messages.Errors.empty())
  {
    // It says why it refuses the file (an extent left empty); a matrix that is
    // not finite is the one case the program's own option gets round.
    error = WithoutFileName(reader, messages.Errors.front());
    if (error.find("not finite") != std::string::npos)
    {
      error += "; --voxel-space reads the file in voxel space";
    }
    return false;
  }
  if (!std::equal(extent, extent + 6, volume.WholeExtent))
  {
    std::ostringstream s;
    s << "the reader's extent (" << extent[0] << " " << extent[1] << " " << extent[2] << " "
      << extent[3] << " " << extent[4] << " " << extent[5] << ") differs from the header's ("
      << volume.WholeExtent[0] << " " << volume.WholeExtent[1] << " " << volume.WholeExtent[2]
      << " " << volume.WholeExtent[3] << " " << volume.WholeExtent[4] << " "
      << volume.WholeExtent[5] << ")"
      << (messages.Errors.empty() ? std::string() : ": " + messages.Errors.front());
    error = s.str();
    return false;
  }
  return true;
}

// A volume read whole has the extent the header check vouched for (vtkNrrdReader,
// for one, takes the first axis of some 3D files as components).
bool SameImageExtent(vtkImageData* image, const Volume& volume, std::string& error)
{
  int extent[6];
  image->GetExtent(extent);
  if (!std::equal(extent, extent + 6, volume.WholeExtent))
  {
    std::ostringstream s;
    s << "the reader read " << image->GetDimensions()[0] << " x " << image->GetDimensions()[1]
      << " x " << image->GetDimensions()[2] << " voxels, not the header's "
      << volume.WholeExtent[1] - volume.WholeExtent[0] + 1 << " x "
      << volume.WholeExtent[3] - volume.WholeExtent[2] + 1 << " x "
      << volume.WholeExtent[5] - volume.WholeExtent[4] + 1;
    error = s.str();
    return false;
  }
  return true;
}

bool CheckImage(vtkImageData* image, std::string& error)
{
  if (!image || image->GetNumberOfPoints() == 0)
  {
    error = "the reader produced no voxels";
    return false;
  }
  if (image->GetPointData()->GetNumberOfArrays() == 0)
  {
    error = "the volume has no point-data array";
    return false;
  }
  return true;
}

// Origin, spacing and direction finite (a NIfTI sform or qform, or a VTI's
// Origin and Direction, can hold NaN or infinity: the points would too).
bool CheckGeometry(vtkImageData* image, const std::string& frame, std::string& error)
{
  double values[15];
  image->GetOrigin(values);
  image->GetSpacing(values + 3);
  std::copy(image->GetDirectionMatrix()->GetData(), image->GetDirectionMatrix()->GetData() + 9,
    values + 6);
  if (!std::all_of(values, values + 15, [](double v) { return std::isfinite(v); }))
  {
    error = "the volume's origin, spacing or direction is not finite" +
      (frame == "voxel" ? std::string()
                        : " (from the " + frame + " matrix; --voxel-space ignores it)");
    return false;
  }
  return true;
}
}

const char* VolumeSuffixes()
{
  return ".vti, .nii, .nii.gz, .hdr, .nrrd, .nhdr, .mhd, .mha";
}

bool CheckVolumeFile(const std::string& path, Volume& volume, std::string& error)
{
  volume = Volume();
  volume.Path = path;
  bool& streamable = volume.StreamableFile;
  bool ok = false;
  if (vtkBlueNoiseVolumeFileCheck::FileSize(path) < 0)
  {
    error = path + ": " + std::strerror(errno);
    return false;
  }
  if (EndsWith(path, ".vti"))
    ok = headers::CheckVTI(path, volume, streamable, error);
  else if (EndsWith(path, ".nii") || EndsWith(path, ".nii.gz") || EndsWith(path, ".hdr") ||
    EndsWith(path, ".hdr.gz"))
    ok = headers::CheckNIfTI(path, volume, error);
  else if (EndsWith(path, ".nrrd") || EndsWith(path, ".nhdr"))
    ok = headers::CheckNRRD(path, volume, streamable, error);
  else if (EndsWith(path, ".mhd") || EndsWith(path, ".mha"))
    ok = headers::CheckMetaImage(path, volume, streamable, error);
  else
  {
    error = path + ": unknown volume format (expected " + VolumeSuffixes() + ")";
    return false;
  }
  if (!ok)
  {
    error = path + ": " + error;
    return false;
  }
  volume.Frame = "file";
  return true;
}

bool OpenVolume(
  const std::string& path, const VolumeOptions& options, Volume& volume, std::string& error)
{
  return CheckVolumeFile(path, volume, error) && ReadVolume(options, volume, error);
}

bool ReadVolume(const VolumeOptions& options, Volume& volume, std::string& error)
{
  const std::string& path = volume.Path;
  const bool streamable = volume.StreamableFile;
  auto reader = streamable && volume.Format == "MetaImage" ? NewRawReader(volume) : NewReader(path, options);
  if (!reader)
  {
    error = path + ": unknown volume format (expected " + std::string(VolumeSuffixes()) + ")";
    return false;
  }
  // The reader's own reading of the header must agree with the check's
  // before it reads a byte of data.
  if (!SameExtent(reader, volume, error))
  {
    error = path + ": " + error;
    return false;
  }
  if (streamable && options.AllowStreaming)
  {
    // The first layer only: the arrays' names and types, and a read that works.
    int layer[6];
    std::copy(volume.WholeExtent, volume.WholeExtent + 6, layer);
    layer[5] = layer[4];
    if (!RunReader(reader, layer, error))
    {
      error = path + ": " + error;
      return false;
    }
    volume.Reader = reader;
  }
  else if (!RunReader(reader, nullptr, error))
  {
    error = path + ": " + error;
    return false;
  }
  auto image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!CheckImage(image, error) || (!volume.Reader && !SameImageExtent(image, volume, error)))
  {
    error = path + ": " + error;
    return false;
  }
  volume.Image = vtkSmartPointer<vtkImageData>::New();
  volume.Image->ShallowCopy(image);
  if (auto nifti = vtkBlueNoiseNIfTIReader::SafeDownCast(reader))
  {
    volume.Frame = nifti->GetFrame();
  }
  if (!CheckGeometry(volume.Image, volume.Frame, error))
  {
    error = path + ": " + error;
    return false;
  }
  return true;
}
}
