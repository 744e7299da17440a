# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Every property of the plugin's proxies reaches its VTK object.

    pvpython TestPluginProperties.py --plugin BlueNoiseSampling.so --xml BlueNoiseSampling.xml \
        --xml BlueNoiseReaders.xml

Needs the bluenoise Python package on PYTHONPATH (so that GetClientSideObject()
returns the wrapped vtkErrorDiffusionSampler / vtkBlueNoiseSpectrum).

1. The XML: every proxy and property documented, every vector/proxy property
   with a domain, ShowInMenu category "Sampling", the Representation/View hints
   naming proxies that exist, the XML defaults equal to the VTK defaults.
2. The property walk: for ErrorDiffusionSampler and BlueNoiseSpectrum, every
   property from the proxy's property iterator is set to a valid non-default
   value chosen from its domain (every entry of an enumeration, both values of
   a boolean, values inside ranges, another array, a piecewise function proxy,
   a temporary parameter file), pushed with UpdateVTKObjects(), and read back
   with the VTK object's Get method. A property without a getter fails.
   The readers (BlueNoiseNIfTIReader) too: documented, with a ReaderFactory
   hint instead of a menu category, walked on a small NIfTI file.
3. ParameterSet Custom with that parameter file actually samples with it.
"""
import argparse
import math
import os
import tempfile
import xml.etree.ElementTree as ET

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.util.numpy_support import vtk_to_numpy

from bluenoise_testing import check, finish
from nifti_testing import write_nifti

PROXIES = ("ErrorDiffusionSampler", "BlueNoiseSpectrum")
READERS = ("BlueNoiseNIfTIReader",)
VECTOR_TAGS = ("IntVectorProperty", "DoubleVectorProperty", "StringVectorProperty", "ProxyProperty")


# ---------------------------------------------------------------------------
# 1. The XML.
def xml_proxies(paths):
    proxies = {}
    for group in (g for path in paths for g in ET.parse(path).getroot().iter("ProxyGroup")):
        for proxy in group:
            if proxy.tag.endswith("Proxy") and proxy.get("name"):
                proxies[proxy.get("name")] = proxy
    return proxies


def xml_properties(proxy):
    return [child for child in proxy if child.tag.endswith("Property")]


def doc_text(element):
    doc = element.find("Documentation")
    if doc is None:
        return ""
    return " ".join(("".join(doc.itertext()) + " " + doc.get("short_help", "")).split())


def check_xml(paths):
    proxies = xml_proxies(paths)
    for name in PROXIES + READERS:
        if not check(name in proxies, "XML defines proxy %s" % name):
            continue
        proxy = proxies[name]
        check(bool(doc_text(proxy)), "%s: proxy documented" % name)
        for prop in xml_properties(proxy):
            pname = prop.get("name")
            check(bool(doc_text(prop)), "%s.%s: documentation text in the XML" % (name, pname))
            if prop.tag in VECTOR_TAGS:
                domains = [child.tag for child in prop if child.tag.endswith("Domain")]
                check(bool(domains), "%s.%s (%s): has a domain %s" % (name, pname, prop.tag, domains))
        hints = proxy.find("Hints")
        if name in READERS:
            factory = hints.find("ReaderFactory") if hints is not None else None
            check(factory is not None and factory.get("extensions") and factory.get("file_description"),
                  "%s: a ReaderFactory hint with extensions and a file description" % name)
            continue
        menu = hints.find("ShowInMenu") if hints is not None else None
        category = menu.get("category") if menu is not None else None
        check(category == "Sampling", "%s: ShowInMenu category %r == 'Sampling'" % (name, category))
    return proxies


def check_hints(proxies):
    """Hints that name other proxies must name proxies ParaView has."""
    pxm = servermanager.ProxyManager().SMProxyManager
    for name in PROXIES:
        hints = proxies[name].find("Hints") if name in proxies else None
        if hints is None:
            continue
        for rep in hints.findall("Representation"):
            rtype = rep.get("type")
            check(pxm.GetPrototypeProxy("representations", rtype) is not None,
                  "%s: <Representation view=%r type=%r/> names a representation proxy "
                  "(a representation *type* such as Points needs <RepresentationType .../>)"
                  % (name, rep.get("view"), rtype))
        for view in hints.findall("View"):
            # "None": the port is not shown on Apply.
            check(view.get("type") == "None" or pxm.GetPrototypeProxy("views", view.get("type")) is not None,
                  "%s: <View type=%r/> names a view proxy or None" % (name, view.get("type")))
        # The pipeline browser loads an icon name as a pixmap unless it is one of its own
        # (a view type name it has no icon for makes it warn): every port says which.
        known_icons = ("GEOMETRY", "XYChartView", "SpreadSheetView")
        for port in range(len(proxies[name].findall("OutputPort"))):
            icon = [i.get("name") for i in hints.findall("PipelineIcon") if i.get("port", str(port)) == str(port)]
            views = [v.get("type") for v in hints.findall("View") if v.get("port", str(port)) == str(port)]
            check((icon and icon[0] in known_icons) or (not icon and all(v in known_icons for v in views)),
                  "%s: port %d has a pipeline icon the GUI knows (PipelineIcon %s, View %s)"
                  % (name, port, icon, views))
        # The loaded proxy carries the same menu category.
        sm_hints = servermanager.ProxyManager().SMProxyManager.GetPrototypeProxy("filters", name).GetHints()
        menu = sm_hints.FindNestedElementByName("ShowInMenu") if sm_hints else None
        check(menu is not None and menu.GetAttribute("category") == "Sampling",
              "%s: loaded proxy hints ShowInMenu category Sampling" % name)
    for name in READERS:
        prototype = pxm.GetPrototypeProxy("sources", name)
        sm_hints = prototype.GetHints() if prototype is not None else None
        factory = sm_hints.FindNestedElementByName("ReaderFactory") if sm_hints else None
        check(factory is not None, "%s: loaded as a source with its ReaderFactory hint" % name)


def parse_default(prop):
    text = prop.get("default_values")
    if text is None:
        return None
    if prop.tag == "StringVectorProperty":
        return text
    items = text.split()
    if prop.tag in ("IntVectorProperty", "IdTypeVectorProperty"):
        values = [int(v) for v in items]
    else:
        values = [float(v) for v in items]
    return values[0] if len(values) == 1 else tuple(values)


# Defaults the GUI sets apart from the VTK class's, on purpose.
GUI_DEFAULTS = {
    # The GUI shows the points: on the voxel lattice they read as lines in
    # perspective. VTK pipelines keep the lattice unless asked.
    ("ErrorDiffusionSampler", "Jitter"): 1,
    # The 3D spectrum doubles the filter's memory and the GUI does not show it:
    # made when asked for. VTK pipelines that slice it keep getting it.
    ("BlueNoiseSpectrum", "GenerateSpectrumImage"): 0,
}


def check_xml_defaults(proxies, vtk_classes):
    """The XML defaults are the VTK defaults (but for GUI_DEFAULTS): pvpython and VTK users get
    the same filter."""
    for name, cls in vtk_classes.items():
        obj = cls()
        for prop in xml_properties(proxies[name]):
            command = prop.get("command", "")
            default = parse_default(prop)
            if default is None or not command.startswith("Set") or command == "SetInputArrayToProcess":
                continue
            getter = "Get" + command[3:]
            if not hasattr(obj, getter):
                continue  # reported by the walk
            got = getattr(obj, getter)()
            if (name, prop.get("name")) in GUI_DEFAULTS:
                check(default == GUI_DEFAULTS[(name, prop.get("name"))] and not values_equal(got, default),
                      "%s.%s: GUI default %r on purpose (VTK %r)" % (name, prop.get("name"), default, got))
                continue
            if isinstance(default, str):
                same = (got or "") == default
            else:
                same = values_equal(got, default)
            check(same, "%s.%s: XML default %r == VTK default %r" % (name, prop.get("name"), default, got))


# ---------------------------------------------------------------------------
# 2. The walk.
def values_equal(got, want):
    if isinstance(want, (tuple, list)):
        if not isinstance(got, (tuple, list)) or len(got) != len(want):
            return False
        return all(values_equal(g, w) for g, w in zip(got, want))
    if isinstance(want, str):
        return (got or "") == want
    if isinstance(want, float) or isinstance(got, float):
        return math.isclose(float(got), float(want), rel_tol=1e-12, abs_tol=1e-12)
    return int(got) == int(want)


def upstream_algorithm(algorithm):
    """The algorithm feeding input 0 of `algorithm`, seen through ParaView's vtkPVPostFilter."""
    upstream = algorithm.GetInputAlgorithm(0, 0)
    while upstream is not None and upstream.IsA("vtkPVPostFilter"):
        upstream = upstream.GetInputAlgorithm(0, 0)
    return upstream


def element_values(prop):
    return [prop.GetElement(i) for i in range(prop.GetNumberOfElements())]


def domains_of(prop):
    it = prop.NewDomainIterator()
    it.Begin()
    result = []
    while not it.IsAtEnd():
        result.append(it.GetDomain())
        it.Next()
    return result


def domain_problem(domain, prop):
    """Why the property's current value is outside `domain`, or None."""
    cls = domain.GetClassName()
    if cls in ("vtkSMIntRangeDomain", "vtkSMDoubleRangeDomain", "vtkSMArrayRangeDomain"):
        values = element_values(prop)
        for i, v in enumerate(values):
            entry = 0 if cls == "vtkSMArrayRangeDomain" else i  # Get*Exists is false past the entries
            if domain.GetMinimumExists(entry) and v < domain.GetMinimum(entry):
                return "%s: element %d = %r < %r" % (cls, i, v, domain.GetMinimum(entry))
            if domain.GetMaximumExists(entry) and v > domain.GetMaximum(entry):
                return "%s: element %d = %r > %r" % (cls, i, v, domain.GetMaximum(entry))
        return None
    if cls == "vtkSMEnumerationDomain":
        allowed = [domain.GetEntryValue(i) for i in range(domain.GetNumberOfEntries())]
        v = prop.GetElement(0)
        return None if v in allowed else "%s: %r not in %r" % (cls, v, allowed)
    if cls == "vtkSMBooleanDomain":
        v = prop.GetElement(0)
        return None if v in (0, 1) else "%s: %r" % (cls, v)
    if cls == "vtkSMArrayListDomain":
        names = [domain.GetString(i) for i in range(domain.GetNumberOfStrings())]
        v = prop.GetElement(prop.GetNumberOfElements() - 1)
        return None if v in names else "%s: %r not in %r" % (cls, v, names)
    if cls == "vtkSMFileListDomain":
        v = prop.GetElement(0)
        return None if os.path.isfile(v) else "%s: no file %r" % (cls, v)
    if cls == "vtkSMProxyListDomain":
        types = [domain.GetProxyName(i) for i in range(domain.GetNumberOfProxyTypes())]
        names = [prop.GetProxy(i).GetXMLName() for i in range(prop.GetNumberOfProxies())]
        return None if all(n in types for n in names) else "%s: %r not in %r" % (cls, names, types)
    return None


def range_value(domain, index, default, is_int):
    """A value inside the range domain, different from the default."""
    lo = domain.GetMinimum(index) if domain.GetMinimumExists(index) else None
    hi = domain.GetMaximum(index) if domain.GetMaximumExists(index) else None
    if lo is not None and hi is not None:
        candidates = [lo + (hi - lo) * f for f in (0.5, 0.25, 0.75, 1.0, 0.0)]
    else:
        base = default if lo is None else max(default, lo)
        candidates = [base + 3 + index, base + 1.375 + index] if not is_int else [base + 3 + index]
    for c in candidates:
        c = int(math.floor(c)) if is_int else float(c)
        if c != default:
            return c
    raise RuntimeError("no non-default value in range")


class Walker:
    def __init__(self, proxy, name, context):
        self.proxy = proxy
        self.name = name
        self.context = context
        self.obj = proxy.GetClientSideObject()

    def push_and_get(self, key, prop, value):
        self.proxy.SetPropertyWithName(key, value)
        self.proxy.UpdateVTKObjects()
        # vtkSMProperty::IsInDomains() of ParaView 5.11 rejects in-range values of
        # min+max range domains (Shrink's ShrinkFactor 0.5 too): check here instead.
        problems = [p for p in (domain_problem(d, prop) for d in domains_of(prop)) if p]
        check(not problems, "%s.%s: value %r is inside the property's domains %s" % (self.name, key, value, problems))

    def walk(self):
        check(self.obj is not None and self.obj.GetClassName() == self.proxy.SMProxy.GetVTKClassName(),
              "%s: client-side object is a %s" % (self.name, self.proxy.SMProxy.GetVTKClassName()))
        python_names = set(self.proxy.ListProperties())
        it = self.proxy.SMProxy.NewPropertyIterator()
        it.Begin()
        seen = []
        while not it.IsAtEnd():
            key, prop = it.GetKey(), it.GetProperty()
            it.Next()
            if prop.GetInformationOnly():
                continue
            seen.append(key)
            check(key in python_names, "%s.%s: listed by ListProperties()" % (self.name, key))
            try:
                self.walk_property(key, prop)
            except Exception as error:  # a crash in one property must not hide the others
                check(False, "%s.%s: %s: %s" % (self.name, key, type(error).__name__, error))
        return seen

    def walk_property(self, key, prop):
        command = prop.GetCommand() or ""
        cls = prop.GetClassName()
        if cls == "vtkSMInputProperty":
            return self.walk_input(key, prop)
        if command == "SetInputArrayToProcess":
            return self.walk_array(key, prop)
        if not command.startswith("Set"):
            return check(False, "%s.%s: command %r has no Get counterpart" % (self.name, key, command))
        getter = "Get" + command[3:]
        if not check(hasattr(self.obj, getter), "%s.%s: %s has %s()" % (self.name, key, self.obj.GetClassName(), getter)):
            return
        get = getattr(self.obj, getter)
        domains = {d.GetClassName(): d for d in domains_of(prop)}

        if cls == "vtkSMProxyProperty":
            # With Density Mapping = Color Map Opacity (the walk may have left it there) the
            # proxy sets the function itself (TestPluginColorMapOpacity): set one here.
            if self.proxy.GetProperty("DensityMapping") is not None:
                self.proxy.SetPropertyWithName("DensityMapping", "Transfer Function")
            pf = CreatePiecewiseFunction(Points=[0.0, 0.0, 0.5, 0.0, 100.0, 0.25, 0.5, 0.0, 250.0, 1.0, 0.5, 0.0])
            self.push_and_get(key, prop, pf)
            got = get()
            check(got is not None and got is pf.GetClientSideObject() and got.GetSize() == 3,
                  "%s.%s: %s() is the piecewise function set (%s)"
                  % (self.name, key, getter, got.GetClassName() if got else None))
            return

        if cls == "vtkSMStringVectorProperty":
            if "vtkSMFileListDomain" in domains:
                value = self.context["files"].get(self.name, self.context["parameter_file"])
            else:
                value = "bluenoise test value"
            self.push_and_get(key, prop, value)
            check(values_equal(get(), value), "%s.%s: %s() %r == %r" % (self.name, key, getter, get(), value))
            return

        is_int = cls in ("vtkSMIntVectorProperty", "vtkSMIdTypeVectorProperty")
        default = element_values(prop)
        n = len(default)
        if "vtkSMEnumerationDomain" in domains:
            enum = domains["vtkSMEnumerationDomain"]
            entries = [(enum.GetEntryText(i), enum.GetEntryValue(i)) for i in range(enum.GetNumberOfEntries())]
            entries.sort(key=lambda e: e[1] != default[0])  # the default first, end on another entry
            check(len(entries) >= 2, "%s.%s: enumeration with %d entries" % (self.name, key, len(entries)))
            for text, value in entries:
                self.push_and_get(key, prop, text)
                check(values_equal(get(), value),
                      "%s.%s = %r: %s() %r == %r" % (self.name, key, text, getter, get(), value))
            return
        if "vtkSMBooleanDomain" in domains:
            for value in (1 - default[0], default[0], 1 - default[0]):
                self.push_and_get(key, prop, value)
                check(values_equal(get(), value), "%s.%s = %r: %s() %r" % (self.name, key, value, getter, get()))
            return
        if "vtkSMArrayRangeDomain" in domains:
            domain = domains["vtkSMArrayRangeDomain"]
            lo, hi = domain.GetMinimum(0), domain.GetMaximum(0)
            check(hi > lo, "%s.%s: array range domain [%g, %g] from the input" % (self.name, key, lo, hi))
            value = [lo + 0.25 * (hi - lo), hi - 0.125 * (hi - lo)][:n]
        elif any(d in domains for d in ("vtkSMIntRangeDomain", "vtkSMDoubleRangeDomain", "vtkSMIdTypeRangeDomain")):
            domain = (domains.get("vtkSMIntRangeDomain") or domains.get("vtkSMDoubleRangeDomain")
                      or domains.get("vtkSMIdTypeRangeDomain"))
            value = [range_value(domain, i, default[i], is_int) for i in range(n)]
        else:
            # No domain (reported by the XML check): any distinct values.
            value = [default[i] + (3 + i if is_int else (-1.5 if i % 2 == 0 else 2.25 + i)) for i in range(n)]
        check(any(not values_equal(v, d) for v, d in zip(value, default)),
              "%s.%s: chose non-default %r (default %r)" % (self.name, key, value, default))
        self.push_and_get(key, prop, value[0] if n == 1 else value)
        got = get()
        check(values_equal(got, value[0] if n == 1 else tuple(value)),
              "%s.%s = %r: %s() %r" % (self.name, key, value, getter, got))

    def walk_input(self, key, prop):
        producers = self.context["inputs"][self.name]
        value = producers if prop.GetMultipleInput() else producers[0]
        self.proxy.SetPropertyWithName(key, value)
        self.proxy.UpdateVTKObjects()
        got = self.obj.GetNumberOfInputConnections(0)
        check(got == len(producers), "%s.%s: %d input connection(s) (%d)" % (self.name, key, len(producers), got))
        upstream = upstream_algorithm(self.obj)
        check(upstream is producers[0].GetClientSideObject(),
              "%s.%s: the input algorithm is the producer's (%s)" % (self.name, key,
                                                                     upstream.GetClassName() if upstream else None))

    def walk_array(self, key, prop):
        domain = prop.GetDomain("array_list")
        names = [domain.GetString(i) for i in range(domain.GetNumberOfStrings())] if domain else []
        current = prop.GetElement(4)
        others = [a for a in names if a != current]
        if not check(bool(others), "%s.%s: arrays to choose from %s besides %r" % (self.name, key, names, current)):
            return
        choice = others[0]
        self.push_and_get(key, prop, ["POINTS", choice])
        info = self.obj.GetInputArrayInformation(0)
        got_name = info.Get(vtkDataObject.FIELD_NAME()) if info.Has(vtkDataObject.FIELD_NAME()) else None
        got_assoc = info.Get(vtkDataObject.FIELD_ASSOCIATION()) if info.Has(vtkDataObject.FIELD_ASSOCIATION()) else None
        check(got_name == choice and got_assoc == vtkDataObject.FIELD_ASSOCIATION_POINTS,
              "%s.%s = POINTS %s: GetInputArrayInformation(0) gives %r, association %r"
              % (self.name, key, choice, got_name, got_assoc))


# ---------------------------------------------------------------------------
PARAMETER_TABLE = """# level A100 A-110 A010 A0-11 A-101 A001 m  (test table, not tuned)
  4   5 1 3 1 1 2   0.8
 40   4 2 4 2 2 2   0.6
127   3 2 3 2 2 3   0.4
"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--xml", required=True, action="append", help="each XML file of the plugin")
    args = parser.parse_args()

    try:
        from bluenoise import vtkBlueNoiseNIfTIReader, vtkBlueNoiseSpectrum, vtkErrorDiffusionSampler
    except ImportError as error:
        check(False, "import bluenoise (PYTHONPATH must hold the package): %s" % error)
        finish()

    proxies = check_xml(args.xml)
    if not check(os.path.exists(args.plugin), "plugin %s exists" % args.plugin):
        finish()
    LoadPlugin(args.plugin, remote=False, ns=globals())
    check_hints(proxies)
    check_xml_defaults(proxies, {"ErrorDiffusionSampler": vtkErrorDiffusionSampler,
                                 "BlueNoiseSpectrum": vtkBlueNoiseSpectrum,
                                 "BlueNoiseNIfTIReader": vtkBlueNoiseNIfTIReader})

    with tempfile.TemporaryDirectory(prefix="bluenoise-props-") as tmp:
        parameter_file = os.path.join(tmp, "custom parameters.txt")
        with open(parameter_file, "w") as f:
            f.write(PARAMETER_TABLE)

        wavelet = Wavelet()
        calc = Calculator(Input=wavelet, Function="300-RTData", ResultArrayName="Inverted")
        calc.UpdatePipeline()
        feeder = ErrorDiffusionSampler(Input=calc, NumberOfPoints=3000)
        feeder2 = ErrorDiffusionSampler(Input=calc, NumberOfPoints=3000, Seed=3)
        feeder.UpdatePipeline()
        feeder2.UpdatePipeline()
        nifti_files = [write_nifti(os.path.join(tmp, name)) for name in ("a.nii.gz", "b.nii")]
        context = {"parameter_file": parameter_file, "files": {"BlueNoiseNIfTIReader": nifti_files[1]},
                   "inputs": {"ErrorDiffusionSampler": [calc], "BlueNoiseSpectrum": [feeder, feeder2]}}

        sampler = ErrorDiffusionSampler(Input=calc)
        spectrum = BlueNoiseSpectrum(Input=feeder)
        reader = BlueNoiseNIfTIReader(FileName=nifti_files[0])
        xml = {name: {p.get("name") for p in xml_properties(proxies[name])}
               for name in PROXIES + READERS if name in proxies}
        for name, proxy in (("ErrorDiffusionSampler", sampler), ("BlueNoiseSpectrum", spectrum),
                            ("BlueNoiseNIfTIReader", reader)):
            seen = Walker(proxy, name, context).walk()
            print("%s: walked %d properties: %s" % (name, len(seen), ", ".join(seen)))
            check(set(seen) == xml.get(name, set()),
                  "%s: the proxy's properties are those of the XML (%s)" % (name, sorted(set(seen) ^ xml.get(name, set()))))

        # 3. ParameterSet Custom reads the file: other points than Paper, same seed.
        paper = ErrorDiffusionSampler(Input=calc, Scalars=["POINTS", "RTData"], NumberOfPoints=5000,
                                      ParameterSet="Paper")
        paper.UpdatePipeline()
        custom = ErrorDiffusionSampler(Input=calc, Scalars=["POINTS", "RTData"], NumberOfPoints=5000,
                                       ParameterSet="Custom", ParameterFile=parameter_file)
        custom.UpdatePipeline()
        a = servermanager.Fetch(paper)
        b = servermanager.Fetch(custom)
        check(b.GetNumberOfPoints() > 0 and abs(b.GetNumberOfPoints() - a.GetNumberOfPoints()) < 0.03 * a.GetNumberOfPoints(),
              "Custom parameters: %d points (Paper %d)" % (b.GetNumberOfPoints(), a.GetNumberOfPoints()))
        if a.GetNumberOfPoints() and b.GetNumberOfPoints():
            pa = vtk_to_numpy(a.GetPoints().GetData())
            pb = vtk_to_numpy(b.GetPoints().GetData())
            check(pa.shape != pb.shape or not (pa == pb).all(), "Custom parameters give other points than Paper")
        for proxy in (reader, custom, paper, spectrum, sampler, feeder2, feeder, calc, wavelet):
            Delete(proxy)
    finish()


if __name__ == "__main__":
    main()
