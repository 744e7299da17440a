// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
// Off-screen pictures of the main job; see bluenoise_pictures.h.
#include "bluenoise_pictures.h"

#include "vtkActor.h"
#include "vtkAxis.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkChartLegend.h"
#include "vtkChartXY.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkContextScene.h"
#include "vtkContextView.h"
#include "vtkCoordinate.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkPen.h"
#include "vtkPlot.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRect.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkScalarBarActor.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"

#ifdef BLUENOISE_HAVE_XLIB
#include <X11/Xlib.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <vector>

namespace
{
// Collects the error messages VTK objects report while we render, so that a
// failure becomes a message and a return value instead of a blank picture.
class ErrorCollector : public vtkCommand
{
public:
  static ErrorCollector* New() { return new ErrorCollector; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    const char* text = static_cast<const char*>(callData);
    if (!this->Messages.empty())
    {
      this->Messages += "; ";
    }
    std::string message = text ? text : "unknown error";
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
    {
      message.pop_back();
    }
    this->Messages += message;
  }
  void Watch(vtkObject* object) { object->AddObserver(vtkCommand::ErrorEvent, this); }
  std::string Messages;
};

// The settings both pictures share: off-screen, fixed size, no multisampling
// (exact pixels), on the session's display, with errors collected.
void PrepareOffScreen(const bluenoise::PictureSession& session, vtkRenderWindow* window,
  ErrorCollector* errors, int width, int height)
{
  session.Attach(window);
  errors->Watch(window);
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->SetMultiSamples(0);
}

std::string DisplayName()
{
  const char* display = std::getenv("DISPLAY");
  return display ? display : "";
}

std::string Format(const char* format, double value)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

// A sequential color map from dark blue-violet through teal and green to
// yellow, with a lightness that rises monotonically.
vtkSmartPointer<vtkLookupTable> MakeColorMap(const double range[2])
{
  vtkNew<vtkColorTransferFunction> ramp;
  ramp->SetColorSpaceToRGB();
  const double stops[][4] = { { 0.00, 0.27, 0.00, 0.33 }, { 0.25, 0.23, 0.32, 0.55 },
    { 0.50, 0.13, 0.57, 0.55 }, { 0.75, 0.37, 0.79, 0.38 }, { 1.00, 0.99, 0.91, 0.14 } };
  for (const auto& s : stops)
  {
    ramp->AddRGBPoint(s[0], s[1], s[2], s[3]);
  }
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  const int n = 256;
  table->SetNumberOfTableValues(n);
  for (int i = 0; i < n; ++i)
  {
    double rgb[3];
    ramp->GetColor(i / (n - 1.0), rgb);
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  table->SetTableRange(range[0], range[1]);
  return table;
}

// The samples whose coordinate `axis` lies within `half` of `center`.
vtkSmartPointer<vtkPolyData> Slab(vtkPolyData* samples, vtkDataArray* colors, int axis,
  double center, double half)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> values;
  values->SetName(colors->GetName() ? colors->GetName() : "values");
  const vtkIdType n = samples->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    samples->GetPoint(i, p);
    if (std::abs(p[axis] - center) <= half)
    {
      points->InsertNextPoint(p);
      values->InsertNextValue(static_cast<float>(colors->GetComponent(i, 0)));
    }
  }
  vtkNew<vtkCellArray> vertices;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    vertices->InsertNextCell(1, &i);
  }
  auto slab = vtkSmartPointer<vtkPolyData>::New();
  slab->SetPoints(points);
  slab->SetVerts(vertices);
  slab->GetPointData()->SetScalars(values);
  return slab;
}

vtkSmartPointer<vtkActor> PointsActor(
  vtkPolyData* points, const char* array, vtkLookupTable* colors, double pointSize)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(points);
  mapper->SetLookupTable(colors);
  mapper->SetUseLookupTableScalarRange(true);
  mapper->SetColorModeToMapScalars(); // unsigned char values are values, not colors
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray(array);
  mapper->ScalarVisibilityOn();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetRepresentationToPoints();
  actor->GetProperty()->SetPointSize(static_cast<float>(pointSize));
  actor->GetProperty()->SetRenderPointsAsSpheres(true);
  actor->GetProperty()->SetAmbient(0.25);
  actor->GetProperty()->SetDiffuse(0.8);
  return actor;
}

// The color of every caption and label on the samples picture.
const double Ink[3] = { 0.12, 0.12, 0.15 };

// Text whose top edge is at y and whose left edge (VTK_TEXT_LEFT) or middle
// (VTK_TEXT_CENTERED) is at x, in normalized viewport coordinates.
vtkSmartPointer<vtkTextActor> Text(const std::string& text, int size, const double rgb[3],
  int justification, double x, double y)
{
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text.c_str());
  actor->GetTextProperty()->SetFontSize(size);
  actor->GetTextProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->GetTextProperty()->SetJustification(justification);
  actor->GetTextProperty()->SetVerticalJustification(VTK_TEXT_TOP);
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(x, y);
  return actor;
}

// Text whose top left corner is at (x, y) in normalized viewport coordinates.
vtkSmartPointer<vtkTextActor> Caption(const std::string& text, int size, double x, double y)
{
  return Text(text, size, Ink, VTK_TEXT_LEFT, x, y);
}

// Renders `window` (already populated) and writes it as a PNG.
bool Capture(vtkRenderWindow* window, ErrorCollector* errors, const std::string& png,
  std::string& error)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  errors->Watch(grab);
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  int dims[3] = { 0, 0, 0 };
  image->GetDimensions(dims);
  if (!errors->Messages.empty() || dims[0] < 2 || dims[1] < 2)
  {
    error = "rendering failed" + (errors->Messages.empty() ? "" : ": " + errors->Messages);
    return false;
  }
  vtkNew<vtkPNGWriter> writer;
  errors->Watch(writer);
  writer->SetInputData(image);
  writer->SetFileName(png.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0 || !errors->Messages.empty())
  {
    error = "cannot write " + png + (errors->Messages.empty() ? "" : ": " + errors->Messages);
    return false;
  }
  return true;
}

vtkSmartPointer<vtkDoubleArray> Column(const char* name, const std::vector<double>& values)
{
  auto column = vtkSmartPointer<vtkDoubleArray>::New();
  column->SetName(name);
  column->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (size_t i = 0; i < values.size(); ++i)
  {
    column->SetValue(static_cast<vtkIdType>(i), values[i]);
  }
  return column;
}

// A two-point line (x0, y0) - (x1, y1) as a table for a chart plot.
vtkSmartPointer<vtkTable> Segment(double x0, double y0, double x1, double y1)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(Column("x", { x0, x1 }));
  table->AddColumn(Column("y", { y0, y1 }));
  return table;
}

double FieldValue(vtkTable* table, const char* name)
{
  vtkDataArray* a = table->GetFieldData()->GetArray(name);
  return a && a->GetNumberOfTuples() > 0 ? a->GetComponent(0, 0)
                                         : std::numeric_limits<double>::quiet_NaN();
}

vtkPlot* AddLine(vtkChartXY* chart, vtkTable* table, const char* x, const char* y,
  const char* label, const unsigned char rgb[3], float width, int lineType)
{
  vtkPlot* line = chart->AddPlot(vtkChart::LINE);
  line->SetInputData(table, x, y);
  line->SetLabel(label);
  line->SetColor(rgb[0], rgb[1], rgb[2], 255);
  line->SetWidth(width);
  line->GetPen()->SetLineType(lineType);
  return line;
}

void StyleChart(vtkChartXY* chart, const std::string& title, const char* yTitle, double xMax,
  double yMin, double yMax)
{
  chart->SetTitle(title);
  chart->GetTitleProperties()->SetFontSize(17);
  chart->GetTitleProperties()->SetBold(true);
  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  x->SetTitle("frequency f (cycles per voxel)");
  x->SetBehavior(vtkAxis::FIXED);
  x->SetRange(0.0, xMax);
  vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
  y->SetTitle(yTitle);
  y->SetBehavior(vtkAxis::FIXED);
  y->SetRange(yMin, yMax);
  for (vtkAxis* axis : { x, y })
  {
    axis->GetTitleProperties()->SetFontSize(15);
    axis->GetTitleProperties()->SetBold(false);
    axis->GetLabelProperties()->SetFontSize(13);
  }
  chart->SetShowLegend(true);
  chart->GetLegend()->GetLabelProperties()->SetFontSize(14);
  chart->GetLegend()->SetLabelSize(14);
}

// ---------------------------------------------------------------------------
// The steps of WriteSamplesPicture.

// The array to color the samples by: `name` when the points carry it with one
// component, else Density; null when neither is there.
vtkDataArray* ColorsOf(vtkPolyData* samples, const std::string& name)
{
  vtkDataArray* colors = nullptr;
  if (!name.empty())
  {
    colors = samples->GetPointData()->GetArray(name.c_str());
  }
  if (!colors || colors->GetNumberOfComponents() != 1)
  {
    colors = samples->GetPointData()->GetArray("Density");
  }
  return colors;
}

// The color map over the values of `colors`; a constant array gets a range of
// one so that the map does not collapse to a single entry.
vtkSmartPointer<vtkLookupTable> ColorMapOf(vtkDataArray* colors)
{
  double range[2];
  colors->GetRange(range, 0);
  if (!(range[1] > range[0]))
  {
    range[1] = range[0] + 1.0;
  }
  return MakeColorMap(range);
}

// Where the samples picture puts things: the 3D view takes the left `Split`
// of the width, the two slabs share the rest, one above the other, all framed
// on the point cloud's bounding box.
struct CloudLayout
{
  CloudLayout(vtkPolyData* samples, const bluenoise::SamplesPicture& options)
  {
    double bounds[6];
    samples->GetBounds(bounds);
    for (int c = 0; c < 3; ++c)
    {
      this->Center[c] = 0.5 * (bounds[2 * c] + bounds[2 * c + 1]);
      this->Size[c] = bounds[2 * c + 1] - bounds[2 * c];
    }
    this->Half = 0.5 * std::max(options.SlabThickness, 1e-12);
    this->SlabAspect = ((1.0 - Split) * options.Width) / (0.5 * options.Height);
  }
  static constexpr double Split = 0.62;
  double Center[3];
  double Size[3];
  double Half;       // half the slab thickness
  double SlabAspect; // width over height of a slab's viewport
};

// Left: every point in 3D, seen from -x, a little from +y and from above
// (for a brain in RAS orientation such as the MNI templates: from the left,
// slightly from the front, z up).
vtkSmartPointer<vtkRenderer> WholeView(vtkPolyData* samples, vtkDataArray* colors,
  vtkLookupTable* lut, const CloudLayout& layout)
{
  auto whole = vtkSmartPointer<vtkRenderer>::New();
  whole->SetViewport(0.0, 0.0, CloudLayout::Split, 1.0);
  whole->SetBackground(1.0, 1.0, 1.0);
  whole->AddActor(PointsActor(samples, colors->GetName(), lut, 2.5));
  whole->UseFXAAOn();
  const double* center = layout.Center;
  vtkCamera* camera = whole->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] - 1.0, center[1] + 0.45, center[2] + 0.35);
  camera->SetViewUp(0.0, 0.0, 1.0);
  whole->ResetCamera();
  camera->Zoom(1.15);
  whole->ResetCameraClippingRange();
  return whole;
}

// The caption of the 3D view: the input's name, how many points, what colors them.
std::string SamplesCaption(const bluenoise::SamplesPicture& options, vtkPolyData* samples,
  const std::string& colorTitle)
{
  const std::string count = std::to_string(samples->GetNumberOfPoints());
  std::string caption = options.Caption.empty() ? "" : options.Caption + "\n";
  caption += count + " blue-noise samples, colored by " +
    (colorTitle == "Density" ? "the density they were drawn with"
                             : "the input array " + colorTitle);
  return caption;
}

void StyleBarText(vtkTextProperty* text, int size)
{
  text->SetFontSize(size);
  text->SetColor(Ink[0], Ink[1], Ink[2]);
  text->ItalicOff();
  text->ShadowOff();
}

// The color bar at the right edge of the 3D view.
vtkSmartPointer<vtkScalarBarActor> ColorBar(vtkLookupTable* lut, const std::string& title)
{
  auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
  bar->SetLookupTable(lut);
  bar->SetTitle(title.c_str());
  bar->SetNumberOfLabels(5);
  bar->SetLabelFormat("%.3g");
  bar->SetOrientationToVertical();
  bar->UnconstrainedFontSizeOn();
  StyleBarText(bar->GetTitleTextProperty(), 15);
  StyleBarText(bar->GetLabelTextProperty(), 13);
  bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  bar->GetPositionCoordinate()->SetValue(0.87, 0.2);
  bar->SetWidth(0.12);
  bar->SetHeight(0.6);
  bar->SetBarRatio(0.3);
  return bar;
}

// Right: an axial (z) and a sagittal (x) slab through the center, head-on.
struct SlabView
{
  int Axis;
  const char* Name;
  double ViewportY0;
  int Up;
};
const SlabView SlabViews[2] = { { 2, "axial", 0.5, 1 }, { 0, "sagittal", 0.0, 2 } };

std::string SlabCaption(const SlabView& v, const CloudLayout& layout, vtkIdType points)
{
  const char axis = "xyz"[v.Axis];
  return std::string(v.Name) + " slab " + axis + " = " + Format("%.4g", layout.Center[v.Axis]) +
    " \xC2\xB1 " + Format("%.3g", layout.Half) + ", seen from " + (v.Axis == 2 ? "+" : "-") +
    axis + " (" + std::to_string(points) + " points)";
}

vtkSmartPointer<vtkRenderer> SlabRenderer(vtkPolyData* samples, vtkDataArray* colors,
  vtkLookupTable* lut, const CloudLayout& layout, const SlabView& v)
{
  const double* center = layout.Center;
  const double* size = layout.Size;
  auto slab = Slab(samples, colors, v.Axis, center[v.Axis], layout.Half);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetViewport(CloudLayout::Split, v.ViewportY0, 1.0, v.ViewportY0 + 0.5);
  renderer->SetBackground(0.95, 0.95, 0.96);
  renderer->AddActor(PointsActor(slab, colors->GetName(), lut, 4.0));
  renderer->UseFXAAOn();
  vtkCamera* c = renderer->GetActiveCamera();
  c->ParallelProjectionOn();
  c->SetFocalPoint(center);
  // Axial: from above; sagittal: from the left side, anterior to the left.
  const double depth = std::max({ size[0], size[1], size[2], 1.0 });
  double position[3] = { center[0], center[1], center[2] };
  position[v.Axis] += v.Axis == 2 ? depth : -depth;
  c->SetPosition(position);
  double up[3] = { 0.0, 0.0, 0.0 };
  up[v.Up] = 1.0;
  c->SetViewUp(up);
  // Fit the in-plane extent of the whole cloud (same scale for every slab).
  int across = 3 - v.Axis - v.Up;
  c->SetParallelScale(0.5 * 1.25 * std::max(size[v.Up], size[across] / layout.SlabAspect));
  renderer->ResetCameraClippingRange();
  renderer->AddViewProp(Caption(SlabCaption(v, layout, slab->GetNumberOfPoints()), 15, 0.03, 0.97));
  return renderer;
}

// ---------------------------------------------------------------------------
// The steps of WriteSpectrumPlot.

const unsigned char Blue[3] = { 31, 90, 180 };
const unsigned char Orange[3] = { 214, 100, 20 };
const unsigned char Red[3] = { 200, 30, 45 };
const unsigned char Gray[3] = { 120, 120, 120 };

vtkDataArray* NumericColumn(vtkTable* table, const char* name)
{
  return table ? vtkDataArray::SafeDownCast(table->GetColumnByName(name)) : nullptr;
}

// The curves to plot, and the ranges of the axes.
struct SpectrumCurves
{
  vtkNew<vtkTable> Power;      // f, power
  vtkNew<vtkTable> Anisotropy; // f, dB
  double FMax = 0.0, PMax = 0.0, AMin = 0.0, AMax = 0.0;
};

// The curves, without shells whose anisotropy is undefined (floored at
// -300 dB: fewer than two samples, or no power). The axis ranges leave out
// the few sparse shells near the corner frequency (beyond f = 0.5 the
// shells are only partly inside the spectrum; their estimates scatter
// widely and would flatten the rest); their curves are clipped instead.
// False when the table lacks a column the plot needs.
bool ReadCurves(vtkTable* spectrum, SpectrumCurves& curves)
{
  vtkDataArray* frequency = NumericColumn(spectrum, "Frequency");
  vtkDataArray* power = NumericColumn(spectrum, "RadialPower");
  vtkDataArray* anisotropy = NumericColumn(spectrum, "AnisotropyDB");
  vtkDataArray* counts = NumericColumn(spectrum, "ShellCount");
  if (!frequency || !power || !anisotropy || spectrum->GetNumberOfRows() < 2)
  {
    return false;
  }
  std::vector<double> f, p, fa, a;
  for (vtkIdType i = 0; i < spectrum->GetNumberOfRows(); ++i)
  {
    f.push_back(frequency->GetComponent(i, 0));
    p.push_back(power->GetComponent(i, 0));
    const bool dense = f.back() <= 0.5 || !counts || counts->GetComponent(i, 0) >= 500.0;
    if (dense)
    {
      curves.PMax = std::max(curves.PMax, p.back());
    }
    const double db = anisotropy->GetComponent(i, 0);
    if (db > -299.0)
    {
      fa.push_back(f.back());
      a.push_back(db);
      if (dense)
      {
        curves.AMin = std::min(curves.AMin, db);
        curves.AMax = std::max(curves.AMax, db);
      }
    }
  }
  curves.FMax = f.back();
  curves.Power->AddColumn(Column("f", f));
  curves.Power->AddColumn(Column("power", p));
  curves.Anisotropy->AddColumn(Column("f", fa));
  curves.Anisotropy->AddColumn(Column("dB", a));
  return true;
}

// A dashed marker line from (x0, y0) to (x1, y1); the plot keeps its table
// (through the plot's input), so the table needs no owner here.
void AddMarker(vtkChartXY* chart, double x0, double y0, double x1, double y1,
  const std::string& label, const unsigned char rgb[3])
{
  AddLine(chart, Segment(x0, y0, x1, y1), "x", "y", label.c_str(), rgb, 1.5f, vtkPen::DASH_LINE);
}

// Both charts get the same axes rectangle within their half of a `width`
// wide view (the axes, not the labels, are placed), so their frequency axes
// line up.
vtkRectf AxesRect(float width, float bottom, float height)
{
  const float left = 85.0f, right = 25.0f, below = 52.0f, above = 32.0f;
  return vtkRectf(left, bottom + below, width - left - right, height - below - above);
}

// Puts `chart` into `view` with its axes on `axes` and its legend at the bottom right.
void PlaceChart(vtkContextView* view, vtkChartXY* chart, const vtkRectf& axes)
{
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::BOTTOM);
  chart->SetLayoutStrategy(vtkChart::AXES_TO_RECT);
  chart->SetSize(axes);
  view->GetScene()->AddItem(chart);
}

// Top: radially averaged power, with the white-noise level 1 - g and f_g.
void AddPowerChart(vtkContextView* view, const SpectrumCurves& curves, double g, double fg,
  const vtkRectf& axes)
{
  vtkNew<vtkChartXY> chart;
  const double fMax = curves.FMax;
  const double pTop = 1.12 * std::max(curves.PMax, std::isfinite(g) ? 1.0 - g : 0.0);
  StyleChart(chart, "Radially averaged power spectrum", "power P(f)", fMax, 0.0, pTop);
  AddLine(chart, curves.Power, "f", "power", "RadialPower", Blue, 2.5f, vtkPen::SOLID_LINE);
  if (std::isfinite(g))
  {
    AddMarker(chart, 0.0, 1.0 - g, fMax, 1.0 - g, "white noise 1 - g = " + Format("%.3f", 1.0 - g),
      Gray);
  }
  if (std::isfinite(fg) && fg > 0.0)
  {
    AddMarker(chart, fg, 0.0, fg, pTop, "principal frequency f_g = " + Format("%.3f", fg), Red);
  }
  PlaceChart(view, chart, axes);
}

// Bottom: anisotropy in dB, with the 0 dB line and f_g.
void AddAnisotropyChart(vtkContextView* view, const SpectrumCurves& curves, double fg,
  const vtkRectf& axes)
{
  vtkNew<vtkChartXY> chart;
  const double fMax = curves.FMax;
  const double aLow = std::floor(curves.AMin - 1.0), aHigh = std::ceil(curves.AMax + 1.0);
  StyleChart(chart, "Anisotropy (one realization: isotropic noise is about 0 dB)",
    "anisotropy (dB)", fMax, aLow, aHigh);
  AddLine(chart, curves.Anisotropy, "f", "dB", "Anisotropy (dB)", Orange, 2.0f,
    vtkPen::SOLID_LINE);
  AddMarker(chart, 0.0, 0.0, fMax, 0.0, "0 dB", Gray);
  if (std::isfinite(fg) && fg > 0.0)
  {
    AddMarker(chart, fg, aLow, fg, aHigh, "f_g", Red);
  }
  PlaceChart(view, chart, axes);
}

// The overall title: the caller's, then the subtitle and the scalar metrics
// on one line (two lines fit above the charts).
std::string PlotTitle(vtkTable* spectrum, const std::string& title, const std::string& subtitle)
{
  std::string metrics = "L(g) = " + Format("%.4f", FieldValue(spectrum, "LowFrequencyRatio")) +
    "   S(g) = " + Format("%.4f", FieldValue(spectrum, "Symmetry")) +
    "   T(g) = " + Format("%.4f", FieldValue(spectrum, "TargetValue"));
  if (!subtitle.empty())
  {
    metrics = subtitle + ":   " + metrics;
  }
  return title.empty() ? metrics : title + "\n" + metrics;
}
}

namespace bluenoise
{
PictureSession::~PictureSession()
{
#ifdef BLUENOISE_HAVE_XLIB
  if (this->XDisplay)
  {
    XCloseDisplay(static_cast<::Display*>(this->XDisplay));
  }
#endif
}

void PictureSession::Attach(vtkRenderWindow* window) const
{
  if (this->XDisplay)
  {
    window->SetDisplayId(this->XDisplay);
  }
}

bool PictureSession::Start(std::string& why)
{
  vtkSmartPointer<vtkRenderWindow> probe = vtkSmartPointer<vtkRenderWindow>::New();
  if (!probe)
  {
    why = "this VTK has no render window implementation (VTK::RenderingOpenGL2 not loaded)";
    return false;
  }
  if (probe->IsA("vtkXOpenGLRenderWindow"))
  {
    const std::string display = DisplayName();
    const std::string hint = "; run under xvfb-run -a (package xvfb), or pass --no-pictures";
#ifdef BLUENOISE_HAVE_XLIB
    if (!this->XDisplay)
    {
      ::Display* connection = XOpenDisplay(nullptr);
      if (!connection)
      {
        why = display.empty() ? "no X display (DISPLAY is not set)"
                              : "cannot open the X display DISPLAY=" + display;
        why += hint;
        return false;
      }
      int opcode = 0, event = 0, errorBase = 0;
      if (!XQueryExtension(connection, "GLX", &opcode, &event, &errorBase))
      {
        XCloseDisplay(connection);
        why = "the X display DISPLAY=" + display + " has no GLX (OpenGL) extension" + hint;
        return false;
      }
      this->XDisplay = connection;
    }
#else
    if (display.empty())
    {
      why = "no X display (DISPLAY is not set)" + hint;
      return false;
    }
#endif
  }
  this->Attach(probe);
  probe->SetOffScreenRendering(1);
  if (!probe->SupportsOpenGL())
  {
    why = "OpenGL 3.2 is not available";
    if (auto gl = vtkOpenGLRenderWindow::SafeDownCast(probe))
    {
      const std::string message = gl->GetOpenGLSupportMessage();
      if (!message.empty())
      {
        why += " (" + message + ")";
      }
    }
    why += "; try xvfb-run -a, or pass --no-pictures";
    return false;
  }
  return true;
}

bool WriteSamplesPicture(const PictureSession& session, vtkPolyData* samples,
  const SamplesPicture& options, const std::string& png, std::string& error)
{
  if (!samples || samples->GetNumberOfPoints() == 0)
  {
    error = "no points to render";
    return false;
  }
  vtkDataArray* colors = ColorsOf(samples, options.ColorArray);
  if (!colors || !colors->GetName())
  {
    error = "the points carry no array to color by";
    return false;
  }
  auto lut = ColorMapOf(colors);
  const std::string colorTitle = colors->GetName();
  const CloudLayout layout(samples, options);

  vtkNew<vtkRenderWindow> window;
  vtkNew<ErrorCollector> errors;
  PrepareOffScreen(session, window, errors, options.Width, options.Height);
  auto whole = WholeView(samples, colors, lut, layout);
  window->AddRenderer(whole);
  whole->AddViewProp(Caption(SamplesCaption(options, samples, colorTitle), 18, 0.02, 0.98));
  whole->AddViewProp(ColorBar(lut, colorTitle));
  for (const SlabView& v : SlabViews)
  {
    window->AddRenderer(SlabRenderer(samples, colors, lut, layout, v));
  }
  return Capture(window, errors, png, error);
}

bool WriteSpectrumPlot(const PictureSession& session, vtkTable* spectrum,
  const SpectrumPlot& options, const std::string& png, std::string& error)
{
  SpectrumCurves curves;
  if (!ReadCurves(spectrum, curves))
  {
    error = "the spectrum table lacks Frequency, RadialPower or AnisotropyDB";
    return false;
  }
  const double g = FieldValue(spectrum, "Density");
  const double fg = FieldValue(spectrum, "PrincipalFrequency");

  vtkNew<vtkContextView> view;
  vtkRenderWindow* window = view->GetRenderWindow();
  vtkNew<ErrorCollector> errors;
  PrepareOffScreen(session, window, errors, options.Width, options.Height);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);

  // The charts share the height below the title, the power chart on top.
  const float w = static_cast<float>(options.Width);
  const float h = static_cast<float>(options.Height);
  const float titleSpace = 58.0f;
  const float top = h - titleSpace;
  AddPowerChart(view, curves, g, fg, AxesRect(w, 0.5f * top, 0.5f * top));
  AddAnisotropyChart(view, curves, fg, AxesRect(w, 0.0f, 0.5f * top));
  const double titleColor[3] = { 0.1, 0.1, 0.12 };
  view->GetRenderer()->AddViewProp(Text(PlotTitle(spectrum, options.Title, options.Subtitle), 17, titleColor,
    VTK_TEXT_CENTERED, 0.5, 1.0 - 6.0 / h));

  view->Render();
  return Capture(window, errors, png, error);
}
}
