// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkErrorDiffusionLayerBacklog.h"

#include <limits>

//------------------------------------------------------------------------------
void vtkErrorDiffusionLayerBacklog::SetSink(Sink* sink)
{
  this->Clear();
  this->Output = sink;
  this->Pushes = 0;
}

//------------------------------------------------------------------------------
// The next Push is number Pushes + 1: it may overwrite what Push number
// Pushes - 1 (and any before it) returned.
void vtkErrorDiffusionLayerBacklog::BeforePush()
{
  this->EmitThrough(this->Pushes - 1);
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionLayerBacklog::AfterPush(const std::vector<Layer>& layers)
{
  ++this->Pushes;
  for (const Layer& layer : layers)
  {
    {
      std::lock_guard<std::mutex> lock(this->Queue);
      this->Entries.push_back({ layer, this->Pushes });
    }
    if (layer.Borrowed)
    {
      this->EmitAll(); // the caller's buffers: emitted, in order, before the caller goes on
    }
  }
}

//------------------------------------------------------------------------------
bool vtkErrorDiffusionLayerBacklog::EmitOne()
{
  std::unique_lock<std::mutex> emitting(this->Emitting, std::try_to_lock);
  Layer layer;
  if (!emitting.owns_lock() || !this->Take(std::numeric_limits<long>::max(), layer))
  {
    return false;
  }
  this->Output->Emit(layer);
  return true;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionLayerBacklog::EmitAll()
{
  this->EmitThrough(this->Pushes);
}

//------------------------------------------------------------------------------
// Emits the layers of Push number `push` and before, after the one another
// thread may be emitting (the lock also makes what that thread wrote visible
// here).
void vtkErrorDiffusionLayerBacklog::EmitThrough(long push)
{
  std::lock_guard<std::mutex> emitting(this->Emitting);
  for (Layer layer; this->Take(push, layer);)
  {
    this->Output->Emit(layer);
  }
}

//------------------------------------------------------------------------------
// The oldest layer queued, if Push number `push` or one before it returned it.
bool vtkErrorDiffusionLayerBacklog::Take(long push, Layer& layer)
{
  std::lock_guard<std::mutex> lock(this->Queue);
  if (this->Entries.empty() || this->Entries.front().Push > push)
  {
    return false;
  }
  layer = this->Entries.front().Final;
  this->Entries.pop_front();
  return true;
}

//------------------------------------------------------------------------------
void vtkErrorDiffusionLayerBacklog::Clear()
{
  std::lock_guard<std::mutex> emitting(this->Emitting);
  std::lock_guard<std::mutex> lock(this->Queue);
  this->Entries.clear();
}
