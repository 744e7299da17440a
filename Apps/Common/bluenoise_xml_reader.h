// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Reading VTK XML image files (.vti) for the main job (bluenoise-sample).
//
// VTK's XML parser (VTK < 9.3.1) stops feeding Expat at the <AppendedData>
// tag and waits for Expat to report that tag before it reads the appended
// bytes itself. Expat 2.6.0 (and Debian bookworm's expat 2.5.0-1+deb12u1 and
// later, which back-port it) defers parsing of an incomplete-looking last
// token ("reparse deferral"), so the tag is never reported and every file with
// appended data fails with "not well-formed (invalid token)" (raw data) or
// "junk after document element" (base64), in ParaView too. The reader made
// here turns reparse deferral off for its parser when the Expat that VTK uses
// has the switch; otherwise it is a plain vtkXMLImageDataReader.
#ifndef bluenoise_xml_reader_h
#define bluenoise_xml_reader_h

#include "vtkSmartPointer.h"
#include "vtkXMLImageDataReader.h"

namespace bluenoise
{
vtkSmartPointer<vtkXMLImageDataReader> NewXMLImageDataReader();
}

#endif
