// bluenoise-sample: the project's main job. Samples a volume by importance
// with vtkErrorDiffusionSampler and writes the points as a .vtp.
//
//   bluenoise-sample [VOLUME] [--output DIR] [--points N | --scale S]
//                    [--array NAME] [--seed K] [--parameters paper|fixed|FILE]
//
// VOLUME: .vti, .nii / .nii.gz, .nrrd / .nhdr or .mhd / .mha. Without one, the
// MRI brain ch2bet.nii.gz of Debian's mricron-data is used when installed,
// else the small volume shipped in Data/.
#include "vtkErrorDiffusionSampler.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkXMLImageDataReader.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#ifndef BLUENOISE_DATA_DIR
#define BLUENOISE_DATA_DIR ""
#endif

namespace
{
const char* const DefaultVolume = "/usr/share/mricron/templates/ch2bet.nii.gz";

void Usage(std::ostream& os)
{
  os << "usage: bluenoise-sample [VOLUME] [--output DIR] [--points N | --scale S]\n"
        "                        [--array NAME] [--seed K] [--parameters paper|fixed|FILE]\n"
        "  VOLUME        .vti, .nii(.gz), .nrrd/.nhdr or .mhd/.mha (default: the MRI brain\n"
        "                " << DefaultVolume << ",\n"
        "                else Data/brain-small.vti)\n"
        "  --output DIR  where to write samples.vtp (default: bluenoise-output)\n"
        "  --points N    expected number of points (default 100000)\n"
        "  --scale S     DensityScale instead of --points\n"
        "  --array NAME  point array to sample by (default: the active scalars)\n"
        "  --seed K      seed of the threshold noise (default 0)\n";
}

bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
    vtksys::SystemTools::LowerCase(s.substr(s.size() - suffix.size())) == suffix;
}

// Sum over the voxels of the density the sampler will use (scalar-range
// mapping of component 0, times `scale`, clamped to [0, 1]).
double ExpectedCount(vtkDataArray* scalars, double scale)
{
  double range[2];
  scalars->GetFiniteRange(range, 0);
  const double inverseWidth = range[1] > range[0] ? 1.0 / (range[1] - range[0]) : 1.0;
  double sum = 0.0;
  const vtkIdType n = scalars->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double g = scale * (scalars->GetComponent(i, 0) - range[0]) * inverseWidth;
    sum += g > 0.0 ? std::min(g, 1.0) : 0.0;
  }
  return sum;
}

vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, std::string& error)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  if (EndsWith(path, ".vti"))
  {
    auto r = vtkSmartPointer<vtkXMLImageDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (EndsWith(path, ".nii") || EndsWith(path, ".nii.gz") || EndsWith(path, ".hdr"))
  {
    auto r = vtkSmartPointer<vtkNIFTIImageReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (EndsWith(path, ".nrrd") || EndsWith(path, ".nhdr"))
  {
    auto r = vtkSmartPointer<vtkNrrdReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (EndsWith(path, ".mhd") || EndsWith(path, ".mha"))
  {
    auto r = vtkSmartPointer<vtkMetaImageReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else
  {
    error = "unknown volume format (expected .vti, .nii, .nii.gz, .nrrd, .nhdr, .mhd, .mha): " + path;
    return nullptr;
  }
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    error = "no such file: " + path;
    return nullptr;
  }
  reader->Update();
  auto image = vtkImageData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!image || image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetNumberOfArrays())
  {
    error = "could not read a volume with point data from " + path;
    return nullptr;
  }
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->ShallowCopy(image);
  return copy;
}
}

int main(int argc, char* argv[])
{
  std::string volume;
  std::string outputDir = "bluenoise-output";
  std::string arrayName;
  std::string parameters = "paper";
  double points = 100000.0;
  double scale = -1.0;
  int seed = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    auto value = [&](const char* flag) -> std::string {
      if (i + 1 >= argc)
      {
        std::cerr << "bluenoise-sample: " << flag << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help")
    {
      Usage(std::cout);
      return 0;
    }
    else if (arg == "--output")
    {
      outputDir = value("--output");
    }
    else if (arg == "--points")
    {
      points = std::atof(value("--points").c_str());
    }
    else if (arg == "--scale")
    {
      scale = std::atof(value("--scale").c_str());
    }
    else if (arg == "--array")
    {
      arrayName = value("--array");
    }
    else if (arg == "--seed")
    {
      seed = std::atoi(value("--seed").c_str());
    }
    else if (arg == "--parameters")
    {
      parameters = value("--parameters");
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      std::cerr << "bluenoise-sample: unknown option " << arg << "\n";
      Usage(std::cerr);
      return 2;
    }
    else
    {
      volume = arg;
    }
  }
  if (volume.empty())
  {
    volume = vtksys::SystemTools::FileExists(DefaultVolume, true)
      ? DefaultVolume
      : std::string(BLUENOISE_DATA_DIR) + "/brain-small.vti";
  }
  if (!(points > 0.0) && !(scale >= 0.0))
  {
    std::cerr << "bluenoise-sample: --points must be > 0\n";
    return 2;
  }

  std::string error;
  auto image = ReadVolume(volume, error);
  if (!image)
  {
    std::cerr << "bluenoise-sample: " << error << "\n";
    return 1;
  }

  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(image);
  if (!arrayName.empty())
  {
    if (!image->GetPointData()->GetArray(arrayName.c_str()))
    {
      std::cerr << "bluenoise-sample: no point array '" << arrayName << "' in " << volume << "\n";
      return 1;
    }
    sampler->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, arrayName.c_str());
  }
  else if (!image->GetPointData()->GetScalars())
  {
    image->GetPointData()->SetActiveScalars(image->GetPointData()->GetArrayName(0));
  }
  sampler->SetDensityMappingToScalarRange();
  sampler->SetSeed(seed);
  if (parameters == "fixed")
  {
    sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_FIXED);
  }
  else if (parameters != "paper")
  {
    sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_CUSTOM);
    sampler->SetParameterFile(parameters.c_str());
  }

  // The expected count is the sum of the mapped densities; choose the scale
  // that makes it `points` (the clamp at 1 can only lower it, so refine).
  vtkDataArray* scalars = arrayName.empty() ? image->GetPointData()->GetScalars()
                                            : image->GetPointData()->GetArray(arrayName.c_str());
  if (scale < 0.0)
  {
    scale = 1.0;
    for (int iteration = 0; iteration < 8; ++iteration)
    {
      const double sum = ExpectedCount(scalars, scale);
      if (!(sum > 0.0))
      {
        break;
      }
      scale *= points / sum;
    }
  }
  sampler->SetDensityScale(scale);
  const double expected = ExpectedCount(scalars, scale);

  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  sampler->Update();
  timer->StopTimer();
  vtkPolyData* samples = sampler->GetOutput();
  if (samples->GetNumberOfPoints() == 0)
  {
    std::cerr << "bluenoise-sample: no samples were drawn from " << volume << "\n";
    return 1;
  }

  vtksys::SystemTools::MakeDirectory(outputDir);
  const std::string vtp = outputDir + "/samples.vtp";
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(samples);
  writer->SetFileName(vtp.c_str());
  writer->SetDataModeToAppended();
  writer->SetCompressorTypeToZLib();
  if (!writer->Write())
  {
    std::cerr << "bluenoise-sample: cannot write " << vtp << "\n";
    return 1;
  }

  std::cout << "input: " << volume << "\n";
  std::cout << "points: " << vtp << "\n";
  std::cout << "voxels=" << image->GetNumberOfPoints() << " points=" << samples->GetNumberOfPoints()
            << " expected=" << static_cast<long long>(std::llround(expected))
            << " seconds=" << timer->GetElapsedTime() << std::endl;
  return 0;
}
