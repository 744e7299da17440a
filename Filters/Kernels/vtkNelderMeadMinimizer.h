// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkNelderMeadMinimizer
 * @brief   Derivative-free minimization with the Nelder-Mead simplex.
 *
 * Minimizes f: R^n -> R from a start point and an initial step per
 * coordinate (the start simplex is the start point plus one step along each
 * axis), with the usual coefficients: reflection 1, expansion 2, contraction
 * 1/2, shrink 1/2 (Lagarias et al. 1998). It stops after MaximumEvaluations
 * calls of f, or when the spread of f over the simplex, max - min, falls to
 * Tolerance * (|min| + 1e-12) or below. Non-finite values of f count as +inf,
 * so a caller can reject a point by returning NaN or infinity.
 *
 * The paper's parameter search (section 4.2) uses this "simplex optimization"
 * (Press et al., Numerical Recipes); vtkErrorDiffusionOptimizer drives it.
 * Plain C++; the function is called from the calling thread only.
 */
#ifndef vtkNelderMeadMinimizer_h
#define vtkNelderMeadMinimizer_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <functional>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkNelderMeadMinimizer
{
public:
  using Function = std::function<double(const std::vector<double>&)>;
  /// Called after every iteration with the evaluations so far and the best value.
  using Observer = std::function<void(int evaluations, double best)>;

  struct Result
  {
    std::vector<double> Point; ///< best point found
    double Value = 0.0;        ///< f at Point
    int Evaluations = 0;
    int Iterations = 0;
    bool Converged = false; ///< stopped on Tolerance rather than on the budget
  };

  void SetMaximumEvaluations(int n) { this->MaximumEvaluations = n; }
  int GetMaximumEvaluations() const { return this->MaximumEvaluations; }
  void SetTolerance(double t) { this->Tolerance = t; }
  double GetTolerance() const { return this->Tolerance; }
  void SetObserver(Observer observer) { this->Watch = std::move(observer); }

  Result Minimize(
    const Function& f, const std::vector<double>& start, const std::vector<double>& steps) const;

private:
  int MaximumEvaluations = 1000;
  double Tolerance = 1e-8;
  Observer Watch;
};

#endif
