// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_messages.h.
#include "bluenoise_messages.h"

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"

namespace bluenoise
{
std::string PlainMessage(const char* message)
{
  std::string text = message ? message : "";
  // VTK's macros: "<kind>: In <file>, line <n>\n<Class> (<address>): <text>\n\n".
  const size_t line = text.find(", line ");
  const size_t newline = line == std::string::npos ? line : text.find('\n', line);
  if (newline != std::string::npos)
  {
    const size_t close = text.find("): ", newline);
    text = text.substr(close == std::string::npos ? newline + 1 : close + 3);
  }
  const size_t first = text.find_first_not_of(" \t\r\n");
  const size_t last = text.find_last_not_of(" \t\r\n");
  text = first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  return text.empty() ? std::string("unknown error") : text;
}

VTKMessages::~VTKMessages()
{
  for (const Observed& o : this->Objects)
  {
    o.Object->RemoveObserver(o.Tags[0]);
    o.Object->RemoveObserver(o.Tags[1]);
  }
}

void VTKMessages::Attach(vtkObject* object)
{
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(&VTKMessages::Record);
  callback->SetClientData(this);
  this->Objects.push_back({ object, { object->AddObserver(vtkCommand::ErrorEvent, callback),
                                      object->AddObserver(vtkCommand::WarningEvent, callback) } });
}

void VTKMessages::Record(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto* self = static_cast<VTKMessages*>(clientData);
  const std::string text = PlainMessage(static_cast<const char*>(callData));
  (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings).push_back(text);
}
}
