// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Reading the raw data of a MetaImage (the layout parsed from its header) for
// the main job (bluenoise-sample).
//
// vtkImageReader, which VTK offers for raw data, copies what it reads byte by
// byte, and vtkImageReader2 seeks and reads row by row. A streamed volume is
// read twice (the statistics of the densities, then the sampling), in z-slabs
// that span whole layers: the reader made here reads such an extent (and the
// whole volume) with one seek and large reads straight into the output, any
// other extent as vtkImageReader2 does. It is a vtkImageReader2 otherwise
// (set it up the same way), and names its scalars "MetaImage", as
// vtkMetaImageReader does.
#ifndef bluenoise_raw_reader_h
#define bluenoise_raw_reader_h

#include "vtkImageReader2.h"
#include "vtkSmartPointer.h"

namespace bluenoise
{
vtkSmartPointer<vtkImageReader2> NewRawImageReader();
}

#endif
