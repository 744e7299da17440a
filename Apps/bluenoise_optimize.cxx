// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// bluenoise-optimize: the paper's parameter search (section 4.2). For each key
// density level it minimises T(g) = w L(g) + (1 - w) S(g) over the six
// diffusion coefficients and m(g) with Nelder-Mead, starting from a table's
// parameters at that level, and writes the result as a parameter table that
// the sampler's Custom parameter set reads, with T, L, S per level as comments.
//
//   bluenoise-optimize [--output FILE] [--size L] [--seeds K] [--weight W]
//                      [--evaluations N] [--levels 1,8,16,...] [--start paper|fixed|FILE]
//                      [--threads T] [--resume]
#include "vtkErrorDiffusionOptimizer.h"
#include "vtkErrorDiffusionParameterTable.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
using Key = vtkErrorDiffusionParameterTable::Key;
using LevelResult = vtkErrorDiffusionOptimizer::LevelResult;

void Usage(std::ostream& os)
{
  os << "usage: bluenoise-optimize [--output FILE] [--size L] [--seeds K] [--weight W]\n"
        "                          [--evaluations N] [--levels 1,8,...] [--start paper|fixed|FILE]\n"
        "                          [--threads T] [--resume]\n"
        "  --output FILE      table to write (default optimized-parameters.txt)\n"
        "  --size L           edge of the constant-density cube sampled per evaluation (64)\n"
        "  --seeds K          realisations averaged per evaluation, seeds 0..K-1 (4)\n"
        "  --weight W         w in T = w L + (1 - w) S (0.02)\n"
        "  --evaluations N    Nelder-Mead budget per level (400)\n"
        "  --levels LIST      key levels in 1/255 units (the paper's 17)\n"
        "  --start SET        start parameters: paper, fixed or a table file (paper)\n"
        "  --threads T        levels optimised in parallel (the number of cores)\n"
        "  --resume           keep the levels already in FILE and do the others\n";
}

// One comment line per level: the whole-volume figures the search minimised,
// the start point's, and the interior's (faces cropped) of the result.
std::string Comment(const LevelResult& r, const vtkErrorDiffusionOptimizer::Metrics& interior)
{
  std::ostringstream s;
  s.precision(6);
  s << "level " << r.Level << ": T=" << r.OptimizedMetrics.Target
    << " L=" << r.OptimizedMetrics.LowFrequencyRatio << " S=" << r.OptimizedMetrics.Symmetry
    << " anisotropy_dB=" << r.OptimizedMetrics.AnisotropyDB << " (start T=" << r.StartMetrics.Target
    << " L=" << r.StartMetrics.LowFrequencyRatio << " S=" << r.StartMetrics.Symmetry
    << ") interior T=" << interior.Target << " L=" << interior.LowFrequencyRatio
    << " S=" << interior.Symmetry << " evaluations=" << r.Evaluations;
  return s.str();
}

// Writes every finished level, sorted, with the settings as a header.
bool WriteTable(const std::string& file, const std::map<double, std::pair<Key, std::string>>& done,
  const std::string& header)
{
  std::vector<Key> keys;
  std::ostringstream comment;
  comment << header;
  for (const auto& entry : done)
  {
    keys.push_back(entry.second.first);
    comment << "\n" << entry.second.second;
  }
  vtkErrorDiffusionParameterTable table;
  std::string error;
  if (!table.SetKeys(keys, &error))
  {
    std::cerr << "bluenoise-optimize: " << error << "\n";
    return false;
  }
  const std::string temporary = file + ".partial";
  if (!table.WriteFile(temporary, comment.str()))
  {
    return false;
  }
  return std::rename(temporary.c_str(), file.c_str()) == 0;
}

// Levels and their comment lines from a table this program wrote.
void ReadDone(const std::string& file, std::map<double, std::pair<Key, std::string>>& done)
{
  vtkErrorDiffusionParameterTable table;
  std::string error;
  if (!vtkErrorDiffusionParameterTable::ReadFile(file, table, error))
  {
    return;
  }
  std::map<double, std::string> comments;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.rfind("# level ", 0) == 0)
    {
      comments[std::atof(line.c_str() + 8)] = line.substr(2);
    }
  }
  for (const Key& k : table.GetKeys())
  {
    done[k.Level] = { k, comments.count(k.Level) ? comments[k.Level] : "level (resumed)" };
  }
}
}

int main(int argc, char* argv[])
{
  std::string output = "optimized-parameters.txt";
  std::string start = "paper";
  bool resume = false;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  vtkErrorDiffusionOptimizer::Settings settings;
  std::vector<double> levels = { 1, 8, 16, 24, 32, 40, 48, 56, 64, 72, 80, 88, 96, 104, 112, 120,
    127 };
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc)
      {
        std::cerr << "bluenoise-optimize: " << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "-h" || a == "--help")
    {
      Usage(std::cout);
      return 0;
    }
    else if (a == "--output")
      output = value();
    else if (a == "--size")
      settings.GridSize = std::atoi(value().c_str());
    else if (a == "--seeds")
      settings.Seeds = std::atoi(value().c_str());
    else if (a == "--weight")
      settings.Weight = std::atof(value().c_str());
    else if (a == "--evaluations")
      settings.MaximumEvaluations = std::atoi(value().c_str());
    else if (a == "--start")
      start = value();
    else if (a == "--threads")
      threads = static_cast<unsigned>(std::max(1, std::atoi(value().c_str())));
    else if (a == "--resume")
      resume = true;
    else if (a == "--levels")
    {
      levels.clear();
      std::stringstream list(value());
      std::string item;
      while (std::getline(list, item, ','))
      {
        levels.push_back(std::atof(item.c_str()));
      }
    }
    else
    {
      std::cerr << "bluenoise-optimize: unknown option " << a << "\n";
      Usage(std::cerr);
      return 2;
    }
  }
  for (double level : levels)
  {
    if (!(level > 0.0 && level <= 127.5))
    {
      std::cerr << "bluenoise-optimize: levels must be in (0, 127.5], not " << level << "\n";
      return 2;
    }
  }
  if (settings.GridSize < 8 || settings.Seeds < 1 || settings.MaximumEvaluations < 1)
  {
    std::cerr << "bluenoise-optimize: --size >= 8, --seeds >= 1, --evaluations >= 1\n";
    return 2;
  }

  vtkErrorDiffusionParameterTable startTable = vtkErrorDiffusionParameterTable::Paper();
  if (start == "fixed")
  {
    startTable = vtkErrorDiffusionParameterTable::Fixed();
  }
  else if (start != "paper")
  {
    std::string error;
    if (!vtkErrorDiffusionParameterTable::ReadFile(start, startTable, error))
    {
      std::cerr << "bluenoise-optimize: " << error << "\n";
      return 1;
    }
  }

  std::map<double, std::pair<Key, std::string>> done;
  if (resume)
  {
    ReadDone(output, done);
    std::cout << "resuming: " << done.size() << " level(s) already in " << output << std::endl;
  }
  std::vector<double> todo;
  for (double level : levels)
  {
    if (!done.count(level))
    {
      todo.push_back(level);
    }
  }
  std::ostringstream header;
  header << "Optimised by bluenoise-optimize: minimum of T = w L + (1 - w) S per level\n"
         << "cube " << settings.GridSize << "^3, seeds 0.." << settings.Seeds - 1
         << " averaged, w = " << settings.Weight << ", Nelder-Mead budget "
         << settings.MaximumEvaluations << " per level, start " << start
         << ", ModulationScale " << settings.ModulationScale << ", steady-state boundaries;\n"
         << "interior: the same seeds with the faces cropped by " << settings.CropFaces
         << " voxels";

  std::mutex lock;
  std::atomic<size_t> next{ 0 };
  const auto begin = std::chrono::steady_clock::now();
  auto worker = [&]() {
    for (size_t i = next++; i < todo.size(); i = next++)
    {
      const double level = todo[i];
      const Key from = vtkErrorDiffusionOptimizer::KeyAt(startTable, level);
      int lastReport = 0;
      const auto result = vtkErrorDiffusionOptimizer::OptimizeLevel(
        level, from, settings, [&](int evaluations, double best) {
          if (evaluations - lastReport >= 50)
          {
            lastReport = evaluations;
            std::lock_guard<std::mutex> guard(lock);
            std::cout << "level " << level << ": " << evaluations << "/"
                      << settings.MaximumEvaluations << " evaluations, best T " << best
                      << std::endl;
          }
        });
      vtkErrorDiffusionOptimizer::Evaluation interior;
      vtkErrorDiffusionOptimizer::Evaluate(
        vtkErrorDiffusionOptimizer::SingleKeyTable(result.Optimized, level), level, settings,
        interior, true);
      std::lock_guard<std::mutex> guard(lock);
      done[level] = { result.Optimized, Comment(result, interior.Interior) };
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
      std::cout << done[level].second << " [" << seconds << " s]" << std::endl;
      if (!WriteTable(output, done, header.str()))
      {
        std::cerr << "bluenoise-optimize: cannot write " << output << "\n";
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<size_t>(threads, todo.size()); ++t)
  {
    pool.emplace_back(worker);
  }
  for (auto& t : pool)
  {
    t.join();
  }
  if (todo.empty() && !done.empty())
  {
    WriteTable(output, done, header.str());
  }
  std::cout << "table: " << output << " (" << done.size() << " levels)" << std::endl;
  return done.empty() ? 1 : 0;
}
