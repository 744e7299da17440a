# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Running the ParaView GUI under Xvfb for the GUI tests (TestPluginGUI, the
event-playback tests of Testing/GUI): one process group, a timeout that ends
xvfb-run, Xvfb and paraview together, and the lines of its output that are a
warning or an error."""
import os
import shutil
import signal
import subprocess
import sys

from bluenoise_testing import SKIP

# Lines of the paraview output that are not the GUI's: Xvfb's own start-up notes.
HARMLESS = ("_XSERVTransmkdir", "xvfb-run:", "Process started",
            # pqTestUtility's image comparison figures (ImageError: the difference)
            "<DartMeasurement")


def is_complaint(line):
    """A warning or error of ParaView, VTK, Qt or the plugin."""
    text = line.strip()
    if not text or any(h in text for h in HARMLESS):
        return False
    lowered = text.lower()
    return any(word in lowered for word in ("warn", "error", "err|", "could not", "cannot", "failed",
                                            "traceback"))


def complaints(output):
    return [line for line in output.splitlines() if is_complaint(line)]


def run_paraview(paraview_args, out, timeout, xvfb_run, env_extra=None):
    """Runs `paraview paraview_args...` (under `xvfb-run -a` when xvfb_run is set;
    exits SKIP when there is neither a display nor xvfb-run). Returns (exit code,
    or None on timeout; the output, stdout and stderr together), and prints the output."""
    command = list(paraview_args)
    if xvfb_run:
        # -noreset: a connection opened while the server resets (after its
        # last client left) fails.
        command = [xvfb_run, "-a", "-s", "-screen 0 1280x1024x24 -noreset"] + command
    elif not os.environ.get("DISPLAY"):
        print("SKIP: no DISPLAY and no xvfb-run to start the ParaView GUI")
        sys.exit(SKIP)
    env = dict(os.environ)
    env.update(env_extra or {})
    # The plugin must come from --plugins, not from a PV_PLUGIN_PATH of the caller.
    env.pop("PV_PLUGIN_PATH", None)
    if not env.get("XDG_RUNTIME_DIR"):
        runtime = os.path.join(out, "runtime")
        os.makedirs(runtime, mode=0o700, exist_ok=True)
        env["XDG_RUNTIME_DIR"] = runtime
    print("running: " + " ".join(command), flush=True)
    process = subprocess.Popen(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               start_new_session=True)
    try:
        output, _ = process.communicate(timeout=timeout)
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
    return returncode, output


def add_paraview_arguments(parser):
    """The options every GUI driver takes: the program, the plugin, the output folder."""
    parser.add_argument("--paraview", required=True)
    parser.add_argument("--plugin-dir", required=True)
    parser.add_argument("--plugin-name", default="BlueNoiseSampling")
    parser.add_argument("--out", required=True)
    parser.add_argument("--xvfb-run", default=shutil.which("xvfb-run") or "")
    parser.add_argument("--timeout", type=float, default=240)
