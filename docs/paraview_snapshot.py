# ParaView 5.11 (Debian), XDMF Reader: ψ coloured, ψ contours, velocity glyphs near the body.
import sys
from paraview.simple import *
r = XDMFReader(FileNames=[sys.argv[1]])
v = CreateRenderView(); v.ViewSize = [800, 600]; v.OrientationAxesVisibility = 0; v.Background = [1, 1, 1]
try:
    v.UseColorPaletteForBackground = 0
except AttributeError:
    pass
d = Show(r, v); ColorBy(d, ('POINTS', 'cp')); lut = GetColorTransferFunction('cp'); lut.RescaleTransferFunction(-3.0, 1.0)
d.SetScalarBarVisibility(v, True)
c = Contour(Input=r); c.ContourBy = ['POINTS', 'psi']; c.Isosurfaces = [x * 0.25 for x in range(-12, 13)]
cd = Show(c, v); ColorBy(cd, None); cd.DiffuseColor = [0, 0, 0]; cd.AmbientColor = [0, 0, 0]; cd.LineWidth = 1.5
Render(v)
v.CameraPosition = [0, 0, 3]; v.CameraFocalPoint = [0, 0, 0]; v.CameraViewUp = [0, 1, 0]
v.CameraParallelProjection = 1; v.CameraParallelScale = 0.35
Render(v); SaveScreenshot(sys.argv[2], v, ImageResolution=[800, 600])
