// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// The parameter table: Table 1 verbatim, interpolation between keys, the
// g > 0.5 mirror, and the text format (round trip, errors naming the line).
#include "BlueNoiseTestUtilities.h"
#include "vtkErrorDiffusionParameterTable.h"

#include <cmath>
#include <sstream>

using namespace bluenoise_test;

namespace
{
bool Near(double a, double b, double tol = 1e-6)
{
  return std::abs(a - b) <= tol;
}

/// What Write prints parses back to the same keys, exactly.
bool RoundTrips(const vtkErrorDiffusionParameterTable& table)
{
  std::stringstream text;
  table.Write(text, "written by the test\nsecond comment line");
  vtkErrorDiffusionParameterTable back;
  std::string error;
  if (!vtkErrorDiffusionParameterTable::Parse(text, back, error))
  {
    return false;
  }
  bool same = back.GetKeys().size() == table.GetKeys().size();
  for (size_t i = 0; same && i < back.GetKeys().size(); ++i)
  {
    same = back.GetKeys()[i].Level == table.GetKeys()[i].Level &&
      back.GetKeys()[i].Coefficients == table.GetKeys()[i].Coefficients &&
      back.GetKeys()[i].Modulation == table.GetKeys()[i].Modulation;
  }
  return same;
}

void ExpectParseError(const std::string& text, const std::string& expected)
{
  std::istringstream in(text);
  vtkErrorDiffusionParameterTable table;
  std::string error;
  const bool ok = vtkErrorDiffusionParameterTable::Parse(in, table, error);
  Check(!ok, "malformed table accepted: " + text);
  Check(error.find(expected) != std::string::npos,
    "error '" + error + "' does not contain '" + expected + "'");
}
}

int main()
{
  const auto paper = vtkErrorDiffusionParameterTable::Paper();
  Check(paper.GetKeys().size() == 17, "Table 1 has 17 key levels");
  Check(paper.GetKeys()[1].Level == 8 && paper.GetKeys()[1].Coefficients[0] == 525 &&
      paper.GetKeys()[16].Modulation == 1.23,
    "Table 1 values");

  // At a key: A / M exactly.
  {
    const auto p = paper.Evaluate(8.0 / 255.0);
    const double m = 525 + 319 + 719 + 291 + 132 + 204;
    Check(Near(p.Weights[0], 525 / m) && Near(p.Weights[5], 204 / m) && Near(p.Modulation, 1.19),
      "parameters at key 8");
    double sum = 0;
    for (float w : p.Weights)
    {
      sum += w;
    }
    Check(Near(sum, 1.0), "weights sum to 1");
  }
  // Halfway between keys 8 and 16: the mean of the normalized parameters.
  {
    const auto a = paper.Evaluate(8.0 / 255.0);
    const auto b = paper.Evaluate(16.0 / 255.0);
    const auto p = paper.Evaluate(12.0 / 255.0);
    bool ok = Near(p.Modulation, 0.5 * (a.Modulation + b.Modulation));
    for (int c = 0; c < 6; ++c)
    {
      ok = ok && Near(p.Weights[c], 0.5 * (a.Weights[c] + b.Weights[c]));
    }
    Check(ok, "linear interpolation between keys 8 and 16");
  }
  // Mirror: g and 1 - g share their parameters.
  for (double level : { 3.0, 8.0, 50.5, 100.0, 127.0 })
  {
    const auto lo = paper.Evaluate(level / 255.0);
    const auto hi = paper.Evaluate(1.0 - level / 255.0);
    bool ok = Near(lo.Modulation, hi.Modulation);
    for (int c = 0; c < 6; ++c)
    {
      ok = ok && Near(lo.Weights[c], hi.Weights[c]);
    }
    Check(ok, "mirror at level " + Str(level));
  }
  // Below the first and above the last key: clamped.
  Check(Near(paper.Evaluate(0.0).Modulation, 1.00) && Near(paper.Evaluate(0.5).Modulation, 1.23),
    "clamping outside the keys");

  // The shipped Optimized table parses and covers the paper's 17 key levels.
  {
    const auto optimized = vtkErrorDiffusionParameterTable::Optimized();
    bool same = optimized.GetKeys().size() == paper.GetKeys().size();
    for (size_t i = 0; same && i < paper.GetKeys().size(); ++i)
    {
      same = optimized.GetKeys()[i].Level == paper.GetKeys()[i].Level;
    }
    Check(same, "Optimized table has the 17 key levels");
    double sum = 0;
    for (float w : optimized.Evaluate(20.0 / 255.0).Weights)
    {
      sum += w;
    }
    Check(Near(sum, 1.0), "Optimized weights sum to 1");
  }

  const auto fixed = vtkErrorDiffusionParameterTable::Fixed();
  Check(Near(fixed.Evaluate(0.3).Weights[0], 4.0 / 16.0) &&
      Near(fixed.Evaluate(0.01).Weights[1], 2.0 / 16.0) && Near(fixed.Evaluate(0.7).Modulation, 1.0),
    "Fixed parameters");

  // Round trip through the text format.
  Check(RoundTrips(paper), "round trip keeps every key of Table 1");
  // Values that ten digits do not hold (found by FuzzErrorDiffusionParameterTable:
  // Write printed 0.22379437252 as 0.2237943725), and levels that differ beyond
  // the tenth digit, which then collided and no longer increased.
  {
    std::istringstream in("1.00000000001 1 1 1 1 1 1 1\n1.00000000002 1 1 1 1 1 1 1\n"
                          "56 0.2149282335 0.08268727514 0.2393145864 0.05878002222 "
                          "0.1804955102 0.22379437252 1.058935205\n");
    vtkErrorDiffusionParameterTable precise;
    std::string error;
    Check(vtkErrorDiffusionParameterTable::Parse(in, precise, error), "parse: " + error);
    Check(RoundTrips(precise), "round trip keeps values beyond ten digits");
    std::ostringstream out;
    paper.Write(out);
    Check(out.str().find("\n8 525 319 719 291 132 204 1.19\n") != std::string::npos,
      "short values stay short: " + out.str());
  }
  // Commas, comments and blank lines are accepted.
  {
    std::istringstream in("# header\n\n 4, 1,1,1,1,1,1, 0.5  # trailing\n64 2 2 2 2 2 2 1\n");
    vtkErrorDiffusionParameterTable t;
    std::string error;
    Check(vtkErrorDiffusionParameterTable::Parse(in, t, error) && t.GetKeys().size() == 2,
      "lenient syntax: " + error);
  }
  // Malformed tables: the error names the line.
  ExpectParseError("1 2 3 4 5 6 7\n", "line 1: expected 8 numbers");
  ExpectParseError("# c\n8 1 1 1 1 1 1 1\n4 1 1 1 1 1 1 1\n", "line 3");
  ExpectParseError("8 1 1 1 1 1 1 1\n16 1 1 x 1 1 1 1\n", "line 2: 'x' is not a number");
  ExpectParseError("8 1 -1 1 1 1 1 1\n", "non-negative");
  ExpectParseError("8 0 0 0 0 0 0 1\n", "line 1");
  ExpectParseError("200 1 1 1 1 1 1 1\n", "127.5");
  ExpectParseError("# only comments\n", "no parameter lines");
  // Found by fuzzing: coefficients whose sum overflows (every weight became 0),
  // an m(g) too large for the float it is used as (it became infinite), and a
  // field with a NUL byte inside (read as the number before it).
  ExpectParseError("8 1e308 1e308 1 1 1 1 1\n", "finite sum");
  ExpectParseError("8 1 1 1 1 1 1 1e66\n", "m(g)");
  ExpectParseError(std::string("8 1 1 1 1 1 1 1\n16 1 2\0x 1 1 1 1 1\n", 35), "line 2");
  // A long table parses (each line is checked against the one before; checking
  // the whole table again per line took hours for this one).
  {
    std::ostringstream text;
    for (int i = 1; i <= 100000; ++i)
    {
      text << i * 0.001 << " 1 2 3 4 5 6 1\n";
    }
    std::istringstream in(text.str());
    vtkErrorDiffusionParameterTable t;
    std::string error;
    Check(vtkErrorDiffusionParameterTable::Parse(in, t, error) && t.GetKeys().size() == 100000,
      "a table of 100000 keys: " + error);
  }
  {
    vtkErrorDiffusionParameterTable t;
    std::string error;
    Check(!vtkErrorDiffusionParameterTable::ReadFile("/nonexistent/table.txt", t, error) &&
        error.find("cannot open") != std::string::npos,
      "missing file reported");
  }
  return Summary("TestErrorDiffusionParameterTable");
}
