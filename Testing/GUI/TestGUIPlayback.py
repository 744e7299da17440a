# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Plays recorded Qt events back in the real ParaView GUI, as ParaView tests itself
(pqTestUtility: `paraview --test-script=X.xml`), under Xvfb.

    python3 TestGUIPlayback.py --paraview paraview --plugin-dir DIR --out DIR
        (--script EVENTS.xml | --panel-widgets PLUGIN.xml [PLUGIN.xml ...])
        [--set PROXY.PROPERTY=TEXT ...] [--data-dir DIR] [--baseline-dir DIR]
        [--xvfb-run xvfb-run] [--timeout 240]

--script plays a recorded session (menus, the panel's fields, Apply, pqcheck of
widget values, where {count:N} stands for a count as this ParaView prints it, pqcompareview of a view against a baseline image: a missing
baseline fails and leaves the image under --out to inspect and copy).
--panel-widgets writes and plays a session that opens the example volume, makes
every filter of the plugin XML from its menu and checks that each property a
user may set (not information_only, not panel_visibility="never", not the
input) has its widget in the Properties panel, whatever its panel visibility
(advanced ones are hidden until the gear is pressed, but exist), then Apply.
Fails on a failed event or check, a nonzero exit, a timeout, or any warning or
error in the GUI's output.
"""
import argparse
import os
import re
import shutil
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from bluenoise_testing import check, finish  # noqa: E402
from paraview_gui import add_paraview_arguments, complaints, run_paraview  # noqa: E402

PANEL = ("pqClientMainWindow/propertiesDock/propertiesPanel/scrollArea/qt_scrollarea_viewport/"
         "scrollAreaWidgetContents/PropertiesFrame/ProxyPanel")
ACCEPT = "pqClientMainWindow/propertiesDock/propertiesPanel/Accept"


def settable_properties(proxy):
    """The properties of a proxy element that the panel must show."""
    names = []
    for element in proxy:
        if not element.tag.endswith("Property") or element.tag == "InputProperty":
            continue
        if element.get("information_only") == "1" or element.get("panel_visibility") == "never":
            continue
        names.append(element.get("name"))
    return names


def panel_widget_events(plugin_xmls, data_file, values):
    """The events of --panel-widgets, and the number of widgets they check; `values`
    maps "Proxy.Property" to a text typed into its first line edit before Apply."""
    events = [("pqevent", "pqClientMainWindow/MainControlsToolbar/actionOpenData", "activate", ""),
              ("pqevent", "pqClientMainWindow/FileOpenDialog", "filesSelected", data_file),
              ("pqevent", ACCEPT, "activate", "")]
    checked = 0
    for path in plugin_xmls:
        for group in ET.parse(path).getroot().iter("ProxyGroup"):
            if group.get("name") != "filters":
                continue
            for proxy in group:
                menu = proxy.find("Hints/ShowInMenu")
                category = menu.get("category") if menu is not None else "Alphabetical"
                events.append(("pqevent", "pqClientMainWindow/menubar", "activate", "menuFilters"))
                events.append(("pqevent", "pqClientMainWindow/menubar/menuFilters/" + category,
                               "activate", proxy.get("name")))
                for name in settable_properties(proxy):
                    # pqcheck fails when the object does not exist.
                    events.append(("pqcheck", PANEL + "/" + name, "objectName", name))
                    checked += 1
                    value = values.get(proxy.get("name") + "." + name)
                    if value is not None:
                        events.append(("pqevent", PANEL + "/" + name + "/LineEdit0", "set_string",
                                       value))
                events.append(("pqevent", ACCEPT, "activate", ""))
    return events, checked


def format_counts(script, version, out):
    """A copy of `script` in which each {count:N} is N as the Information panel of
    this ParaView prints it: grouped by thousands before ParaView 6, plain from 6 on."""
    major = int(version.split(".")[0]) if version else 5
    with open(script) as f:
        text = f.read()
    text = re.sub(r"\{count:(\d+)\}",
                  lambda m: format(int(m.group(1)), "," if major < 6 else "d"), text)
    path = os.path.join(out, os.path.basename(script))
    with open(path, "w") as f:
        f.write(text)
    return path


def write_events(events, path):
    root = ET.Element("pqevents")
    for kind, obj, command, arguments in events:
        attributes = {"object": obj, "arguments": arguments}
        attributes["property" if kind == "pqcheck" else "command"] = command
        ET.SubElement(root, kind, attributes)
    ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)


def main():
    parser = argparse.ArgumentParser()
    add_paraview_arguments(parser)
    parser.add_argument("--script")
    parser.add_argument("--panel-widgets", nargs="+")
    parser.add_argument("--set", action="append", default=[], metavar="PROXY.PROPERTY=TEXT",
                        help="with --panel-widgets: a value typed in before Apply")
    parser.add_argument("--paraview-version", default="",
                        help="MAJOR.MINOR: how {count:N} in --script is printed")
    parser.add_argument("--data-dir", default="")
    parser.add_argument("--baseline-dir", default="")
    args = parser.parse_args()
    if os.path.isdir(args.out):
        shutil.rmtree(args.out)
    os.makedirs(args.out)

    script = format_counts(args.script, args.paraview_version, args.out) if args.script else None
    if args.panel_widgets:
        script = os.path.join(args.out, "PanelWidgets.xml")
        events, checked = panel_widget_events(
            args.panel_widgets, os.path.join(args.data_dir, "brain-small.vti"),
            dict(item.split("=", 1) for item in args.set))
        write_events(events, script)
        check(checked >= 20, "the session checks %d property widgets" % checked)

    command = [args.paraview, "--dr", "--plugin-search-paths=" + args.plugin_dir,
               "--plugins=" + args.plugin_name, "--test-script=" + script,
               "--test-directory=" + args.out, "--exit"]
    if args.data_dir:
        command.append("--data-directory=" + args.data_dir)
    if args.baseline_dir:
        command.append("--baseline-directory=" + args.baseline_dir)
    # VTK 9.3+ warns when the image comparison's method is left to its default.
    returncode, output = run_paraview(command, args.out, args.timeout, args.xvfb_run,
                                      {"VTK_TESTING_IMAGE_COMPARE_METHOD": "LEGACY_VALID"})
    bad = complaints(output)
    check(not bad, "no warning or error in the GUI's output (%d line(s)%s)"
          % (len(bad), "".join("\n      " + line for line in bad[:10])))
    check(returncode == 0, "the playback of %s passed: paraview exited with 0 (got %r%s)"
          % (os.path.basename(script), returncode,
             ", timed out after %gs" % args.timeout if returncode is None else ""))
    finish()


if __name__ == "__main__":
    main()
