// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Small helpers shared by the C++ tests: failure reporting, an error observer
// and constant / ramp volumes.
#ifndef BlueNoiseTestUtilities_h
#define BlueNoiseTestUtilities_h

#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <cstdlib>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>

namespace bluenoise_test
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

// Records a failed check with its message; tests return Summary() at the end.
inline bool Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << std::endl;
    ++Failures();
  }
  return ok;
}

inline int Summary(const char* test)
{
  if (Failures() == 0)
  {
    std::cout << test << ": all checks passed" << std::endl;
    return EXIT_SUCCESS;
  }
  std::cerr << test << ": " << Failures() << " check(s) failed" << std::endl;
  return EXIT_FAILURE;
}

template <typename T>
std::string Str(const T& value)
{
  std::ostringstream s;
  s << value;
  return s.str();
}

// Catches ErrorEvent/WarningEvent messages of an object instead of printing them.
class MessageObserver : public vtkCommand
{
public:
  static MessageObserver* New() { return new MessageObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    if (event == vtkCommand::ErrorEvent)
    {
      this->Errors += text;
      ++this->ErrorCount;
    }
    else if (event == vtkCommand::WarningEvent)
    {
      this->Warnings += text;
      ++this->WarningCount;
    }
  }
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
    this->ErrorCount = this->WarningCount = 0;
  }
  bool ErrorContains(const std::string& part) const
  {
    return this->Errors.find(part) != std::string::npos;
  }
  std::string Errors;
  std::string Warnings;
  int ErrorCount = 0;
  int WarningCount = 0;
};

// An nx*ny*nz image with a float point array "density" = f(i, j, k).
inline vtkSmartPointer<vtkImageData> MakeVolume(
  int nx, int ny, int nz, const std::function<float(int, int, int)>& f, const char* name = "density")
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  auto values = vtkSmartPointer<vtkFloatArray>::New();
  values->SetName(name);
  values->SetNumberOfValues(static_cast<vtkIdType>(nx) * ny * nz);
  vtkIdType id = 0;
  for (int k = 0; k < nz; ++k)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        values->SetValue(id++, f(i, j, k));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

inline vtkSmartPointer<vtkImageData> MakeConstantVolume(int n, float g)
{
  return MakeVolume(n, n, n, [g](int, int, int) { return g; });
}
}

#endif
