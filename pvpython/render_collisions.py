"""Renders where a run's toolpath collides (needs an X server):

    xvfb-run -a -s "-screen 0 1280x1024x24" pvpython pvpython/render_collisions.py RUNDIR OUT.png [TITLE]

RUNDIR is a `geolattice run` output directory. The picture shows its curved layers (layers.vtp)
translucent, every colliding toolpath station (toolpath.vtp points with Collision > 0) in blue
and the obstacles the verifier reported for the first of them (toolpath_collisions.vtp, Role 1)
in red. docs/performance.md's residual pictures were made with it.
"""
import os
import sys

from paraview import simple


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    run, out = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) > 3 else os.path.basename(os.path.normpath(run))
    view = simple.CreateRenderView()
    view.ViewSize = [1000, 800]
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    view.OrientationAxesVisibility = 1

    layers = simple.XMLPolyDataReader(FileName=[os.path.join(run, "layers.vtp")])
    shown = simple.Show(layers, view)
    shown.ColorArrayName = [None, ""]
    shown.Opacity = 0.04
    shown.DiffuseColor = [0.5, 0.5, 0.5]

    # The part's size sets the glyphs' size.
    bounds = layers.GetDataInformation().GetBounds()
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])

    def spheres(source, colour, scale):
        glyphs = simple.Glyph(Input=source, GlyphType="Sphere")
        glyphs.ScaleArray = ["POINTS", "No scale array"]
        glyphs.OrientationArray = ["POINTS", "No orientation array"]
        glyphs.ScaleFactor = scale * size
        glyphs.GlyphMode = "All Points"
        d = simple.Show(glyphs, view)
        d.ColorArrayName = [None, ""]
        d.DiffuseColor = colour
        d.AmbientColor = colour

    def points_where(file_name, array, lower, upper):
        """The points of a file (as vertices) whose point array lies in [lower, upper]."""
        vertices = simple.MaskPoints(Input=simple.XMLPolyDataReader(FileName=[file_name]))
        vertices.OnRatio = 1
        vertices.MaximumNumberofPoints = 1 << 30
        vertices.GenerateVertices = 1
        vertices.SingleVertexPerCell = 1
        selected = simple.Threshold(Input=vertices)
        selected.Scalars = ["POINTS", array]
        selected.LowerThreshold = lower
        selected.UpperThreshold = upper
        return selected

    spheres(points_where(os.path.join(run, "toolpath.vtp"), "Collision", 1, 255),
            [0.1, 0.3, 1.0], 0.012)
    pairs = os.path.join(run, "toolpath_collisions.vtp")
    if os.path.exists(pairs):
        spheres(points_where(pairs, "Role", 1, 1), [1.0, 0.1, 0.1], 0.008)

    text = simple.Show(simple.Text(Text=title), view)
    text.FontSize = 14
    text.Color = [0, 0, 0]
    text.WindowLocation = "Upper Left Corner"
    view.ResetCamera()
    camera = view.GetActiveCamera()
    focal, distance = camera.GetFocalPoint(), camera.GetDistance()
    camera.SetViewUp(0, 0, 1)
    camera.SetPosition(focal[0] + 0.6 * distance, focal[1] - 0.8 * distance,
                       focal[2] + 0.3 * distance)
    view.ResetCamera()
    simple.Render(view)
    simple.SaveScreenshot(out, view, ImageResolution=[1000, 800])


if __name__ == "__main__":
    main()
