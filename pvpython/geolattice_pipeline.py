"""GeoLattice end-to-end pipeline in pvpython.

Builds the same pipeline as the `geolattice` command-line tool from the plugin's proxies:

    GLMeshReader -> GLPlaceOnPlatform -> GLTetrahedralizeSurface -> GLGeodesicDistanceFields
    -> GLCurvedLayerSlicer -> GLLatticeInfill -> GLSkeletonTree (with the fields)
    -> GLPrintSequencer -> GLCollisionVerifier, GLPrintSequencer -> GLToolpathPlanner ->
    GLCollisionVerifier (time = PointIndex), GLToolpathPlanner -> GLToolpathReplay, GLToolpathPlanner + its verifier -> GLPrintSummary, and
    GLOverhangAnalysis on the fields

and saves the tet mesh and the fields as VTK XML files (binary mode: ParaView 5.11 on Debian 12
cannot read appended-mode files). Run it with pvpython (no X server needed):

    pvpython pvpython/geolattice_pipeline.py testdata/bunny.obj -o out --fit-size 100

The plugin is looked for in $GEOLATTICE_PLUGIN, then in build/lib/paraview-5.11/plugins/.
"""
import argparse
import os
import sys

from paraview import simple

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_PLUGIN = os.path.join(HERE, "..", "build", "lib", "paraview-5.11", "plugins", "GeoLattice", "GeoLattice.so")
TET_MESH_EXTENSIONS = (".vtu", ".tet", ".node", ".ele")


def load_plugin(path=None):
    """Loads the GeoLattice plugin into this session (client side; also fine for builtin)."""
    path = path or os.environ.get("GEOLATTICE_PLUGIN") or DEFAULT_PLUGIN
    if not os.path.isfile(path):
        raise FileNotFoundError("GeoLattice plugin not found: %s (build it or set GEOLATTICE_PLUGIN)" % path)
    # Without ns, the proxies are added to paraview.simple (simple.GLMeshReader etc.).
    simple.LoadPlugin(path, remote=False)
    return path


STRATEGIES = ("LPT", "DPT", "A4", "Best")  # GLPrintSequencer's Strategy values, in the order of its enumeration

# The pipeline of filters/GLPrintPipeline.h, stage by stage: (key, proxy, inputs as (key, port) per
# input property). tests/pvpython/test_pipeline_description.py checks it against the C++ one
# (`geolattice --describe-pipeline`).
STAGES = [
    ("reader", "GLMeshReader", {}),
    ("place", "GLPlaceOnPlatform", {"Input": ("reader", 0)}),
    ("orient", "GLAutoOrient", {"Input": ("place", 0)}),
    ("pedestal", "GLPedestal", {"Input": ("orient", 0)}),
    ("tets", "GLTetrahedralizeSurface", {"Input": ("pedestal", 0)}),
    ("fields", "GLGeodesicDistanceFields", {"Input": ("tets", 0)}),
    ("layers", "GLCurvedLayerSlicer", {"Input": ("fields", 0)}),
    ("overhang", "GLOverhangAnalysis", {"Input": ("fields", 0)}),
    ("lattice", "GLLatticeInfill", {"Input": ("layers", 0)}),
    ("skeleton", "GLSkeletonTree", {"Input": ("lattice", 0), "TetMesh": ("fields", 0)}),
    ("sequencer", "GLPrintSequencer", {"Input": ("lattice", 0), "Skeleton": ("skeleton", 0)}),
    ("verifier", "GLCollisionVerifier", {"Input": ("sequencer", 0)}),
    ("toolpath", "GLToolpathPlanner", {"Input": ("sequencer", 0), "Skeleton": ("sequencer", 1)}),
    ("toolpath_verifier", "GLCollisionVerifier", {"Input": ("toolpath", 0)}),
    ("summary", "GLPrintSummary", {"Input": ("toolpath", 0), "Verifier": ("toolpath_verifier", 0)}),
    ("replay", "GLToolpathReplay", {"Input": ("toolpath", 0)}),
]

# build_pipeline keywords -> (stage key(s), property). Anything not given keeps the filter's
# default (the XML default, checked against the filters by tests/pvpython/test_defaults.py).
PARAMETERS = {
    "scale": (("place",), "Scale"),
    "fit_size": (("place",), "FitSize"),
    "center": (("place",), "CenterXY"),
    "fill_holes": (("place",), "FillHoles"),
    "fill_cavities": (("place",), "FillCavities"),
    "wrap": (("place",), "Wrap"),
    "orient": (("orient",), "Orient"),
    "min_base_area": (("orient",), "MinBaseArea"),
    "edge_length": (("tets",), "TargetEdgeLength"),
    "radius_edge": (("tets",), "RadiusEdgeRatio"),
    "base_tolerance": (("fields",), "BaseTolerance"),
    "base_flat_band": (("fields",), "BaseFlatBand"),
    "time_factor": (("fields",), "TimeFactor"),
    "reference": (("fields",), "ReferenceVector"),
    "turn_reference": (("fields",), "TurnReference"),
    "layer_interval": (("layers",), "LayerInterval"),
    "first_layer": (("layers",), "FirstLayerOffset"),
    "alpha_width": (("lattice",), "AlphaWidth"),
    "beta_width": (("lattice",), "BetaWidth"),
    "strategy": (("sequencer",), "Strategy"),
    "split_rounds": (("sequencer",), "SplitRounds"),
    "nozzle_angle": (("orient", "sequencer", "verifier", "toolpath", "toolpath_verifier"), "NozzleAngle"),
    "printhead": (("orient", "sequencer", "verifier", "toolpath", "toolpath_verifier"), "PrintheadFile"),
    "sample_spacing": (("sequencer", "verifier"), "SampleSpacing"),
    "path_width": (("toolpath",), "PathWidth"),
    "filament_diameter": (("toolpath",), "FilamentDiameter"),
    "flow_correction": (("toolpath",), "FlowCorrection"),
    "support_perimeter": (("toolpath",), "SupportPerimeter"),
    "time_steps": (("replay",), "NumberOfTimeSteps"),
    "filament_density": (("summary",), "FilamentDensity"),
}


def get_property(proxy, name):
    """A property's value by its XML name. ParaView names a property's Python attribute after its
    panel label, units included ("Layer Interval (mm)" -> LayerIntervalmm); the XML name
    (LayerInterval) is the one the C++ filters, the CLI's --list-options and this module use."""
    return proxy.GetPropertyValue(name)


def set_property(proxy, name, value):
    """Sets a property by its XML name (see get_property)."""
    proxy.SetPropertyWithName(name, value)


def build_pipeline(model, lattice_width=None, **parameters):
    """Returns a dict of the pipeline's proxies by key (see STAGES): reader, place, tets, fields, layers,
    overhang, lattice, skeleton, sequencer (output ports 0 Sequenced Lattice, 1 Sequenced Skeleton,
    2 Print Order), verifier (the sequenced lattice, time PrintOrder), toolpath (GLToolpathPlanner, the whole
    toolpath), toolpath_verifier (time PointIndex, air points no material) and replay (GLToolpathReplay:
    its time steps 0..1 replay the print, e.g. replay.UpdatePipeline(0.5) for the part printed by then) and
    summary (GLPrintSummary: a table of layers, print time, filament and the strict verdict). For a tet-mesh model "tets" is the
    placement. Keywords (PARAMETERS; lattice_width sets both widths; pedestal: see set_pedestal) set properties; everything else
    keeps the filters' defaults, the same as the command line's. As on the command line, the first
    layer follows layer_interval unless first_layer is given."""
    if lattice_width is not None:
        parameters.setdefault("alpha_width", lattice_width)
        parameters.setdefault("beta_width", lattice_width)
    if "layer_interval" in parameters:
        parameters.setdefault("first_layer", parameters["layer_interval"])
    if isinstance(parameters.get("strategy"), str) and parameters["strategy"].lower() in ("lpt", "dpt", "a4", "best"):
        parameters["strategy"] = {"lpt": "LPT", "dpt": "DPT", "a4": "A4", "best": "Best"}[parameters["strategy"].lower()]
    if isinstance(parameters.get("orient"), str):
        parameters["orient"] = {"keep": "Keep", "auto": "Auto"}[parameters["orient"].lower()]
    if isinstance(parameters.get("reference"), str) and parameters["reference"].lower() == "auto":
        del parameters["reference"]  # the default vector, turned where it lies along the normal
    elif "reference" in parameters:
        parameters.setdefault("turn_reference", 0)  # a given reference is used as given (CLI too)
    for key in ("center", "fill_holes", "fill_cavities", "support_perimeter", "turn_reference"):
        if key in parameters:
            parameters[key] = int(parameters[key])
    pedestal = parameters.pop("pedestal", None)
    unknown = sorted(set(parameters) - set(PARAMETERS))
    if unknown:
        raise TypeError("build_pipeline: unknown parameters %s (known: %s)" % (unknown, sorted(PARAMETERS)))
    tet_mesh = model.lower().endswith(TET_MESH_EXTENSIONS)
    p = {}
    for key, proxy_name, inputs in STAGES:
        if key in ("orient", "pedestal", "tets") and tet_mesh:
            p[key] = p["place"]
            continue
        properties = {}
        for name, (source, port) in inputs.items():
            properties[name] = simple.OutputPort(p[source], port) if port else p[source]
        if key == "reader":
            properties["FileName"] = model
        if proxy_name == "GLCollisionVerifier":
            properties["TimeArrayName"] = "PrintOrder" if key == "verifier" else "PointIndex"
        p[key] = getattr(simple, proxy_name)(**properties)
    for name, value in parameters.items():
        keys, prop = PARAMETERS[name]
        for key in keys:
            set_property(p[key], prop, list(value) if isinstance(value, (tuple, list)) else value)
    if not tet_mesh:
        if pedestal is not None:
            set_pedestal(p, pedestal)
        match_orientation_to_print(p)
    return p


def set_pedestal(p, pedestal):
    """The pedestal as --pedestal asks for it (GLPrintPipeline::SetPedestalRequest): "auto" or a negative
    number = the orientation search decides where it helps, 0 = never, a height = always that tall."""
    if pedestal == "auto" or float(pedestal) < 0:
        p["orient"].Pedestal = "When It Helps"
        set_property(p["pedestal"], "Height", 0)
    elif float(pedestal) == 0:
        p["orient"].Pedestal = "Never"
        set_property(p["pedestal"], "Height", 0)
    else:
        p["orient"].Pedestal = "Always"
        set_property(p["orient"], "PedestalHeight", float(pedestal))
        set_property(p["pedestal"], "Height", float(pedestal))


def match_orientation_to_print(p):
    """The orientation search's refinement at the print's layer interval, lattice width, order and
    largest axis tilt (GLPrintPipeline::MatchOrientationToPrint)."""
    set_property(p["orient"], "RefineLayerInterval", get_property(p["layers"], "LayerInterval"))
    set_property(p["orient"], "RefineLatticeWidth",
                 min(get_property(p["lattice"], "AlphaWidth"), get_property(p["lattice"], "BetaWidth")))
    p["orient"].RefineStrategy = p["sequencer"].Strategy
    set_property(p["orient"], "MaxAxisTilt", get_property(p["toolpath"], "MaxAxisTilt"))


def summary_values(table):
    """GL Print Summary's table (a fetched vtkTable) as {key: value}, the keys of report.json's
    "summary" section (layers, print_time_min, filament_g, collision_free, ...)."""
    return {table.GetValueByName(r, "Key").ToString(): table.GetValueByName(r, "Value").ToDouble()
            for r in range(table.GetNumberOfRows())}


def save_binary(proxy, path):
    """Writes proxy's output as VTK XML in binary inline mode, via a temporary file in the same
    directory (same extension, so ParaView picks the same writer) renamed over path at the end."""
    folder, name = os.path.split(os.path.abspath(path))
    tmp = os.path.join(folder, ".tmp-%d-%s" % (os.getpid(), name))
    try:
        simple.SaveData(tmp, proxy=proxy, DataMode="Binary")
        if not os.path.isfile(tmp):
            raise OSError("could not write %s" % path)
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.remove(tmp)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("model", help="closed surface (.stl .obj .ply .vtp .off) or tet mesh (.vtu .tet .node .ele)")
    parser.add_argument("-o", "--output", required=True, help="output directory")
    parser.add_argument("--plugin", help="path of GeoLattice.so")
    # No defaults here: what is not given keeps the filters' defaults (the same as the CLI's).
    parser.add_argument("--scale", type=float, help="uniform scale factor")
    parser.add_argument("--fit-size", type=float, help="largest bounding-box side in mm")
    parser.add_argument("--fill-holes", action="store_true", default=None,
                        help="close the holes of an open surface (a scan) before placing it")
    parser.add_argument("--fill-cavities", action="store_true", default=None,
                        help="fill the part's sealed inner voids before placing it (printed solid)")
    parser.add_argument("--wrap", type=float,
                        help="replace the surface by a closed wrap of it this fine, mm (CGAL alpha wrap)")
    parser.add_argument("--edge-length", type=float, help="target tet edge length in mm (0 = automatic)")
    parser.add_argument("--base-tolerance", type=float,
                        help="vertices this far above the lowest point are the base, mm")
    parser.add_argument("--base-flat-band", type=float,
                        help="faces facing down this far above the lowest point are base too, mm (0 = off)")
    parser.add_argument("--time-factor", type=float, help="heat time factor")
    parser.add_argument("--layer-interval", type=float, help="curved layer interval, mm")
    parser.add_argument("--lattice-width", type=float, help="lattice line spacing, mm")
    parser.add_argument("--strategy", choices=STRATEGIES, help="printing order strategy")
    parser.add_argument("--nozzle-angle", type=float, help="nozzle cone half-angle, degrees")
    args = parser.parse_args(argv)

    load_plugin(args.plugin)
    os.makedirs(args.output, exist_ok=True)
    given = dict(scale=args.scale, fit_size=args.fit_size, fill_holes=args.fill_holes,
                 fill_cavities=args.fill_cavities, wrap=args.wrap,
                 edge_length=args.edge_length,
                 base_tolerance=args.base_tolerance, base_flat_band=args.base_flat_band,
                 time_factor=args.time_factor,
                 layer_interval=args.layer_interval, strategy=args.strategy, nozzle_angle=args.nozzle_angle)
    p = build_pipeline(args.model, lattice_width=args.lattice_width,
                       **{k: v for k, v in given.items() if v is not None})
    p["fields"].UpdatePipeline()
    fields = simple.servermanager.Fetch(p["fields"])
    if fields is None or fields.GetNumberOfCells() == 0:
        print("geolattice_pipeline: the pipeline produced no fields (see the errors above)", file=sys.stderr)
        return 1
    save_binary(p["tets"], os.path.join(args.output, "tets.vtu"))
    save_binary(p["fields"], os.path.join(args.output, "fields.vtu"))
    save_binary(p["layers"], os.path.join(args.output, "layers.vtp"))
    save_binary(p["overhang"], os.path.join(args.output, "overhang.vtp"))
    save_binary(p["lattice"], os.path.join(args.output, "lattice.vtp"))
    save_binary(p["skeleton"], os.path.join(args.output, "skeleton.vtp"))
    save_binary(simple.OutputPort(p["sequencer"], 0), os.path.join(args.output, "sequenced_lattice.vtp"))
    save_binary(simple.OutputPort(p["sequencer"], 2), os.path.join(args.output, "print_order.vtp"))
    save_binary(p["verifier"], os.path.join(args.output, "collisions.vtp"))
    p["toolpath"].UpdatePipeline(1.0)  # the whole path (time 1 = print progress 100 %)
    save_binary(p["toolpath"], os.path.join(args.output, "toolpath.vtp"))
    save_binary(p["toolpath_verifier"], os.path.join(args.output, "toolpath_collisions.vtp"))
    gamma = fields.GetPointData().GetArray("Gamma").GetRange()
    print("geolattice_pipeline: %d points, %d tets, gamma max %.3f mm; wrote %s" %
          (fields.GetNumberOfPoints(), fields.GetNumberOfCells(), gamma[1], args.output))
    fd = simple.servermanager.Fetch(p["verifier"]).GetFieldData()
    free, order_free = fd.GetArray("CollisionFree"), fd.GetArray("CollisionOrderFree")
    if free is None or order_free is None:
        verdict = "no verdict (see the errors above)"
    elif free.GetValue(0) == 1:
        verdict = "collision-free"
    elif order_free.GetValue(0) == 1:
        verdict = "only unavoidable collisions (with material of skeleton ancestors, see collisions.vtp)"
    else:
        verdict = "COLLISIONS (see collisions.vtp)"
    print("geolattice_pipeline: %s printing order at nozzle angle %g: %s" %
          (p["sequencer"].Strategy, p["sequencer"].NozzleAngle, verdict))
    tfd = simple.servermanager.Fetch(p["toolpath"]).GetFieldData()
    if tfd.GetArray("ToolpathPrintLength") is not None:
        print("geolattice_pipeline: toolpath %.1f mm printed, %.1f mm air, %d retractions, filament %.1f mm" %
              (tfd.GetArray("ToolpathPrintLength").GetValue(0), tfd.GetArray("ToolpathAirLength").GetValue(0),
               tfd.GetArray("ToolpathRetractions").GetValue(0), tfd.GetArray("ToolpathFilament").GetValue(0)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
