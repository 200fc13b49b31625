"""GeoLattice end-to-end pipeline in pvpython.

Builds the same pipeline as the `geolattice` command-line tool from the plugin's proxies:

    GLMeshReader -> GLPlaceOnPlatform -> GLTetrahedralizeSurface -> GLGeodesicDistanceFields
    -> GLCurvedLayerSlicer -> GLLatticeInfill -> GLSkeletonTree (with the fields)
    -> GLPrintSequencer -> GLCollisionVerifier, GLPrintSequencer -> GLToolpathPlanner ->
    GLCollisionVerifier (time = PointIndex), and GLOverhangAnalysis on the fields

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


def build_pipeline(model, scale=1.0, fit_size=0.0, center=True, edge_length=0.0, radius_edge=1.414,
                   base_tolerance=0.05, time_factor=4.0, reference=(1.0, 0.0, 0.0), layer_interval=0.6,
                   first_layer=None, lattice_width=4.0, strategy="A4", nozzle_angle=45.0, sample_spacing=1.0,
                   path_width=0.6, filament_diameter=1.75, flow_correction=0.95, support_perimeter=True,
                   time_steps=200):
    """Returns a dict of the pipeline's proxies: reader, place, tets, fields, layers, lattice, skeleton,
    sequencer (output ports 0 Sequenced Lattice, 1 Sequenced Skeleton, 2 Print Order), verifier (checks
    the sequenced lattice with the same nozzle and sample spacing), toolpath (GLToolpathPlanner on the
    sequencer's outputs 0 and 1; it has `time_steps` time steps 0..1 of print progress, so the animation
    controls replay the print; update it with a time, e.g. toolpath.UpdatePipeline(0.5), for the part
    printed by then), toolpath_verifier (the verifier on the toolpath: time = PointIndex, air points are no
    material) and overhang."""
    reader = simple.GLMeshReader(FileName=model)
    place = simple.GLPlaceOnPlatform(Input=reader, Scale=scale, FitSize=fit_size, CenterXY=int(center))
    if model.lower().endswith(TET_MESH_EXTENSIONS):
        tets = place
    else:
        tets = simple.GLTetrahedralizeSurface(Input=place, TargetEdgeLength=edge_length,
                                              RadiusEdgeRatio=radius_edge)
    fields = simple.GLGeodesicDistanceFields(Input=tets, SourceMode=0, BaseTolerance=base_tolerance,
                                             TimeFactor=time_factor, ReferenceVector=list(reference))
    layers = simple.GLCurvedLayerSlicer(Input=fields, LayerInterval=layer_interval,
                                        FirstLayerOffset=layer_interval if first_layer is None else first_layer)
    lattice = simple.GLLatticeInfill(Input=layers, AlphaWidth=lattice_width, BetaWidth=lattice_width)
    skeleton = simple.GLSkeletonTree(Input=lattice, TetMesh=fields)
    sequencer = simple.GLPrintSequencer(Input=lattice, Skeleton=skeleton, Strategy=strategy,
                                        NozzleAngle=nozzle_angle, SampleSpacing=sample_spacing)
    verifier = simple.GLCollisionVerifier(Input=simple.OutputPort(sequencer, 0), TimeArrayName="PrintOrder",
                                          NozzleAngle=nozzle_angle, SampleSpacing=sample_spacing)
    toolpath = simple.GLToolpathPlanner(Input=simple.OutputPort(sequencer, 0),
                                        Skeleton=simple.OutputPort(sequencer, 1), PathWidth=path_width,
                                        FilamentDiameter=filament_diameter, FlowCorrection=flow_correction,
                                        SupportPerimeter=int(support_perimeter), NumberOfTimeSteps=time_steps)
    toolpath_verifier = simple.GLCollisionVerifier(Input=toolpath, TimeArrayName="PointIndex",
                                                   NozzleAngle=nozzle_angle)
    overhang = simple.GLOverhangAnalysis(Input=fields)
    return {"reader": reader, "place": place, "tets": tets, "fields": fields, "layers": layers,
            "lattice": lattice, "skeleton": skeleton, "sequencer": sequencer, "verifier": verifier,
            "toolpath": toolpath, "toolpath_verifier": toolpath_verifier, "overhang": overhang}


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
    parser.add_argument("--scale", type=float, default=1.0, help="uniform scale factor [1]")
    parser.add_argument("--fit-size", type=float, default=0.0, help="largest bounding-box side in mm [off]")
    parser.add_argument("--edge-length", type=float, default=0.0, help="target tet edge length in mm [auto]")
    parser.add_argument("--base-tolerance", type=float, default=0.05,
                        help="vertices this far above the lowest point are the base, mm [0.05]")
    parser.add_argument("--time-factor", type=float, default=4.0, help="heat time factor [4]")
    parser.add_argument("--layer-interval", type=float, default=0.6, help="curved layer interval, mm [0.6]")
    parser.add_argument("--lattice-width", type=float, default=4.0, help="lattice line spacing, mm [4]")
    parser.add_argument("--strategy", choices=STRATEGIES, default="A4", help="printing order strategy [A4]")
    parser.add_argument("--nozzle-angle", type=float, default=45.0, help="nozzle cone half-angle, degrees [45]")
    args = parser.parse_args(argv)

    load_plugin(args.plugin)
    os.makedirs(args.output, exist_ok=True)
    p = build_pipeline(args.model, scale=args.scale, fit_size=args.fit_size, edge_length=args.edge_length,
                       base_tolerance=args.base_tolerance, time_factor=args.time_factor,
                       layer_interval=args.layer_interval, lattice_width=args.lattice_width,
                       strategy=args.strategy, nozzle_angle=args.nozzle_angle)
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
    print("geolattice_pipeline: %s printing order at nozzle angle %g: %s" % (args.strategy, args.nozzle_angle, verdict))
    tfd = simple.servermanager.Fetch(p["toolpath"]).GetFieldData()
    if tfd.GetArray("ToolpathPrintLength") is not None:
        print("geolattice_pipeline: toolpath %.1f mm printed, %.1f mm air, %d retractions, filament %.1f mm" %
              (tfd.GetArray("ToolpathPrintLength").GetValue(0), tfd.GetArray("ToolpathAirLength").GetValue(0),
               tfd.GetArray("ToolpathRetractions").GetValue(0), tfd.GetArray("ToolpathFilament").GetValue(0)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
