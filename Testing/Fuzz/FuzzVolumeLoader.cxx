// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the programs' volume loading (bluenoise::OpenVolume, with
// its header checks and VTK's readers) on arbitrary bytes. The bytes are
// written to a scratch file under each suffix whose format they could be
// (those whose magic they start with, else all) and loaded;
// a load must end in success or a message, never in a crash, a hang or an
// allocation beyond what the file's real size allows (libFuzzer's
// -rss_limit_mb and -malloc_limit_mb catch the latter).
#include "bluenoise_volume.h"

#include "vtkImageData.h"
#include "vtkObject.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
const char* const Suffixes[] = { ".vti", ".nii", ".nii.gz", ".nrrd", ".nhdr", ".mhd", ".mha" };

// The suffixes worth trying for these bytes: the formats whose magic they
// start with, or every suffix when they start with none (arbitrary bytes
// still go through every loader, recognizable ones only through theirs).
std::vector<const char*> SuffixesFor(const uint8_t* data, size_t size)
{
  const std::string head(reinterpret_cast<const char*>(data), std::min<size_t>(size, 16));
  int32_t sizeofHeader = 0;
  if (size >= 4)
  {
    std::memcpy(&sizeofHeader, data, 4);
  }
  if (head.compare(0, 4, "NRRD") == 0)
    return { ".nrrd", ".nhdr" };
  if (head.compare(0, 1, "<") == 0)
    return { ".vti" };
  if (size >= 2 && data[0] == 0x1f && data[1] == 0x8b)
    return { ".nii.gz" };
  if (sizeofHeader == 348 || sizeofHeader == 540 || sizeofHeader == 0x5C010000 ||
    sizeofHeader == 0x1C020000)
    return { ".nii" };
  if (head.compare(0, 5, "NDims") == 0 || head.compare(0, 10, "ObjectType") == 0)
    return { ".mhd", ".mha" };
  return std::vector<const char*>(std::begin(Suffixes), std::end(Suffixes));
}

// One scratch folder per process, removed at exit.
std::string ScratchFolder()
{
  static std::string folder;
  if (folder.empty())
  {
    char name[] = "/tmp/bluenoise-fuzz-volume.XXXXXX";
    if (!mkdtemp(name))
    {
      std::abort();
    }
    folder = name;
    std::atexit([] {
      for (const char* suffix : Suffixes)
      {
        std::remove((folder + "/input" + suffix).c_str());
      }
      rmdir(folder.c_str());
    });
  }
  return folder;
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  static const bool quiet = [] {
    vtkObject::GlobalWarningDisplayOff(); // readers' complaints are expected
    return true;
  }();
  (void)quiet;
  const std::string folder = ScratchFolder();
  for (const char* suffix : SuffixesFor(data, size))
  {
    const std::string path = folder + "/input" + suffix;
    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file)
    {
      std::abort();
    }
    if (size > 0 && std::fwrite(data, 1, size, file) != size)
    {
      std::abort();
    }
    std::fclose(file);
    bluenoise::Volume volume;
    bluenoise::VolumeOptions options;
    std::string error;
    if (bluenoise::OpenVolume(path, options, volume, error))
    {
      // A volume that loads has what the header check promised.
      if (!volume.Image || volume.Image->GetNumberOfPoints() != volume.Voxels)
      {
        std::abort();
      }
    }
    else if (error.empty())
    {
      std::abort(); // every failure says why
    }
    std::remove(path.c_str());
  }
  return 0;
}
