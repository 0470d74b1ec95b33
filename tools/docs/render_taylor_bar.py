"""The Taylor bar's final shape coloured by an element field (docs/verification/taylor-bar.md), from
a run of input/taylor_bar_axisymmetric.xml (the equivalent plastic strain, the default) or of
input/taylor_bar_johnson_cook_axisymmetric.xml (TEMPERATURE):
    xvfb-run -a pvbatch tools/docs/render_taylor_bar.py OUT/impact.exo taylor-bar.png [FIELD LOW HIGH TITLE]"""
import sys

from paraview.simple import (ColorBy, ExodusIIReader, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, Reflect, Render, SaveScreenshot, Show, UpdatePipeline, WarpByVector)

exo, png = sys.argv[1:3]
field, low, high, title = (sys.argv[3], float(sys.argv[4]), float(sys.argv[5]), sys.argv[6]) if len(sys.argv) > 6 \
    else ("EQ_PLASTIC_STRAIN", 0.0, 3.0, "equivalent plastic strain")
r = ExodusIIReader(FileName=[exo])
r.ApplyDisplacements = 0
r.ElementVariables = [field]
r.PointVariables = ["DISP_"]
r.UpdatePipelineInformation()
UpdatePipeline(time=r.TimestepValues[-1], proxy=r)
w = WarpByVector(Input=r, Vectors=["POINTS", "DISP_"], ScaleFactor=1.0)
m = Reflect(Input=w, Plane="X")  # the meridian section mirrored about the axis
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [700, 900]
view.ViewTime = r.TimestepValues[-1]
view.OrientationAxesVisibility = 0
d = Show(m, view)
ColorBy(d, ("CELLS", field))
lut = GetColorTransferFunction(field)
lut.RescaleTransferFunction(low, high)
bar = GetScalarBar(lut, view)
bar.Title = title
bar.ComponentTitle = ""
d.SetScalarBarVisibility(view, True)
view.CameraPosition = [0, 0.011, 0.09]
view.CameraFocalPoint = [0, 0.011, 0]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.013
Render(view)
SaveScreenshot(png, view, ImageResolution=[700, 900])
