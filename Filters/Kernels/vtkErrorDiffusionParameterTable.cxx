// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionParameterTable.h"
#include "vtkErrorDiffusionOptimizedParameters.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace
{
// Table 1 of the paper: level, A100, A-110, A010, A0-11, A-101, A001, m(g).
const double PaperTable[17][8] = {
  { 1, 380, 79, 270, 62, 72, 59, 1.00 },
  { 8, 525, 319, 719, 291, 132, 204, 1.19 },
  { 16, 355, 202, 394, 171, 213, 110, 1.09 },
  { 24, 338, 211, 240, 196, 164, 114, 1.06 },
  { 32, 187, 179, 403, 132, 170, 144, 0.99 },
  { 40, 163, 84, 394, 127, 236, 102, 1.04 },
  { 48, 181, 90, 317, 75, 110, 154, 0.93 },
  { 56, 114, 141, 446, 110, 211, 163, 1.04 },
  { 64, 169, 99, 321, 101, 103, 154, 0.89 },
  { 72, 225, 251, 221, 199, 54, 164, 0.98 },
  { 80, 164, 209, 419, 236, 41, 179, 1.06 },
  { 88, 130, 212, 498, 203, 54, 198, 1.05 },
  { 96, 228, 209, 325, 140, 314, 380, 1.01 },
  { 104, 173, 104, 368, 67, 65, 203, 0.94 },
  { 112, 122, 184, 436, 109, 234, 166, 1.09 },
  { 120, 75, 225, 535, 82, 129, 236, 1.02 },
  { 127, 366, 322, 324, 80, 125, 283, 1.23 },
};

constexpr double MaxLevel = 127.5; // g = 0.5 in 1/255 units

std::string Trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos)
  {
    return std::string();
  }
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// Ten significant digits keep a table readable; a value they do not reproduce
// exactly gets 17 (enough for any double), so that what Write prints parses
// back to the same table.
std::string Format(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.10g", value);
  if (std::strtod(text, nullptr) != value)
  {
    std::snprintf(text, sizeof(text), "%.17g", value);
  }
  return text;
}

using Key = vtkErrorDiffusionParameterTable::Key;

/// What is wrong with one key after `previous` (nullptr for the first), or nullptr.
const char* KeyProblem(const Key& k, const Key* previous)
{
  if (!std::isfinite(k.Level) || k.Level <= 0.0 || k.Level > MaxLevel)
  {
    return "level must be in (0, 127.5] (1/255 units)";
  }
  if (previous && !(k.Level > previous->Level))
  {
    return "levels must increase strictly";
  }
  double sum = 0.0;
  for (double a : k.Coefficients)
  {
    if (!std::isfinite(a) || a < 0.0)
    {
      return "coefficients must be finite and non-negative";
    }
    sum += a;
  }
  if (!(sum > 0.0))
  {
    return "coefficients must not all be zero";
  }
  // An infinite sum would turn every weight into 0 (or NaN).
  if (!std::isfinite(sum))
  {
    return "coefficients must have a finite sum";
  }
  // m(g) is used as a float: a larger value would become infinite.
  if (!std::isfinite(k.Modulation) || k.Modulation < 0.0 ||
    k.Modulation > std::numeric_limits<float>::max())
  {
    return "m(g) must be finite and non-negative";
  }
  return nullptr;
}

std::string KeyName(size_t index, const Key& k)
{
  std::ostringstream where;
  where << "key " << index + 1 << " (level " << k.Level << "): ";
  return where.str();
}
}

//------------------------------------------------------------------------------
vtkErrorDiffusionParameterTable vtkErrorDiffusionParameterTable::Paper()
{
  std::vector<Key> keys;
  for (const auto& row : PaperTable)
  {
    Key k;
    k.Level = row[0];
    std::copy(row + 1, row + 7, k.Coefficients.begin());
    k.Modulation = row[7];
    keys.push_back(k);
  }
  vtkErrorDiffusionParameterTable table;
  table.SetKeys(keys);
  return table;
}

//------------------------------------------------------------------------------
vtkErrorDiffusionParameterTable vtkErrorDiffusionParameterTable::Fixed()
{
  Key k;
  k.Level = 1;
  k.Coefficients = { 4, 2, 4, 2, 2, 2 };
  k.Modulation = 1.0;
  vtkErrorDiffusionParameterTable table;
  table.SetKeys({ k });
  return table;
}

//------------------------------------------------------------------------------
vtkErrorDiffusionParameterTable vtkErrorDiffusionParameterTable::Optimized()
{
  static const vtkErrorDiffusionParameterTable table = []() {
    std::istringstream text(vtkErrorDiffusionOptimizedParametersText);
    vtkErrorDiffusionParameterTable parsed;
    std::string error;
    // The file is checked by the test of this class; a broken one leaves the table empty.
    Parse(text, parsed, error);
    return parsed;
  }();
  return table;
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionParameterTable::SetKeys(const std::vector<Key>& keys, std::string* error)
{
  auto fail = [error](const std::string& why) {
    if (error)
    {
      *error = why;
    }
    return false;
  };
  if (keys.empty())
  {
    return fail("the table has no key levels");
  }
  for (size_t i = 0; i < keys.size(); ++i)
  {
    if (const char* why = KeyProblem(keys[i], i > 0 ? &keys[i - 1] : nullptr))
    {
      return fail(KeyName(i, keys[i]) + why);
    }
  }
  this->Keys = keys;
  this->BuildSegments();
  return true;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionParameterTable::BuildSegments()
{
  this->Normalized.clear();
  for (const Key& k : this->Keys)
  {
    double sum = 0.0;
    for (double a : k.Coefficients)
    {
      sum += a;
    }
    Parameters p;
    for (int c = 0; c < NumberOfCoefficients; ++c)
    {
      p.Weights[c] = static_cast<float>(k.Coefficients[c] / sum);
    }
    p.Modulation = static_cast<float>(k.Modulation);
    this->Normalized.push_back(p);
  }
}

//------------------------------------------------------------------------------
vtkErrorDiffusionParameterTable::Parameters vtkErrorDiffusionParameterTable::Evaluate(
  double g) const
{
  if (this->Normalized.empty())
  {
    return Parameters();
  }
  if (!(g >= 0.0)) // NaN too
  {
    g = 0.0;
  }
  g = std::min(g, 1.0);
  const double level = 255.0 * (g > 0.5 ? 1.0 - g : g);
  const size_t n = this->Keys.size();
  if (level <= this->Keys.front().Level)
  {
    return this->Normalized.front();
  }
  if (level >= this->Keys.back().Level)
  {
    return this->Normalized.back();
  }
  // At most 17 keys: a linear search is as fast as anything else here.
  size_t i = 0;
  while (i + 2 < n && this->Keys[i + 1].Level <= level)
  {
    ++i;
  }
  const double l0 = this->Keys[i].Level;
  const double l1 = this->Keys[i + 1].Level;
  const float t = static_cast<float>((level - l0) / (l1 - l0));
  const Parameters& p0 = this->Normalized[i];
  const Parameters& p1 = this->Normalized[i + 1];
  Parameters p;
  for (int c = 0; c < NumberOfCoefficients; ++c)
  {
    p.Weights[c] = p0.Weights[c] + t * (p1.Weights[c] - p0.Weights[c]);
  }
  p.Modulation = p0.Modulation + t * (p1.Modulation - p0.Modulation);
  return p;
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionParameterTable::Parse(
  std::istream& in, vtkErrorDiffusionParameterTable& table, std::string& error)
{
  std::vector<Key> keys;
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line))
  {
    ++lineNumber;
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    std::replace(line.begin(), line.end(), ',', ' ');
    line = Trim(line);
    if (line.empty())
    {
      continue;
    }
    std::istringstream fields(line);
    std::vector<double> values;
    std::string field;
    while (fields >> field)
    {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      // The whole field, up to a NUL byte inside it too.
      if (end == field.c_str() || end != field.c_str() + field.size())
      {
        error = "line " + std::to_string(lineNumber) + ": '" + field + "' is not a number";
        return false;
      }
      values.push_back(v);
    }
    if (values.size() != 8)
    {
      error = "line " + std::to_string(lineNumber) + ": expected 8 numbers (level, six " +
        "coefficients, m), found " + std::to_string(values.size());
      return false;
    }
    Key k;
    k.Level = values[0];
    std::copy(values.begin() + 1, values.begin() + 7, k.Coefficients.begin());
    k.Modulation = values[7];
    // Validate key by key so the message can name the line (against the key
    // before only: checking the whole table again per line made a long file
    // take quadratic time).
    if (const char* why = KeyProblem(k, keys.empty() ? nullptr : &keys.back()))
    {
      error = "line " + std::to_string(lineNumber) + ": " + KeyName(keys.size(), k) + why;
      return false;
    }
    keys.push_back(k);
  }
  if (keys.empty())
  {
    error = "no parameter lines found (expected: level A100 A-110 A010 A0-11 A-101 A001 m)";
    return false;
  }
  return table.SetKeys(keys, &error);
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionParameterTable::ReadFile(
  const std::string& fileName, vtkErrorDiffusionParameterTable& table, std::string& error)
{
  std::ifstream in(fileName);
  if (!in)
  {
    error = "cannot open '" + fileName + "'";
    return false;
  }
  if (!Parse(in, table, error))
  {
    error = fileName + ": " + error;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionParameterTable::Write(std::ostream& out, const std::string& comment) const
{
  if (!comment.empty())
  {
    std::istringstream lines(comment);
    std::string line;
    while (std::getline(lines, line))
    {
      out << "# " << line << "\n";
    }
  }
  out << "# level  A100  A-110  A010  A0-11  A-101  A001  m\n";
  for (const Key& k : this->Keys)
  {
    out << Format(k.Level);
    for (double a : k.Coefficients)
    {
      out << ' ' << Format(a);
    }
    out << ' ' << Format(k.Modulation) << "\n";
  }
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionParameterTable::WriteFile(
  const std::string& fileName, const std::string& comment) const
{
  std::ofstream out(fileName);
  if (!out)
  {
    return false;
  }
  this->Write(out, comment);
  return static_cast<bool>(out);
}
