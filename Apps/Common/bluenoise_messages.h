// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// VTK's errors and warnings of one object (vtkErrorMacro, vtkWarningMacro)
// collected instead of printed, without VTK's "In file, line" prefix, so a
// program can say them in its own words.
#ifndef bluenoise_messages_h
#define bluenoise_messages_h

#include <string>
#include <vector>

class vtkObject;

namespace bluenoise
{
class VTKMessages
{
public:
  VTKMessages() = default;
  ~VTKMessages();
  VTKMessages(const VTKMessages&) = delete;
  VTKMessages& operator=(const VTKMessages&) = delete;

  /// Collects `object`'s ErrorEvent and WarningEvent until destroyed (several
  /// objects may be attached; `object` must outlive this).
  void Attach(vtkObject* object);
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;

private:
  static void Record(vtkObject*, unsigned long event, void* clientData, void* callData);
  struct Observed
  {
    vtkObject* Object;
    unsigned long Tags[2];
  };
  std::vector<Observed> Objects;
};

/// VTK's message text without the "ERROR: In file, line N\nClass (0x...): " prefix.
std::string PlainMessage(const char* message);
}

#endif
