# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin in the real ParaView GUI, under Xvfb.

    python3 TestPluginGUI.py --paraview /usr/bin/paraview --plugin-dir DIR --out DIR \
        [--xvfb-run /usr/bin/xvfb-run] [--timeout 240]

Starts `xvfb-run -a paraview --dr --plugin-search-paths=DIR --plugins=BlueNoiseSampling
--script=TestPluginGUIScript.py --exit`, then checks what the script recorded
(plugin loaded, ShowInMenu category Sampling, points shown, one execution of each
filter, the spectrum view), that the GUI's output holds no warning or error line,
and that the screenshots exist and are not blank. Exits 125 (skip) only when there is no
display and no xvfb-run; 1 on any failure.
"""
import argparse
import json
import os
import shutil

from bluenoise_testing import check, finish
from paraview_gui import add_paraview_arguments, complaints, run_paraview


def image_stats(path):
    """(width, height, fraction of pixels unlike the background, number of colors,
    fraction of the most frequent color)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    import numpy as np

    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    scalars = image.GetPointData().GetScalars()
    if scalars is None or w * h == 0:
        return w, h, 0.0, 0, 0.0
    pixels = vtk_to_numpy(scalars).reshape(h * w, -1)[:, :3].astype(np.int32)
    # The background is the most frequent color.
    colors, counts = np.unique(pixels, axis=0, return_counts=True)
    background = colors[np.argmax(counts)]
    differs = np.any(np.abs(pixels - background) > 8, axis=1)
    return w, h, float(differs.mean()), len(colors), float(counts.max()) / len(pixels)


def main():
    parser = argparse.ArgumentParser()
    add_paraview_arguments(parser)
    args = parser.parse_args()

    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "TestPluginGUIScript.py")
    if os.path.isdir(args.out):
        shutil.rmtree(args.out)
    os.makedirs(args.out)

    command = [args.paraview, "--dr", "--plugin-search-paths=" + args.plugin_dir,
               "--plugins=" + args.plugin_name, "--script=" + script, "--exit"]
    returncode, output = run_paraview(command, args.out, args.timeout, args.xvfb_run,
                                      {"BLUENOISE_GUI_OUTPUT": args.out})
    # The session's log: no warning or error anywhere (a GUI user sees them as popups or in
    # the Output Messages window, which echoes them on stderr).
    result_file = os.path.join(args.out, "result.json")
    result = {}
    if os.path.exists(result_file):
        with open(result_file) as f:
            result = json.load(f)
    # The messages the script provokes on purpose (a bad run), and nothing else.
    expected = result.get("expected_messages", [])
    bad = [line for line in complaints(output) if not any(e in line for e in expected)]
    check(not bad, "no warning or error in the GUI's output (%d line(s)%s)"
          % (len(bad), "".join("\n      " + line for line in bad[:10])))
    check(returncode == 0, "paraview exited with 0 (got %r%s)"
          % (returncode, ", timed out after %gs" % args.timeout if returncode is None else ""))

    if not check(os.path.exists(result_file), "the GUI script ran (%s written)" % result_file):
        finish()
    print("script result: " + json.dumps(result, indent=1))
    check(args.plugin_name in result.get("loaded_plugins", []),
          "--plugins loaded %s (loaded: %s)" % (args.plugin_name, result.get("loaded_plugins")))
    for name in ("ErrorDiffusionSampler", "BlueNoiseSpectrum"):
        category = result.get("categories", {}).get(name)
        check(category == "Sampling", "%s is in the Sampling menu category (%r)" % (name, category))
    check("error" not in result, "the GUI script ran without error" +
          ("" if "error" not in result else ":\n" + result["error"]))
    check(result.get("finished") is True, "the GUI script finished")
    if "representation_type" in result:
        check(result["representation_type"] == "Points",
              "the sampler is shown as Points (%r)" % result["representation_type"])
    if "points" in result:
        check(result["points"] > 1000, "the sampler made %d points" % result["points"])
    if "spectrum_rows" in result:
        check(result["spectrum_rows"] > 10, "the spectrum has %d rows" % result["spectrum_rows"])
    if result.get("finished"):
        check(result["chart_x_array"] == "Frequency",
              "the spectrum chart plots against Frequency (%r)" % result["chart_x_array"])
        check(sorted(result["chart_visible_series"]) == ["AnisotropyDB", "PrincipalFrequencyMarker",
                                                          "RadialPower"],
              "the chart shows RadialPower, AnisotropyDB and the f_g marker (%r)"
              % result["chart_visible_series"])
        check(result["chart_left_log"] == 1 and all(result["chart_titles"]),
              "the chart's power axis is logarithmic and its axes titled (%r, %r)"
              % (result["chart_left_log"], result["chart_titles"]))
        # Apply shows the samples in the render view and the spectrum table in a view of its
        # own; neither the mask nor the 3D spectrum is shown.
        check(result["sampler_views"] == ["RenderView", None],
              "Apply of the sampler shows %r (RenderView, not the mask)" % result["sampler_views"])
        check(result["spectrum_views"] == ["BlueNoiseSpectrumView", None],
              "Apply of the spectrum shows %r (its chart view, not the 3D spectrum)"
              % result["spectrum_views"])
        check(result["executions_after_samples"] == {"sampler": 1, "spectrum": 0},
              "showing the samples executed %r" % result["executions_after_samples"])
        check(result["chart_ranges"] == [[1, 0.0, 0.5], [1, 0.01, 10.0], [1, -10.0, 10.0]],
              "the spectrum chart's axes have fixed ranges: frequency [0, 0.5], power [0.01, 10], "
              "anisotropy [-10, 10] dB (%r)" % result["chart_ranges"])
        for run in result["chart_runs"]:
            rows, power = run["produced"]
            for key in ("chart", "second_chart"):
                check(run[key] == [rows, power],
                      "Number Of Points %d: the %s shows what the spectrum made (%d rows%s; "
                      "shows %r)" % (run["points"], key.replace("_", " "), rows,
                                     ", an error: cleared" if rows == 0 else "", run[key]))
            check((rows == 0) == (run["points"] == 0), "Number Of Points %d: %d spectrum rows"
                  % (run["points"], rows))
        check(result["executions"] == {"sampler": 1, "spectrum": 1},
              "samples, then spectrum, then a display change: executions %r (1 each)"
              % result["executions"])

    for key, what, size in (("screenshot", "render view", (640, 480)),
                            ("chart_screenshot", "spectrum chart", (640, 480)),
                            ("layout_screenshot", "render view and spectrum side by side", (1280, 480))):
        path = result.get(key)
        if not check(path is not None and os.path.exists(path), "%s screenshot saved (%s)" % (what, path)):
            continue
        w, h, fraction, colors, background = image_stats(path)
        check((w, h) == size, "%s screenshot is %dx%d (%dx%d)" % (what, size[0], size[1], w, h))
        check(fraction > 0.005 and colors > 16,
              "%s screenshot is not blank (%.2f%% of pixels unlike the background, %d colors)"
              % (what, 100 * fraction, colors))
        # A rendered view has a background; an unrealized window gives noise.
        check(background > 0.3, "%s screenshot has a background (%.1f%% of pixels), not noise"
              % (what, 100 * background))
    finish()


if __name__ == "__main__":
    main()
