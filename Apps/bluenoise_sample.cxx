// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// bluenoise-sample: the project's main job. Samples a volume by importance
// with vtkErrorDiffusionSampler and writes the points (.vtp, .csv or .ply),
// the blue-noise spectrum of a uniform-density run with the same number of
// points, method and parameters (vtkBlueNoiseSpectrum) as CSV, and two pictures: the
// points rendered off screen and the spectrum plotted (see --help).
//
// The steps, in order: options; the input checked (its header against the
// file, the parameter file); the output folder proven writable; the display;
// the volume read (or, for readers that read sub-extents, streamed in
// z-slabs by the sampler); sampling; the spectrum; every file written under a
// temporary name, and all renamed at the end, so a failed run leaves an
// existing output folder as it was.
#include "bluenoise_messages.h"
#include "bluenoise_options.h"
#include "bluenoise_output.h"
#include "bluenoise_pictures.h"
#include "bluenoise_sampler_choices.h"
#include "bluenoise_volume.h"
#include "vtkBlueNoiseSpectrum.h"
#include "vtkBlueNoiseThreads.h"
#include "vtkErrorDiffusionParameterTable.h"
#include "vtkErrorDiffusionSampler.h"

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkTimerLog.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#ifndef BLUENOISE_DATA_DIR
#define BLUENOISE_DATA_DIR ""
#endif

namespace
{
const char* const Program = "bluenoise-sample";
const char* const DefaultVolume = "/usr/share/mricron/templates/ch2bet.nii.gz";

struct Settings
{
  std::string Volume;
  std::string OutputDir = "bluenoise-output";
  std::string SamplesName = "samples.vtp";
  std::string ArrayName;
  // vtkErrorDiffusionSampler's own defaults (Method, ParameterSet), by name.
  std::string Method = bluenoise::DefaultMethodName();
  std::string Parameters = bluenoise::DefaultParameterSetName();
  long long Points = 100000;
  double Scale = -1.0; // unset: the budget --points
  int Seed = 0;
  int SpectrumGrid = 128;
  double SlabMegabytes = 64.0;
  bool NoPictures = false;
  bool VoxelSpace = false;
};

// What one sampling run produced.
struct Run
{
  vtkSmartPointer<vtkPolyData> Samples;
  vtkSmartPointer<vtkTable> Spectrum;
  double UniformDensity = 0.0;
  double Seconds = 0.0;
  int Slabs = 1;
};

const char* const Footer =
  "The volume's array is mapped to a density by its scalar range, times the scale\n"
  "that makes the expected number of points (the sum of the densities) --points;\n"
  "the sampler solves it (a budget above what the volume holds is reported). Files\n"
  "written to DIR, all at the end (a failed run leaves DIR as it was):\n"
  "  samples.vtp   the points (vertices at voxel centers, every input array, Density);\n"
  "                --samples NAME.csv or NAME.ply writes CSV or binary PLY instead\n"
  "  spectrum.csv  vtkBlueNoiseSpectrum of a uniform-density run at the same point\n"
  "                count: a constant density g = n / L^3 (n: the points drawn above,\n"
  "                g clamped to (0, 0.5]) on an L^3 grid, L = --spectrum-grid, sampled\n"
  "                with the same seed and parameters. Header line, then one row per\n"
  "                radial shell: Frequency (cycles per voxel), RadialPower, Anisotropy,\n"
  "                AnisotropyDB, SRAPS_XY, SRAPS_XZ, SRAPS_YZ, ShellCount\n"
  "  metrics.csv   the scalar metrics of that spectrum, one 'Metric,Value' row each:\n"
  "                NumberOfPoints, Density (g), PrincipalFrequency (f_g),\n"
  "                LowFrequencyRatio (L), SymmetryCorrelation, Symmetry (S),\n"
  "                TargetValue (T), Realizations, GridDimensions (space separated),\n"
  "                then the run's Seed, Method and Parameters\n"
  "  samples.png   the points rendered off screen: all in 3D, and an axial and a\n"
  "                sagittal slab through the center, colored by the sampled array\n"
  "  spectrum.png  RadialPower and Anisotropy (dB) against Frequency, f_g marked;\n"
  "                the title names the method and parameters used\n"
  "Methods and parameter sets are those of vtkErrorDiffusionSampler and the\n"
  "ParaView panel (Method, Parameter Set), with the same defaults; the\n"
  "parameters are those of the error diffusion (the two error-diffusion methods).\n"
  "Frames: NIfTI volumes are sampled in the file's world frame (sform, else qform;\n"
  "millimetres) unless --voxel-space; other formats in their origin and spacing.\n"
  "Streaming: raw MetaImage, raw NRRD and VTI with raw appended data are read in\n"
  "z-slabs of about --slab-size MiB, so memory is one slab plus the points; NIfTI,\n"
  "compressed and ASCII files are read whole. A volume of several z-parts (64\n"
  "layers and 2^22 voxels at least, sampled side by side) gets slabs of one part per\n"
  "thread at least (VTK_SMP_MAX_THREADS caps the threads, hence the slabs).\n"
  "The pictures need OpenGL through an X display: without DISPLAY run the program\n"
  "under xvfb-run -a (scripts/main.sh does), or pass --no-pictures.\n"
  "Every failure exits with status 1 (2 for a bad option) and a message.\n"
  "The last line printed is the summary\n"
  "  voxels=... points=... expected=... seconds=... frame=...\n"
  "(expected: the sum of the densities; seconds: the importance sampling, with the\n"
  "reading of the slabs when streamed;\n"
  "frame: sform, qform, voxel or file).";

int ParseOptions(int argc, char* argv[], Settings& s)
{
  bluenoise::CommandLine cli(Program, "Blue-noise importance sampling of a volume (the main job).");
  const std::string defaultVolume = std::string("volume to sample: ") +
    bluenoise::VolumeSuffixes() + " (default: " + DefaultVolume + " when installed, else " +
    "Data/brain-small.vti)";
  cli.AddPositional("volume", s.Volume, defaultVolume);
  cli.AddText("--output", s.OutputDir, "DIR", "output folder");
  cli.AddText("--samples", s.SamplesName, "NAME", "file name of the points in the output folder; "
                                          "its extension (.vtp, .csv, .ply) chooses the format");
  cli.AddInteger("--points", s.Points, 1, 1000000000000LL, "expected number of points");
  cli.AddReal("--scale", s.Scale, 0.0, 1.0e6, "DensityScale instead of --points");
  cli.Exclude("--points", "--scale");
  cli.AddText("--array", s.ArrayName, "NAME", "point array to sample by (default: the active scalars, "
                                      "else the first array)");
  cli.AddInteger("--seed", s.Seed, 0, 2147483647, "seed of the threshold noise");
  std::vector<std::string> methods;
  for (const auto& method : bluenoise::SamplerMethods())
  {
    methods.push_back(method.Name);
  }
  cli.AddChoice("--method", s.Method, methods, "sampling method");
  cli.AddText("--parameters", s.Parameters, "SET|FILE",
    "diffusion parameters: " + bluenoise::ChoiceNames(bluenoise::SamplerParameterSets()) +
      " (paper: Table 1), or a parameter table file");
  cli.AddInteger("--spectrum-grid", s.SpectrumGrid, 8, 512,
    "edge L of the cubic grid of the uniform-density run");
  cli.AddReal("--slab-size", s.SlabMegabytes, 0.0, 1.0e6,
    "MiB per z-slab when a volume is streamed", true);
  cli.AddFlag("--voxel-space", s.VoxelSpace, "NIfTI: sample in voxel space, not the world frame");
  cli.AddFlag("--no-pictures", s.NoPictures,
    "skip samples.png and spectrum.png (no display or OpenGL needed)");
  cli.SetFooter(Footer);
  const int status = cli.Parse(argc, argv);
  if (status < 0 && !bluenoise::IsPointFileName(s.SamplesName))
  {
    std::cerr << Program << ": --samples: '" << s.SamplesName
              << "' does not end in .vtp, .csv or .ply\n";
    return 2;
  }
  if (status < 0 && s.SamplesName.find('/') != std::string::npos)
  {
    std::cerr << Program << ": --samples: '" << s.SamplesName
              << "' must be a file name (it goes into --output)\n";
    return 2;
  }
  return status;
}

bool IsNamedSet(const std::string& parameters)
{
  bluenoise::SamplerChoice set;
  return bluenoise::FindChoice(bluenoise::SamplerParameterSets(), parameters, set);
}

bool IsDiffusion(const std::string& method)
{
  bluenoise::SamplerChoice choice;
  return bluenoise::FindChoice(bluenoise::SamplerMethods(), method, choice) &&
    vtkErrorDiffusionSampler::IsErrorDiffusion(choice.Value);
}

// The parameter file of --parameters, read once here so that a bad one
// stops the run before anything else.
bool CheckParameters(const std::string& parameters, std::string& error)
{
  if (IsNamedSet(parameters))
  {
    return true;
  }
  vtkErrorDiffusionParameterTable table;
  std::string why;
  if (!vtkErrorDiffusionParameterTable::ReadFile(parameters, table, why))
  {
    error = "--parameters: " + why;
    return false;
  }
  return true;
}

// The density array: --array, else the active scalars, else the first array;
// it must be numeric.
bool ChooseArray(vtkImageData* image, const std::string& requested, std::string& name,
  std::string& error)
{
  vtkPointData* pd = image->GetPointData();
  vtkAbstractArray* array = !requested.empty() ? pd->GetAbstractArray(requested.c_str())
    : pd->GetScalars()                         ? pd->GetScalars()
                                               : pd->GetAbstractArray(0);
  if (!array)
  {
    error = "no point array '" + requested + "'; the arrays are:";
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
    {
      const char* n = pd->GetArrayName(a);
      error += std::string(" '") + (n ? n : "") + "'";
    }
    return false;
  }
  const std::string shown = array->GetName() ? array->GetName() : "(unnamed)";
  if (!vtkDataArray::SafeDownCast(array))
  {
    error = "the point array '" + shown + "' is not numeric (" + array->GetClassName() +
      "); choose a numeric one with --array";
    return false;
  }
  name = array->GetName() ? array->GetName() : "";
  return true;
}

// --method and --parameters (a named set or a file), set explicitly even
// when they are the class's defaults.
void SetMethodAndParameters(
  vtkErrorDiffusionSampler* sampler, const std::string& method, const std::string& parameters)
{
  bluenoise::SamplerChoice choice;
  if (bluenoise::FindChoice(bluenoise::SamplerMethods(), method, choice))
  {
    sampler->SetMethod(choice.Value);
  }
  if (bluenoise::FindChoice(bluenoise::SamplerParameterSets(), parameters, choice))
  {
    sampler->SetParameterSet(choice.Value);
  }
  else
  {
    sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_CUSTOM);
    sampler->SetParameterFile(parameters.c_str());
  }
}

// The spectrum of a uniform-density run: a constant density g = points / L^3
// (clamped to (0, 0.5]) on an L^3 grid, sampled like the volume (same seed,
// method and parameters), then measured by vtkBlueNoiseSpectrum on the
// sampler's grid (its SamplingGrid field data).
vtkSmartPointer<vtkTable> UniformSpectrum(vtkIdType points, int edge, int seed,
  const std::string& method, const std::string& parameters, double& density, std::string& error)
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
  sampler->UseNumberOfPointsOff(); // the density is the value itself
  sampler->SetSeed(seed);
  SetMethodAndParameters(sampler, method, parameters);
  vtkNew<vtkBlueNoiseSpectrum> spectrum;
  spectrum->SetInputConnection(sampler->GetOutputPort());
  spectrum->GenerateSpectrumImageOff();
  bluenoise::VTKMessages samplerMessages, spectrumMessages;
  samplerMessages.Attach(sampler);
  spectrumMessages.Attach(spectrum);
  spectrum->Update();
  if (spectrum->GetOutput()->GetNumberOfRows() == 0)
  {
    const auto& errors =
      samplerMessages.Errors.empty() ? spectrumMessages.Errors : samplerMessages.Errors;
    error = "the spectrum of the uniform-density run (" + std::to_string(points) +
      " points) failed: " + (errors.empty() ? std::string("no rows") : errors.front());
    return nullptr;
  }
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
bool WriteMetricsCSV(vtkTable* table, int seed, const std::string& method,
  const std::string& parameters, const std::string& path)
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
  out << "Method," << method << "\n";
  out << "Parameters," << quoted << "\n";
  out.close();
  return static_cast<bool>(out);
}

// The z-slabs a streamed volume is sampled in (the sampler's method set):
// about --slab-size MiB each, and, where the volume has several z-parts, one
// part per thread at least, as the threads sample a slab's parts side by
// side. (A volume of one part is scanned beside its relaxation whatever its
// slabs.)
int SlabsOf(const bluenoise::Volume& volume, const Settings& s, vtkErrorDiffusionSampler* sampler)
{
  const double bytes = static_cast<double>(volume.Voxels) * volume.BytesPerVoxel;
  const int layers = volume.WholeExtent[5] - volume.WholeExtent[4] + 1;
  int slabs = static_cast<int>(std::min<double>(
    std::min(layers, 65536), std::max(1.0, std::ceil(bytes / (s.SlabMegabytes * 1048576.0)))));
  const int parts = sampler->GetNumberOfPartsFor(layers, volume.Voxels / layers);
  if (parts > 1)
  {
    const int threads = std::min(parts, vtkBlueNoiseThreads::Available());
    slabs = std::max(1, std::min(slabs, parts / threads));
  }
  return slabs;
}

// The sampler on the volume: read whole, or streamed in z-slabs (SlabsOf)
// from a reader that reads sub-extents.
bool Sample(const bluenoise::Volume& volume, const Settings& s, const std::string& arrayName,
  Run& run, std::string& error)
{
  vtkNew<vtkErrorDiffusionSampler> sampler;
  if (volume.Streamable())
  {
    sampler->SetInputConnection(volume.Reader->GetOutputPort());
  }
  else
  {
    sampler->SetInputData(volume.Image);
  }
  if (!arrayName.empty())
  {
    sampler->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, arrayName.c_str());
  }
  sampler->SetDensityMappingToScalarRange();
  sampler->SetSeed(s.Seed);
  SetMethodAndParameters(sampler, s.Method, s.Parameters);
  if (volume.Streamable())
  {
    run.Slabs = SlabsOf(volume, s, sampler);
    sampler->SetNumberOfSlabs(run.Slabs);
  }
  if (s.Scale >= 0.0)
  {
    sampler->UseNumberOfPointsOff();
    sampler->SetDensityScale(s.Scale);
  }
  else
  {
    sampler->SetNumberOfPoints(static_cast<vtkIdType>(s.Points));
  }
  bluenoise::VTKMessages messages;
  messages.Attach(sampler);
  if (volume.Reader)
  {
    messages.Attach(volume.Reader);
  }
  bluenoise::ProgressBar progress;
  progress.Attach(sampler, "sampling");
  vtkNew<vtkTimerLog> timer;
  try
  {
    if (volume.Streamable() && run.Slabs == 1)
    {
      volume.Reader->Update(); // read whole: the timer is for the sampling
    }
    timer->StartTimer();
    sampler->Update();
  }
  catch (const std::bad_alloc&)
  {
    messages.Errors.push_back("out of memory while sampling");
  }
  timer->StopTimer();
  run.Seconds = timer->GetElapsedTime();
  for (const std::string& warning : messages.Warnings)
  {
    std::cerr << Program << ": warning: " << warning << "\n";
  }
  run.Samples = sampler->GetOutput();
  if (!messages.Errors.empty() || run.Samples->GetNumberOfPoints() == 0)
  {
    error = volume.Path + ": " +
      (messages.Errors.empty() ? std::string("no samples were drawn (the density is zero everywhere)")
                               : messages.Errors.front());
    return false;
  }
  return true;
}

// The method and parameters of the run in words: "relaxed error diffusion,
// optimized parameters"; the parameters only for the error-diffusion methods,
// which use them.
std::string MethodLabel(const Settings& s)
{
  bluenoise::SamplerChoice choice;
  std::string label = bluenoise::FindChoice(bluenoise::SamplerMethods(), s.Method, choice)
    ? choice.Label
    : s.Method;
  if (!IsDiffusion(s.Method))
  {
    return label;
  }
  return label + ", " +
    (bluenoise::FindChoice(bluenoise::SamplerParameterSets(), s.Parameters, choice)
        ? std::string(choice.Label)
        : "parameters of " + vtksys::SystemTools::GetFilenameName(s.Parameters));
}

std::string SpectrumTitle(const Settings& s, const Run& run)
{
  vtkDataArray* count = run.Spectrum->GetFieldData()->GetArray("NumberOfPoints");
  char title[256];
  std::snprintf(title, sizeof(title),
    "Spectrum of a uniform-density run: g = %.4g on %d^3 voxels, %lld points, seed %d",
    run.UniformDensity, s.SpectrumGrid,
    static_cast<long long>(count ? std::llround(count->GetComponent(0, 0)) : 0), s.Seed);
  return title;
}

// samples.png and spectrum.png, to temporary names in the output folder.
bool WritePictures(const bluenoise::PictureSession& session, bluenoise::OutputFolder& output,
  const Settings& s, const Run& run, const std::string& colorArray, std::string& error)
{
  bluenoise::SamplesPicture picture;
  picture.ColorArray = colorArray;
  picture.Caption = vtksys::SystemTools::GetFilenameName(s.Volume);
  // About one mean point spacing, from the points' bounding box.
  double b[6];
  run.Samples->GetBounds(b);
  const double box = std::max(1e-300, (b[1] - b[0]) * (b[3] - b[2]) * (b[5] - b[4]));
  picture.SlabThickness =
    std::cbrt(box / static_cast<double>(run.Samples->GetNumberOfPoints()));
  if (!(picture.SlabThickness > 0.0))
  {
    picture.SlabThickness = 1.0;
  }
  bluenoise::SpectrumPlot plot;
  plot.Title = SpectrumTitle(s, run);
  plot.Subtitle = MethodLabel(s); // the method and parameters actually used
  std::string why;
  if (!bluenoise::WriteSamplesPicture(
        session, run.Samples, picture, output.Temporary("samples.png"), why))
  {
    error = "samples.png: " + why;
    return false;
  }
  if (!bluenoise::WriteSpectrumPlot(
        session, run.Spectrum, plot, output.Temporary("spectrum.png"), why))
  {
    error = "spectrum.png: " + why;
    return false;
  }
  return true;
}

// Every file under a temporary name; nothing is final until Commit().
bool WriteFiles(const bluenoise::PictureSession& session, bluenoise::OutputFolder& output,
  const Settings& s, const Run& run, const std::string& colorArray, std::string& error)
{
  if (!bluenoise::WritePoints(
        run.Samples, output.Temporary(s.SamplesName), s.SamplesName, error))
  {
    error = output.Final(s.SamplesName) + ": " + error;
    return false;
  }
  errno = 0;
  if (!WriteSpectrumCSV(run.Spectrum, output.Temporary("spectrum.csv")) ||
    !WriteMetricsCSV(
      run.Spectrum, s.Seed, s.Method, s.Parameters, output.Temporary("metrics.csv")))
  {
    error = "cannot write spectrum.csv or metrics.csv in " + s.OutputDir + ": " +
      (errno ? std::strerror(errno) : "write failed");
    return false;
  }
  return s.NoPictures || WritePictures(session, output, s, run, colorArray, error);
}

void PrintResults(const Settings& s, const bluenoise::OutputFolder& output,
  const bluenoise::Volume& volume, const Run& run)
{
  static const char* const frames[][2] = { { "sform", "the NIfTI sform (world, millimetres)" },
    { "qform", "the NIfTI qform (world, millimetres)" },
    { "voxel", "voxel space (origin 0, spacing from the header)" },
    { "file", "the file's origin and spacing" } };
  std::cout << "input: " << s.Volume << " (" << volume.Format
            << (volume.Streamable() ? ", streamed in " + std::to_string(run.Slabs) + " z-slabs" : "")
            << ")\n";
  for (const auto& frame : frames)
  {
    if (volume.Frame == frame[0])
    {
      std::cout << "frame: " << frame[1] << "\n";
    }
  }
  std::cout << "method: " << MethodLabel(s) << " (--method " << s.Method << " --parameters "
            << s.Parameters << ")\n";
  std::cout << "points: " << output.Final(s.SamplesName) << "\n";
  std::cout << "spectrum: " << output.Final("spectrum.csv") << " (uniform density g="
            << run.UniformDensity << " on " << s.SpectrumGrid << "^3 voxels)\n";
  std::cout << "metrics: " << output.Final("metrics.csv") << "\n";
  if (!s.NoPictures)
  {
    std::cout << "picture: " << output.Final("samples.png") << "\n";
    std::cout << "plot: " << output.Final("spectrum.png") << "\n";
  }
  vtkDataArray* expected = run.Samples->GetFieldData()->GetArray("ExpectedNumberOfPoints");
  std::cout << "voxels=" << volume.Voxels << " points=" << run.Samples->GetNumberOfPoints()
            << " expected="
            << static_cast<long long>(expected ? std::llround(expected->GetComponent(0, 0)) : 0)
            << " seconds=" << run.Seconds << " frame=" << volume.Frame << std::endl;
}

int Fail(const std::string& message)
{
  std::cerr << Program << ": " << message << "\n";
  return 1;
}
}

int main(int argc, char* argv[])
{
  Settings s;
  const int parsed = ParseOptions(argc, argv, s);
  if (parsed >= 0)
  {
    return parsed;
  }
  if (s.Volume.empty())
  {
    s.Volume = vtksys::SystemTools::FileExists(DefaultVolume, true)
      ? DefaultVolume
      : std::string(BLUENOISE_DATA_DIR) + "/brain-small.vti";
  }

  // The inputs first, then the output folder, then the display.
  std::string error;
  bluenoise::Volume volume;
  if (!bluenoise::CheckVolumeFile(s.Volume, volume, error) || !CheckParameters(s.Parameters, error))
  {
    return Fail(error);
  }
  bluenoise::OutputFolder output;
  if (!output.Open(s.OutputDir, error))
  {
    return Fail(error);
  }
  bluenoise::PictureSession session;
  if (!s.NoPictures && !session.Start(error))
  {
    return Fail("cannot render the pictures: " + error);
  }

  bluenoise::VolumeOptions options;
  options.VoxelSpace = s.VoxelSpace;
  options.AllowStreaming = true;
  std::string arrayName;
  if (!bluenoise::ReadVolume(options, volume, error))
  {
    return Fail(error);
  }
  if (!ChooseArray(volume.Image, s.ArrayName, arrayName, error))
  {
    return Fail(s.Volume + ": " + error);
  }

  Run run;
  if (!Sample(volume, s, arrayName, run, error))
  {
    return Fail(error);
  }
  run.Spectrum = UniformSpectrum(run.Samples->GetNumberOfPoints(), s.SpectrumGrid, s.Seed,
    s.Method, s.Parameters, run.UniformDensity, error);
  if (!run.Spectrum)
  {
    return Fail(error);
  }
  if (!WriteFiles(session, output, s, run, arrayName, error) || !output.Commit(error))
  {
    return Fail(error + " (nothing in " + s.OutputDir + " was changed)");
  }
  PrintResults(s, output, volume, run);
  return 0;
}
