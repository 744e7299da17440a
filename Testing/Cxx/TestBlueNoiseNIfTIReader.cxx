// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBlueNoiseNIfTIReader on small NIfTI-1 files the test writes itself
// (NIfTITestUtilities.h), .nii and .nii.gz:
// - sform (a rotation, anisotropic voxels, a translation): every voxel of the
//   file is found at srow * (i, j, k, 1) in the output with its value;
// - qform with qfac -1 (VTK's reader stores the slices in reverse) and a 180
//   degree rotation: every voxel at R (i dx, j dy, -k dz) + qoffset;
// - VoxelSpace: origin 0, spacing pixdim, identity direction, frame "voxel";
// - the field-data array NIfTIFrame and GetFrame name the frame;
// - the main job's loader (bluenoise::OpenVolume) gives the same origin,
//   spacing, direction, frame and values;
// - the MRI volume of mricron-data (ch2bet.nii.gz) when present: the same
//   image as the main job's loader, and its sform applied (skipped otherwise).
#include "BlueNoiseTestUtilities.h"
#include "NIfTITestUtilities.h"

#include "bluenoise_volume.h"
#include "vtkBlueNoiseNIfTIReader.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstdlib>
#include <functional>
#include <unistd.h>

using namespace bluenoise_test;

namespace
{
std::string FrameArray(vtkImageData* image)
{
  auto frame = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("NIfTIFrame"));
  return frame && frame->GetNumberOfValues() == 1 ? frame->GetValue(0) : std::string("(none)");
}

// Every voxel (i, j, k) of the file at world(i, j, k) in `image`, with its value.
void CheckVoxels(vtkImageData* image, const NIfTIFile& file,
  const std::function<void(int, int, int, double*)>& world, const std::string& what)
{
  int misplaced = 0, wrong = 0;
  vtkDataArray* values = image->GetPointData()->GetScalars();
  if (!Check(values != nullptr && image->GetNumberOfPoints() ==
        static_cast<vtkIdType>(file.Dims[0]) * file.Dims[1] * file.Dims[2],
        what + ": " + Str(image->GetNumberOfPoints()) + " voxels with scalars"))
  {
    return;
  }
  for (int k = 0; k < file.Dims[2]; ++k)
  {
    for (int j = 0; j < file.Dims[1]; ++j)
    {
      for (int i = 0; i < file.Dims[0]; ++i)
      {
        double p[3], index[3];
        world(i, j, k, p);
        image->TransformPhysicalPointToContinuousIndex(p, index);
        int ijk[3];
        bool onVoxel = true;
        for (int a = 0; a < 3; ++a)
        {
          ijk[a] = static_cast<int>(std::lround(index[a]));
          onVoxel = onVoxel && std::abs(index[a] - ijk[a]) < 1e-4 && ijk[a] >= 0 &&
            ijk[a] < image->GetDimensions()[a];
        }
        if (!onVoxel)
        {
          ++misplaced;
          continue;
        }
        const double v = values->GetComponent(image->ComputePointId(ijk), 0);
        wrong += v != NIfTIFile::Value(i, j, k);
      }
    }
  }
  Check(misplaced == 0, what + ": " + Str(misplaced) + " voxels not on a voxel of the output");
  Check(wrong == 0, what + ": " + Str(wrong) + " voxels with another value");
}

vtkSmartPointer<vtkImageData> Read(const std::string& path, bool voxelSpace, std::string& frame)
{
  vtkNew<vtkBlueNoiseNIfTIReader> reader;
  vtkNew<MessageObserver> messages;
  messages->Watch(reader);
  reader->SetFileName(path.c_str());
  reader->SetVoxelSpace(voxelSpace);
  reader->Update();
  Check(messages->ErrorCount == 0, path + ": no error (" + messages->Errors + ")");
  frame = reader->GetFrame();
  return reader->GetOutput();
}

bool Close(const double* a, const double* b, int n, double tolerance = 1e-9)
{
  for (int i = 0; i < n; ++i)
  {
    if (!(std::abs(a[i] - b[i]) <= tolerance * (1.0 + std::abs(b[i]))))
    {
      return false;
    }
  }
  return true;
}

// The reader's output against the main job's loader on the same file.
void CompareWithMainJob(const std::string& path, bool voxelSpace, vtkImageData* image,
  const std::string& frame)
{
  bluenoise::VolumeOptions options;
  options.VoxelSpace = voxelSpace;
  bluenoise::Volume volume;
  std::string error;
  if (!Check(bluenoise::OpenVolume(path, options, volume, error), path + ": main job: " + error))
  {
    return;
  }
  vtkImageData* other = volume.Image;
  Check(volume.Frame == frame, path + ": main job's frame " + volume.Frame + " == " + frame);
  Check(Close(other->GetOrigin(), image->GetOrigin(), 3) &&
      Close(other->GetSpacing(), image->GetSpacing(), 3) &&
      Close(other->GetDirectionMatrix()->GetData(), image->GetDirectionMatrix()->GetData(), 9),
    path + ": main job's origin, spacing and direction");
  int a[6], b[6];
  other->GetExtent(a);
  image->GetExtent(b);
  Check(std::equal(a, a + 6, b), path + ": main job's extent");
  vtkDataArray* x = other->GetPointData()->GetScalars();
  vtkDataArray* y = image->GetPointData()->GetScalars();
  bool same = x && y && x->GetNumberOfTuples() == y->GetNumberOfTuples() &&
    x->GetDataType() == y->GetDataType();
  for (vtkIdType i = 0; same && i < x->GetNumberOfTuples(); ++i)
  {
    same = x->GetComponent(i, 0) == y->GetComponent(i, 0);
  }
  Check(same, path + ": main job's values");
}
}

int main(int argc, char* argv[])
{
  char dirTemplate[] = "/tmp/bluenoise-nifti-XXXXXX";
  const char* dir = mkdtemp(dirTemplate);
  if (!Check(dir != nullptr, "temporary folder"))
  {
    return Summary("TestBlueNoiseNIfTIReader");
  }
  std::vector<std::string> written;

  // sform: x = -j dy + 10, y = i dx - 20, z = k dz + 5 (a 90 degree turn about z).
  NIfTIFile sform;
  sform.SFormCode = 1;
  sform.QFormCode = 0;
  const float srow[3][4] = { { 0, -2.0f, 0, 10 }, { 1.5f, 0, 0, -20 }, { 0, 0, 2.5f, 5 } };
  std::memcpy(sform.SRow, srow, sizeof(srow));
  auto sformWorld = [&srow](int i, int j, int k, double* p) {
    for (int r = 0; r < 3; ++r)
    {
      p[r] = srow[r][0] * i + srow[r][1] * j + srow[r][2] * k + srow[r][3];
    }
  };

  // qform: 180 degrees about x (b = 1), qfac -1: x = i dx, y = -j dy, z = -(-k dz), plus offsets.
  NIfTIFile qform;
  qform.QFormCode = 1;
  qform.SFormCode = 0;
  qform.QFac = -1.0f;
  qform.Quatern[0] = 1.0f;
  qform.QOffset[0] = -3.0f;
  qform.QOffset[1] = 7.0f;
  qform.QOffset[2] = 11.0f;
  auto qformWorld = [&qform](int i, int j, int k, double* p) {
    // R = diag(1, -1, -1) for b = 1; (i dx, j dy, qfac k dz).
    p[0] = i * qform.PixDim[0] + qform.QOffset[0];
    p[1] = -(j * qform.PixDim[1]) + qform.QOffset[1];
    p[2] = -(qform.QFac * k * qform.PixDim[2]) + qform.QOffset[2];
  };

  for (const char* suffix : { ".nii", ".nii.gz" })
  {
    const std::string s = std::string(dir) + "/sform" + suffix;
    const std::string q = std::string(dir) + "/qform" + suffix;
    Check(WriteFile(s, sform.Bytes()) && WriteFile(q, qform.Bytes()), "writing the test files");
    written.push_back(s);
    written.push_back(q);

    std::string frame;
    auto image = Read(s, false, frame);
    Check(frame == "sform" && FrameArray(image) == "sform",
      s + ": frame " + frame + ", NIfTIFrame " + FrameArray(image));
    CheckVoxels(image, sform, sformWorld, s);
    CompareWithMainJob(s, false, image, frame);

    image = Read(q, false, frame);
    Check(frame == "qform" && FrameArray(image) == "qform",
      q + ": frame " + frame + ", NIfTIFrame " + FrameArray(image));
    CheckVoxels(image, qform, qformWorld, q);
    CompareWithMainJob(q, false, image, frame);

    // Voxel space: the matrices ignored.
    image = Read(s, true, frame);
    const double zero[3] = { 0, 0, 0 }, pixdim[3] = { 1.5, 2.0, 2.5 };
    const double identity[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    Check(frame == "voxel" && FrameArray(image) == "voxel", s + ": voxel space frame " + frame);
    Check(Close(image->GetOrigin(), zero, 3) && Close(image->GetSpacing(), pixdim, 3) &&
        Close(image->GetDirectionMatrix()->GetData(), identity, 9),
      s + ": voxel space: origin 0, spacing pixdim, identity direction");
    CheckVoxels(image, sform,
      [&sform](int i, int j, int k, double* p) {
        p[0] = i * sform.PixDim[0];
        p[1] = j * sform.PixDim[1];
        p[2] = k * sform.PixDim[2];
      },
      s + " (voxel space)");
    CompareWithMainJob(s, true, image, frame);
  }

  // The MRI volume: the same image as the main job's loader, in its sform.
  const std::string mri = argc > 1 ? argv[1] : "/usr/share/mricron/templates/ch2bet.nii.gz";
  if (access(mri.c_str(), R_OK) == 0)
  {
    std::string frame;
    auto image = Read(mri, false, frame);
    Check(frame == "sform" || frame == "qform", mri + ": a world frame (" + frame + ")");
    CompareWithMainJob(mri, false, image, frame);
    // Independently: VTK's reader's matrix maps its voxel space to the world.
    vtkNew<vtkNIFTIImageReader> plain;
    plain->SetFileName(mri.c_str());
    plain->Update();
    vtkMatrix4x4* m = frame == "sform" ? plain->GetSFormMatrix() : plain->GetQFormMatrix();
    vtkImageData* raw = plain->GetOutput();
    int mismatched = 0;
    const int* dims = raw->GetDimensions();
    for (int c = 0; c < 8; ++c)
    {
      const int ijk[3] = { (c & 1) ? dims[0] - 1 : 0, (c & 2) ? dims[1] - 1 : 0,
        (c & 4) ? dims[2] - 1 : 0 };
      double local[4] = { 0, 0, 0, 1 }, world[4], mine[3];
      raw->TransformIndexToPhysicalPoint(ijk[0], ijk[1], ijk[2], local);
      local[3] = 1.0;
      m->MultiplyPoint(local, world);
      image->TransformIndexToPhysicalPoint(ijk[0], ijk[1], ijk[2], mine);
      mismatched += !Close(mine, world, 3, 1e-6);
    }
    Check(mismatched == 0, mri + ": " + Str(mismatched) + " of 8 corners off the matrix's world");
  }
  else
  {
    std::cout << "(" << mri << " not found: the MRI part is skipped)" << std::endl;
  }

  for (const auto& path : written)
  {
    std::remove(path.c_str());
  }
  rmdir(dir);
  return Summary("TestBlueNoiseNIfTIReader");
}
