// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBlueNoiseThreads.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

//------------------------------------------------------------------------------
bool vtkBlueNoiseThreads::SequentialBackend()
{
  const char* backend = vtkSMPTools::GetBackend();
  return backend && std::string(backend) == "Sequential";
}

//------------------------------------------------------------------------------
int vtkBlueNoiseThreads::Available()
{
  if (!SequentialBackend())
  {
    return std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  }
  if (const char* limit = std::getenv("VTK_SMP_MAX_THREADS"))
  {
    char* end = nullptr;
    const long n = std::strtol(limit, &end, 10);
    if (end != limit && *end == '\0' && n > 0)
    {
      return static_cast<int>(std::min<long>(n, 1024));
    }
  }
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

//------------------------------------------------------------------------------
int vtkBlueNoiseThreads::OwnThreads()
{
  return SequentialBackend() ? Available() : 1;
}

//------------------------------------------------------------------------------
void vtkBlueNoiseThreads::Split(int parts, const std::function<void(int)>& task)
{
  std::vector<std::thread> workers;
  for (int part = 1; part < parts; ++part)
  {
    workers.emplace_back([&task, part] { task(part); });
  }
  if (parts > 0)
  {
    task(0);
  }
  for (std::thread& worker : workers)
  {
    worker.join();
  }
}

//------------------------------------------------------------------------------
void vtkBlueNoiseThreads::ForEach(int count, const std::function<void(int)>& task)
{
  if (count <= 0)
  {
    return;
  }
  if (!SequentialBackend())
  {
    vtkSMPTools::For(0, count, 1, [&task](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        task(static_cast<int>(i));
      }
    });
    return;
  }
  std::atomic<int> next(0);
  Split(std::min(count, Available()), [&](int) {
    for (int i = next++; i < count; i = next++)
    {
      task(i);
    }
  });
}
