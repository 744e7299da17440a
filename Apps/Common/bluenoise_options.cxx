// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_options.h.
#include "bluenoise_options.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>

namespace bluenoise
{
namespace
{
// The help's layout kept across CLI11 versions. CLI11 2.5 and later reflow the
// description and the footer as paragraphs (the footer's indented table of
// files would lose its indentation) and print the usage line without its
// "Usage:" label; earlier versions print both as written, with the label.
class HelpFormatter : public CLI::Formatter
{
public:
  HelpFormatter()
  {
#if CLI11_VERSION_MAJOR > 2 || (CLI11_VERSION_MAJOR == 2 && CLI11_VERSION_MINOR >= 5)
    this->enable_description_formatting(false);
    this->enable_footer_formatting(false);
#endif
  }

  std::string make_usage(const CLI::App* app, std::string name) const override
  {
    std::string usage = CLI::Formatter::make_usage(app, name);
    const std::string label = this->get_label("Usage") + ":";
    if (usage.find(label) == std::string::npos)
    {
      usage.erase(0, usage.find_first_not_of('\n'));
      usage.insert(0, label + " ");
    }
    return usage;
  }
};

std::string Quoted(const std::string& text)
{
  return "'" + text + "'";
}

std::string RangeText(double lo, double hi, bool loOpen)
{
  std::ostringstream s;
  s << (loOpen ? "(" : "[") << lo << ", " << hi << "]";
  return s.str();
}

double StrictReal(const std::string& name, const std::string& text, double lo, double hi,
  bool loOpen)
{
  double value = 0.0;
  if (!ParseReal(text, value))
  {
    throw CLI::ValidationError(name, Quoted(text) + " is not a finite number");
  }
  if (value < lo || value > hi || (loOpen && value == lo))
  {
    throw CLI::ValidationError(
      name, Quoted(text) + " is out of range " + RangeText(lo, hi, loOpen));
  }
  return value;
}

long long StrictInteger(const std::string& name, const std::string& text, long long lo, long long hi)
{
  long long value = 0;
  if (!ParseInteger(text, value))
  {
    throw CLI::ValidationError(name, Quoted(text) + " is not an integer (or overflows)");
  }
  if (value < lo || value > hi)
  {
    throw CLI::ValidationError(name,
      Quoted(text) + " is out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return value;
}
}

bool ParseReal(const std::string& text, double& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const double parsed = std::strtod(text.c_str(), &end);
  if (errno == ERANGE || *end != '\0' || !std::isfinite(parsed))
  {
    return false;
  }
  value = parsed;
  return true;
}

bool ParseInteger(const std::string& text, long long& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long long parsed = std::strtoll(text.c_str(), &end, 10);
  if (errno == ERANGE || *end != '\0')
  {
    return false;
  }
  value = parsed;
  return true;
}

CommandLine::CommandLine(const std::string& program, const std::string& description)
  : Program(program)
  , App(new CLI::App(description, program))
{
  auto formatter = std::make_shared<HelpFormatter>();
  formatter->column_width(28);
  this->App->formatter(formatter);
}

CommandLine::~CommandLine() = default;

void CommandLine::AddInteger(const std::string& name, long long& value, long long lo,
  long long hi, const std::string& help)
{
  this->App
    ->add_option_function<std::string>(
      name, [&value, name, lo, hi](const std::string& text) {
        value = StrictInteger(name, text, lo, hi);
      },
      help + " (default " + std::to_string(value) + ")")
    ->type_name("INT");
}

void CommandLine::AddInteger(
  const std::string& name, int& value, int lo, int hi, const std::string& help)
{
  this->App
    ->add_option_function<std::string>(
      name, [&value, name, lo, hi](const std::string& text) {
        value = static_cast<int>(StrictInteger(name, text, lo, hi));
      },
      help + " (default " + std::to_string(value) + ")")
    ->type_name("INT");
}

void CommandLine::AddReal(const std::string& name, double& value, double lo, double hi,
  const std::string& help, bool loOpen)
{
  std::ostringstream defaultText;
  defaultText << value;
  this->App
    ->add_option_function<std::string>(
      name, [&value, name, lo, hi, loOpen](const std::string& text) {
        value = StrictReal(name, text, lo, hi, loOpen);
      },
      help + (value >= lo ? " (default " + defaultText.str() + ")" : std::string()))
    ->type_name("REAL");
}

void CommandLine::AddRealList(const std::string& name, std::vector<double>& values, double lo,
  double hi, const std::string& help)
{
  this->App
    ->add_option_function<std::string>(
      name, [&values, name, lo, hi](const std::string& text) {
        std::vector<double> parsed;
        std::stringstream list(text);
        std::string item;
        while (std::getline(list, item, ','))
        {
          parsed.push_back(StrictReal(name, item, lo, hi, true));
        }
        if (parsed.empty())
        {
          throw CLI::ValidationError(name, "an empty list");
        }
        values = parsed;
      },
      help)
    ->type_name("LIST");
}

void CommandLine::AddText(const std::string& name, std::string& value, const std::string& type,
  const std::string& help)
{
  this->App
    ->add_option_function<std::string>(
      name, [&value, name](const std::string& text) {
        if (text.empty())
        {
          throw CLI::ValidationError(name, "an empty value");
        }
        value = text;
      },
      help + (value.empty() ? std::string() : " (default " + value + ")"))
    ->type_name(type);
}

void CommandLine::AddChoice(const std::string& name, std::string& value,
  const std::vector<std::string>& choices, const std::string& help)
{
  std::string list;
  for (size_t i = 0; i < choices.size(); ++i)
  {
    list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  }
  this->App
    ->add_option_function<std::string>(
      name, [&value, name, choices, list](const std::string& text) {
        if (std::find(choices.begin(), choices.end(), text) == choices.end())
        {
          throw CLI::ValidationError(name, Quoted(text) + " is not one of " + list);
        }
        value = text;
      },
      help + ": " + list + (value.empty() ? std::string() : " (default " + value + ")"))
    ->type_name("NAME");
}

void CommandLine::AddFlag(const std::string& name, bool& value, const std::string& help)
{
  this->App->add_flag(name, value, help);
}

void CommandLine::AddPositional(
  const std::string& name, std::string& value, const std::string& help)
{
  this->App->add_option(name, value, help)->type_name("FILE");
}

void CommandLine::Exclude(const std::string& a, const std::string& b)
{
  this->App->get_option(a)->excludes(this->App->get_option(b));
}

void CommandLine::SetFooter(const std::string& footer)
{
  this->App->footer(footer);
}

void CommandLine::AddCubeSize(int& value)
{
  this->AddInteger("--size", value, 8, 1024, "edge L of the constant-density cube sampled per measurement");
}

void CommandLine::AddSeedCount(int& value, int lo)
{
  this->AddInteger("--seeds", value, lo, 10000, "realizations averaged per measurement");
}

void CommandLine::AddWeight(double& value)
{
  this->AddReal("--weight", value, 0.0, 1.0, "w in the target value T = w L + (1 - w) S");
}

void CommandLine::AddLevels(std::vector<double>& values)
{
  std::ostringstream help;
  help << "comma-separated density levels in 1/255 units, each in (0, 127.5] (default";
  for (size_t i = 0; i < values.size(); ++i)
  {
    help << (i ? "," : " ") << values[i];
  }
  help << ")";
  this->AddRealList("--levels", values, 0.0, 127.5, help.str());
}

int CommandLine::Parse(int argc, char* argv[])
{
  try
  {
    this->App->parse(argc, argv);
  }
  catch (const CLI::CallForHelp&)
  {
    std::cout << this->App->help();
    return 0;
  }
  catch (const CLI::ParseError& e)
  {
    std::cerr << this->Program << ": " << e.what() << "\n"
              << "(" << this->Program << " --help lists the options)\n";
    return 2;
  }
  return -1;
}
}
