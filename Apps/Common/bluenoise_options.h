// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The one option parser of the programs (bluenoise-sample, -optimize,
// -quality): CLI11 with strict numbers and the options several programs
// share defined once, so that each option name has one meaning.
//
// Numbers are parsed whole: "abc", "12x", "inf", "nan", a value outside the
// option's range or one that overflows its type is an error naming the option
// and the value. Parse() prints --help to stdout and nothing else; every
// parse error is printed to stderr as "program: message".
#ifndef bluenoise_options_h
#define bluenoise_options_h

#include <memory>
#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace bluenoise
{
class CommandLine
{
public:
  /// `program`: the name in messages; `description`: the first line of --help.
  CommandLine(const std::string& program, const std::string& description);
  ~CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  /// An integer in [lo, hi].
  void AddInteger(const std::string& name, long long& value, long long lo, long long hi,
    const std::string& help);
  void AddInteger(
    const std::string& name, int& value, int lo, int hi, const std::string& help);
  /// A finite real in [lo, hi] (or (lo, hi] with `loOpen`).
  void AddReal(const std::string& name, double& value, double lo, double hi,
    const std::string& help, bool loOpen = false);
  /// A comma-separated list of finite reals, each in (lo, hi].
  void AddRealList(const std::string& name, std::vector<double>& values, double lo, double hi,
    const std::string& help);
  /// A string; `type` names it in --help (FILE, DIR, NAME, ...).
  void AddText(const std::string& name, std::string& value, const std::string& type,
    const std::string& help);
  /// One of `choices`, spelled exactly; anything else is an error that lists them.
  void AddChoice(const std::string& name, std::string& value,
    const std::vector<std::string>& choices, const std::string& help);
  void AddFlag(const std::string& name, bool& value, const std::string& help);
  /// At most one positional argument.
  void AddPositional(const std::string& name, std::string& value, const std::string& help);
  /// Two options that exclude each other.
  void Exclude(const std::string& a, const std::string& b);
  /// Text printed after the options by --help.
  void SetFooter(const std::string& footer);

  // Options several programs share: one name, one meaning, one range.
  /// --size L: the edge of the cube a measurement samples, in [8, 1024].
  void AddCubeSize(int& value);
  /// --seeds K: realizations per measurement, seeds first..first+K-1, in [lo, 10000].
  void AddSeedCount(int& value, int lo);
  /// --weight W: w in T = w L + (1 - w) S, in [0, 1].
  void AddWeight(double& value);
  /// --levels LIST: density levels in 1/255 units, each in (0, 127.5].
  void AddLevels(std::vector<double>& values);

  /// -1 to go on; otherwise the exit status (0 after --help, 2 after an error).
  int Parse(int argc, char* argv[]);

private:
  std::string Program;
  std::unique_ptr<CLI::App> App;
};

/// Strict parsing, also for files: false unless `text` is one whole finite number.
bool ParseReal(const std::string& text, double& value);
bool ParseInteger(const std::string& text, long long& value);
}

#endif
