// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkErrorDiffusionPointAssembler
 * @brief   Builds the sampler's output points, layer by layer, from the
 *          sample masks of an image's layers.
 *
 * For the samples of each layer (the voxels whose mask is 1) it appends the
 * voxel centre in world coordinates (the image's origin, spacing and
 * direction matrix), the density the sample was drawn with (float array
 * `Density`) and the tuple of every point-data array of the image (numeric
 * arrays through vtkArrayDispatch, others tuple by tuple). The arrays reserve
 * room for up to 2^22 points up front, grow beyond that (VTK's Resize,
 * amortised) and are trimmed to size by End(). Large arrays with the standard
 * memory layout are allocated 2 MB aligned and, on Linux, advised for
 * transparent huge pages: the output is written once, in order, and most of
 * the cost of fresh memory is the page faults (a quarter of the filter's time
 * with 4 kB pages at g = 0.5).
 *
 * Layers must come in z order, each once. The image and its arrays are only
 * read, so another thread may read them at the same time (the sampler scans
 * the next layers meanwhile).
 */
#ifndef vtkErrorDiffusionPointAssembler_h
#define vtkErrorDiffusionPointAssembler_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkSmartPointer.h"           // for members
#include "vtkType.h"                   // for vtkIdType

#include <vector>

class vtkAbstractArray;
class vtkCellArray;
class vtkDataArray;
class vtkFloatArray;
class vtkImageData;
class vtkPointData;
class vtkPoints;

class VTKFILTERSBLUENOISE_EXPORT vtkErrorDiffusionPointAssembler
{
public:
  vtkErrorDiffusionPointAssembler();
  ~vtkErrorDiffusionPointAssembler();
  vtkErrorDiffusionPointAssembler(const vtkErrorDiffusionPointAssembler&) = delete;
  vtkErrorDiffusionPointAssembler& operator=(const vtkErrorDiffusionPointAssembler&) = delete;

  /**
   * Starts the points of `image`. outPD receives (CopyAllocate) every array
   * of the image's point data, except one named `Density`, which End()
   * replaces by the densities. pointsType: VTK_FLOAT or VTK_DOUBLE.
   */
  void Begin(vtkImageData* image, vtkPointData* outPD, int pointsType);

  /**
   * Appends the samples of layer k (0-based from the bottom of the image's
   * extent): density and mask hold nx * ny values, x fastest; count is the
   * number of ones in mask.
   */
  void AddLayer(int k, const float* density, const unsigned char* mask, vtkIdType count);

  /// Points appended so far.
  vtkIdType GetNumberOfPoints() const { return this->Total; }

  /**
   * Trims the arrays to the number of points, adds `Density` to the point
   * data given to Begin() and returns the points.
   */
  vtkSmartPointer<vtkPoints> End();

  /**
   * One vertex cell per point, for n points (32-bit storage when it fits,
   * to halve the memory). Does not depend on a Begin() or End().
   */
  static vtkSmartPointer<vtkCellArray> MakeVertices(vtkIdType n);

private:
  void Reserve(vtkIdType tuples);

  int Extent[6] = { 0, -1, 0, -1, 0, -1 };
  double IndexToPhysical[16];
  vtkIdType Total = 0;
  vtkIdType Capacity = 0;
  vtkPointData* OutputPointData = nullptr;
  vtkSmartPointer<vtkDataArray> Coordinates;
  vtkSmartPointer<vtkFloatArray> Densities;
  std::vector<vtkAbstractArray*> Sources; // image arrays, read at the sampled voxels
  std::vector<vtkAbstractArray*> Targets; // their copies in the output
  std::vector<vtkIdType> LayerIds;        // in-layer indices of one layer's samples
  std::vector<vtkIdType> RowEnds;         // where each row's samples end in LayerIds
};

#endif
