// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// bluenoise-sample: the project's main job. Samples a volume by importance
// with vtkErrorDiffusionSampler and writes the points as a .vtp, the blue-noise
// spectrum of a uniform-density run with the same number of points and
// parameters (vtkBlueNoiseSpectrum) as CSV, and two pictures: the points
// rendered off screen and the spectrum plotted (see --help).
//
//   bluenoise-sample [VOLUME] [--output DIR] [--points N | --scale S]
//                    [--array NAME] [--seed K] [--parameters paper|fixed|optimized|FILE]
//                    [--spectrum-grid L] [--no-pictures]
//
// VOLUME: .vti, .nii / .nii.gz, .nrrd / .nhdr or .mhd / .mha. Without one, the
// MRI brain ch2bet.nii.gz of Debian's mricron-data is used when installed,
// else the small volume shipped in Data/.
#include "bluenoise_pictures.h"
#include "bluenoise_xml_reader.h"
#include "vtkBlueNoiseSpectrum.h"
#include "vtkErrorDiffusionSampler.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkImageReader2.h"
#include "vtkMetaImageReader.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkNrrdReader.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkTimerLog.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#ifndef BLUENOISE_DATA_DIR
#define BLUENOISE_DATA_DIR ""
#endif

namespace
{
const char* const DefaultVolume = "/usr/share/mricron/templates/ch2bet.nii.gz";

const int DefaultSpectrumGrid = 128;

void Usage(std::ostream& os)
{
  os << "usage: bluenoise-sample [VOLUME] [--output DIR] [--points N | --scale S]\n"
        "                        [--array NAME] [--seed K] [--parameters paper|fixed|optimized|FILE]\n"
        "                        [--spectrum-grid L] [--no-pictures]\n"
        "  VOLUME        .vti, .nii(.gz), .nrrd/.nhdr or .mhd/.mha (default: the MRI brain\n"
        "                " << DefaultVolume << ",\n"
        "                else Data/brain-small.vti)\n"
        "  --output DIR  where to write the files below (default: bluenoise-output)\n"
        "  --points N    expected number of points (default 100000)\n"
        "  --scale S     DensityScale instead of --points\n"
        "  --array NAME  point array to sample by (default: the active scalars)\n"
        "  --seed K      seed of the threshold noise (default 0)\n"
        "  --parameters  diffusion parameters: paper (Table 1, default), fixed, optimized,\n"
        "                or a parameter table file\n"
        "  --spectrum-grid L\n"
        "                edge of the cubic grid of the uniform-density run (default "
     << DefaultSpectrumGrid << ")\n"
        "  --no-pictures skip samples.png and spectrum.png (no display or OpenGL needed)\n"
        "\n"
        "The volume's array is mapped to a density by its scalar range, times the scale\n"
        "that makes the expected number of points N (the sum of the densities) equal to\n"
        "--points. Files written to DIR:\n"
        "  samples.vtp   the N points (vertices at voxel centres, every input array, Density)\n"
        "  spectrum.csv  vtkBlueNoiseSpectrum of a uniform-density run at the same point\n"
        "                count: a constant density g = n / L^3 (n: the points drawn above,\n"
        "                g clamped to (0, 0.5]) on an L^3 grid, L = --spectrum-grid (128:\n"
        "                the FFT takes a fraction of a second), sampled with the same seed\n"
        "                and parameters. Header line, then one row per radial shell:\n"
        "                Frequency (cycles per voxel), RadialPower, Anisotropy,\n"
        "                AnisotropyDB, SRAPS_XY, SRAPS_XZ, SRAPS_YZ, ShellCount\n"
        "  metrics.csv   the scalar metrics of that spectrum, one 'Metric,Value' row each:\n"
        "                NumberOfPoints, Density (g), PrincipalFrequency (f_g),\n"
        "                LowFrequencyRatio (L), SymmetryCorrelation, Symmetry (S),\n"
        "                TargetValue (T), Realisations, GridDimensions (space separated),\n"
        "                then the run's Seed and Parameters\n"
        "  samples.png   the points rendered off screen: all in 3D, and an axial and a\n"
        "                sagittal slab through the centre, coloured by the sampled array\n"
        "  spectrum.png  RadialPower and Anisotropy (dB) against Frequency, f_g marked\n"
        "The pictures need OpenGL through an X display: without DISPLAY run the program\n"
        "under xvfb-run -a (scripts/main.sh does), or pass --no-pictures. When they are\n"
        "asked for and rendering is impossible, the program stops with a message before\n"
        "sampling (exit status 1); should rendering fail later, the other files are\n"
        "still written and the exit status is 1.\n"
        "The last line printed is the summary\n"
        "  voxels=... points=... expected=... seconds=...\n"
        "(expected: the sum of the densities; seconds: the importance sampling alone).\n";
}

bool EndsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() &&
    vtksys::SystemTools::LowerCase(s.substr(s.size() - suffix.size())) == suffix;
}

// Sum over the voxels of the density the sampler will use (scalar-range
// mapping of component 0, times `scale`, clamped to [0, 1]); `occupied`, when
// given, receives the number of voxels of positive density.
double ExpectedCount(vtkDataArray* scalars, double scale, vtkIdType* occupied = nullptr)
{
  vtkIdType positive = 0;
  double range[2];
  scalars->GetFiniteRange(range, 0);
  const double inverseWidth = range[1] > range[0] ? 1.0 / (range[1] - range[0]) : 1.0;
  double sum = 0.0;
  const vtkIdType n = scalars->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double g = scale * (scalars->GetComponent(i, 0) - range[0]) * inverseWidth;
    sum += g > 0.0 ? std::min(g, 1.0) : 0.0;
    positive += g > 0.0 ? 1 : 0;
  }
  if (occupied)
  {
    *occupied = positive;
  }
  return sum;
}

vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, std::string& error)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  if (EndsWith(path, ".vti"))
  {
    auto r = bluenoise::NewXMLImageDataReader();
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

// The parameter set of --parameters (paper, fixed, optimized, or a file).
void SetParameters(vtkErrorDiffusionSampler* sampler, const std::string& parameters)
{
  if (parameters == "fixed")
  {
    sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_FIXED);
  }
  else if (parameters == "optimized")
  {
    sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_OPTIMIZED);
  }
  else if (parameters != "paper")
  {
    sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_CUSTOM);
    sampler->SetParameterFile(parameters.c_str());
  }
}

// The spectrum of a uniform-density run: a constant density g = points / L^3
// (clamped to (0, 0.5]) on an L^3 grid, sampled like the volume (same seed,
// same parameters), then measured by vtkBlueNoiseSpectrum on the sampler's
// grid (its SamplingGrid field data).
vtkSmartPointer<vtkTable> UniformSpectrum(
  vtkIdType points, int edge, int seed, const std::string& parameters, double& density)
{
  const double voxels = static_cast<double>(edge) * edge * edge;
  density = std::min(std::max(static_cast<double>(points) / voxels, 1.0 / voxels), 0.5);
  auto cube = vtkSmartPointer<vtkImageData>::New();
  cube->SetDimensions(edge, edge, edge);
  vtkNew<vtkFloatArray> g;
  g->SetName("UniformDensity");
  g->SetNumberOfTuples(cube->GetNumberOfPoints());
  g->FillValue(static_cast<float>(density));
  cube->GetPointData()->SetScalars(g);

  vtkNew<vtkErrorDiffusionSampler> sampler;
  sampler->SetInputData(cube);
  sampler->SetDensityMappingToIdentity();
  sampler->SetSeed(seed);
  SetParameters(sampler, parameters);
  vtkNew<vtkBlueNoiseSpectrum> spectrum;
  spectrum->SetInputConnection(sampler->GetOutputPort());
  spectrum->GenerateSpectrumImageOff();
  spectrum->Update();
  auto table = vtkSmartPointer<vtkTable>::New();
  table->ShallowCopy(spectrum->GetOutput());
  return table;
}

std::string FormatNumber(vtkDataArray* array, vtkIdType tuple, int component)
{
  const double v = array->GetComponent(tuple, component);
  char buffer[64];
  if (array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE)
  {
    std::snprintf(buffer, sizeof(buffer), "%lld", static_cast<long long>(std::llround(v)));
  }
  else
  {
    std::snprintf(buffer, sizeof(buffer), "%.12g", v);
  }
  return buffer;
}

// Every column of the spectrum table, a header line, one row per shell.
bool WriteSpectrumCSV(vtkTable* table, const std::string& path)
{
  std::ofstream out(path);
  std::vector<vtkDataArray*> columns;
  for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
  {
    auto column = vtkDataArray::SafeDownCast(table->GetColumn(c));
    if (column && column->GetName())
    {
      out << (columns.empty() ? "" : ",") << column->GetName();
      columns.push_back(column);
    }
  }
  out << "\n";
  for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
  {
    for (size_t c = 0; c < columns.size(); ++c)
    {
      out << (c ? "," : "") << FormatNumber(columns[c], r, 0);
    }
    out << "\n";
  }
  out.close();
  return static_cast<bool>(out);
}

// The scalar metrics (the table's field data), one `Metric,Value` row each;
// several components are written space separated.
bool WriteMetricsCSV(
  vtkTable* table, int seed, const std::string& parameters, const std::string& path)
{
  std::ofstream out(path);
  out << "Metric,Value\n";
  vtkFieldData* fd = table->GetFieldData();
  for (int a = 0; a < fd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = fd->GetArray(a);
    if (!array || !array->GetName() || array->GetNumberOfTuples() < 1)
    {
      continue;
    }
    out << array->GetName() << ",";
    for (int c = 0; c < array->GetNumberOfComponents(); ++c)
    {
      out << (c ? " " : "") << FormatNumber(array, 0, c);
    }
    out << "\n";
  }
  std::string quoted = parameters;
  if (quoted.find_first_of(",\"\n") != std::string::npos)
  {
    std::string escaped;
    for (char ch : quoted)
    {
      escaped += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    }
    quoted = "\"" + escaped + "\"";
  }
  out << "Seed," << seed << "\n";
  out << "Parameters," << quoted << "\n";
  out.close();
  return static_cast<bool>(out);
}

std::string FileName(const std::string& path)
{
  return vtksys::SystemTools::GetFilenameName(path);
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
  int spectrumGrid = DefaultSpectrumGrid;
  bool pictures = true;
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
    else if (arg == "--spectrum-grid")
    {
      spectrumGrid = std::atoi(value("--spectrum-grid").c_str());
    }
    else if (arg == "--no-pictures")
    {
      pictures = false;
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
  if (spectrumGrid < 8 || spectrumGrid > 512)
  {
    std::cerr << "bluenoise-sample: --spectrum-grid must be in [8, 512]\n";
    return 2;
  }

  // Fail before the work, not after it, when the pictures cannot be made.
  bluenoise::PictureSession session;
  if (pictures)
  {
    std::string why;
    if (!session.Start(why))
    {
      std::cerr << "bluenoise-sample: cannot render the pictures: " << why << "\n";
      return 1;
    }
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
  SetParameters(sampler, parameters);

  // The point budget (the module solves the density scale), or a scale.
  vtkDataArray* scalars = arrayName.empty() ? image->GetPointData()->GetScalars()
                                            : image->GetPointData()->GetArray(arrayName.c_str());
  if (scale >= 0.0)
  {
    sampler->UseNumberOfPointsOff();
    sampler->SetDensityScale(scale);
  }
  else
  {
    sampler->SetNumberOfPoints(static_cast<vtkIdType>(std::llround(points)));
  }
  vtkIdType occupied = 0;
  ExpectedCount(scalars, 1.0, &occupied);

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
  // Inline binary (base64, compressed), not appended: appended data cannot be
  // read by VTK < 9.3.1 with Expat >= 2.6.0, e.g. Debian's ParaView 5.11 (see
  // bluenoise_xml_reader.h), whereas inline data is plain XML every VTK reads.
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToZLib();
  if (!writer->Write())
  {
    std::cerr << "bluenoise-sample: cannot write " << vtp << "\n";
    return 1;
  }
  std::cout << "input: " << volume << "\n";
  std::cout << "points: " << vtp << "\n";

  // The spectrum of a uniform-density run at the same number of points.
  double uniformDensity = 0.0;
  auto spectrum =
    UniformSpectrum(samples->GetNumberOfPoints(), spectrumGrid, seed, parameters, uniformDensity);
  if (spectrum->GetNumberOfRows() == 0)
  {
    std::cerr << "bluenoise-sample: the spectrum of the uniform-density run failed\n";
    return 1;
  }
  const std::string csv = outputDir + "/spectrum.csv";
  const std::string metrics = outputDir + "/metrics.csv";
  if (!WriteSpectrumCSV(spectrum, csv) || !WriteMetricsCSV(spectrum, seed, parameters, metrics))
  {
    std::cerr << "bluenoise-sample: cannot write " << csv << " or " << metrics << "\n";
    return 1;
  }
  std::cout << "spectrum: " << csv << " (uniform density g=" << uniformDensity << " on "
            << spectrumGrid << "^3 voxels)\n";
  std::cout << "metrics: " << metrics << "\n";

  int status = 0;
  if (pictures)
  {
    const std::string samplesPng = outputDir + "/samples.png";
    const std::string spectrumPng = outputDir + "/spectrum.png";
    bluenoise::SamplesPicture picture;
    picture.ColorArray = scalars->GetName() ? scalars->GetName() : "";
    picture.Caption = FileName(volume);
    // About one mean point spacing: (occupied volume / points)^(1/3).
    double spacing[3];
    image->GetSpacing(spacing);
    const double voxelVolume = std::abs(spacing[0] * spacing[1] * spacing[2]);
    picture.SlabThickness =
      std::max(std::cbrt(voxelVolume * static_cast<double>(occupied) /
                 static_cast<double>(samples->GetNumberOfPoints())),
        std::max({ std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2]) }));
    bluenoise::SpectrumPlot plot;
    char title[256];
    std::snprintf(title, sizeof(title), "Spectrum of a uniform-density run: g = %.4g on %d^3 voxels, %lld points, seed %d, %s parameters",
      uniformDensity, spectrumGrid,
      static_cast<long long>(spectrum->GetFieldData()->GetArray("NumberOfPoints")
          ? std::llround(spectrum->GetFieldData()->GetArray("NumberOfPoints")->GetComponent(0, 0))
          : 0),
      seed, parameters == "paper" || parameters == "fixed" || parameters == "optimized" ? parameters.c_str() : "custom");
    plot.Title = title;
    if (bluenoise::WriteSamplesPicture(session, samples, picture, samplesPng, error))
    {
      std::cout << "picture: " << samplesPng << "\n";
    }
    else
    {
      std::cerr << "bluenoise-sample: samples.png: " << error << "\n";
      status = 1;
    }
    if (bluenoise::WriteSpectrumPlot(session, spectrum, plot, spectrumPng, error))
    {
      std::cout << "plot: " << spectrumPng << "\n";
    }
    else
    {
      std::cerr << "bluenoise-sample: spectrum.png: " << error << "\n";
      status = 1;
    }
  }

  const double expected =
    samples->GetFieldData()->GetArray("ExpectedNumberOfPoints")->GetComponent(0, 0);
  std::cout << "voxels=" << image->GetNumberOfPoints() << " points=" << samples->GetNumberOfPoints()
            << " expected=" << static_cast<long long>(std::llround(expected))
            << " seconds=" << timer->GetElapsedTime() << std::endl;
  return status;
}
