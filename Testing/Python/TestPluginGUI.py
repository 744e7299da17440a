# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin in the real ParaView GUI, under Xvfb.

    python3 TestPluginGUI.py --paraview /usr/bin/paraview --plugin-dir DIR --out DIR \
        [--xvfb-run /usr/bin/xvfb-run] [--timeout 240]

Starts `xvfb-run -a paraview --dr --plugin-search-paths=DIR --plugins=BlueNoiseSampling
--script=TestPluginGUIScript.py --exit`, then checks what the script recorded
(plugin loaded, ShowInMenu category Sampling, points shown) and that the
screenshots exist and are not blank. Exits 125 (skip) only when there is no
display and no xvfb-run; 1 on any failure.
"""
import argparse
import json
import os
import shutil
import signal
import subprocess
import sys

from bluenoise_testing import SKIP, check, finish


def image_stats(path):
    """(width, height, fraction of pixels unlike the background, number of colours,
    fraction of the most frequent colour)."""
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
    # The background is the most frequent colour.
    colours, counts = np.unique(pixels, axis=0, return_counts=True)
    background = colours[np.argmax(counts)]
    differs = np.any(np.abs(pixels - background) > 8, axis=1)
    return w, h, float(differs.mean()), len(colours), float(counts.max()) / len(pixels)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--paraview", required=True)
    parser.add_argument("--plugin-dir", required=True)
    parser.add_argument("--plugin-name", default="BlueNoiseSampling")
    parser.add_argument("--out", required=True)
    parser.add_argument("--xvfb-run", default=shutil.which("xvfb-run") or "")
    parser.add_argument("--timeout", type=float, default=240)
    args = parser.parse_args()

    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "TestPluginGUIScript.py")
    if os.path.isdir(args.out):
        shutil.rmtree(args.out)
    os.makedirs(args.out)

    command = [args.paraview, "--dr", "--plugin-search-paths=" + args.plugin_dir,
               "--plugins=" + args.plugin_name, "--script=" + script, "--exit"]
    if args.xvfb_run:
        command = [args.xvfb_run, "-a", "-s", "-screen 0 1280x1024x24"] + command
    elif not os.environ.get("DISPLAY"):
        print("SKIP: no DISPLAY and no xvfb-run to start the ParaView GUI")
        sys.exit(SKIP)

    env = dict(os.environ)
    env["BLUENOISE_GUI_OUTPUT"] = args.out
    # The plugin must come from --plugins, not from a PV_PLUGIN_PATH of the caller.
    env.pop("PV_PLUGIN_PATH", None)
    if not env.get("XDG_RUNTIME_DIR"):
        runtime = os.path.join(args.out, "runtime")
        os.makedirs(runtime, mode=0o700)
        env["XDG_RUNTIME_DIR"] = runtime
    print("running: " + " ".join(command), flush=True)
    # A session of its own, so that a timeout ends xvfb-run, Xvfb and paraview together.
    process = subprocess.Popen(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               start_new_session=True)
    try:
        output, _ = process.communicate(timeout=args.timeout)
        returncode = process.returncode
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGTERM)  # lets xvfb-run stop Xvfb and clean up
        try:
            output, _ = process.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            output, _ = process.communicate()
        returncode = None
    output = output.decode(errors="replace")
    print("---- paraview output ----\n" + output.rstrip() + "\n-------------------------", flush=True)
    check(returncode == 0, "paraview exited with 0 (got %r%s)"
          % (returncode, ", timed out after %gs" % args.timeout if returncode is None else ""))

    result_file = os.path.join(args.out, "result.json")
    if not check(os.path.exists(result_file), "the GUI script ran (%s written)" % result_file):
        finish()
    with open(result_file) as f:
        result = json.load(f)
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
        check(sorted(result["chart_visible_series"]) == ["Anisotropy", "RadialPower"],
              "the chart shows RadialPower and Anisotropy (%r)" % result["chart_visible_series"])

    for key, what in (("screenshot", "render view"), ("chart_screenshot", "spectrum chart")):
        path = result.get(key)
        if not check(path is not None and os.path.exists(path), "%s screenshot saved (%s)" % (what, path)):
            continue
        w, h, fraction, colours, background = image_stats(path)
        check((w, h) == (640, 480), "%s screenshot is 640x480 (%dx%d)" % (what, w, h))
        check(fraction > 0.005 and colours > 16,
              "%s screenshot is not blank (%.2f%% of pixels unlike the background, %d colours)"
              % (what, 100 * fraction, colours))
        # A rendered view has a background; an unrealised window gives noise.
        check(background > 0.3, "%s screenshot has a background (%.1f%% of pixels), not noise"
              % (what, 100 * background))
    finish()


if __name__ == "__main__":
    main()
