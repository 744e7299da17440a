// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Volume loading of the programs: .vti, .nii / .nii.gz (and .hdr/.img),
// .nrrd / .nhdr, .mhd / .mha.
//
// Files are distrusted. Before a reader allocates anything the header is
// parsed here and checked against the real size of the file(s): dimensions
// and spacing must be positive and finite, a NIfTI data offset must lie in
// the file, the data (a MetaImage's or a detached NRRD's data file, a NIfTI
// body, decompressed when gzipped) must hold at least what the header
// declares (a VTI's arrays: their components, tuples and types); compressed
// data is bounded by zlib's largest ratio. So time and memory follow the
// file's real size, whatever its header claims. Text headers with a NUL byte
// are refused, NRRD fields are read as vtkNrrdReader reads them (": ", the
// first axis as components when it has at most 9 entries), NIfTI headers as
// vtkNIFTIImageReader reads them (the version from the magic, only the
// datatype codes it knows, the .img of a .hdr by its suffix), and the reader's
// own extent must equal the checked one before it reads any data. Reader
// errors (VTK's ErrorEvent) and failed allocations (std::bad_alloc) are
// caught too. Every failure is a message naming the file and the problem.
//
// Streaming: raw MetaImage (read by bluenoise_raw_reader.h's reader from the
// layout parsed here: VTK's vtkMetaImageReader reads the whole file into any
// extent it is asked for, overrunning a slab), raw NRRD and VTI files with raw
// (uncompressed, appended) data read any sub-extent, so ReadVolume leaves
// those unread (Volume::Streamable) for a consumer that requests z-slabs
// (vtkErrorDiffusionSampler::SetNumberOfSlabs). NIfTI, compressed and ASCII
// files are read whole.
//
// World frame: NIfTI volumes are read by the module's vtkBlueNoiseNIfTIReader
// (its checks, then VTK's vtkNIFTIImageReader), in the file's world frame (the sform
// when its code is set, else the qform; millimetres) through the image's
// origin, spacing and direction, unless VoxelSpace is asked for; other
// formats keep the origin and spacing their readers give.
#ifndef bluenoise_volume_h
#define bluenoise_volume_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>

class vtkAlgorithm;
class vtkImageData;

namespace bluenoise
{
struct VolumeOptions
{
  /// NIfTI: keep voxel space (origin 0, spacing pixdim) instead of the world frame.
  bool VoxelSpace = false;
  /// Leave streamable files unread (Volume::Reader) instead of reading them whole.
  bool AllowStreaming = false;
};

/// Where and how a raw MetaImage keeps its voxels (for a reader of sub-extents).
struct RawLayout
{
  std::string DataFile;
  double HeaderBytes = 0.0;
  int ScalarType = 0; // VTK_UNSIGNED_CHAR, ...
  int Components = 1;
  bool BigEndian = false;
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
};

struct Volume
{
  std::string Path;
  /// "VTI", "NIfTI", "NRRD" or "MetaImage".
  std::string Format;
  /// The frame of the image: "sform" or "qform" (a NIfTI world frame, millimetres),
  /// "voxel" (NIfTI in voxel space: origin 0, spacing pixdim), "file" (the
  /// origin and spacing the other formats' readers give).
  std::string Frame;
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  vtkIdType Voxels = 0;
  /// Bytes of one voxel over all arrays the header declares (a lower bound).
  double BytesPerVoxel = 0.0;
  /// The file's reader reads sub-extents (raw MetaImage, raw NRRD, raw appended VTI).
  bool StreamableFile = false;
  /// Raw MetaImage: its layout, read with NewRawImageReader() (vtkMetaImageReader
  /// reads the whole file into whatever extent it was asked for).
  RawLayout Raw;
  /// Streamed: the reader, its information updated and one layer read (Sample); else null.
  vtkSmartPointer<vtkAlgorithm> Reader;
  /// Read whole: the volume. Streamed: the first layer, for the array names and types.
  vtkSmartPointer<vtkImageData> Image;
  bool Streamable() const { return this->Reader != nullptr; }
};

/// Checks the file (header against real size) without reading its data.
bool CheckVolumeFile(const std::string& path, Volume& volume, std::string& error);

/// Reads (or, streamable and allowed, prepares) a volume CheckVolumeFile vouched for.
bool ReadVolume(const VolumeOptions& options, Volume& volume, std::string& error);

/// CheckVolumeFile, then ReadVolume.
bool OpenVolume(
  const std::string& path, const VolumeOptions& options, Volume& volume, std::string& error);

/// The volume's formats for messages: ".vti, .nii, .nii.gz, ...".
const char* VolumeSuffixes();
}

#endif
