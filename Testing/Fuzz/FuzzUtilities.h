// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Shared pieces of the libFuzzer targets: an observer that collects a filter's
// errors and warnings (so that nothing is printed per input), the check that
// stops the fuzzer with a message, and value pickers that favor the values
// filters stumble on (NaN, infinities, extremes, zero).
#ifndef BlueNoiseFuzzUtilities_h
#define BlueNoiseFuzzUtilities_h

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

namespace bluenoise_fuzz
{
/// Collects ErrorEvent and WarningEvent messages of the objects it watches.
class MessageObserver : public vtkCommand
{
public:
  static MessageObserver* New() { return new MessageObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const char* text = static_cast<const char*>(data);
    if (event == vtkCommand::ErrorEvent)
    {
      ++this->NumberOfErrors;
      this->Errors += text ? text : "(null)";
    }
  }
  /// Watch the algorithm and its executive (which reports failed passes).
  void Watch(vtkAlgorithm* algorithm)
  {
    for (vtkObject* object : { static_cast<vtkObject*>(algorithm),
           static_cast<vtkObject*>(algorithm->GetExecutive()) })
    {
      object->AddObserver(vtkCommand::ErrorEvent, this);
      object->AddObserver(vtkCommand::WarningEvent, this);
    }
  }
  void Reset()
  {
    this->NumberOfErrors = 0;
    this->Errors.clear();
  }
  int NumberOfErrors = 0;
  std::string Errors;
};

/// A broken promise of the filter under test: print and abort, which libFuzzer
/// reports as a crash with the input that caused it.
inline void Require(bool condition, const char* what, const std::string& detail = std::string())
{
  if (!condition)
  {
    std::fprintf(stderr, "FUZZ CHECK FAILED: %s %s\n", what, detail.c_str());
    std::abort();
  }
}

/// A double that is often one of the values filters mishandle.
inline double PickDouble(FuzzedDataProvider& fdp, double lo, double hi)
{
  constexpr double specials[] = { std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
    std::numeric_limits<double>::denorm_min(), 0.0, -0.0, 1.0, -1.0, 1e300, -1e300 };
  switch (fdp.ConsumeIntegralInRange<int>(0, 3))
  {
    case 0:
      return fdp.PickValueInArray(specials);
    case 1:
      return fdp.ConsumeFloatingPoint<double>();
    default:
      return fdp.ConsumeFloatingPointInRange<double>(lo, hi);
  }
}

/// Discards what objects without observers print. (vtkObject's global warning
/// display cannot be switched off instead: it silences ErrorEvent too.)
class NullOutputWindow : public vtkOutputWindow
{
public:
  static NullOutputWindow* New() { return new NullOutputWindow; }
  void DisplayText(const char*) override {}
};

/// Quiet VTK's output window once per process.
inline void Quiet()
{
  static const bool once = []() {
    vtkNew<NullOutputWindow> window;
    vtkOutputWindow::SetInstance(window);
    return true;
  }();
  (void)once;
}
}

#endif
