"""Each default once: every parameter's default lives in the core options structs and is taken
from there by the filters; this test checks that nothing else drifted from it:

  - every XML default_values of every GeoLattice proxy equals the VTK object's getter;
  - every "(... default X ...)" in a filter header's Set/Get block equals the getter;
  - every `geolattice run` option's default (`geolattice --list-options`, read by the CLI from the
    filters) equals the XML default of the property it sets;
  - docs/cli-reference.md is the current `geolattice --help`.
"""
import os
import re
import subprocess
import sys
import unittest
import xml.etree.ElementTree as ET

SOURCE_DIR = os.environ["GEOLATTICE_SOURCE_DIR"]
CLI = os.environ["GEOLATTICE_CLI"]


VECTOR_TAGS = ("IntVectorProperty", "DoubleVectorProperty", "StringVectorProperty", "IdTypeVectorProperty")

# CLI choice names -> the property values they set.
CLI_CHOICES = {
    "GLPrintSequencer.Strategy": {"lpt": 0, "dpt": 1, "a4": 2, "best": 3},
    "GLGeodesicDistanceFields.SourceMode": {"lowest": 0, "faces": 2},
    "GLGeodesicDistanceFields.UseCholmod": {"cholmod": 1, "eigen": 0},
    "GLGCodeWriter.Kinematics": {"ac": 0, "bc": 1},
    "GLPlaceOnPlatform.CenterXY": {"centred": 1, "kept": 0},
    "GLPlaceOnPlatform.FillHoles": {"on": 1, "off": 0},
    "GLPlaceOnPlatform.FillCavities": {"on": 1, "off": 0},
    "GLToolpathPlanner.SupportPerimeter": {"perimeter": 1, "none": 0},
    "GLURScriptWriter.AllowUnreachable": {"on": 1, "off": 0},
    "GLNozzle.BuildPlate": {"obstacle": 1, "none": 0},
    "GLAutoOrient.Orient": {"keep": 0, "auto": 1},
    "GLPrintPart.PedestalHeight": {"auto": -1},
    "GLGeodesicDistanceFields.TurnReference": {"auto": 1},
    "GLGCodeWriter.Flavor": {"linuxcnc": 0, "reprap": 1},
    "GLURScriptWriter.SearchCellLayout": {"search": 1, "off": 0},
    "GLURScriptWriter.Reconfigure": {"on": 1, "off": 0},
    "GLGCodeWriter.ToolCentrePoint": {"controller": 0, "cam": 1},
}


def proxies():
    """(group, name, class, {property: (command, [default values])}) of every plugin proxy."""
    out = []
    for name in sorted(os.listdir(os.path.join(SOURCE_DIR, "plugin", "xml"))):
        root = ET.parse(os.path.join(SOURCE_DIR, "plugin", "xml", name)).getroot()
        for group in root.iter("ProxyGroup"):
            for proxy in group:
                props = {}
                for p in proxy:
                    if p.tag in VECTOR_TAGS and p.get("command") and p.get("information_only") != "1" \
                            and p.get("default_values") is not None:
                        values = p.get("default_values")
                        delimiter = p.get("default_values_delimiter")
                        parts = values.split(delimiter) if delimiter else values.split()
                        props[p.get("name")] = (p.get("command"), p.tag, parts)
                out.append((group.get("name"), proxy.get("name"), proxy.get("class"), props))
    return out


def same(a, b):
    try:
        return abs(float(a) - float(b)) <= 1e-12 * max(1.0, abs(float(a)))
    except (TypeError, ValueError):
        return str(a) == str(b)


def printed_values(text):
    """{property: [values]} from the object's PrintSelf (every filter lists every property there,
    "Name: value [unit]"; the client-side objects are wrapped as their VTK base class, so PrintSelf
    is the way to read them from Python)."""
    out = {}
    for name, text in re.findall(r"^  (\w+): (.*)$", text, re.M):
        tokens = text.replace("(", " ").replace(")", " ").replace(",", " ").split()
        numbers = []
        for t in tokens:
            try:
                numbers.append(float(t))
            except ValueError:
                break
        if numbers:
            out[name] = numbers
        elif text in ("on", "off"):
            out[name] = [1 if text == "on" else 0]
        else:
            out[name] = ["" if text == "(none)" else text]
    return out


def getter_value(printed, command):
    """The printed value of the property set by `command` (SetX -> X), or None."""
    if not command.startswith("Set"):
        return None
    return printed.get(command[3:])


class DefaultsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # The filters' own defaults: PrintSelf of default-constructed objects (a proxy would have
        # pushed the XML defaults into its object already).
        text = subprocess.run([CLI, "--print-filter-defaults"], capture_output=True, text=True,
                              check=True).stdout
        printed = {}
        for part in text.split("== ")[1:]:
            class_name, body = part.split("\n", 1)
            printed[class_name.strip()] = printed_values(body)
        cls.objects = {}
        cls.xml = {}
        for group, name, cls_name, props in proxies():
            cls.objects[name] = printed.get(cls_name, {})
            cls.xml[name] = (cls_name, props)

    def test_xml_defaults_equal_the_filters(self):
        checked = 0
        for name, (cls_name, props) in self.xml.items():
            obj = self.objects[name]
            for prop, (command, tag, xml_values) in props.items():
                value = getter_value(obj, command)
                if command.startswith("Set") and command != "SetInputArrayToProcess":
                    with self.subTest(proxy=name, property=prop):
                        self.assertIsNotNone(value, "%s's PrintSelf does not list %s" % (cls_name, command[3:]))
                if value is None:
                    continue
                if tag == "StringVectorProperty":
                    value = [v if v is not None else "" for v in value]
                with self.subTest(proxy=name, property=prop):
                    self.assertEqual(len(value), len(xml_values), (value, xml_values))
                    for a, b in zip(value, xml_values):
                        self.assertTrue(same(a, b), "%s.%s: filter %r, XML %r" % (name, prop, value, xml_values))
                checked += 1
        self.assertGreaterEqual(checked, 60)

    def test_header_defaults_equal_the_filters(self):
        block = re.compile(r"///@\{\n((?:\s*///[^\n]*\n)+)\s*vtkSet\w*Macro\((\w+),")
        checked = 0
        for name, (cls_name, props) in self.xml.items():
            header = os.path.join(SOURCE_DIR, "filters", cls_name + ".h")
            if not os.path.isfile(header):
                continue
            with open(header) as f:
                text = f.read()
            obj = self.objects[name]
            for comment, prop in block.findall(text):
                m = re.search(r"default (-?[0-9][0-9.e+-]*|on|off|\"[^\"]*\")", comment)
                if not m:
                    continue
                value = getter_value(obj, "Set" + prop)
                if value is None:
                    continue
                stated = {"on": 1, "off": 0}.get(m.group(1), m.group(1).strip('"'))
                with self.subTest(header=cls_name, property=prop):
                    self.assertTrue(same(value[0], stated),
                                    "%s.h says %s default %s, the filter has %r" % (cls_name, prop, stated, value))
                checked += 1
            # The @class comment's parameter list, "Name (..., default X, ...)".
            intro = text.split("#ifndef", 1)[0]
            for prop, stated in re.findall(r"\b([A-Z]\w+) \([^()]*?\bdefault (-?[0-9][0-9.e+-]*)", intro):
                value = obj.get(prop)
                if value is None:
                    continue
                with self.subTest(header=cls_name, property=prop, where="@class"):
                    self.assertTrue(same(value[0], stated.rstrip(".")),
                                    "%s.h's class comment says %s default %s, the filter has %r" %
                                    (cls_name, prop, stated, value))
                checked += 1
        self.assertGreaterEqual(checked, 40)

    def test_cli_defaults_equal_the_xml(self):
        listing = subprocess.run([CLI, "--list-options"], capture_output=True, text=True, check=True).stdout
        checked = 0
        for line in listing.splitlines():
            flag, prop, value = line.split("\t")
            if "." not in prop or flag in ("--first-layer", "--part-offset"):
                continue  # CLI-only; the first layer follows --layer-interval; part offset is a pose entry
            proxy, names = prop.split(".")
            cls_name, props = self.xml[proxy]
            if any(name not in props for name in names.split("+")):
                continue
            # "A+B": the flag sets both properties, its values A's then B's.
            xml_values = [v for name in names.split("+") for v in props[name][2]]
            if prop in CLI_CHOICES:
                value = str(CLI_CHOICES[prop][value])
            cli_values = value.split(",")
            with self.subTest(flag=flag):
                self.assertEqual(len(cli_values), len(xml_values), (flag, value, xml_values))
                for a, b in zip(cli_values, xml_values):
                    self.assertTrue(same(a, b), "%s: CLI %s, XML %s" % (flag, value, xml_values))
            checked += 1
        self.assertGreaterEqual(checked, 50)

    def test_every_length_and_angle_label_carries_its_unit(self):
        """The panels show each quantity's unit in its label, one unit per dimension (mm, deg, mm/s,
        mm², g/cm³: never metres or radians, which the writers convert to themselves): a numeric
        property whose documentation states a unit ("(mm", "(degrees, ...") has that unit in its
        label, a label's unit is stated in its documentation, and a property of the same name has
        the same unit in every panel."""
        doc_units = re.compile(r"\((mm/s|mm²|g/cm³|mm|degrees|deg|m|rad)[,;)\s]")
        allowed = {"mm", "deg", "mm/s", "mm²", "g/cm³"}
        unit_of = {}
        checked = 0
        for name in sorted(os.listdir(os.path.join(SOURCE_DIR, "plugin", "xml"))):
            root = ET.parse(os.path.join(SOURCE_DIR, "plugin", "xml", name)).getroot()
            for group in root.iter("ProxyGroup"):
                for proxy in group:
                    for p in proxy:
                        if p.tag not in ("DoubleVectorProperty", "IntVectorProperty", "IdTypeVectorProperty") \
                                or p.get("information_only") == "1" or p.get("panel_visibility") == "never" \
                                or p.find("BooleanDomain") is not None or p.find("EnumerationDomain") is not None:
                            continue
                        d = p.find("Documentation")
                        doc = " ".join((d.text or "").split()) if d is not None else ""
                        stated = {"deg" if u == "degrees" else u for u in doc_units.findall(doc)}
                        label = p.get("label") or ""
                        m = re.search(r"\(([^()]*)\)$", label)
                        shown = m.group(1) if m else None
                        where = "%s.%s" % (proxy.get("name"), p.get("name"))
                        with self.subTest(property=where):
                            if stated:
                                self.assertEqual(len(stated), 1, "%s: its documentation states %s" % (where, stated))
                                self.assertEqual(shown, next(iter(stated)),
                                                 "%s: label %r lacks the unit %s" % (where, label, stated))
                            if shown is not None:
                                self.assertIn(shown, allowed, "%s: label unit %s" % (where, shown))
                                self.assertEqual(stated, {shown}, "%s: label says %s, documentation %s"
                                                 % (where, shown, stated))
                                previous = unit_of.setdefault(p.get("name"), (shown, where))
                                self.assertEqual(previous[0], shown, "%s in %s, %s in %s" %
                                                 (previous[0], previous[1], shown, where))
                                checked += 1
        self.assertGreaterEqual(checked, 60)

    def test_cli_reference_is_current(self):
        help_text = subprocess.run([CLI, "--help"], capture_output=True, text=True, check=True).stdout
        with open(os.path.join(SOURCE_DIR, "docs", "cli-reference.md")) as f:
            doc = f.read()
        body = doc.split("```\n", 1)[1].rsplit("```", 1)[0]
        self.assertEqual(body, help_text, "regenerate with scripts/make-cli-reference.sh")


if __name__ == "__main__":
    result = unittest.main(exit=False, verbosity=2).result
    sys.exit(0 if result.wasSuccessful() else 1)
