"""Converts an X window dump (`xwd -root`: ZPixmap, 24 or 32 bits per pixel, as Xvfb's 24-bit screen gives) to
PNG with VTK's writer, so the GUI test needs no image tool besides xwd (Debian x11-apps).

    from xwd_to_png import xwd_to_png; xwd_to_png("screen.xwd", "screen.png", crop=(x, y, w, h))
"""
import struct


def xwd_to_png(xwd_path, png_path, crop=None):
    """Writes png_path; crop = (x, y, width, height) in screen pixels (top-left origin), or None: the
    lit part of the screen."""
    import numpy
    from paraview.vtk.vtkIOImage import vtkPNGWriter
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData

    with open(xwd_path, "rb") as f:
        data = f.read()
    header = struct.unpack(">25I", data[:100])
    header_size, version, pixmap_format, _depth, width, height = header[:6]
    byte_order, bits_per_pixel, bytes_per_line = header[7], header[11], header[12]
    masks, ncolors = header[14:17], header[19]
    if version != 7 or pixmap_format != 2 or bits_per_pixel not in (24, 32):
        raise ValueError("%s: unsupported xwd (version %d, format %d, %d bits per pixel)"
                         % (xwd_path, version, pixmap_format, bits_per_pixel))
    offset = header_size + 12 * ncolors
    step = bits_per_pixel // 8
    raw = numpy.frombuffer(data, dtype=numpy.uint8, count=height * bytes_per_line, offset=offset)
    raw = raw.reshape(height, bytes_per_line)[:, :width * step].reshape(height, width, step).astype(numpy.uint32)
    order = range(step) if byte_order == 0 else range(step - 1, -1, -1)  # 0: least significant byte first
    words = sum(raw[:, :, b] << (8 * k) for k, b in enumerate(order))
    if crop is None:  # the windows: the screen without its black margin (no window manager, no desktop)
        lit = numpy.argwhere(words & (masks[0] | masks[1] | masks[2]))
        (y_lo, x_lo), (y_hi, x_hi) = lit.min(axis=0), lit.max(axis=0)
        crop = (int(x_lo), int(y_lo), int(x_hi - x_lo + 1), int(y_hi - y_lo + 1))
    x0, y0, w, h = crop
    words = words[y0:y0 + h, x0:x0 + w]
    rgb = numpy.stack([(words & m) >> ((m & -m).bit_length() - 1) for m in masks], axis=-1).astype(numpy.uint8)
    rgb = numpy.ascontiguousarray(rgb[::-1])  # VTK images start at the bottom row
    image = vtkImageData()
    image.SetDimensions(rgb.shape[1], rgb.shape[0], 1)
    image.GetPointData().SetScalars(numpy_to_vtk(rgb.reshape(-1, 3), deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(png_path)
    writer.SetInputData(image)
    writer.Write()
