// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBlueNoiseNIfTIReader
 * @brief   Reads a NIfTI volume (.nii, .nii.gz, .hdr/.img) in its world frame, distrusting the file.
 *
 * Input: a file, FileName: NIfTI-1 or NIfTI-2 as a single file (.nii, or
 * gzipped .nii.gz) or a header and image pair (.hdr with .img, either
 * gzipped), or an Analyze 7.5 pair. Output: vtkImageData with the first time
 * point's voxels as point data (a fifth dimension as components), read by
 * VTK's vtkNIFTIImageReader, and a field-data string array "NIfTIFrame"
 * naming the frame of the output's geometry (ParaView's Information tab
 * lists it):
 *
 * - "sform": the file's sform (when its code is set), in millimetres;
 * - "qform": else its qform (when its code is set);
 * - "voxel": neither set, or VoxelSpace on: origin 0, spacing pixdim.
 *
 * The world frame is the image's origin, spacing and direction: with M the
 * 4x4 matrix, world = M (origin + D diag(spacing) ijk), so the output's
 * direction columns are those of M D diag(spacing) normalized and their
 * lengths its spacing. Every point of the output then sits where the file's
 * matrix puts the voxel (vtkNIFTIImageReader stores a left-handed qform's
 * slices in reverse, and its matrix accounts for it).
 *
 * Files are distrusted (CheckFile): before any data is read the header is
 * parsed here and checked against the real size of the data (decompressed,
 * for a gzipped file; vtkBlueNoiseVolumeFileCheck), the datatype must be one
 * vtkNIFTIImageReader knows (VTK 9.2's reader reads past its type table for
 * others), a row of the data must fit in an int, and vtkNIFTIImageReader's
 * own extent must equal the checked one. A file that fails, a corrupt or
 * truncated gzip stream, a failed allocation, or a matrix that puts the
 * volume at NaN or infinity is reported with vtkErrorMacro (the message
 * names the file and the problem) and gives an empty output; the next good
 * file reads normally.
 *
 * Caveats: only the first time point is read; the data are read whole (or the
 * requested extent, which the NIfTI reader still has to decompress up to),
 * so a gzipped file is decompressed twice (once counted, once read). The
 * output's origin, spacing and direction are those of the world frame: a
 * filter that ignores the direction matrix places the volume axis-aligned.
 *
 * The same check and frame serve bluenoise-sample (Apps/Common/bluenoise_volume).
 */
#ifndef vtkBlueNoiseNIfTIReader_h
#define vtkBlueNoiseNIfTIReader_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkImageAlgorithm.h"
#include "vtkNew.h" // for vtkNew

#include <string> // for std::string

#ifndef __VTK_WRAP__
#include "vtkBlueNoiseVolumeFileCheck.h" // for vtkBlueNoiseVolumeFileCheck::Checked
#endif

class vtkNIFTIImageReader;

class VTKFILTERSBLUENOISE_EXPORT vtkBlueNoiseNIfTIReader : public vtkImageAlgorithm
{
public:
  static vtkBlueNoiseNIfTIReader* New();
  vtkTypeMacro(vtkBlueNoiseNIfTIReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file: .nii, .nii.gz, .hdr, .hdr.gz (with its .img or .img.gz).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Off (default): the world frame of the sform, else the qform. On: voxel
  /// space (origin 0, spacing pixdim, identity direction), whatever the file says.
  vtkSetMacro(VoxelSpace, vtkTypeBool);
  vtkGetMacro(VoxelSpace, vtkTypeBool);
  vtkBooleanMacro(VoxelSpace, vtkTypeBool);
  ///@}

  /// The frame of the last output ("sform", "qform" or "voxel"), as in its
  /// "NIfTIFrame" field-data array; empty before a successful read.
  const char* GetFrame() const { return this->Frame.c_str(); }

  /// 1 when the file's header parses as NIfTI-1, NIfTI-2 or Analyze 7.5 and
  /// passes the checks that need no more than the header, else 0.
  static int CanReadFile(const char* fileName);

#ifndef __VTK_WRAP__
  /// The header checks, without reading the data: fills `checked` (the
  /// extent, voxels and bytes per voxel the file holds) or says why not.
  static bool CheckFile(
    const std::string& path, vtkBlueNoiseVolumeFileCheck::Checked& checked, std::string& error);
#endif

protected:
  vtkBlueNoiseNIfTIReader();
  ~vtkBlueNoiseNIfTIReader() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName = nullptr;
  vtkTypeBool VoxelSpace = false;

private:
  vtkBlueNoiseNIfTIReader(const vtkBlueNoiseNIfTIReader&) = delete;
  void operator=(const vtkBlueNoiseNIfTIReader&) = delete;

  // Reports `message` (prefixed with the file name) and marks the file unreadable.
  void Fail(const std::string& message);
  // The steps of RequestInformation (see the .cxx); false after a Fail.
  bool ReadHeader(int extent[6]);
  std::string ComputeFrame();
  bool FrameIsFinite(const std::string& frame);

  vtkNew<vtkNIFTIImageReader> Reader;
  // The result of RequestInformation: the file vouched for, and its world frame.
  bool InformationOK = false;
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  std::string Frame;
  std::string PendingFrame;
};

#endif
