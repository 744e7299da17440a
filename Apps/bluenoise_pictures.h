// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Off-screen pictures of the main job (bluenoise-sample): the sampled points
// rendered in 3D (samples.png) and the blue-noise spectrum plotted as in the
// paper's Fig. 7(b) (spectrum.png). Both need an OpenGL context; with VTK's X
// (GLX) render window that means a reachable X display, e.g. from xvfb-run.
#ifndef bluenoise_pictures_h
#define bluenoise_pictures_h

#include <string>

class vtkPolyData;
class vtkRenderWindow;
class vtkTable;

namespace bluenoise
{
/**
 * What the pictures need to render off screen, checked once and kept open.
 * VTK's X render window aborts the process when it cannot open the display,
 * so Start() opens it first (and requires the server's GLX extension), then
 * asks VTK whether OpenGL is supported. The connection stays open until the
 * session is destroyed and is lent to every render window (Attach): an X
 * server resets when its last client disconnects, and a window opening its
 * own connection during that reset would fail (and abort).
 */
class PictureSession
{
public:
  PictureSession() = default;
  ~PictureSession();
  PictureSession(const PictureSession&) = delete;
  PictureSession& operator=(const PictureSession&) = delete;

  /// False, with `why` saying what is missing and what to do, when rendering is impossible.
  bool Start(std::string& why);
  /// Makes `window` use the session's display connection (if any).
  void Attach(vtkRenderWindow* window) const;

private:
  void* XDisplay = nullptr; // the X connection (Display*), when VTK renders through X
};

struct SamplesPicture
{
  /// Point array to color by (1 component); empty or absent: `Density`.
  std::string ColorArray;
  /// First line of the caption (e.g. the input's file name).
  std::string Caption;
  /// Thickness of the two slabs shown beside the 3D view, world units.
  double SlabThickness = 1.0;
  int Width = 1280;
  int Height = 800;
};

/**
 * Renders the sample points off screen and writes a PNG: on the left all
 * points in 3D (small spheres, colored by SamplesPicture::ColorArray with a
 * color bar), on the right an axial and a sagittal slab through the center
 * seen head-on, where the even spacing and the density following the color
 * can be seen. Returns false with `error` set when rendering or writing fails.
 */
bool WriteSamplesPicture(const PictureSession& session, vtkPolyData* samples,
  const SamplesPicture& options, const std::string& png, std::string& error);

struct SpectrumPlot
{
  /// Title above the plots.
  std::string Title;
  /// Second line, before the scalar metrics (e.g. the method and parameters).
  std::string Subtitle;
  int Width = 1024;
  int Height = 800;
};

/**
 * Plots a vtkBlueNoiseSpectrum table off screen and writes a PNG: radially
 * averaged power (top) and anisotropy in dB (bottom) against frequency, with
 * the principal frequency f_g and the white-noise power level 1 - g marked
 * and the scalar metrics (L, S, T) in the caption. Returns false with `error`
 * set when the table lacks columns or rendering or writing fails.
 */
bool WriteSpectrumPlot(const PictureSession& session, vtkTable* spectrum,
  const SpectrumPlot& options, const std::string& png, std::string& error);
}

#endif
