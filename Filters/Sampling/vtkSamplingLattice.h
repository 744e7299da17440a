// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSamplingLattice
 * @brief   The sample sites of an image: its points, or the centres of its cells.
 *
 * vtkErrorDiffusionSampler samples one site per tuple of its density array.
 * For a point-data array the sites are the image's points; for a cell-data
 * array (voxels stored as cells, as simulation output often is) they are the
 * cells' centres, which form an image of their own: one point fewer along
 * every axis that has more than one point, its origin half a step inside
 * (along the direction matrix), the same spacing and direction. Cell (i, j, k)
 * of the image is point (i, j, k) of that lattice, so the cell data, read as
 * point data of the lattice, is sampled like any point array.
 *
 * An axis with a single point (a 2D or 1D image) keeps that point: its cells
 * are flat along it, and their centres lie on it.
 *
 * Cell ghost flags are translated to point ghost flags (a duplicate cell is a
 * duplicate site, a hidden cell a hidden site), so that what the sampler skips
 * means the same on both lattices.
 */
#ifndef vtkSamplingLattice_h
#define vtkSamplingLattice_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkSmartPointer.h"           // for the returned image

class vtkImageData;
class vtkInformation;

class VTKFILTERSBLUENOISE_EXPORT vtkSamplingLattice
{
public:
  /// The extent of the cell centres of an image whose point extent is `points`.
  static void CellExtent(const int points[6], int cells[6]);

  /**
   * The point extent that holds the cells of `cells`, within an image whose
   * whole point extent is `whole` (the inverse of CellExtent).
   */
  static void PointExtent(const int cells[6], const int whole[6], int points[6]);

  /**
   * The origin of the cell-centre lattice of an image with this point extent,
   * origin, spacing and direction (row-major 3x3).
   */
  static void CellOrigin(const int points[6], const double origin[3], const double spacing[3],
    const double direction[9], double cellOrigin[3]);

  /**
   * Rewrites pipeline information of an image (WHOLE_EXTENT, ORIGIN) into that
   * of its cell-centre lattice; SPACING and DIRECTION are unchanged.
   */
  static void ToCellLattice(vtkInformation* info);

  /**
   * The cell-centre lattice of `image`, its cell data as point data (shallow:
   * the same arrays), ghost flags translated.
   */
  static vtkSmartPointer<vtkImageData> FromCells(vtkImageData* image);
};

#endif
