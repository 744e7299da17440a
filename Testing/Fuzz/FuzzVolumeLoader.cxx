// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the programs' volume loading (bluenoise::OpenVolume, with
// its header checks and VTK's readers) on arbitrary bytes. The bytes are
// written to a scratch file under each supported suffix in turn and loaded;
// a load must end in success or a message, never in a crash, a hang or an
// allocation beyond what the file's real size allows (libFuzzer's
// -rss_limit_mb and -malloc_limit_mb catch the latter).
#include "bluenoise_volume.h"

#include "vtkImageData.h"
#include "vtkObject.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <unistd.h>

namespace
{
const char* const Suffixes[] = { ".vti", ".nii", ".nii.gz", ".nrrd", ".nhdr", ".mhd", ".mha" };

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
  for (const char* suffix : Suffixes)
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
