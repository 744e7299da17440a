// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_raw_reader.h.
#include "bluenoise_raw_reader.h"

#include "vtkByteSwap.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <istream>

namespace
{
class RawImageReader : public vtkImageReader2
{
public:
  static RawImageReader* New();
  vtkTypeMacro(RawImageReader, vtkImageReader2);

protected:
  RawImageReader() = default;
  ~RawImageReader() override = default;

  void ExecuteDataWithInformation(vtkDataObject* output, vtkInformation* outInfo) override
  {
    int extent[6];
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
    if (this->SpansLayers(extent))
    {
      this->ReadLayers(this->AllocateOutputData(output, outInfo));
    }
    else
    {
      this->Superclass::ExecuteDataWithInformation(output, outInfo);
    }
    auto* image = vtkImageData::SafeDownCast(output);
    if (image && image->GetPointData()->GetScalars())
    {
      image->GetPointData()->GetScalars()->SetName("MetaImage");
    }
  }

private:
  // Whether `extent` is whole layers of the volume, which lie one after the
  // other in a 3D file stored bottom row first.
  bool SpansLayers(const int extent[6]) const
  {
    return this->FileDimensionality == 3 && this->FileLowerLeft &&
      extent[0] == this->DataExtent[0] && extent[1] == this->DataExtent[1] &&
      extent[2] == this->DataExtent[2] && extent[3] == this->DataExtent[3] &&
      extent[4] >= this->DataExtent[4] && extent[5] <= this->DataExtent[5] &&
      extent[4] <= extent[5];
  }

  void ReadLayers(vtkImageData* data)
  {
    if (!this->FileName)
    {
      vtkErrorMacro("No file name.");
      return;
    }
    this->ComputeDataIncrements(); // DataIncrements[2]: the bytes of a layer
    const int* extent = data->GetExtent();
    const size_t layer = this->DataIncrements[2];
    const size_t bytes = layer * static_cast<size_t>(extent[5] - extent[4] + 1);
    this->ComputeInternalFileName(0);
    if (!this->OpenFile())
    {
      return; // OpenFile reports the error
    }
    this->File->seekg(static_cast<std::streamoff>(this->GetHeaderSize() +
      layer * static_cast<size_t>(extent[4] - this->DataExtent[4])));
    char* out = static_cast<char*>(data->GetScalarPointer());
    const size_t chunk = size_t(64) << 20; // for progress and abort
    for (size_t done = 0; done < bytes && !this->AbortExecute;)
    {
      const size_t n = std::min(chunk, bytes - done);
      if (!this->File->read(out + done, static_cast<std::streamsize>(n)))
      {
        vtkErrorMacro("Reading " << this->InternalFileName << " failed at byte "
                                 << done << " of the layers " << extent[4] << " to "
                                 << extent[5] << ".");
        this->CloseFile();
        return;
      }
      done += n;
      this->UpdateProgress(static_cast<double>(done) / static_cast<double>(bytes));
    }
    this->CloseFile();
    const int size = vtkDataArray::GetDataTypeSize(this->DataScalarType);
    if (this->GetSwapBytes() && size > 1)
    {
      vtkByteSwap::SwapVoidRange(out, bytes / size, size);
    }
  }

  RawImageReader(const RawImageReader&) = delete;
  void operator=(const RawImageReader&) = delete;
};
vtkStandardNewMacro(RawImageReader);
}

namespace bluenoise
{
vtkSmartPointer<vtkImageReader2> NewRawImageReader()
{
  return vtkSmartPointer<RawImageReader>::New();
}
}
