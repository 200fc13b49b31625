"""Renders the documentation pictures from the real pipeline output (needs an X server):

    xvfb-run -a -s "-screen 0 1280x1024x24" pvpython pvpython/render_docs.py [OUTDIR]

Writes into docs/images/ (or OUTDIR): gdf_<model>.png (γ on the part), layers_<model>.png
(curved layers coloured by LayerId over the translucent part), lattice_layer_<model>.png (the
lattice of one layer) and overhang_<kind>_<model>.png (overhang angle, planar and curved slicing).
"""
import os
import sys

from paraview import simple

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import geolattice_pipeline as pipeline  # noqa: E402
from geolattice_view import front_camera, white_view  # noqa: E402

MODELS = {"bunny": ("bunny.obj", 80.0), "y_shape": ("y_shape.obj", 0.0)}


def show_colored(proxy, view, array, association, preset, bar_title):
    rep = simple.Show(proxy, view)
    simple.ColorBy(rep, (association, array))
    lut = simple.GetColorTransferFunction(array)
    lut.ApplyPreset(preset, True)
    rep.RescaleTransferFunctionToDataRange(True, False)
    rep.SetScalarBarVisibility(view, True)
    bar = simple.GetScalarBar(lut, view)
    bar.Title = bar_title
    bar.ComponentTitle = ""
    bar.TitleColor = [0, 0, 0]
    bar.LabelColor = [0, 0, 0]
    return rep


def render_model(name, model, fit, outdir):
    p = pipeline.build_pipeline(os.path.join(HERE, "..", "testdata", model), fit_size=fit, base_tolerance=0.5)
    surface = simple.ExtractSurface(Input=p["fields"])

    view = white_view((1000, 800))
    show_colored(surface, view, "Gamma", "POINTS", "Viridis (matplotlib)", "Gamma (mm)")
    front_camera(view)
    simple.SaveScreenshot(os.path.join(outdir, "gdf_%s.png" % name), view, ImageResolution=[1000, 800])
    simple.Delete(view)

    view = white_view((1000, 800))
    part = simple.Show(surface, view)
    part.Opacity = 0.15
    simple.ColorBy(part, None)
    part.DiffuseColor = [0.6, 0.6, 0.6]
    every_fourth = simple.Threshold(Input=simple.Calculator(
        Input=p["layers"], AttributeType="Cell Data", ResultArrayName="Every4",
        Function="LayerId - 4*floor(LayerId/4)"), Scalars=["CELLS", "Every4"])
    try:
        every_fourth.LowerThreshold = 0
        every_fourth.UpperThreshold = 0
    except AttributeError:
        every_fourth.ThresholdRange = [0, 0]
    show_colored(every_fourth, view, "LayerId", "CELLS", "Turbo", "LayerId")
    front_camera(view)
    simple.SaveScreenshot(os.path.join(outdir, "layers_%s.png" % name), view, ImageResolution=[1000, 800])
    simple.Delete(view)

    # Lattice of one mid-height layer over the translucent part, coloured by sub-graph.
    view = white_view((1000, 800))
    part = simple.Show(surface, view)
    part.Opacity = 0.12
    simple.ColorBy(part, None)
    part.DiffuseColor = [0.6, 0.6, 0.6]
    p["lattice"].UpdatePipeline()
    ids = simple.servermanager.Fetch(p["lattice"]).GetCellData().GetArray("LayerId").GetRange()
    middle = int((ids[0] + ids[1]) / 2)
    one_layer = simple.Threshold(Input=p["lattice"], Scalars=["CELLS", "LayerId"])
    try:
        one_layer.LowerThreshold = middle
        one_layer.UpperThreshold = middle
    except AttributeError:
        one_layer.ThresholdRange = [middle, middle]
    rep = show_colored(one_layer, view, "EdgeKind", "CELLS", "Rainbow Uniform", "EdgeKind (0 α, 1 β, 2 boundary)")
    rep.LineWidth = 3.0
    front_camera(view, azimuth=20, elevation=35)
    simple.SaveScreenshot(os.path.join(outdir, "lattice_layer_%s.png" % name), view, ImageResolution=[1000, 800])
    simple.Delete(view)

    for mode in ("OverhangPlanar", "OverhangCurved"):
        view = white_view((800, 800))
        rep = show_colored(p["overhang"], view, mode, "CELLS", "Cool to Warm", "Overhang angle, " + mode[8:].lower() + " (deg)")
        lut = simple.GetColorTransferFunction(mode)
        lut.RescaleTransferFunction(0.0, 180.0)
        front_camera(view, azimuth=30, elevation=-20)
        simple.SaveScreenshot(os.path.join(outdir, "overhang_%s_%s.png" % (mode[8:].lower(), name)), view,
                              ImageResolution=[800, 800])
        simple.Delete(view)


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "docs", "images")
    os.makedirs(outdir, exist_ok=True)
    pipeline.load_plugin()
    for name, (model, fit) in MODELS.items():
        render_model(name, model, fit, outdir)
    print("render_docs: wrote pictures into %s" % os.path.abspath(outdir))


if __name__ == "__main__":
    main()
