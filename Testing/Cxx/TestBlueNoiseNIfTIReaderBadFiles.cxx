// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkBlueNoiseNIfTIReader on bad files: each gives an error naming the file
// and the problem (vtkErrorMacro, ErrorEvent) and an empty output, and the
// same reader then reads a good file again:
// - no file name, a missing file;
// - a .nii.gz cut in half (truncated gzip stream), and one with its
//   compressed bytes damaged in the middle;
// - a bad header (sizeof_hdr neither 348 nor 540);
// - a header declaring 2048^3 voxels in a small .nii.gz (refused from the
//   compressed size, before any decompression);
// - a plain .nii shorter than its header declares;
// - an sform with NaN (read in voxel space with VoxelSpace on).
#include "BlueNoiseTestUtilities.h"
#include "NIfTITestUtilities.h"

#include "vtkBlueNoiseNIfTIReader.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"

#include <cmath>
#include <unistd.h>

using namespace bluenoise_test;

namespace
{
// Reads `path` with `reader`: true when it read voxels without an error.
bool ReadsWell(vtkBlueNoiseNIfTIReader* reader, const std::string& path, MessageObserver* messages)
{
  messages->Clear();
  reader->SetFileName(path.c_str());
  reader->Update();
  return messages->ErrorCount == 0 && reader->GetOutput()->GetNumberOfPoints() == 60;
}

void ExpectFailure(vtkBlueNoiseNIfTIReader* reader, MessageObserver* messages,
  const std::string& path, const std::string& part, const std::string& good)
{
  messages->Clear();
  reader->SetFileName(path.empty() ? nullptr : path.c_str());
  reader->Update();
  vtkImageData* output = reader->GetOutput();
  Check(messages->ErrorCount >= 1, path + ": an error");
  Check(messages->ErrorContains(part),
    path + ": the error names the problem ('" + part + "'): " + messages->Errors);
  Check(path.empty() || messages->ErrorContains(path), path + ": the error names the file");
  Check(output->GetNumberOfPoints() == 0 && output->GetPointData()->GetNumberOfArrays() == 0 &&
      output->GetFieldData()->GetNumberOfArrays() == 0,
    path + ": empty output (" + Str(output->GetNumberOfPoints()) + " points)");
  Check(std::string(reader->GetFrame()).empty(), path + ": no frame");
  Check(ReadsWell(reader, good, messages), path + ": the same reader then reads " + good);
}
}

int main(int, char*[])
{
  char dirTemplate[] = "/tmp/bluenoise-nifti-bad-XXXXXX";
  const char* dir = mkdtemp(dirTemplate);
  if (!Check(dir != nullptr, "temporary folder"))
  {
    return Summary("TestBlueNoiseNIfTIReaderBadFiles");
  }
  const std::string d = dir;
  std::vector<std::string> written;
  auto write = [&written](const std::string& path, const std::string& bytes) {
    Check(WriteFile(path, bytes), "writing " + path);
    written.push_back(path);
    return path;
  };

  NIfTIFile file;
  file.SFormCode = 1;
  const std::string good = write(d + "/good.nii.gz", file.Bytes());
  const std::string gz = ReadFile(good);

  vtkNew<vtkBlueNoiseNIfTIReader> reader;
  vtkNew<MessageObserver> messages;
  messages->Watch(reader);
  Check(ReadsWell(reader, good, messages), "the good file reads: " + messages->Errors);
  Check(vtkBlueNoiseNIfTIReader::CanReadFile(good.c_str()) == 1, "CanReadFile(good) is 1");

  ExpectFailure(reader, messages, "", "no FileName", good);
  ExpectFailure(reader, messages, d + "/missing.nii.gz", "No such file", good);

  // Raw bytes (not gzipped again).
  auto writeRaw = [&written](const std::string& path, const std::string& bytes) {
    FILE* f = std::fopen(path.c_str(), "wb");
    Check(f && std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fclose(f) == 0,
      "writing " + path);
    written.push_back(path);
    return path;
  };
  ExpectFailure(reader, messages, writeRaw(d + "/cut.nii.gz", gz.substr(0, gz.size() / 2)), "", good);

  std::string damaged = gz;
  for (size_t i = damaged.size() / 3; i < damaged.size() / 3 + 16; ++i)
  {
    damaged[i] = static_cast<char>(damaged[i] ^ 0x5a);
  }
  const std::string broken = writeRaw(d + "/damaged.nii.gz", damaged);
  ExpectFailure(reader, messages, broken, "", good);

  NIfTIFile badHeader = file;
  badHeader.SizeOfHeader = 1234;
  const std::string bad = write(d + "/badheader.nii.gz", badHeader.Bytes());
  ExpectFailure(reader, messages, bad, "sizeof_hdr", good);
  Check(vtkBlueNoiseNIfTIReader::CanReadFile(bad.c_str()) == 0, "CanReadFile(bad header) is 0");

  NIfTIFile lying = file;
  std::string lyingBytes = lying.Bytes();
  const int16_t big = 2048;
  for (int a = 0; a < 3; ++a)
  {
    std::memcpy(&lyingBytes[42 + 2 * a], &big, 2);
  }
  ExpectFailure(reader, messages, write(d + "/lying.nii.gz", lyingBytes), "2048 x 2048 x 2048", good);

  const std::string plain = file.Bytes();
  ExpectFailure(reader, messages, write(d + "/short.nii", plain.substr(0, plain.size() - 10)),
    "the data has only", good);

  NIfTIFile nan = file;
  nan.SRow[1][1] = std::nanf("");
  const std::string nanPath = write(d + "/nan.nii.gz", nan.Bytes());
  ExpectFailure(reader, messages, nanPath, "not finite", good);
  reader->VoxelSpaceOn();
  Check(ReadsWell(reader, nanPath, messages) && std::string(reader->GetFrame()) == "voxel",
    "the NaN sform in voxel space: " + messages->Errors);

  for (const auto& path : written)
  {
    std::remove(path.c_str());
  }
  rmdir(dir);
  return Summary("TestBlueNoiseNIfTIReaderBadFiles");
}
