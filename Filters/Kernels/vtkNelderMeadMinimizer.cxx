// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkNelderMeadMinimizer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace
{
// The simplex of one minimization and its moves.
class Simplex
{
public:
  Simplex(const vtkNelderMeadMinimizer::Function& f, const std::vector<double>& start,
    const std::vector<double>& steps)
    : F(f)
    , N(start.size())
    , Points(start.size() + 1, start)
    , Values(start.size() + 1)
    , Order(start.size() + 1)
    , Centroid(start.size())
    , Trial(start.size())
    , Second(start.size())
  {
    this->Values[0] = this->Evaluate(start);
    for (size_t i = 0; i < this->N; ++i)
    {
      this->Points[i + 1][i] += (i < steps.size() && steps[i] != 0.0) ? steps[i] : 0.05;
      this->Values[i + 1] = this->Evaluate(this->Points[i + 1]);
    }
  }

  int Evaluations = 0;

  // Sorts the vertices; true when best and worst agree within the tolerance.
  bool Converged(double tolerance)
  {
    std::iota(this->Order.begin(), this->Order.end(), 0);
    std::sort(this->Order.begin(), this->Order.end(),
      [&](size_t a, size_t b) { return this->Values[a] < this->Values[b]; });
    const double best = this->Values[this->Order[0]];
    const double worst = this->Values[this->Order[this->N]];
    return std::isfinite(worst) && worst - best <= tolerance * (std::abs(best) + 1e-12);
  }

  // One iteration: reflect, expand, contract or shrink (after Converged()).
  void Step()
  {
    const size_t n = this->N;
    std::fill(this->Centroid.begin(), this->Centroid.end(), 0.0);
    for (size_t i = 0; i < n; ++i)
    {
      for (size_t j = 0; j < n; ++j)
      {
        this->Centroid[j] += this->Points[this->Order[i]][j] / static_cast<double>(n);
      }
    }
    const double best = this->Values[this->Order[0]];
    const double secondWorst = this->Values[this->Order[n - 1]];
    const double worst = this->Values[this->Order[n]];
    this->Along(1.0, this->Trial);
    const double reflected = this->Evaluate(this->Trial);
    if (reflected < best)
    {
      this->Along(2.0, this->Second);
      const double expanded = this->Evaluate(this->Second);
      this->ReplaceWorst(expanded < reflected ? this->Second : this->Trial,
        std::min(expanded, reflected));
    }
    else if (reflected < secondWorst)
    {
      this->ReplaceWorst(this->Trial, reflected);
    }
    else
    {
      this->Contract(reflected, worst);
    }
  }

  double Best() const { return *std::min_element(this->Values.begin(), this->Values.end()); }

  vtkNelderMeadMinimizer::Result Outcome(int iterations, bool converged) const
  {
    vtkNelderMeadMinimizer::Result result;
    const size_t best = std::min_element(this->Values.begin(), this->Values.end()) - this->Values.begin();
    result.Point = this->Points[best];
    result.Value = this->Values[best];
    result.Evaluations = this->Evaluations;
    result.Iterations = iterations;
    result.Converged = converged;
    return result;
  }

private:
  double Evaluate(const std::vector<double>& x)
  {
    ++this->Evaluations;
    const double v = this->F(x);
    return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
  }

  // centroid + t * (centroid - worst)
  void Along(double t, std::vector<double>& out) const
  {
    const std::vector<double>& worst = this->Points[this->Order[this->N]];
    for (size_t j = 0; j < this->N; ++j)
    {
      out[j] = this->Centroid[j] + t * (this->Centroid[j] - worst[j]);
    }
  }

  void ReplaceWorst(const std::vector<double>& x, double value)
  {
    this->Points[this->Order[this->N]] = x;
    this->Values[this->Order[this->N]] = value;
  }

  // Contract towards the better of the worst point and its reflection, or
  // shrink the whole simplex towards the best point.
  void Contract(double reflected, double worst)
  {
    const bool outside = reflected < worst;
    this->Along(outside ? 0.5 : -0.5, this->Second);
    const double contracted = this->Evaluate(this->Second);
    if (contracted < (outside ? reflected : worst))
    {
      this->ReplaceWorst(this->Second, contracted);
      return;
    }
    const std::vector<double> keep = this->Points[this->Order[0]];
    for (size_t i = 1; i <= this->N; ++i)
    {
      std::vector<double>& x = this->Points[this->Order[i]];
      for (size_t j = 0; j < this->N; ++j)
      {
        x[j] = keep[j] + 0.5 * (x[j] - keep[j]);
      }
      this->Values[this->Order[i]] = this->Evaluate(x);
    }
  }

  const vtkNelderMeadMinimizer::Function& F;
  size_t N;
  std::vector<std::vector<double>> Points;
  std::vector<double> Values;
  std::vector<size_t> Order;
  std::vector<double> Centroid, Trial, Second;
};
}

//------------------------------------------------------------------------------
vtkNelderMeadMinimizer::Result vtkNelderMeadMinimizer::Minimize(
  const Function& f, const std::vector<double>& start, const std::vector<double>& steps) const
{
  Simplex simplex(f, start, steps);
  int iterations = 0;
  bool converged = false;
  while (simplex.Evaluations < this->MaximumEvaluations)
  {
    if (simplex.Converged(this->Tolerance))
    {
      converged = true;
      break;
    }
    ++iterations;
    simplex.Step();
    if (this->Watch)
    {
      this->Watch(simplex.Evaluations, simplex.Best());
    }
  }
  return simplex.Outcome(iterations, converged);
}
