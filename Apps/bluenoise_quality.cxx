// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// bluenoise-quality: the quality report of the sampling methods. For each
// density level it measures L(g), S(g), T(g) and the mean anisotropy (dB,
// shells 1 .. L/2) of single realizations on an L^3 cube, mean and standard
// deviation over seeds, for:
//   Optimized, Paper, Fixed   the paper's error diffusion with that parameter set;
//   Relaxed (default)         the sampler's defaults (relaxed error
//                             diffusion, Optimized parameters);
//   Energy                    energy relaxed error diffusion (Optimized
//                             parameters);
//   WhiteNoise, PoissonDisk, SampleElimination
//                             the sampler's other methods;
//   ContinuousPoissonDisk     a 3D Poisson-disk set in continuous space
//                             (Bridson's algorithm, like scipy's qmc.PoissonDisk)
//                             of about the same count, binned to the voxels;
//   RelaxedSubCube, EnergySubCube
//                             the sampler's defaults and the energy relaxed
//                             method on a varying volume: the L^3 cube of
//                             density g inside a margin of L/4 voxels whose
//                             density ramps along z, measured on the cube's
//                             voxels alone.
// Then the local density of the error-diffusion methods: the
// points per 16-layer slab against their expectation on a ramp, a step, a
// sphere and a real MRI volume. It prints Markdown tables.
//
//   bluenoise-quality [--size L] [--seeds K] [--first-seed S] [--levels 1,4,8,...]
//                     [--optimized FILE] [--weight W] [--mri FILE]
#include "bluenoise_options.h"
#include "vtkBlueNoiseNIfTIReader.h"
#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkErrorDiffusionOptimizer.h"
#include "vtkErrorDiffusionParameterTable.h"
#include "vtkErrorDiffusionSampler.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
// Bridson's Poisson-disk sampling in the box [0, L)^3 with radius r: every
// point at least r from every other, new points tried in the shell [r, 2r)
// around active ones, k tries each.
std::vector<std::array<double, 3>> PoissonDisk(double L, double r, unsigned seed, int k = 30)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double cell = r / std::sqrt(3.0);
  const int n = static_cast<int>(std::ceil(L / cell));
  std::vector<int> grid(static_cast<size_t>(n) * n * n, -1);
  std::vector<std::array<double, 3>> points;
  std::vector<int> active;
  auto cellOf = [&](const std::array<double, 3>& p, int c) {
    return std::min(n - 1, static_cast<int>(p[c] / cell));
  };
  auto fits = [&](const std::array<double, 3>& p) {
    const int ci = cellOf(p, 0), cj = cellOf(p, 1), ck = cellOf(p, 2);
    for (int k2 = std::max(0, ck - 2); k2 <= std::min(n - 1, ck + 2); ++k2)
      for (int j2 = std::max(0, cj - 2); j2 <= std::min(n - 1, cj + 2); ++j2)
        for (int i2 = std::max(0, ci - 2); i2 <= std::min(n - 1, ci + 2); ++i2)
        {
          const int q = grid[i2 + static_cast<size_t>(n) * (j2 + static_cast<size_t>(n) * k2)];
          if (q >= 0)
          {
            const auto& o = points[q];
            const double d2 = (o[0] - p[0]) * (o[0] - p[0]) + (o[1] - p[1]) * (o[1] - p[1]) +
              (o[2] - p[2]) * (o[2] - p[2]);
            if (d2 < r * r)
            {
              return false;
            }
          }
        }
    return true;
  };
  auto add = [&](const std::array<double, 3>& p) {
    grid[cellOf(p, 0) + static_cast<size_t>(n) * (cellOf(p, 1) + static_cast<size_t>(n) * cellOf(p, 2))] =
      static_cast<int>(points.size());
    active.push_back(static_cast<int>(points.size()));
    points.push_back(p);
  };
  add({ unit(random) * L, unit(random) * L, unit(random) * L });
  while (!active.empty())
  {
    const size_t pick = static_cast<size_t>(unit(random) * active.size()) % active.size();
    const auto center = points[active[pick]];
    bool placed = false;
    for (int t = 0; t < k && !placed; ++t)
    {
      // A uniform direction and a radius uniform in volume over [r, 2r).
      const double z = 2.0 * unit(random) - 1.0;
      const double phi = 2.0 * M_PI * unit(random);
      const double s = std::sqrt(1.0 - z * z);
      const double radius = r * std::cbrt(1.0 + 7.0 * unit(random));
      const std::array<double, 3> p = { center[0] + radius * s * std::cos(phi),
        center[1] + radius * s * std::sin(phi), center[2] + radius * z };
      if (p[0] < 0 || p[1] < 0 || p[2] < 0 || p[0] >= L || p[1] >= L || p[2] >= L || !fits(p))
      {
        continue;
      }
      add(p);
      placed = true;
    }
    if (!placed)
    {
      active[pick] = active.back();
      active.pop_back();
    }
  }
  return points;
}

// A Poisson-disk mask of about `target` points: the radius is adjusted from
// the count of a first try (count ~ 1 / r^3).
std::vector<unsigned char> PoissonDiskMask(int L, double target, unsigned seed)
{
  double r = std::cbrt(0.7 * L * L * L / target);
  std::vector<unsigned char> mask;
  for (int attempt = 0; attempt < 4; ++attempt)
  {
    const auto points = PoissonDisk(L, r, seed);
    mask.assign(static_cast<size_t>(L) * L * L, 0);
    size_t count = 0;
    for (const auto& p : points)
    {
      const size_t id = static_cast<size_t>(p[0]) +
        static_cast<size_t>(L) * (static_cast<size_t>(p[1]) + static_cast<size_t>(L) * static_cast<size_t>(p[2]));
      count += mask[id] ? 0 : 1;
      mask[id] = 1;
    }
    if (std::abs(count - target) < 0.01 * target)
    {
      break;
    }
    r *= std::cbrt(count / target);
  }
  return mask;
}

// The sampler with `method` on `image` (its densities as they are), updated;
// the paper's error diffusion with the paper's parameters, the other methods
// with the default ones.
vtkSmartPointer<vtkErrorDiffusionSampler> RunSampler(
  vtkImageData* image, int method, int seed, bool mask)
{
  auto sampler = vtkSmartPointer<vtkErrorDiffusionSampler>::New();
  sampler->SetInputData(image);
  sampler->SetMethod(method);
  sampler->SetDensityMappingToIdentity();
  sampler->SetUseNumberOfPoints(false);
  sampler->SetSeed(seed);
  if (method == vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION)
  {
    sampler->SetParameterSet(vtkErrorDiffusionSampler::PARAMETERS_PAPER);
  }
  sampler->SetGenerateMask(mask);
  sampler->Update();
  return sampler;
}

// A volume of nx x ny x nz voxels whose density at (x, y, z) is density(x, y, z).
template <typename Density>
vtkSmartPointer<vtkImageData> DensityVolume(int nx, int ny, int nz, Density density)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfValues(static_cast<vtkIdType>(nx) * ny * nz);
  float* v = values->GetPointer(0);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        *v++ = static_cast<float>(density(x, y, z));
  image->GetPointData()->SetScalars(values);
  return image;
}

// The sampler's sample mask of `image`.
std::vector<unsigned char> SamplerMask(vtkImageData* image, int method, int seed)
{
  auto sampler = RunSampler(image, method, seed, true);
  auto* mask = vtkUnsignedCharArray::SafeDownCast(
    sampler->GetMaskOutput()->GetPointData()->GetArray("SampleMask"));
  if (!mask || mask->GetNumberOfValues() != image->GetNumberOfPoints())
  {
    std::cerr << "bluenoise-quality: the sampler gave no mask (method " << method << ")\n";
    std::exit(1);
  }
  return std::vector<unsigned char>(mask->GetPointer(0), mask->GetPointer(0) + mask->GetNumberOfValues());
}

// The sampler on a constant L^3 volume of density g: its sample mask.
std::vector<unsigned char> SamplerMask(int size, double g, int method, int seed)
{
  return SamplerMask(DensityVolume(size, size, size, [g](int, int, int) { return g; }), method, seed);
}

// `method` on a varying volume: the L^3 cube of density g in the
// middle of a margin of L/4 voxels on every side, whose density ramps along z
// as the local-density profile's ramp does (0.004 at the first layer, 0.304
// at the last). The mask of the cube's voxels alone: what the sampler does
// inside a region of constant density among others, boundaries included.
std::vector<unsigned char> SubCubeMask(int size, double g, int method, int seed)
{
  const int margin = size / 4, n = size + 2 * margin;
  const auto inside = [=](int c) { return c >= margin && c < margin + size; };
  auto image = DensityVolume(n, n, n, [=](int x, int y, int z) {
    return inside(x) && inside(y) && inside(z) ? g : 0.004 + 0.3 * z / (n - 1.0);
  });
  const std::vector<unsigned char> whole = SamplerMask(image, method, seed);
  std::vector<unsigned char> cube;
  cube.reserve(static_cast<size_t>(size) * size * size);
  for (int z = margin; z < margin + size; ++z)
    for (int y = margin; y < margin + size; ++y)
    {
      const auto row = whole.begin() + margin + n * (y + static_cast<size_t>(n) * z);
      cube.insert(cube.end(), row, row + size);
    }
  return cube;
}

// The points of `method` per 16-layer slab of `image` (float densities,
// sampled as they are) against the sum of its densities there: the table's
// header and a row for each error-diffusion method, in % off.
void PrintProfile(const std::string& name, vtkImageData* image, int seed)
{
  const int slab = 16;
  const int* dims = image->GetDimensions();
  const vtkIdType layer = static_cast<vtkIdType>(dims[0]) * dims[1];
  vtkDataArray* values = image->GetPointData()->GetScalars();
  std::vector<double> expected((dims[2] + slab - 1) / slab, 0.0);
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
    expected[static_cast<size_t>(i / layer / slab)] += values->GetComponent(i, 0);
  std::cout << "\n" << name << ":\n\n| method |";
  for (size_t k = 0; k < expected.size(); ++k)
    std::cout << " " << k * slab << " |";
  std::cout << "\n| --- |";
  for (size_t k = 0; k < expected.size(); ++k)
    std::cout << " ---: |";
  std::cout << "\n| expected |";
  for (double e : expected)
    std::cout << " " << static_cast<long>(std::lround(e)) << " |";
  std::cout << "\n";
  const std::pair<const char*, int> methods[] = {
    { "Relaxed", vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION },
    { "Energy", vtkErrorDiffusionSampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION },
    { "Paper", vtkErrorDiffusionSampler::METHOD_ERROR_DIFFUSION },
  };
  for (const auto& [label, method] : methods)
  {
    auto sampler = RunSampler(image, method, seed, false);
    std::vector<double> got(expected.size(), 0.0);
    vtkPoints* points = sampler->GetOutput()->GetPoints();
    double origin[3], spacing[3];
    image->GetOrigin(origin);
    image->GetSpacing(spacing);
    for (vtkIdType i = 0; points && i < points->GetNumberOfPoints(); ++i)
    {
      const double k = std::floor((points->GetPoint(i)[2] - origin[2]) / spacing[2] + 0.5);
      got[static_cast<size_t>(k) / slab] += 1.0;
    }
    std::cout << "| " << label << " |";
    for (size_t k = 0; k < expected.size(); ++k)
    {
      std::ostringstream cell;
      cell.setf(std::ios::fixed);
      cell.precision(1);
      if (expected[k] >= 50.0)
        cell << std::showpos << 100.0 * (got[k] / expected[k] - 1.0);
      std::cout << " " << cell.str() << " |";
    }
    std::cout << "\n";
  }
}

// The MRI volume at `path` as densities: its intensities mapped linearly from
// their range onto [0, 1/4] (where the default method relaxes); nullptr when
// the file is missing or unreadable.
vtkSmartPointer<vtkImageData> MriDensities(const std::string& path)
{
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    return nullptr;
  }
  vtkNew<vtkBlueNoiseNIfTIReader> reader;
  reader->SetFileName(path.c_str());
  reader->VoxelSpaceOn();
  reader->Update();
  vtkImageData* read = reader->GetOutput();
  vtkDataArray* intensity = read->GetPointData()->GetScalars();
  if (!intensity || intensity->GetNumberOfTuples() == 0)
  {
    return nullptr;
  }
  double range[2];
  intensity->GetRange(range, 0);
  const double scale = range[1] > range[0] ? 0.25 / (range[1] - range[0]) : 0.0;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->CopyStructure(read);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfValues(intensity->GetNumberOfTuples());
  for (vtkIdType i = 0; i < intensity->GetNumberOfTuples(); ++i)
    values->SetValue(i, static_cast<float>((intensity->GetComponent(i, 0) - range[0]) * scale));
  image->GetPointData()->SetScalars(values);
  return image;
}

// Local density: points per 16-layer slab of three 64 x 64 x 256 volumes and
// of the MRI volume against the sum of the densities there, for the default
// method and the paper's.
void PrintProfiles(int seed, const std::string& mri)
{
  std::cout << "\nLocal density (seed " << seed << "): points per 16-layer slab (from the "
               "layer in the header), in % from the sum of the densities of the slab (slabs with "
               "fewer than 50 expected points left blank).\n";
  const int nx = 64, ny = 64, nz = 256;
  PrintProfile("ramp 0.004 to 0.304 along z, 64 x 64 x 256",
    DensityVolume(nx, ny, nz, [](int, int, int z) { return 0.004 + 0.3 * z / 255.0; }), seed);
  PrintProfile("step 0.2 to 0.02 at z = 128, 64 x 64 x 256",
    DensityVolume(nx, ny, nz, [](int, int, int z) { return z < 128 ? 0.2 : 0.02; }), seed);
  PrintProfile("sphere of 0.05, radius 30, in the middle of 64 x 64 x 256 (97 empty layers "
               "before it)",
    DensityVolume(nx, ny, nz,
      [](int x, int y, int z) {
        const double dx = x - 31.5, dy = y - 31.5, dz = z - 127.5;
        return dx * dx + dy * dy + dz * dz <= 900.0 ? 0.05 : 0.0;
      }),
    seed);
  const vtkSmartPointer<vtkImageData> brain = MriDensities(mri);
  if (!brain)
  {
    std::cout << "\n(no MRI volume: " << mri << " is missing or unreadable)\n";
    return;
  }
  const int* dims = brain->GetDimensions();
  PrintProfile("MRI " + vtksys::SystemTools::GetFilenameName(mri) + ", " +
      std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " +
      std::to_string(dims[2]) + ", densities the intensities mapped from their range onto [0, 1/4]",
    brain, seed);
}

struct Stats
{
  std::vector<double> T, L, S, A;
  // One realization's T(g), L(g), S(g) and mean anisotropy (dB).
  void Add(double t, double l, double s, double a)
  {
    this->T.push_back(t);
    this->L.push_back(l);
    this->S.push_back(s);
    this->A.push_back(a);
  }
  static double Mean(const std::vector<double>& v)
  {
    double mean = 0.0;
    for (double x : v)
      mean += x / v.size();
    return mean;
  }
  static double Deviation(const std::vector<double>& v)
  {
    const double mean = Mean(v);
    double var = 0.0;
    for (double x : v)
      var += (x - mean) * (x - mean) / std::max<size_t>(1, v.size() - 1);
    return std::sqrt(var);
  }
  static std::string Format(const std::vector<double>& v, int digits)
  {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << Mean(v) << " ± " << Deviation(v);
    return s.str();
  }
};

struct Options
{
  int Size = 128;
  int Seeds = 4;
  int FirstSeed = 1000;
  double Weight = 0.02;
  std::string OptimizedFile;
  std::string Mri = "/usr/share/mricron/templates/ch2bet.nii.gz";
  std::vector<double> Levels = { 1, 4, 8, 16, 24, 32, 64, 127 };
};

int ParseOptions(int argc, char* argv[], Options& o)
{
  bluenoise::CommandLine cli("bluenoise-quality",
    "The quality report of the sampling methods: L(g), S(g), T(g) and anisotropy per level "
    "for the sampler's methods and parameter sets and a continuous Poisson-disk set, and "
    "local-density profiles, as Markdown tables.");
  cli.AddCubeSize(o.Size);
  cli.AddSeedCount(o.Seeds, 2);
  cli.AddInteger("--first-seed", o.FirstSeed, 0, 2000000000, "the first seed");
  cli.AddLevels(o.Levels);
  cli.AddText("--optimized", o.OptimizedFile, "FILE",
    "parameter table measured as Optimized (default: the built-in Optimized set)");
  cli.AddWeight(o.Weight);
  cli.AddText("--mri", o.Mri, "FILE",
    "NIfTI volume of the last local-density profile (default: Debian's mricron-data ch2bet)");
  return cli.Parse(argc, argv);
}

using LevelStats = std::map<std::string, Stats>;
// Per level, the figures of each method, for the summary under the table.
using Report = std::vector<std::pair<double, LevelStats>>;

// The goals under the table: `a` below `b` in the mean of `metric` (T(g) by
// default) at every level (by more than one standard deviation, the larger of
// the two, with `margin`); `b` may name several methods ("X|Y"): the lowest
// of their means, and with `orEqual` at that mean or below (to the 4 decimals
// of the table).
struct Goal
{
  std::string A, B;
  bool Margin = false;
  std::vector<double> Stats::*Metric = &Stats::T;
  const char* Label = "T(g)";
  bool OrEqual = false;
};

void PrintBelow(const Report& all, const Goal& goal)
{
  std::vector<std::string> others;
  std::istringstream names(goal.B);
  for (std::string name; std::getline(names, name, '|');)
    others.push_back(name);
  std::ostringstream failed;
  int count = 0;
  for (const auto& level : all)
  {
    const Stats& sa = level.second.at(goal.A);
    const auto mean = [&](const Stats& s) { return Stats::Mean(s.*goal.Metric); };
    const Stats* lowest = &level.second.at(others.front());
    for (const std::string& name : others)
      if (mean(level.second.at(name)) < mean(*lowest))
        lowest = &level.second.at(name);
    const double needed = goal.Margin
      ? std::max(Stats::Deviation(sa.*goal.Metric), Stats::Deviation(lowest->*goal.Metric))
      : 0.0;
    const double gap = mean(*lowest) - mean(sa);
    if (gap > needed || (goal.OrEqual && std::lround(1e4 * gap) >= 0))
    {
      ++count;
    }
    else
    {
      failed << " " << level.first;
    }
  }
  std::string b = goal.B;
  if (others.size() > 1)
  {
    b = "the lower of " + others[0];
    for (size_t k = 1; k < others.size(); ++k)
      b += (k + 1 < others.size() ? ", " : " and ") + others[k];
  }
  std::cout << "- mean " << goal.Label << " of " << goal.A << (goal.OrEqual ? " at or" : "")
            << " below " << b << (goal.Margin ? " by more than one standard deviation" : "")
            << ": " << count << " of " << all.size() << " levels";
  if (count < static_cast<int>(all.size()))
  {
    std::cout << " (not at" << failed.str() << ")";
  }
  std::cout << "\n";
}

using NamedTables = std::vector<std::pair<std::string, vtkErrorDiffusionParameterTable>>;

// The parameter sets measured with the optimizer's evaluation: Optimized (or
// the table of --optimized), Paper and Fixed. None, after a message, when the
// file cannot be read.
NamedTables ParameterTables(const Options& o)
{
  NamedTables tables;
  vtkErrorDiffusionParameterTable optimized = vtkErrorDiffusionParameterTable::Optimized();
  if (!o.OptimizedFile.empty())
  {
    std::string error;
    if (!vtkErrorDiffusionParameterTable::ReadFile(o.OptimizedFile, optimized, error))
    {
      std::cerr << "bluenoise-quality: " << error << "\n";
      return tables;
    }
  }
  tables.emplace_back("Optimized", optimized);
  tables.emplace_back("Paper", vtkErrorDiffusionParameterTable::Paper());
  tables.emplace_back("Fixed", vtkErrorDiffusionParameterTable::Fixed());
  return tables;
}

void PrintTableHead(const Options& o)
{
  std::cout << "Whole " << o.Size << "^3 cube, " << o.Seeds << " seeds (" << o.FirstSeed << ".."
            << o.FirstSeed + o.Seeds - 1 << "), w = " << o.Weight
            << ", single realizations: mean ± standard deviation over the seeds. "
               "Anisotropy: mean over shells 1.."
            << o.Size / 2 << " in dB.\n\n";
  std::cout << "| level | method | T(g) | L(g) | S(g) | anisotropy dB |\n"
               "| ---: | --- | ---: | ---: | ---: | ---: |\n";
}

// Keeps a method's figures at a level for the summary and prints their row at
// once (a long run shows its progress).
void AddRow(LevelStats& byMethod, double level, const std::string& name, const Stats& s)
{
  byMethod[name] = s;
  std::cout << "| " << level << " | " << name << " | " << Stats::Format(s.T, 4) << " | "
            << Stats::Format(s.L, 4) << " | " << Stats::Format(s.S, 4) << " | "
            << Stats::Format(s.A, 2) << " |\n"
            << std::flush;
}

// A parameter table at `level`, one realization per seed, as the optimizer
// measures it. False, with a message, when the evaluation fails.
bool MeasureTable(const vtkErrorDiffusionParameterTable& table, double level, const Options& o,
  Stats& s)
{
  vtkErrorDiffusionOptimizer::Settings settings;
  settings.GridSize = o.Size;
  settings.Seeds = 1;
  settings.Weight = o.Weight;
  for (int k = 0; k < o.Seeds; ++k)
  {
    settings.FirstSeed = o.FirstSeed + k;
    vtkErrorDiffusionOptimizer::Evaluation e;
    std::string error;
    if (!vtkErrorDiffusionOptimizer::Evaluate(table, level, settings, e, false, &error))
    {
      std::cerr << "bluenoise-quality: " << error << "\n";
      return false;
    }
    s.Add(e.Whole.Target, e.Whole.LowFrequencyRatio, e.Whole.Symmetry, e.Whole.AnisotropyDB);
  }
  return true;
}

// The spectrum figures of one sample mask of the L^3 cube, added to `s`.
void MeasureMask(const std::vector<unsigned char>& mask, const Options& o, Stats& s)
{
  const int dims[3] = { o.Size, o.Size, o.Size };
  vtkBlueNoiseSpectrumKernel::Result r;
  std::string error;
  if (!vtkBlueNoiseSpectrumKernel::Evaluate(mask.data(), dims, o.Weight, r, &error))
  {
    std::cerr << "bluenoise-quality: " << error << "\n";
    std::exit(1);
  }
  double a = 0.0;
  const size_t shells = std::min<size_t>(r.AnisotropyDB.size(), o.Size / 2);
  for (size_t i = 0; i < shells; ++i)
    a += r.AnisotropyDB[i] / shells;
  s.Add(r.TargetValue, r.LowFrequencyRatio, r.Symmetry, a);
}

// Every method at one level, a row each, in the order of the table. False
// when a parameter table's evaluation fails.
bool MeasureLevel(double level, const NamedTables& tables, const Options& o, LevelStats& byMethod)
{
  for (const auto& named : tables)
  {
    Stats s;
    if (!MeasureTable(named.second, level, o, s))
    {
      return false;
    }
    AddRow(byMethod, level, named.first, s);
  }
  const double g = level / 255.0;
  const std::pair<const char*, int> methods[] = {
    { "Relaxed", vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION },
    { "Energy", vtkErrorDiffusionSampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION },
    { "WhiteNoise", vtkErrorDiffusionSampler::METHOD_WHITE_NOISE },
    { "PoissonDisk", vtkErrorDiffusionSampler::METHOD_POISSON_DISK },
    { "SampleElimination", vtkErrorDiffusionSampler::METHOD_SAMPLE_ELIMINATION },
  };
  for (const auto& method : methods)
  {
    Stats s;
    for (int k = 0; k < o.Seeds; ++k)
      MeasureMask(SamplerMask(o.Size, g, method.second, o.FirstSeed + k), o, s);
    AddRow(byMethod, level, method.first, s);
  }
  Stats continuous;
  for (int k = 0; k < o.Seeds; ++k)
    MeasureMask(PoissonDiskMask(o.Size, g * o.Size * o.Size * o.Size, o.FirstSeed + k), o,
      continuous);
  AddRow(byMethod, level, "ContinuousPoissonDisk", continuous);
  for (const auto& method : methods)
  {
    if (method.second == vtkErrorDiffusionSampler::METHOD_RELAXED_ERROR_DIFFUSION ||
      method.second == vtkErrorDiffusionSampler::METHOD_ENERGY_RELAXED_ERROR_DIFFUSION)
    {
      Stats sub;
      for (int k = 0; k < o.Seeds; ++k)
        MeasureMask(SubCubeMask(o.Size, g, method.second, o.FirstSeed + k), o, sub);
      AddRow(byMethod, level, std::string(method.first) + "SubCube", sub);
    }
  }
  return true;
}

// The relaxed methods inside a varying volume against on the constant cube:
// the change of each figure's mean, per level.
void PrintSubCube(const Report& all)
{
  std::cout << "\nRelaxedSubCube and EnergySubCube against Relaxed and Energy (the same cube "
               "alone), change of the means:\n\n"
               "| level | method | L(g) | S(g) | anisotropy dB |\n"
               "| ---: | --- | ---: | ---: | ---: |\n";
  for (const auto& level : all)
  {
    for (const std::string method : { "Relaxed", "Energy" })
    {
      const Stats& sub = level.second.at(method + "SubCube");
      const Stats& alone = level.second.at(method);
      const auto change = [&](std::vector<double> Stats::*m, bool relative) {
        const double a = Stats::Mean(alone.*m), b = Stats::Mean(sub.*m);
        std::ostringstream cell;
        cell.setf(std::ios::fixed);
        cell.precision(relative ? 1 : 2);
        cell << std::showpos << (relative ? 100.0 * (b / a - 1.0) : b - a) << (relative ? " %" : "");
        return cell.str();
      };
      std::cout << "| " << level.first << " | " << method << " | " << change(&Stats::L, true)
                << " | " << change(&Stats::S, true) << " | " << change(&Stats::A, false) << " |\n";
    }
  }
}

void PrintSummary(const Report& all)
{
  std::cout << "\n";
  PrintBelow(all, { "Optimized", "Paper", true });
  PrintBelow(all, { "Relaxed", "ContinuousPoissonDisk" });
  PrintBelow(all, { "Relaxed", "ContinuousPoissonDisk", false, &Stats::L, "L(g)", true });
  PrintBelow(all, { "Relaxed", "PoissonDisk|SampleElimination", false, &Stats::L, "L(g)", true });
  PrintBelow(all, { "Energy", "PoissonDisk|SampleElimination", false, &Stats::L, "L(g)", true });
  PrintBelow(all, { "Energy", "ContinuousPoissonDisk", false, &Stats::L, "L(g)", true });
  PrintBelow(all, { "Energy", "Relaxed", false, &Stats::L, "L(g)", true });
  PrintBelow(all, { "Paper", "ContinuousPoissonDisk" });
  PrintBelow(all, { "Relaxed", "WhiteNoise" });
  PrintBelow(all, { "Paper", "WhiteNoise" });
  PrintSubCube(all);
}
}

int main(int argc, char* argv[])
{
  Options o;
  const int parsed = ParseOptions(argc, argv, o);
  if (parsed >= 0)
  {
    return parsed;
  }
  const NamedTables tables = ParameterTables(o);
  if (tables.empty())
  {
    return 1;
  }
  PrintTableHead(o);
  Report all;
  for (double level : o.Levels)
  {
    all.emplace_back(level, LevelStats());
    if (!MeasureLevel(level, tables, o, all.back().second))
    {
      return 1;
    }
  }
  PrintSummary(all);
  PrintProfiles(o.FirstSeed, o.Mri);
  return 0;
}
