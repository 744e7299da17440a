# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Runs inside the ParaView GUI (paraview --script=THIS --exit), see TestPluginGUI.py.

The plugin is loaded by the GUI itself (--plugins); this script does what a user
does after Filters > Sampling > Error Diffusion Sampler > Apply: it shows the
sampler's points in the render view and the spectrum in a line chart, and saves
screenshots. ParaView exits 0 even when a --script raises, so the outcome goes
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

    wavelet = Wavelet()
    sampler = ErrorDiffusionSampler(Input=wavelet)
    sampler.UseNumberOfPoints = 0
    sampler.DensityScale = 0.3
    sampler.UpdatePipeline()
    result["points"] = sampler.GetDataInformation().GetNumberOfPoints()
    save()

    # The render view: what Apply shows.
    try:
        view = GetActiveViewOrCreate("RenderView")
        display = Show(sampler, view)
        result["representation"] = display.GetXMLName()
        result["representation_type"] = display.GetProperty("Representation").GetData()
        ColorBy(display, ("POINTS", "RTData"))
        display.PointSize = 3.0
        view.OrientationAxesVisibility = 0
        view.ResetCamera()
        Render(view)
        shot = os.path.join(OUT, "sampler.png")
        SaveScreenshot(shot, view, ImageResolution=[640, 480])
        result["screenshot"] = shot
    except Exception:
        result["error"] = traceback.format_exc()
    save()

    # The spectrum in a line chart, in a layout of its own.
    spectrum = BlueNoiseSpectrum(Input=sampler)
    chart = CreateView("XYChartView")
    # A view outside any layout has no window yet: its screenshot would be garbage.
    AssignViewToLayout(view=chart, layout=CreateLayout("Spectrum"))
    chart_display = Show(spectrum, chart)
    result["chart_representation"] = chart_display.GetXMLName()
    result["chart_x_array"] = chart_display.XArrayName if not chart_display.UseIndexForXAxis else ""
    result["chart_visible_series"] = [
        name for name, visible in zip(chart_display.SeriesVisibility[0::2],
                                      chart_display.SeriesVisibility[1::2]) if visible == "1"]
    Render(chart)
    result["spectrum_rows"] = spectrum.GetDataInformation().GetNumberOfRows()
    chart_shot = os.path.join(OUT, "spectrum.png")
    SaveScreenshot(chart_shot, chart, ImageResolution=[640, 480])
    result["chart_screenshot"] = chart_shot
    result["finished"] = True
except Exception:
    result["error"] = result.get("error", "") + traceback.format_exc()
save()
