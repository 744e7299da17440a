// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionChargeCurve
 * @brief   The steady-state charge C(g) of the 3D error diffusion for one
 *          parameter table and modulation scale, calibrated on demand.
 *
 * Once the paper's process has run long enough at a constant density g, every
 * voxel receives on average the error C(g) from the voxels scanned before it:
 * the process holds a standing charge, close to 0.5 at low densities (points
 * fire when the error reaches the threshold 0.5, and the error field is
 * smooth). Started from empty buffers, the paper's process spends C(g) / g
 * layers charging up (about 120 layers at g = 1/255), and wherever the scan
 * ends it leaves that charge behind. vtkErrorDiffusionKernel lowers its
 * threshold by C(g) instead, which translates the error by C: an empty buffer
 * is then the settled mean state (see the kernel's class comment).
 *
 * Definition. C(g) is measured, for g in (0, 0.5], on a box of n x n voxels
 * (n = 48 + 4 s, s = g^(-1/3) the mean distance between points) as the mean
 * error received by the voxels more than 1.5 s + 2 voxels from the lateral
 * faces over `m` layers after `m` settling layers (m = 4 ceil(2 s + 8)), in the
 * process translated by a guess c0 (the paper's process pre-charged with c0,
 * which settles within a few point spacings): C = c0 + that mean. Two such
 * refinements are made, with seeds 12345 and 12346, the first from the charge
 * of the next level towards 8/255 (0.45 at 8/255 itself), which is calibrated
 * first: a level's charge, and so the samples, do not depend on what the
 * process calibrated before. The repeatability is about 0.001 below g = 8/255
 * and 0.002 above.
 *
 * Levels. C is calibrated at the levels (in 1/255 units) 0.0255, 0.05, 0.1,
 * 0.25, 0.5, 1, 2, 4, 8, 16, 32, 48, 64, 80, 96, 112 and 127.5 and at every
 * key level of the table (C varies with g even where the parameters do not,
 * and with the parameters between the keys), and interpolated linearly in the
 * cube root of the level between them (C varies smoothly in g^(1/3), the
 * inverse point spacing); below 0.0255 (g = 1e-4) the lowest value holds.
 * g > 0.5 uses C(1 - g) (the kernel mirrors the process).
 *
 * Cost and caching. A level costs a few sampled layers of its box (the low
 * levels need wide boxes) and is calibrated only when a density that needs
 * it comes up. Get() shares one curve of a table and scale (the same key
 * values and scale bit for bit) between the kernels that use it at the same
 * time, thread safe; a curve lives as long as a kernel holds it (each kernel
 * keeps the curves it used last, see vtkErrorDiffusionKernel), so nothing
 * calibrated outlives the filters that use it.
 */
#ifndef vtkErrorDiffusionChargeCurve_h
#define vtkErrorDiffusionChargeCurve_h

#include "vtkErrorDiffusionParameterTable.h"
#include "vtkFiltersBlueNoiseModule.h" // for export macro

#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionChargeCurve
{
public:
  /// The curve of this table and scale that a kernel holds, or a new one.
  static std::shared_ptr<vtkErrorDiffusionChargeCurve> Get(
    const vtkErrorDiffusionParameterTable& table, double modulationScale);

  /**
   * A curve of `table` and `modulationScale`. The built-in tables at the
   * sampler's default scale (0.5) start with their charges known (as
   * calibrated; TestErrorDiffusionChargeCurve checks them), unless
   * useKnownCharges is false.
   */
  vtkErrorDiffusionChargeCurve(const vtkErrorDiffusionParameterTable& table, double modulationScale,
    bool useKnownCharges = true);

  /// C(g) for g in [0, 1]; calibrates the levels it needs the first time.
  float At(double g);

  /// The calibration levels (1/255 units) and their charges, all calibrated.
  std::vector<double> GetLevels() const { return this->Levels; }
  std::vector<float> GetCharges();

private:
  float ChargeOfLevel(size_t i); // calibrates level i when needed; Mutex held

  vtkErrorDiffusionParameterTable Table;
  double ModulationScale = 0.5;
  std::vector<double> Levels;    // increasing, 1/255 units
  std::vector<double> RootLevels; // their cube roots
  std::vector<float> Charges;    // NaN until calibrated
  std::mutex Mutex;
};

#endif
