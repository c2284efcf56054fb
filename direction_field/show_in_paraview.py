"""Shows a direction field written by direction_field in ParaView, as the
manual's figure shows it: the shaded mesh, all n directions of the field as
glyphs at the same points (arrows for odd n, whose directions have a sign;
line segments through the point for even n, whose opposite directions are one
line), and the singularities as markers coloured by their index. A field
on faces (--on faces) is drawn at the triangles' centres.

    pvpython show_in_paraview.py FIELD [SINGULARITIES] [--screenshot PNG]

FIELD is the file of --vtk (.vtu or .vtk), SINGULARITIES the file of
--vtk-singularities. Without --screenshot, pvpython stays interactive; in the
ParaView window, the Python shell runs it with
    exec(open("show_in_paraview.py").read()); show_direction_field("f.vtu", "s.vtu")
"""
import sys

from paraview import simple

GLYPHS = 4000  # about this many glyph points, the same points for every direction


def field_layout(reader):
    """n (the number of direction_k arrays) and where they live: "POINTS" for a
    field on vertices, "CELLS" for a field on faces (--on faces)."""
    for association, data in (("POINTS", reader.PointData), ("CELLS", reader.CellData)):
        n = sum(1 for name in data.keys() if name.startswith("direction_"))
        if n > 0:
            return n, association
    return 0, "POINTS"


def show_direction_field(field, singularities=None, view=None):
    """Shows FIELD (and the markers of SINGULARITIES) in VIEW (the active view
    by default); returns the glyph filters, one per direction shown."""
    view = view or simple.GetActiveViewOrCreate("RenderView")
    mesh = simple.OpenDataFile(field)
    surface = simple.Show(mesh, view)
    surface.ColorArrayName = ["POINTS", ""]
    surface.DiffuseColor = [0.92, 0.92, 0.88]
    info = mesh.GetDataInformation()
    bounds = info.GetBounds()
    diagonal = sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5
    n, association = field_layout(mesh)
    shown = range(n) if n % 2 == 1 else range(n // 2)  # direction k + n/2 is the same line as direction k
    # glyphs at the points, or at the triangles' centres for a field on faces
    anchors = info.GetNumberOfPoints() if association == "POINTS" else info.GetNumberOfCells()
    stride = max(1, anchors // GLYPHS)
    # about the spacing of the glyph points on a surface of that size
    size = 0.7 * diagonal / max(1.0, anchors / stride) ** 0.5
    glyphs = []
    for k in shown:
        glyph = simple.Glyph(Input=mesh, GlyphType="Arrow" if n % 2 == 1 else "Line")
        glyph.OrientationArray = [association, "direction_%d" % k]
        glyph.ScaleArray = [association, "No scale array"]
        glyph.ScaleFactor = size
        glyph.GlyphMode = "Every Nth Point"
        glyph.Stride = stride
        display = simple.Show(glyph, view)
        display.ColorArrayName = ["POINTS", ""]
        display.DiffuseColor = [0.1, 0.1, 0.1]
        display.AmbientColor = [0.1, 0.1, 0.1]
        glyphs.append(glyph)
    if singularities:
        markers = simple.OpenDataFile(singularities)
        display = simple.Show(markers, view)
        simple.ColorBy(display, ("POINTS", "singularity_index"))
        lut = simple.GetColorTransferFunction("singularity_index")
        lut.ApplyPreset("Cool to Warm", True)
        largest = max([abs(x) for x in markers.PointData["singularity_index"].GetRange()] + [1e-9])
        lut.RescaleTransferFunction(-largest, largest)
        display.SetScalarBarVisibility(view, True)
    simple.ResetCamera(view)
    simple.Render(view)
    return glyphs


def main(argv):
    args = [a for a in argv[1:] if a != "--screenshot"]
    screenshot = None
    if "--screenshot" in argv:
        i = argv.index("--screenshot")
        if i + 1 >= len(argv):
            sys.exit("show_in_paraview.py: --screenshot needs a file name")
        screenshot = argv[i + 1]
        args.remove(screenshot)
    if not 1 <= len(args) <= 2:
        sys.exit(__doc__)
    view = simple.GetActiveViewOrCreate("RenderView")
    show_direction_field(args[0], args[1] if len(args) > 1 else None, view)
    if screenshot:
        simple.SaveScreenshot(screenshot, view, ImageResolution=[1200, 900])
    else:
        simple.Interact(view)


if __name__ == "__main__" and len(sys.argv) > 1:
    main(sys.argv)
