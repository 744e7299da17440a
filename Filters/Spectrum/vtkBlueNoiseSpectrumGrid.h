// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkBlueNoiseSpectrumGrid
 * @brief   The analysis grid of one realization of vtkBlueNoiseSpectrum.
 *
 * Plain C++ (not wrapped). The grid points (voxel centers) are
 * x = Origin + D ((Lower + ijk) * Spacing) for ijk in [0, Dimensions), D the
 * direction matrix; Locate() gives the grid point nearest to a position.
 *
 * Description is what one piece of a realization tells about its grid before
 * vtkBlueNoiseSpectrum's rules choose one (see its class comment): the
 * sampler's SamplingGrid field data, an image's extent, the bounds and the
 * number of points. The descriptions of the pieces of one realization merge
 * (points added, extents and bounds united) and pack into doubles, so that a
 * distributed filter can combine the pieces of all processes into the grid of
 * the whole realization, the same on every process.
 *
 * @sa vtkBlueNoiseSpectrum vtkPBlueNoiseSpectrum
 */
#ifndef vtkBlueNoiseSpectrumGrid_h
#define vtkBlueNoiseSpectrumGrid_h

#include "vtkFiltersBlueNoiseModule.h" // for export macro
#include "vtkType.h"                   // for vtkIdType

#include <cstddef>
#include <string>

class vtkFieldData;

class VTKFILTERSBLUENOISE_EXPORT vtkBlueNoiseSpectrumGrid
{
public:
  struct VTKFILTERSBLUENOISE_EXPORT Description
  {
    int Connection = 0;           ///< input connection
    int Leaf = 0;                 ///< flat index in a composite input, 0 otherwise
    vtkIdType NumberOfPoints = 0; ///< of the data set (points, or image points)
    bool IsImage = false;
    bool CellArray = false;                       ///< an image's signal is cell data
    int ImageExtent[6] = { 0, -1, 0, -1, 0, -1 }; ///< point extent of an image
    bool HasSamplingGrid = false;                 ///< the sampler's field data
    double Origin[3] = { 0.0, 0.0, 0.0 };
    double Spacing[3] = { 1.0, 1.0, 1.0 };
    double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }; ///< row major, index to physical
    int Extent[6] = { 0, -1, 0, -1, 0, -1 };             ///< the sampled extent
    double Bounds[6] = { 1, -1, 1, -1, 1, -1 };          ///< empty without points

    /// Doubles of Pack() and Unpack().
    static constexpr int PackedSize = 39;
    void Pack(double* out) const;
    void Unpack(const double* in);

    /**
     * Adds another piece of the same realization: points added, image extents,
     * sampled extents and bounds united. False, with the reason in `error`,
     * when the pieces disagree (an image and a point set, point and cell
     * signals, sampling grids of different origin, spacing or direction, or a
     * piece with points but without the sampling grid the others have).
     */
    bool Merge(const Description& piece, std::string& error);

    /**
     * Reads the sampler's SamplingGridOrigin, SamplingGridSpacing,
     * SamplingGridExtent and optional SamplingGridDirection. Returns false with
     * `error` when they are malformed, only partly there, or the direction is
     * singular; HasSamplingGrid tells whether they were there at all.
     */
    bool ReadSamplingGrid(vtkFieldData* fieldData, std::string& error);
  };

  int Dimensions[3] = { 0, 0, 0 };
  int Lower[3] = { 0, 0, 0 };
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Spacing[3] = { 1.0, 1.0, 1.0 };
  double Inverse[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } }; ///< D^-1

  /// The grid of a description's sampling grid (checked by ReadSamplingGrid).
  void SetFromSamplingGrid(const Description& description);

  /// `dimensions` grid points with the first and last on the bounds.
  void SetFromBounds(const int dimensions[3], const double bounds[6]);

  /// Dimensions only: an image read as counts is never located into.
  void SetDimensions(const int dimensions[3]);

  std::size_t Size() const;

  /**
   * The grid in words, as the spectrum names it to its users: "origin (x, y,
   * z), spacing (sx, sy, sz), extent [i0, i1, j0, j1, k0, k1]" (the extent of
   * the grid points in the index space of Origin and Spacing).
   */
  std::string Describe() const;

  /// Widens `into` (xmin, xmax, ...) to hold `bounds`.
  static void UniteBounds(double into[6], const double bounds[6]);

  /// Index (x fastest) of the grid point nearest to p, or -1 outside the grid.
  long long Locate(const double p[3]) const;
};

#endif
