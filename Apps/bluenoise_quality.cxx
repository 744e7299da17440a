// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// bluenoise-quality: the quality report of the parameter sets. For each density
// level it measures L(g), S(g), T(g) and the mean anisotropy (dB, shells
// 1 .. L/2) of single realisations on an L^3 cube, mean and standard deviation
// over seeds, for:
//   Optimized, Paper, Fixed   the sampler with that parameter set;
//   WhiteNoise                independent Bernoulli(g) voxels (hit and miss);
//   PoissonDisk               a 3D Poisson-disk set (Bridson's algorithm) of
//                             about the same count, binned to the voxels.
// It prints a Markdown table.
//
//   bluenoise-quality [--size L] [--seeds K] [--first-seed S] [--levels 1,4,8,...]
//                     [--optimized FILE] [--weight W]
#include "bluenoise_options.h"
#include "vtkBlueNoiseSpectrumKernel.h"
#include "vtkErrorDiffusionOptimizer.h"
#include "vtkErrorDiffusionParameterTable.h"

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
    const auto centre = points[active[pick]];
    bool placed = false;
    for (int t = 0; t < k && !placed; ++t)
    {
      // A uniform direction and a radius uniform in volume over [r, 2r).
      const double z = 2.0 * unit(random) - 1.0;
      const double phi = 2.0 * M_PI * unit(random);
      const double s = std::sqrt(1.0 - z * z);
      const double radius = r * std::cbrt(1.0 + 7.0 * unit(random));
      const std::array<double, 3> p = { centre[0] + radius * s * std::cos(phi),
        centre[1] + radius * s * std::sin(phi), centre[2] + radius * z };
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

struct Stats
{
  std::vector<double> T, L, S, A;
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
  std::vector<double> Levels = { 1, 4, 8, 12, 16, 24, 32, 40, 48, 56, 64, 72, 80, 88, 96, 100,
    104, 112, 120, 127 };
};

int ParseOptions(int argc, char* argv[], Options& o)
{
  bluenoise::CommandLine cli("bluenoise-quality",
    "The quality report of the parameter sets: L(g), S(g), T(g) and anisotropy per level "
    "for Optimized, Paper, Fixed, white noise and a Poisson-disk set, as a Markdown table.");
  cli.AddCubeSize(o.Size);
  cli.AddSeedCount(o.Seeds, 2);
  cli.AddInteger("--first-seed", o.FirstSeed, 0, 2000000000, "the first seed");
  cli.AddLevels(o.Levels);
  cli.AddText("--optimized", o.OptimizedFile, "FILE",
    "parameter table measured as Optimized (default: the built-in Optimized set)");
  cli.AddWeight(o.Weight);
  return cli.Parse(argc, argv);
}

// The goals under the table: `a` below `b` in mean T(g) at every level (by
// more than one standard deviation, the larger of the two, with `margin`).
void PrintBelow(const std::vector<std::pair<double, std::map<std::string, Stats>>>& all,
  const std::string& a, const std::string& b, bool margin)
{
  std::ostringstream failed;
  int count = 0;
  for (const auto& level : all)
  {
    const Stats& sa = level.second.at(a);
    const Stats& sb = level.second.at(b);
    const double gap = Stats::Mean(sb.T) - Stats::Mean(sa.T);
    const double needed = margin ? std::max(Stats::Deviation(sa.T), Stats::Deviation(sb.T)) : 0.0;
    if (gap > needed)
    {
      ++count;
    }
    else
    {
      failed << " " << level.first;
    }
  }
  std::cout << "- mean T(g) of " << a << " below " << b
            << (margin ? " by more than one standard deviation" : "") << ": " << count << " of "
            << all.size() << " levels";
  if (count < static_cast<int>(all.size()))
  {
    std::cout << " (not at" << failed.str() << ")";
  }
  std::cout << "\n";
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
  const int size = o.Size, seeds = o.Seeds, firstSeed = o.FirstSeed;
  const double weight = o.Weight;
  const std::string& optimizedFile = o.OptimizedFile;
  const std::vector<double>& levels = o.Levels;

  std::vector<std::pair<std::string, vtkErrorDiffusionParameterTable>> tables;
  vtkErrorDiffusionParameterTable optimized = vtkErrorDiffusionParameterTable::Optimized();
  if (!optimizedFile.empty())
  {
    std::string error;
    if (!vtkErrorDiffusionParameterTable::ReadFile(optimizedFile, optimized, error))
    {
      std::cerr << "bluenoise-quality: " << error << "\n";
      return 1;
    }
  }
  tables.emplace_back("Optimized", optimized);
  tables.emplace_back("Paper", vtkErrorDiffusionParameterTable::Paper());
  tables.emplace_back("Fixed", vtkErrorDiffusionParameterTable::Fixed());

  std::cout << "Whole " << size << "^3 cube, " << seeds << " seeds (" << firstSeed << ".."
            << firstSeed + seeds - 1 << "), w = " << weight
            << ", single realisations: mean ± standard deviation over the seeds. "
               "Anisotropy: mean over shells 1.."
            << size / 2 << " in dB.\n\n";
  std::cout << "| level | method | T(g) | L(g) | S(g) | anisotropy dB |\n"
               "| ---: | --- | ---: | ---: | ---: | ---: |\n";
  const int dims[3] = { size, size, size };
  // Per level, T of each method, for the summary under the table.
  std::vector<std::pair<double, std::map<std::string, Stats>>> all;
  for (double level : levels)
  {
    all.emplace_back(level, std::map<std::string, Stats>());
    auto& byMethod = all.back().second;
    const double g = level / 255.0;
    auto row = [&](const std::string& name, const Stats& s) {
      byMethod[name] = s;
      std::cout << "| " << level << " | " << name << " | " << Stats::Format(s.T, 4) << " | "
                << Stats::Format(s.L, 4) << " | " << Stats::Format(s.S, 4) << " | "
                << Stats::Format(s.A, 2) << " |\n"
                << std::flush;
    };
    auto measure = [&](const std::vector<unsigned char>& mask, Stats& s) {
      vtkBlueNoiseSpectrumKernel::Result r;
      std::string error;
      if (!vtkBlueNoiseSpectrumKernel::Evaluate(mask.data(), dims, weight, r, &error))
      {
        std::cerr << "bluenoise-quality: " << error << "\n";
        std::exit(1);
      }
      s.T.push_back(r.TargetValue);
      s.L.push_back(r.LowFrequencyRatio);
      s.S.push_back(r.Symmetry);
      double a = 0.0;
      const size_t shells = std::min<size_t>(r.AnisotropyDB.size(), size / 2);
      for (size_t i = 0; i < shells; ++i)
        a += r.AnisotropyDB[i] / shells;
      s.A.push_back(a);
    };
    for (const auto& named : tables)
    {
      Stats s;
      vtkErrorDiffusionOptimizer::Settings settings;
      settings.GridSize = size;
      settings.Seeds = 1;
      settings.Weight = weight;
      for (int k = 0; k < seeds; ++k)
      {
        settings.FirstSeed = firstSeed + k;
        vtkErrorDiffusionOptimizer::Evaluation e;
        std::string error;
        if (!vtkErrorDiffusionOptimizer::Evaluate(named.second, level, settings, e, false, &error))
        {
          std::cerr << "bluenoise-quality: " << error << "\n";
          return 1;
        }
        s.T.push_back(e.Whole.Target);
        s.L.push_back(e.Whole.LowFrequencyRatio);
        s.S.push_back(e.Whole.Symmetry);
        s.A.push_back(e.Whole.AnisotropyDB);
      }
      row(named.first, s);
    }
    Stats white, poisson;
    for (int k = 0; k < seeds; ++k)
    {
      std::mt19937 random(firstSeed + k);
      std::bernoulli_distribution draw(g);
      std::vector<unsigned char> mask(static_cast<size_t>(size) * size * size);
      for (auto& m : mask)
        m = draw(random) ? 1 : 0;
      measure(mask, white);
      measure(PoissonDiskMask(size, g * size * size * size, firstSeed + k), poisson);
    }
    row("WhiteNoise", white);
    row("PoissonDisk", poisson);
  }

  std::cout << "\n";
  PrintBelow(all, "Optimized", "Paper", true);
  PrintBelow(all, "Optimized", "PoissonDisk", false);
  PrintBelow(all, "Paper", "PoissonDisk", false);
  PrintBelow(all, "Optimized", "WhiteNoise", false);
  PrintBelow(all, "Paper", "WhiteNoise", false);
  return 0;
}
