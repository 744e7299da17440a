# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Runs inside the ParaView GUI (paraview --script=THIS --exit), see TestPluginGUI.py.

The plugin is loaded by the GUI itself (--plugins); this script does what a user
does after Filters > Sampling > Error Diffusion Sampler > Apply: it shows every
output port of the sampler and then of the spectrum in its preferred view as Apply
does, counts the filters' executions (StartEvent), and saves screenshots. ParaView exits 0 even when a --script raises, so the outcome goes
to a JSON file ($BLUENOISE_GUI_OUTPUT/result.json) that the driver checks.
"""
import json
import os
import traceback

OUT = os.environ.get("BLUENOISE_GUI_OUTPUT", os.getcwd())
result = {"finished": False}


def save():
    with open(os.path.join(OUT, "result.json"), "w") as f:
        json.dump(result, f, indent=1)


try:
    from paraview.simple import *  # noqa: F401,F403
    from paraview import servermanager

    pxm = servermanager.ProxyManager().SMProxyManager
    plm = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager()
    info = plm.GetLocalInformation()
    result["loaded_plugins"] = [info.GetPluginName(i) for i in range(info.GetNumberOfPlugins())
                                if info.GetPluginLoaded(i)]
    categories = {}
    for name in ("ErrorDiffusionSampler", "BlueNoiseSpectrum"):
        prototype = pxm.GetPrototypeProxy("filters", name)
        hints = prototype.GetHints() if prototype is not None else None
        menu = hints.FindNestedElementByName("ShowInMenu") if hints is not None else None
        categories[name] = menu.GetAttribute("category") if menu is not None else None
    result["categories"] = categories
    save()

    counts = {"sampler": 0, "spectrum": 0}

    def counter(key):
        def on_start(obj, event):
            counts[key] += 1
        return on_start

    def show_as_apply_does(proxy, view):
        """pqApplyBehavior::showData: every output port in its preferred view."""
        controller = servermanager.vtkSMParaViewPipelineControllerWithRendering()
        layout = GetLayout(view)
        shown = []
        for port in range(proxy.GetNumberOfOutputPorts()):
            v = controller.ShowInPreferredView(proxy.SMProxy, port, view.SMProxy)
            if v is not None and v is not view.SMProxy:
                controller.AssignViewToLayout(v, layout.SMProxy, 0)
            shown.append(v.GetXMLName() if v is not None else None)
        return shown

    wavelet = Wavelet(WholeExtent=[-40, 40, -40, 40, -40, 40])
    view = GetActiveViewOrCreate("RenderView")
    Show(wavelet, view)
    sampler = ErrorDiffusionSampler(Input=wavelet)
    sampler.NumberOfPoints = 20000
    sampler.GetClientSideObject().AddObserver("StartEvent", counter("sampler"))
    result["sampler_views"] = show_as_apply_does(sampler, view)
    result["points"] = sampler.GetDataInformation().GetNumberOfPoints()
    result["executions_after_samples"] = dict(counts)
    save()

    # The render view: what Apply shows.
    try:
        display = GetDisplayProperties(sampler, view)
        result["representation"] = display.GetXMLName()
        result["representation_type"] = display.GetProperty("Representation").GetData()
        ColorBy(display, ("POINTS", "RTData"))
        display.PointSize = 2.0
        Hide(wavelet, view)
        view.OrientationAxesVisibility = 0
        view.ResetCamera()
        Render(view)
        shot = os.path.join(OUT, "sampler.png")
        SaveScreenshot(shot, view, ImageResolution=[640, 480])
        result["screenshot"] = shot
    except Exception:
        result["error"] = traceback.format_exc()
    save()

    # The spectrum, as Apply shows it: a view of its own next to the render view.
    spectrum = BlueNoiseSpectrum(Input=sampler)
    spectrum.GetClientSideObject().AddObserver("StartEvent", counter("spectrum"))
    result["spectrum_views"] = show_as_apply_does(spectrum, view)
    chart = [v for v in GetViews() if v.GetXMLName() == "BlueNoiseSpectrumView"][0]
    chart_display = GetDisplayProperties(spectrum, chart)
    result["chart_representation"] = chart_display.GetXMLName()
    result["chart_x_array"] = chart_display.XArrayName if not chart_display.UseIndexForXAxis else ""
    result["chart_visible_series"] = [
        name for name, visible in zip(chart_display.SeriesVisibility[0::2],
                                      chart_display.SeriesVisibility[1::2]) if visible == "1"]
    result["chart_left_log"] = chart.LeftAxisLogScale
    result["chart_titles"] = [chart.BottomAxisTitle, chart.LeftAxisTitle, chart.RightAxisTitle]
    Render(chart)
    result["spectrum_rows"] = spectrum.GetDataInformation().GetNumberOfRows()
    # A display change executes nothing.
    display.PointSize = 3.0
    Render(view)
    Render(chart)
    result["executions"] = dict(counts)
    chart_shot = os.path.join(OUT, "spectrum.png")
    SaveScreenshot(chart_shot, chart, ImageResolution=[640, 480])
    result["chart_screenshot"] = chart_shot
    # Both views side by side, as the README shows them.
    layout_shot = os.path.join(OUT, "paraview-gui.png")
    SaveScreenshot(layout_shot, GetLayout(view), ImageResolution=[1280, 480])
    result["layout_screenshot"] = layout_shot

    # Chart reading: fixed axis ranges, the same after every run.
    result["chart_ranges"] = [
        [getattr(chart, axis + "AxisUseCustomRange"), getattr(chart, axis + "AxisRangeMinimum"),
         getattr(chart, axis + "AxisRangeMaximum")] for axis in ("Bottom", "Left", "Right")]

    # What each chart shows (the table its representation was delivered) against the
    # spectrum's own output, through a bad run and good runs, in two chart views.
    def shown(chart_view):
        """Rows and the first radial powers of the curve the view draws."""
        drawn = chart_view.GetClientSideObject().GetChart()
        for i in range(drawn.GetNumberOfPlots()):
            plot = drawn.GetPlot(i)
            table = plot.GetInput()
            if plot.GetLabel() != "Radial power" or not plot.GetVisible() or table is None:
                continue
            column = table.GetColumnByName("RadialPower")
            rows = table.GetNumberOfRows()
            return rows, [column.GetValue(j) for j in range(1, 4)] if rows and column else []
        return 0, []

    def produced():
        table = servermanager.Fetch(spectrum)
        power = table.GetColumnByName("RadialPower") if table.GetNumberOfRows() else None
        return table.GetNumberOfRows(), [power.GetValue(i) for i in range(1, 4)] if power else []

    second = CreateView("BlueNoiseSpectrumView")
    AssignViewToLayout(second, GetLayout(view), 0)
    second_display = Show(spectrum, second)
    runs = []
    result["expected_messages"] = ["has no points", "NumberOfPoints is 0"]
    for points in (0, 7000, 0, 9000):
        sampler.NumberOfPoints = points
        spectrum.UpdatePipeline()
        # ParaView 6.1 may draw the views while a script's UpdatePipeline runs
        # (the GUI processes events when the sampler reports progress): the
        # sampler's nested request gets its output as it stands, the spectrum
        # runs on that, and the charts keep the table it made, taken for up to
        # date. The check is what a chart shows when drawn after the update, so
        # ParaView is told first that the spectrum's output changed (its
        # representations and their views are marked out of date).
        spectrum.SMProxy.MarkDirty(spectrum.SMProxy)
        Render(chart)
        Render(second)
        runs.append({"points": points, "produced": produced(), "chart": shown(chart),
                     "second_chart": shown(second)})
    result["chart_runs"] = runs
    result["finished"] = True
except Exception:
    result["error"] = result.get("error", "") + traceback.format_exc()
save()
