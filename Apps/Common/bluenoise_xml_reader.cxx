// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_xml_reader.h.
#include "bluenoise_xml_reader.h"

#include "vtkObjectFactory.h"
#include "vtkXMLDataParser.h"
#include "vtk_expat.h"

// Only the system Expat can be switched from here (a VTK-built Expat has
// mangled names and predates reparse deferral). The function is declared weak
// so that an Expat without it (older than 2.6.0, not patched) leaves it null.
#if VTK_MODULE_USE_EXTERNAL_vtkexpat && defined(__GNUC__)
#define BLUENOISE_SWITCH_REPARSE_DEFERRAL 1
extern "C" __attribute__((weak)) XML_Bool XML_SetReparseDeferralEnabled(
  XML_Parser parser, XML_Bool enabled);
#endif

namespace
{
class DataParserWithoutDeferral : public vtkXMLDataParser
{
public:
  static DataParserWithoutDeferral* New();
  vtkTypeMacro(DataParserWithoutDeferral, vtkXMLDataParser);

protected:
  DataParserWithoutDeferral() = default;
  ~DataParserWithoutDeferral() override = default;

  // Called by Parse() once the Expat parser exists, before any input is fed.
  int ParseXML() override
  {
#ifdef BLUENOISE_SWITCH_REPARSE_DEFERRAL
    if (this->Parser && XML_SetReparseDeferralEnabled)
    {
      XML_SetReparseDeferralEnabled(static_cast<XML_Parser>(this->Parser), XML_FALSE);
    }
#endif
    return this->Superclass::ParseXML();
  }

private:
  DataParserWithoutDeferral(const DataParserWithoutDeferral&) = delete;
  void operator=(const DataParserWithoutDeferral&) = delete;
};
vtkStandardNewMacro(DataParserWithoutDeferral);

class ImageReaderWithoutDeferral : public vtkXMLImageDataReader
{
public:
  static ImageReaderWithoutDeferral* New();
  vtkTypeMacro(ImageReaderWithoutDeferral, vtkXMLImageDataReader);

protected:
  ImageReaderWithoutDeferral() = default;
  ~ImageReaderWithoutDeferral() override = default;

  void CreateXMLParser() override
  {
    if (this->XMLParser)
    {
      this->DestroyXMLParser();
    }
    this->XMLParser = DataParserWithoutDeferral::New();
  }

private:
  ImageReaderWithoutDeferral(const ImageReaderWithoutDeferral&) = delete;
  void operator=(const ImageReaderWithoutDeferral&) = delete;
};
vtkStandardNewMacro(ImageReaderWithoutDeferral);
}

namespace bluenoise
{
vtkSmartPointer<vtkXMLImageDataReader> NewXMLImageDataReader()
{
  return vtkSmartPointer<ImageReaderWithoutDeferral>::New();
}
}
