// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Nelder-Mead on known functions: Rosenbrock's valley (2D and 4D) converges
// to (1, ..., 1); a quadratic bowl is found from far away; non-finite values
// are treated as walls.
#include "BlueNoiseTestUtilities.h"
#include "vtkNelderMeadMinimizer.h"

#include <cmath>
#include <limits>

using namespace bluenoise_test;

int main()
{
  auto rosenbrock = [](const std::vector<double>& x) {
    double f = 0.0;
    for (size_t i = 0; i + 1 < x.size(); ++i)
    {
      f += 100.0 * std::pow(x[i + 1] - x[i] * x[i], 2) + std::pow(1.0 - x[i], 2);
    }
    return f;
  };
  vtkNelderMeadMinimizer minimizer;
  minimizer.SetMaximumEvaluations(5000);
  minimizer.SetTolerance(1e-14);
  {
    const auto r = minimizer.Minimize(rosenbrock, { -1.2, 1.0 }, { 0.5, 0.5 });
    std::cout << "Rosenbrock 2D: f=" << r.Value << " at (" << r.Point[0] << ", " << r.Point[1]
              << ") after " << r.Evaluations << " evaluations" << std::endl;
    Check(r.Value < 1e-8 && std::abs(r.Point[0] - 1) < 1e-3 && std::abs(r.Point[1] - 1) < 1e-3,
      "Rosenbrock 2D converges to (1, 1)");
    Check(r.Evaluations <= 5000, "within the budget");
  }
  {
    minimizer.SetMaximumEvaluations(20000);
    const auto r = minimizer.Minimize(rosenbrock, { -1.0, 1.5, -0.5, 2.0 }, { 0.3, 0.3, 0.3, 0.3 });
    std::cout << "Rosenbrock 4D: f=" << r.Value << std::endl;
    Check(r.Value < 1e-6, "Rosenbrock 4D converges");
  }
  {
    // A wall: x[0] < 0 is forbidden; the minimum of the bowl sits at x[0] = 2.
    auto walled = [](const std::vector<double>& x) {
      if (x[0] < 0.0)
      {
        return std::numeric_limits<double>::quiet_NaN();
      }
      return std::pow(x[0] - 2.0, 2) + std::pow(x[1] + 3.0, 2);
    };
    minimizer.SetMaximumEvaluations(2000);
    const auto r = minimizer.Minimize(walled, { 10.0, 10.0 }, { 1.0, 1.0 });
    Check(std::abs(r.Point[0] - 2.0) < 1e-4 && std::abs(r.Point[1] + 3.0) < 1e-4,
      "bowl found past a wall of NaN");
  }
  {
    // The budget is honored.
    vtkNelderMeadMinimizer tight;
    tight.SetMaximumEvaluations(30);
    const auto r = tight.Minimize(rosenbrock, { -1.2, 1.0 }, { 0.5, 0.5 });
    Check(r.Evaluations <= 30 + 2 && !r.Converged, "evaluation budget stops the search");
  }
  return Summary("TestNelderMeadMinimizer");
}
