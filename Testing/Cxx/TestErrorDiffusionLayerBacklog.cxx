// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkErrorDiffusionLayerBacklog: layers are emitted once each, in the order
// the relaxation returned them, whichever thread emits. Emitted as late as
// the backlog allows (no other thread), a relaxation's final layers still
// hold what they held when Push returned them (vtkBlueNoiseRelaxation's
// promise: their buffers last through the next Push), and a borrowed layer
// (the caller's buffers, overwritten by the caller's next layer) is emitted
// before Push returns. With a second thread emitting all it can meanwhile
// (run under ThreadSanitizer in CI) the result is the same.
#include "BlueNoiseTestUtilities.h"
#include "vtkBlueNoiseRelaxation.h"
#include "vtkErrorDiffusionLayerBacklog.h"

#include <atomic>
#include <cstdint>
#include <thread>
#include <utility>
#include <vector>

using namespace bluenoise_test;

namespace
{
using Layer = vtkBlueNoiseRelaxation::Layer;

// A sink that calls `f` with each layer.
template <typename F>
class FunctionSink : public vtkErrorDiffusionLayerBacklog::Sink
{
public:
  explicit FunctionSink(F f)
    : Function(std::move(f))
  {
  }
  void Emit(const Layer& layer) override { this->Function(layer); }

private:
  F Function;
};

template <typename F>
FunctionSink<F> MakeSink(F f)
{
  return FunctionSink<F>(std::move(f));
}
const int N = 40, NZ = 64;
const size_t LayerSize = static_cast<size_t>(N) * N;

struct Emitted
{
  int Z;
  bool Borrowed;
  std::vector<unsigned char> Mask;
  std::vector<float> Density;
};

// Layers above the relaxation's density limit are final as they come:
// borrowed (the first three and the last ones), or copied when a layer before
// them still waits (3, 10, 17, ...).
float LayerDensity(int z)
{
  return z < 3 || z % 7 == 3 || z >= 48 ? 0.5f : 0.05f + 0.001f * static_cast<float>(z % 5);
}

void MakeLayer(int z, std::vector<float>& density, std::vector<unsigned char>& mask)
{
  for (size_t i = 0; i < LayerSize; ++i)
  {
    density[i] = LayerDensity(z);
    std::uint64_t h = (i + 1) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(z) * 0xC2B2AE3D27D4EB4FULL;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ULL;
    mask[i] = static_cast<double>(h >> 11) * 0x1.0p-53 < density[i] ? 1 : 0;
  }
}

Emitted Copy(const Layer& layer)
{
  return { layer.Z, layer.Borrowed, std::vector<unsigned char>(layer.Mask, layer.Mask + LayerSize),
    std::vector<float>(layer.Density, layer.Density + LayerSize) };
}

// Pushes every layer, one buffer pair for all (as the layer runner reuses
// its slots): through the backlog when `backlog`, else emitting what Push
// returns at once (the reference). `helper` adds a thread calling EmitOne.
std::vector<Emitted> Run(bool backlog, bool helper)
{
  std::vector<Emitted> out;
  vtkBlueNoiseRelaxation relaxation;
  relaxation.Begin(N, N, 0, 11);
  vtkErrorDiffusionLayerBacklog queue;
  auto sink = MakeSink([&out](const Layer& layer) { out.push_back(Copy(layer)); });
  queue.SetSink(&sink);
  std::atomic<bool> done{ false };
  std::thread other;
  if (helper)
  {
    other = std::thread([&]() {
      while (!done.load())
      {
        queue.EmitOne();
      }
    });
  }
  std::vector<float> density(LayerSize);
  std::vector<unsigned char> mask(LayerSize);
  for (int z = 0; z < NZ; ++z)
  {
    MakeLayer(z, density, mask);
    if (!backlog)
    {
      for (const Layer& layer : relaxation.Push(z, density.data(), mask.data()))
      {
        out.push_back(Copy(layer));
      }
      continue;
    }
    queue.BeforePush();
    queue.AfterPush(relaxation.Push(z, density.data(), mask.data()));
  }
  if (backlog)
  {
    queue.AfterPush(relaxation.Flush());
    queue.EmitAll();
  }
  else
  {
    for (const Layer& layer : relaxation.Flush())
    {
      out.push_back(Copy(layer));
    }
  }
  done.store(true);
  if (other.joinable())
  {
    other.join();
  }
  return out;
}

bool Same(const std::vector<Emitted>& a, const std::vector<Emitted>& b)
{
  bool same = a.size() == b.size();
  for (size_t k = 0; same && k < a.size(); ++k)
  {
    same = a[k].Z == b[k].Z && a[k].Mask == b[k].Mask && a[k].Density == b[k].Density;
  }
  return same;
}

// The queue on its own: order, and which call emits what.
void CheckOrder()
{
  std::vector<int> order;
  vtkErrorDiffusionLayerBacklog queue;
  auto sink = MakeSink([&order](const Layer& layer) { order.push_back(layer.Z); });
  queue.SetSink(&sink);
  const auto layer = [](int z, bool borrowed) {
    Layer l;
    l.Z = z;
    l.Borrowed = borrowed;
    return l;
  };
  queue.BeforePush();
  queue.AfterPush({ layer(0, false), layer(1, false) });
  Check(queue.EmitOne() && order == std::vector<int>{ 0 }, "EmitOne emits the oldest layer");
  queue.BeforePush();
  Check(order.size() == 1, "BeforePush keeps what the last Push returned");
  queue.AfterPush({ layer(2, false) });
  queue.BeforePush();
  Check(order == std::vector<int>{ 0, 1 }, "BeforePush emits what the Push before the last returned");
  queue.AfterPush({ layer(3, true), layer(4, false) });
  Check(order == std::vector<int>{ 0, 1, 2, 3 }, "a borrowed layer is emitted at once, after those before it");
  queue.EmitAll();
  Check(order == std::vector<int>{ 0, 1, 2, 3, 4 }, "EmitAll emits the rest");
  Check(!queue.EmitOne(), "EmitOne on an empty queue does nothing");
  queue.AfterPush({ layer(5, false) });
  queue.Clear();
  queue.EmitAll();
  Check(order.size() == 5, "Clear drops what is queued");
}
}

int main()
{
  CheckOrder();
  const std::vector<Emitted> reference = Run(false, false);
  int borrowed = 0;
  for (const Emitted& layer : reference)
  {
    borrowed += layer.Borrowed ? 1 : 0;
  }
  Check(static_cast<int>(reference.size()) == NZ && borrowed >= 4 && borrowed < NZ - 40,
    "every layer returned once, " + Str(borrowed) + " of them borrowed");
  Check(Same(Run(true, false), reference), "emitted as late as allowed, the layers are intact");
  for (int k = 0; k < 20; ++k)
  {
    if (!Check(Same(Run(true, true), reference), "with another thread emitting, run " + Str(k)))
    {
      break;
    }
  }
  return Summary("TestErrorDiffusionLayerBacklog");
}
