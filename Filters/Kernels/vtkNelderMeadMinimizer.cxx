// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNelderMeadMinimizer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

//------------------------------------------------------------------------------
vtkNelderMeadMinimizer::Result vtkNelderMeadMinimizer::Minimize(
  const Function& f, const std::vector<double>& start, const std::vector<double>& steps) const
{
  const size_t n = start.size();
  Result result;
  int evaluations = 0;
  auto evaluate = [&](const std::vector<double>& x) {
    ++evaluations;
    const double v = f(x);
    return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
  };

  std::vector<std::vector<double>> simplex(n + 1, start);
  std::vector<double> values(n + 1);
  values[0] = evaluate(start);
  for (size_t i = 0; i < n; ++i)
  {
    simplex[i + 1][i] += (i < steps.size() && steps[i] != 0.0) ? steps[i] : 0.05;
    values[i + 1] = evaluate(simplex[i + 1]);
  }

  std::vector<size_t> order(n + 1);
  std::vector<double> centroid(n), trial(n), second(n);
  auto along = [&](double t, std::vector<double>& out) {
    // centroid + t * (centroid - worst)
    const std::vector<double>& worst = simplex[order[n]];
    for (size_t j = 0; j < n; ++j)
    {
      out[j] = centroid[j] + t * (centroid[j] - worst[j]);
    }
  };

  int iterations = 0;
  bool converged = false;
  while (evaluations < this->MaximumEvaluations)
  {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return values[a] < values[b]; });
    const double best = values[order[0]];
    const double worstValue = values[order[n]];
    if (std::isfinite(worstValue) && worstValue - best <= this->Tolerance * (std::abs(best) + 1e-12))
    {
      converged = true;
      break;
    }
    ++iterations;
    std::fill(centroid.begin(), centroid.end(), 0.0);
    for (size_t i = 0; i < n; ++i)
    {
      for (size_t j = 0; j < n; ++j)
      {
        centroid[j] += simplex[order[i]][j] / static_cast<double>(n);
      }
    }
    const double secondWorst = values[order[n - 1]];

    along(1.0, trial);
    const double reflected = evaluate(trial);
    if (reflected < best)
    {
      along(2.0, second);
      const double expanded = evaluate(second);
      if (expanded < reflected)
      {
        simplex[order[n]] = second;
        values[order[n]] = expanded;
      }
      else
      {
        simplex[order[n]] = trial;
        values[order[n]] = reflected;
      }
    }
    else if (reflected < secondWorst)
    {
      simplex[order[n]] = trial;
      values[order[n]] = reflected;
    }
    else
    {
      // Contract towards the better of the worst point and its reflection.
      const bool outside = reflected < worstValue;
      along(outside ? 0.5 : -0.5, second);
      const double contracted = evaluate(second);
      if (contracted < (outside ? reflected : worstValue))
      {
        simplex[order[n]] = second;
        values[order[n]] = contracted;
      }
      else
      {
        const std::vector<double>& keep = simplex[order[0]];
        for (size_t i = 1; i <= n; ++i)
        {
          std::vector<double>& x = simplex[order[i]];
          for (size_t j = 0; j < n; ++j)
          {
            x[j] = keep[j] + 0.5 * (x[j] - keep[j]);
          }
          values[order[i]] = evaluate(x);
        }
      }
    }
    if (this->Watch)
    {
      this->Watch(evaluations, *std::min_element(values.begin(), values.end()));
    }
  }

  const size_t bestIndex = std::min_element(values.begin(), values.end()) - values.begin();
  result.Point = simplex[bestIndex];
  result.Value = values[bestIndex];
  result.Evaluations = evaluations;
  result.Iterations = iterations;
  result.Converged = converged;
  return result;
}
