// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// bluenoise-optimize: the paper's parameter search (section 4.2). For each key
// density level it minimizes T(g) = w L(g) + (1 - w) S(g) over the six
// diffusion coefficients and m(g) with Nelder-Mead, starting from a table's
// parameters at that level, and writes the result as a parameter table that
// the sampler's Custom parameter set reads, with T, L, S per level as comments.
// --relaxed measures the default method (the scan's samples relaxed; levels
// above the densities the relaxation moves keep the start's parameters);
// --keep-symmetry minimizes L(g) among the parameters of at most the start's
// S(g) and anisotropy.
//
//   bluenoise-optimize [--output FILE] [--size L] [--seeds K] [--weight W]
//                      [--evaluations N] [--levels 1,8,16,...] [--start paper|fixed|FILE]
//                      [--threads T] [--relaxed] [--keep-symmetry] [--resume]
#include "bluenoise_options.h"
#include "vtkBlueNoiseRelaxation.h"
#include "vtkErrorDiffusionOptimizer.h"
#include "vtkErrorDiffusionParameterTable.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
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
// The finished levels: each one's parameters and its comment line.
using Finished = std::map<double, std::pair<Key, std::string>>;

struct Options
{
  std::string Output = "optimized-parameters.txt";
  std::string Start = "paper";
  bool Resume = false;
  int Threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  vtkErrorDiffusionOptimizer::Settings Settings;
  std::vector<double> Levels = { 1, 8, 16, 24, 32, 40, 48, 56, 64, 72, 80, 88, 96, 104, 112, 120,
    127 };
};

int ParseOptions(int argc, char* argv[], Options& o)
{
  bluenoise::CommandLine cli("bluenoise-optimize",
    "The paper's parameter search: per density level, the diffusion coefficients and m(g) "
    "that minimize T(g) = w L(g) + (1 - w) S(g), written as a parameter table.");
  cli.AddText("--output", o.Output, "FILE", "parameter table to write");
  cli.AddCubeSize(o.Settings.GridSize);
  cli.AddSeedCount(o.Settings.Seeds, 1);
  cli.AddWeight(o.Settings.Weight);
  cli.AddInteger("--evaluations", o.Settings.MaximumEvaluations, 1, 1000000,
    "Nelder-Mead budget per level");
  cli.AddLevels(o.Levels);
  cli.AddText("--start", o.Start, "SET|FILE", "start parameters: paper, fixed or a parameter table file");
  cli.AddInteger("--threads", o.Threads, 1, 1024, "levels optimized in parallel");
  cli.AddFlag("--relaxed", o.Settings.Relaxed,
    "measure the default method: the scan's samples after the relaxation pass");
  cli.AddFlag("--keep-symmetry", o.Settings.KeepSymmetry,
    "minimize L(g) instead of T(g), with S(g) and the anisotropy at or below the start's");
  cli.AddFlag("--resume", o.Resume, "keep the levels already in the --output table, do the others");
  return cli.Parse(argc, argv);
}

// One comment line per level: the whole-volume figures the search minimized,
// the start point's, and the interior's (faces cropped) of the result, or why
// there are none (`interior` null: a cube too small to crop).
std::string Comment(const LevelResult& r, const vtkErrorDiffusionOptimizer::Metrics* interior,
  const std::string& noInterior)
{
  std::ostringstream s;
  s.precision(6);
  s << "level " << r.Level << ": T=" << r.OptimizedMetrics.Target
    << " L=" << r.OptimizedMetrics.LowFrequencyRatio << " S=" << r.OptimizedMetrics.Symmetry
    << " anisotropy_dB=" << r.OptimizedMetrics.AnisotropyDB << " (start T=" << r.StartMetrics.Target
    << " L=" << r.StartMetrics.LowFrequencyRatio << " S=" << r.StartMetrics.Symmetry
    << ")";
  if (interior)
  {
    s << " interior T=" << interior->Target << " L=" << interior->LowFrequencyRatio
      << " S=" << interior->Symmetry;
  }
  else
  {
    s << " interior not measured (" << noInterior << ")";
  }
  s << " evaluations=" << r.Evaluations;
  return s.str();
}

// Writes every finished level, sorted, with the settings as a header.
bool WriteTable(const std::string& file, const Finished& done, const std::string& header)
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
void ReadDone(const std::string& file, Finished& done)
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

// The parameters the search starts from (--start): paper, fixed or a table
// file. False, with a message, when the file cannot be read.
bool ReadStart(const std::string& start, vtkErrorDiffusionParameterTable& table)
{
  table = vtkErrorDiffusionParameterTable::Paper();
  if (start == "fixed")
  {
    table = vtkErrorDiffusionParameterTable::Fixed();
  }
  else if (start != "paper")
  {
    std::string error;
    if (!vtkErrorDiffusionParameterTable::ReadFile(start, table, error))
    {
      std::cerr << "bluenoise-optimize: " << error << "\n";
      return false;
    }
  }
  return true;
}

// The table's folder must take the file before hours of search, not after.
bool CanWrite(const std::string& output)
{
  const std::string probe = output + ".partial";
  std::ofstream test(probe, std::ios::app);
  if (!test)
  {
    std::cerr << "bluenoise-optimize: cannot write " << probe << ": " << std::strerror(errno)
              << "\n";
    return false;
  }
  test.close();
  std::remove(probe.c_str());
  return true;
}

// The levels asked for that are not finished yet, in the order asked.
std::vector<double> LevelsToDo(const std::vector<double>& levels, const Finished& done)
{
  std::vector<double> todo;
  for (double level : levels)
  {
    if (!done.count(level))
    {
      todo.push_back(level);
    }
  }
  return todo;
}

// The table's header comment: what was minimized, and with which settings.
std::string TableHeader(const Options& o)
{
  const auto& settings = o.Settings;
  std::ostringstream header;
  header << "Optimized by bluenoise-optimize: "
         << (settings.KeepSymmetry ? "minimum of L, S and anisotropy at most the start's,"
                                   : "minimum of T = w L + (1 - w) S")
         << " per level\n"
         << "cube " << settings.GridSize << "^3, seeds 0.." << settings.Seeds - 1
         << " averaged, w = " << settings.Weight << ", Nelder-Mead budget "
         << settings.MaximumEvaluations << " per level, start " << o.Start
         << ", ModulationScale " << settings.ModulationScale << ", steady-state boundaries;\n"
         << "interior: the same seeds with the faces cropped by " << settings.CropFaces
         << " voxels";
  if (settings.Relaxed)
  {
    header << ";\nmeasured after the relaxation pass (the default method); levels above "
           << 255.0 * vtkBlueNoiseRelaxation::MaximumDensity
           << ", where nothing is relaxed, as in the start table (evaluations=0)";
  }
  return header.str();
}

// The levels to do, searched by a pool of threads: each thread takes the next
// level nobody has taken yet, and a finished level is added to the table and
// the table written at once, so that a run stopped early keeps what it found
// (--resume goes on from there).
class Search
{
public:
  Search(const Options& o, const vtkErrorDiffusionParameterTable& start,
    const std::vector<double>& todo, const std::string& header, Finished& done)
    : Settings(o.Settings)
    , Output(o.Output)
    , Start(start)
    , Todo(todo)
    , Header(header)
    , Done(done)
  {
  }

  void Run(unsigned threads)
  {
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < std::min<size_t>(threads, this->Todo.size()); ++t)
    {
      pool.emplace_back([this]() { this->Work(); });
    }
    for (auto& t : pool)
    {
      t.join();
    }
  }

private:
  // One thread: the next level not taken, until there is none.
  void Work()
  {
    for (size_t i = this->Next++; i < this->Todo.size(); i = this->Next++)
    {
      const double level = this->Todo[i];
      const bool relaxed = level / 255.0 <= vtkBlueNoiseRelaxation::MaximumDensity;
      const LevelResult result =
        this->Settings.Relaxed && !relaxed ? this->Keep(level) : this->Optimize(level);
      vtkErrorDiffusionOptimizer::Evaluation interior;
      std::string why;
      const bool measured = vtkErrorDiffusionOptimizer::Evaluate(
        vtkErrorDiffusionOptimizer::SingleKeyTable(result.Optimized, level), level,
        this->Settings, interior, true, &why);
      this->Finish(level, result, measured ? &interior.Interior : nullptr, why);
    }
  }

  // The search at one level from the start table's parameters there, with a
  // progress line every 50 evaluations.
  LevelResult Optimize(double level)
  {
    const auto& settings = this->Settings;
    const Key from = vtkErrorDiffusionOptimizer::KeyAt(this->Start, level);
    int lastReport = 0;
    return vtkErrorDiffusionOptimizer::OptimizeLevel(
      level, from, settings, [&](int evaluations, double best) {
        if (evaluations - lastReport >= 50)
        {
          lastReport = evaluations;
          std::lock_guard<std::mutex> guard(this->Lock);
          std::cout << "level " << level << ": " << evaluations << "/"
                    << settings.MaximumEvaluations << " evaluations, best T " << best
                    << std::endl;
        }
      });
  }

  // The start table's parameters at one level, not searched: above the
  // densities the relaxation moves, where the default method is the plain
  // scan and the start's search stands. Its key as it is where it has one.
  LevelResult Keep(double level)
  {
    LevelResult result;
    result.Level = level;
    result.Start = vtkErrorDiffusionOptimizer::KeyAt(this->Start, level);
    for (const Key& key : this->Start.GetKeys())
    {
      result.Start = key.Level == level ? key : result.Start;
    }
    result.Optimized = result.Start;
    vtkErrorDiffusionOptimizer::Evaluation e;
    vtkErrorDiffusionOptimizer::Evaluate(
      vtkErrorDiffusionOptimizer::SingleKeyTable(result.Start, level), level, this->Settings, e);
    result.StartMetrics = result.OptimizedMetrics = e.Whole;
    return result;
  }

  // Adds a finished level to the table and writes the table, one thread at a time.
  void Finish(double level, const LevelResult& result,
    const vtkErrorDiffusionOptimizer::Metrics* interior, const std::string& noInterior)
  {
    std::lock_guard<std::mutex> guard(this->Lock);
    this->Done[level] = { result.Optimized, Comment(result, interior, noInterior) };
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Begin).count();
    std::cout << this->Done[level].second << " [" << seconds << " s]" << std::endl;
    if (!WriteTable(this->Output, this->Done, this->Header))
    {
      std::cerr << "bluenoise-optimize: cannot write " << this->Output << ": "
                << std::strerror(errno) << "\n";
    }
  }

  const vtkErrorDiffusionOptimizer::Settings& Settings;
  const std::string& Output;
  const vtkErrorDiffusionParameterTable& Start;
  const std::vector<double>& Todo;
  const std::string& Header;
  Finished& Done;
  std::mutex Lock; // stdout and Done
  std::atomic<size_t> Next{ 0 };
  const std::chrono::steady_clock::time_point Begin = std::chrono::steady_clock::now();
};
}

int main(int argc, char* argv[])
{
  Options o;
  const int parsed = ParseOptions(argc, argv, o);
  if (parsed >= 0)
  {
    return parsed;
  }
  vtkErrorDiffusionParameterTable start;
  if (!ReadStart(o.Start, start) || !CanWrite(o.Output))
  {
    return 1;
  }
  Finished done;
  if (o.Resume)
  {
    ReadDone(o.Output, done);
    std::cout << "resuming: " << done.size() << " level(s) already in " << o.Output << std::endl;
  }
  const std::vector<double> todo = LevelsToDo(o.Levels, done);
  const std::string header = TableHeader(o);
  Search search(o, start, todo, header, done);
  search.Run(static_cast<unsigned>(o.Threads));
  if (todo.empty() && !done.empty())
  {
    WriteTable(o.Output, done, header);
  }
  std::cout << "table: " << o.Output << " (" << done.size() << " levels)" << std::endl;
  return done.empty() ? 1 : 0;
}
