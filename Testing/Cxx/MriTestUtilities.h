// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The real volume of the sampler tests: ch2bet.nii.gz from Debian's
// mricron-data (or the file given as the first argument). Tests that use it
// link VTK::IOImage and VTK::vtksys and skip (exit code 125) without it.
#ifndef MriTestUtilities_h
#define MriTestUtilities_h

#include "vtkImageData.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtksys/SystemTools.hxx"

#include <iostream>
#include <string>

namespace bluenoise_test
{
constexpr int SkipReturnCode = 125;

// The MRI volume, read; nullptr (after printing SKIP) when the file is missing.
inline vtkSmartPointer<vtkImageData> ReadMri(int argc, char* argv[])
{
  const std::string path = argc > 1 ? argv[1] : "/usr/share/mricron/templates/ch2bet.nii.gz";
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    std::cout << "SKIP: " << path << " not found (install Debian's mricron-data)" << std::endl;
    return nullptr;
  }
  vtkNew<vtkNIFTIImageReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkImageData> image = reader->GetOutput();
  return image;
}
}

#endif
