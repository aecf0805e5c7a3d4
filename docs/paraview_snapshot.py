# pvpython docs/paraview_snapshot.py RESULT.xmf OUT.png
# ParaView 5.11 (Debian): Cp coloured with a labelled colour bar, ψ contours in black, on white. The
# camera frames a window of a few radii around the body, computed from the data (any radius, any
# grid type the XDMF sidecar uses: the generic XDMF reader loads it; nothing here depends on it).
import sys
from paraview.simple import (XDMFReader, CreateRenderView, Show, ColorBy, GetColorTransferFunction,
                             GetScalarBar, Contour, Render, ResetCamera, SaveScreenshot)

if len(sys.argv) != 3:
    sys.exit("usage: pvpython paraview_snapshot.py RESULT.xmf OUT.png")
source = XDMFReader(FileNames=[sys.argv[1]])
source.UpdatePipeline()
info = source.GetDataInformation()
xmin, xmax, ymin, ymax, _, _ = info.GetBounds()

# The body radius from the data: the smallest distance of a grid point from the origin is r = a, the
# grid's inner ring. Without point access (client-server), fall back to the outer radius / 20.
radius = None
try:
    from paraview import servermanager
    from vtk.numpy_interface import dataset_adapter as dsa
    import numpy as np
    data = servermanager.Fetch(source)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    pts = dsa.WrapDataObject(data).Points
    radius = float(np.min(np.hypot(pts[:, 0], pts[:, 1])))
except Exception:
    pass
if not radius or radius <= 0.0:
    radius = 0.5 * max(xmax - xmin, ymax - ymin) / 20.0
half = min(4.0 * radius, 0.5 * max(xmax - xmin, ymax - ymin))

view = CreateRenderView()
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.Background = [1.0, 1.0, 1.0]

display = Show(source, view)
ColorBy(display, ('POINTS', 'cp'))
lut = GetColorTransferFunction('cp')
lut.ApplyPreset('Viridis (matplotlib)', True)
# Colours over the data in the window: the range of Cp near the body is what the picture shows.
lo, hi = source.PointData['cp'].GetRange()
lut.AutomaticRescaleRangeMode = 'Never'
lut.RescaleTransferFunction(lo, hi)
display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title = 'Cp'
bar.ComponentTitle = ''
bar.TitleColor = [0.0, 0.0, 0.0]
bar.LabelColor = [0.0, 0.0, 0.0]
bar.TitleFontSize = 18
bar.LabelFontSize = 16
bar.DrawTickLabels = 1

# ψ contours in black: 25 levels over the window. ψ grows about linearly with r (ψ ≈ U r sinθ), so its
# range in the window is the whole grid's range scaled by half/R.
plo, phi = source.PointData['psi'].GetRange()
outer = 0.5 * max(xmax - xmin, ymax - ymin)
span = max(abs(plo), abs(phi)) * half / outer
step = span / 12.0 if span > 0 else 1.0
contours = Contour(Input=source)
contours.ContourBy = ['POINTS', 'psi']
contours.Isosurfaces = [k * step for k in range(-12, 13)]
cdisplay = Show(contours, view)
ColorBy(cdisplay, None)
cdisplay.DiffuseColor = [0.0, 0.0, 0.0]
cdisplay.AmbientColor = [0.0, 0.0, 0.0]
cdisplay.LineWidth = 1.5

# The camera: parallel projection looking down −z at the window |x|, |y| ≤ half around the body.
Render(view)
ResetCamera(view)
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraPosition = [0.0, 0.0, 10.0 * half]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraParallelProjection = 1
view.CameraParallelScale = half
Render(view)
SaveScreenshot(sys.argv[2], view, ImageResolution=[800, 600], TransparentBackground=0)
