// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the text format of vtkErrorDiffusionParameterTable, parsed
// from memory (Parse) and from a file (ReadFile).
//
// The promises checked: no crash and no sanitizer report; both ways give the
// same answer; a failure names its reason and leaves the table as it was; a
// table that parses gives normalized weights (finite, non-negative, sum 1) and
// a finite non-negative modulation at every density; and what Write prints
// parses back to the same keys.
#include "FuzzUtilities.h"

#include "vtkErrorDiffusionParameterTable.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace bluenoise_fuzz;

namespace
{
void CheckEvaluate(const vtkErrorDiffusionParameterTable& table)
{
  for (double g : { -1.0, 0.0, 1e-300, 0.001, 0.01, 0.1, 0.25, 0.3, 0.49, 0.5, 0.51, 0.75, 0.99,
         1.0, 2.0, std::nan("") })
  {
    const auto p = table.Evaluate(g);
    double sum = 0.0;
    for (float w : p.Weights)
    {
      Require(std::isfinite(w) && w >= 0.0f, "finite non-negative weights", std::to_string(w));
      sum += w;
    }
    Require(std::fabs(sum - 1.0) < 1e-4, "weights sum to 1", std::to_string(sum));
    Require(std::isfinite(p.Modulation) && p.Modulation >= 0.0f, "finite non-negative m(g)",
      std::to_string(p.Modulation));
  }
}

void CheckRoundTrip(const vtkErrorDiffusionParameterTable& table, const std::string& comment)
{
  std::ostringstream out;
  table.Write(out, comment);
  std::istringstream in(out.str());
  vtkErrorDiffusionParameterTable again;
  std::string error;
  Require(vtkErrorDiffusionParameterTable::Parse(in, again, error), "Write parses back",
    error + "\n" + out.str());
  const auto& a = table.GetKeys();
  const auto& b = again.GetKeys();
  Require(a.size() == b.size(), "Write keeps every key");
  for (size_t i = 0; i < a.size(); ++i)
  {
    Require(a[i].Level == b[i].Level && a[i].Coefficients == b[i].Coefficients &&
        a[i].Modulation == b[i].Modulation,
      "Write keeps every value", out.str());
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream in(text);
  vtkErrorDiffusionParameterTable table;
  std::string error;
  const bool parsed = vtkErrorDiffusionParameterTable::Parse(in, table, error);

  static const std::string path =
    "/tmp/bluenoise-fuzz-table-" + std::to_string(getpid()) + ".txt";
  std::ofstream(path, std::ios::binary) << text;
  vtkErrorDiffusionParameterTable fromFile = vtkErrorDiffusionParameterTable::Fixed();
  std::string fileError;
  const bool read = vtkErrorDiffusionParameterTable::ReadFile(path, fromFile, fileError);
  Require(read == parsed, "ReadFile and Parse agree");

  if (!parsed)
  {
    Require(!error.empty() && fileError.find(error) != std::string::npos,
      "a failure names its reason", error + " / " + fileError);
    Require(table.IsEmpty(), "a failed Parse leaves the table unchanged");
    Require(fromFile.GetKeys().size() == 1 && fromFile.GetKeys()[0].Level == 1.0,
      "a failed ReadFile leaves the table unchanged");
    return 0;
  }
  Require(!table.IsEmpty() && fromFile.GetKeys().size() == table.GetKeys().size(),
    "both ways give the same keys");
  CheckEvaluate(table);
  CheckRoundTrip(table, text.substr(0, 40));
  return 0;
}
