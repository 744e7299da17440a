// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// See bluenoise_messages.h.
#include "bluenoise_messages.h"

#include "vtkBlueNoiseVolumeFileCheck.h"

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkObject.h"

namespace bluenoise
{
std::string PlainMessage(const char* message)
{
  return vtkBlueNoiseVolumeFileCheck::PlainMessage(message);
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
