"""The render view and camera that the GeoLattice scripts share (the state file, the documentation
pictures, the robot-cell picture and the GUI test): a white view, and the camera that looks at the
part from the front (-y), +z up, turned `azimuth` degrees about z and raised `elevation` degrees."""
from paraview import simple


def white_view(size, axes=True):
    """A new render view of `size` pixels on a white background (the colour palette's background
    switched off where this ParaView has it), with or without the orientation axes."""
    view = simple.CreateRenderView()
    view.ViewSize = list(size)
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 1 if axes else 0
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:  # ParaView before 5.10 has no palette background
        pass
    return view


def front_camera(view, azimuth=30, elevation=15):
    """Fits the camera to what `view` shows, looking from the front (-y) with +z up, then turned
    by `azimuth` and `elevation` (degrees) and fitted again."""
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.SetViewUp(0, 0, 1)
    focal, distance = camera.GetFocalPoint(), camera.GetDistance()
    camera.SetPosition(focal[0], focal[1] - distance, focal[2])
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    view.ResetCamera()
