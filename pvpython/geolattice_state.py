"""Builds the GeoLattice pipeline on a model and saves it as a ParaView state file (.pvsm) with five
linked render views and the print summary in one layout:

    part by Gamma, the verdict in words | curved layers by LayerId (every 4th layer)
    lattice by SubgraphId | summary     | sequenced lattice by PrintOrder | toolpath replay by PointIndex

The overhang analysis, the collision checks, the print order and the toolpath are in the pipeline
too, hidden (the animation time is set to the end: the print replay's time is the print progress). Saving needs no X server:

    pvpython pvpython/geolattice_state.py [MODEL] [-o docs/geolattice_y_shape.pvsm] [--screenshot x.png]

(--screenshot renders the layout, which needs an X server: run it under
`xvfb-run -a -s "-screen 0 1280x1024x24" pvpython ...`).

Loading the state: the plugin must be loaded first (a state file does not load plugins).
GUI: Tools > Manage Plugins > Load New... (GeoLattice.so), or start it with
`paraview --plugin-search-paths=<dir of GeoLattice.so> --plugins=GeoLattice`; then File > Load State,
with "Search files under specified directory" if the model moved (the state stores its absolute path).
pvpython: LoadPlugin(path, remote=False, ns=globals()); LoadState(pvsm, data_directory=<dir with the model>).
"""
import argparse
import os
import sys

from paraview import simple

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import geolattice_pipeline as pipeline  # noqa: E402
from geolattice_view import front_camera  # noqa: E402

DEFAULT_MODEL = os.path.join(HERE, "..", "testdata", "y_shape.obj")
DEFAULT_OUTPUT = os.path.join(HERE, "..", "docs", "geolattice_y_shape.pvsm")

# Names in the pipeline browser, by build_pipeline key (plus the helpers made here).
NAMES = {
    "reader": "Model", "place": "Placed on platform", "tets": "Tet mesh", "fields": "Geodesic fields",
    "layers": "Curved layers", "lattice": "Lattice", "skeleton": "Skeleton tree", "sequencer": "Print sequence",
    "verifier": "Collision check", "overhang": "Overhang", "toolpath": "Toolpath",
    "toolpath_verifier": "Toolpath collision check", "replay": "Print replay",
    "summary": "Summary table", "verdict": "Verdict",
    "surface": "Part surface", "every4": "Layer index mod 4", "some_layers": "Every 4th layer",
}
# (view title, source key, output port, association, array): the coloured representation of each view.
COLOURING = [
    ("Part: geodesic distance Gamma", "surface", 0, "POINTS", "Gamma"),
    ("Curved layers by LayerId", "some_layers", 0, "CELLS", "LayerId"),
    ("Lattice by SubgraphId", "lattice", 0, "CELLS", "SubgraphId"),
    ("Sequenced lattice by PrintOrder", "sequencer", 0, "CELLS", "PrintOrder"),
    ("Toolpath replay by PointIndex", "replay", 0, "POINTS", "PointIndex"),
]
SUMMARY_VIEW = "Print summary"
CAMERA_LINK = "GeoLatticeCamera%d"
SUBGRAPH_PALETTE = "Brewer Qualitative Paired"  # 12 colours, cycled over the sub-graph ids


def _colour(rep, view, association, array, preset, title, bar=True):
    simple.ColorBy(rep, (association, array))
    lut = simple.GetColorTransferFunction(array)
    lut.ApplyPreset(preset, True)
    rep.RescaleTransferFunctionToDataRange(True, False)
    rep.SetScalarBarVisibility(view, bar)
    if bar:
        scalar_bar = simple.GetScalarBar(lut, view)
        scalar_bar.Title = title
        scalar_bar.ComponentTitle = ""
    return lut


def _ghost(source, view, opacity=0.15):
    rep = simple.Show(source, view)
    simple.ColorBy(rep, None)
    rep.DiffuseColor = [0.7, 0.7, 0.7]
    rep.AmbientColor = [0.7, 0.7, 0.7]
    rep.Opacity = opacity
    return rep


def build_state(model=DEFAULT_MODEL, fit_size=0.0, edge_length=0.0, layer_interval=0.6, lattice_width=4.0):
    """Builds the pipeline, the helpers and the layout in the current session; returns (proxies by key,
    views in COLOURING order, layout)."""
    p = pipeline.build_pipeline(os.path.abspath(model), fit_size=fit_size, edge_length=edge_length,
                                layer_interval=layer_interval, lattice_width=lattice_width)
    if "toolpath" not in p and hasattr(simple, "GLToolpathPlanner"):
        p["toolpath"] = simple.GLToolpathPlanner(Input=simple.OutputPort(p["sequencer"], 0), Skeleton=p["skeleton"])
    p["surface"] = simple.ExtractSurface(Input=p["fields"])
    p["every4"] = simple.Calculator(Input=p["layers"], AttributeType="Cell Data", ResultArrayName="LayerMod4",
                                    Function="LayerId - 4*floor(LayerId/4)")
    p["some_layers"] = simple.Threshold(Input=p["every4"], Scalars=["CELLS", "LayerMod4"],
                                        LowerThreshold=0, UpperThreshold=0)
    for key, proxy in p.items():
        simple.RenameSource(NAMES.get(key) or key.replace("_", " ").capitalize(), proxy)
    p["fields"].UpdatePipeline()

    layout = simple.CreateLayout("GeoLattice")
    # Layout cells form a binary tree: splitting cell c gives cells 2c+1 and 2c+2.
    layout.SplitHorizontal(0, 0.5)  # 1 left, 2 right
    layout.SplitVertical(1, 0.5)  # 3 top left, 4 bottom left
    layout.SplitVertical(2, 0.5)  # 5 top right, 6 bottom right
    layout.SplitHorizontal(4, 0.6)  # 9 lattice, 10 the summary table
    layout.SplitHorizontal(6, 0.5)  # 13 print order, 14 the toolpath replay
    cells = [3, 5, 9, 13, 14]
    views = []
    for (title, key, port, association, array), cell in zip(COLOURING, cells):
        view = simple.CreateView("RenderView")
        view.OrientationAxesVisibility = 1
        layout.AssignView(cell, view)
        simple.RenameView(title, view)
        views.append(view)

    v_gamma, v_layers, v_lattice, v_order, v_toolpath = views
    rep = simple.Show(p["surface"], v_gamma)
    _colour(rep, v_gamma, "POINTS", "Gamma", "Viridis (matplotlib)", "Gamma (mm)")

    _ghost(p["surface"], v_layers)
    rep = simple.Show(p["some_layers"], v_layers)
    _colour(rep, v_layers, "CELLS", "LayerId", "Turbo", "LayerId")

    _ghost(p["surface"], v_lattice, 0.1)
    rep = simple.Show(p["lattice"], v_lattice)
    lut = _colour(rep, v_lattice, "CELLS", "SubgraphId", SUBGRAPH_PALETTE, "SubgraphId (colours repeat)")
    p["lattice"].UpdatePipeline()
    lo, hi = p["lattice"].CellData["SubgraphId"].GetRange()
    lut.InterpretValuesAsCategories = 1
    lut.AnnotationsInitialized = 1
    ids = [str(i) for i in range(int(lo), int(hi) + 1)]
    lut.Annotations = [x for i in ids for x in (i, i)]
    palette = list(lut.IndexedColors)  # the preset's colours, cycled over the ids
    n = len(palette) // 3
    lut.IndexedColors = [palette[3 * (k % n) + c] for k in range(len(ids)) for c in range(3)]

    # A categorical legend would list every sub-graph: the bar shows the palette, without labels.
    simple.GetScalarBar(lut, v_lattice).DrawAnnotations = 0

    _ghost(p["surface"], v_order, 0.1)
    rep = simple.Show(simple.OutputPort(p["sequencer"], 0), v_order)
    _colour(rep, v_order, "CELLS", "PrintOrder", "Turbo", "PrintOrder")

    # The toolpath as the replay shows it, by print progress (every point kept: the range is the
    # whole print's; by PointIndex, not LayerId, whose -1 on air moves would stretch the layers' legend).
    _ghost(p["surface"], v_toolpath, 0.1)
    rep = simple.Show(p["replay"], v_toolpath)
    _colour(rep, v_toolpath, "POINTS", "PointIndex", "Turbo", "PointIndex (print progress)")

    # The verdict in words (GL Print Summary's SummaryVerdict) where a user looks first: over the part.
    p["verdict"] = simple.PythonAnnotation(
        registrationName=NAMES["verdict"], Input=p["summary"], ArrayAssociation="Field Data",
        Expression='input.FieldData.GetAbstractArray("SummaryVerdict").GetValue(0)')
    text = simple.Show(p["verdict"], v_gamma)
    text.WindowLocation = "Upper Left Corner"
    text.FontSize = 13

    # The numbers a slicer shows, in a spreadsheet next to the lattice.
    sheet = simple.CreateView("SpreadSheetView")
    layout.AssignView(10, sheet)
    simple.RenameView(SUMMARY_VIEW, sheet)
    simple.Show(p["summary"], sheet)

    for view in views:
        front_camera(view)
    for i, view in enumerate(views[1:]):
        simple.AddCameraLink(views[0], view, CAMERA_LINK % (i + 1))
    if "replay" in p:  # its time steps are the print progress 0..1: start the GUI at the whole path
        scene = simple.GetAnimationScene()
        views_of_scene = list(scene.ViewModules)
        scene.ViewModules = []  # a time change renders the scene's views, which needs an X server
        scene.UpdateAnimationUsingDataTimeSteps()
        scene.AnimationTime = scene.EndTime
        scene.ViewModules = views_of_scene
    simple.SetActiveView(views[0])
    simple.SetActiveSource(p["fields"])
    return p, views, layout


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("model", nargs="?", default=DEFAULT_MODEL, help="surface model [testdata/y_shape.obj]")
    parser.add_argument("-o", "--output", default=DEFAULT_OUTPUT, help="state file [docs/geolattice_y_shape.pvsm]")
    parser.add_argument("--plugin", help="path of GeoLattice.so [$GEOLATTICE_PLUGIN or build/...]")
    parser.add_argument("--fit-size", type=float, default=0.0, help="largest bounding-box side in mm [off]")
    parser.add_argument("--edge-length", type=float, default=0.0, help="target tet edge length in mm [auto]")
    parser.add_argument("--screenshot", help="also render the layout to this PNG (needs an X server)")
    args = parser.parse_args(argv)

    pipeline.load_plugin(args.plugin)
    p, views, layout = build_state(args.model, fit_size=args.fit_size, edge_length=args.edge_length)
    output = os.path.abspath(args.output)
    os.makedirs(os.path.dirname(output), exist_ok=True)
    simple.SaveState(output)
    print("geolattice_state: %d sources, %d views; wrote %s" % (len(p), len(views), output))
    if args.screenshot:
        layout.SetSize(1600, 1200)
        simple.SaveScreenshot(args.screenshot, layout, ImageResolution=[1600, 1200])
        print("geolattice_state: wrote %s" % args.screenshot)
        # After a screenshot of a layout with linked cameras, pvpython 5.11 ends with "X Error:
        # GLXBadContext" (or SIGABRT) and a non-zero exit code unless the links go first.
        for i in range(1, len(views)):
            simple.RemoveCameraLink(CAMERA_LINK % i)
        simple.RemoveViewsAndLayouts()
    return 0


if __name__ == "__main__":
    sys.exit(main())
