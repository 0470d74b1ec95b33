"""The Taylor bar's final shape coloured by the equivalent plastic strain (docs/verification/
taylor-bar.png), from a run of input/taylor_bar_axisymmetric.xml:
    xvfb-run -a pvbatch tools/docs/render_taylor_bar.py OUT/impact.exo taylor-bar.png"""
import sys

from paraview.simple import (ColorBy, ExodusIIReader, GetActiveViewOrCreate, GetColorTransferFunction,
                             GetScalarBar, Reflect, Render, SaveScreenshot, Show, UpdatePipeline, WarpByVector)

exo, png = sys.argv[1:3]
r = ExodusIIReader(FileName=[exo])
r.ApplyDisplacements = 0
r.ElementVariables = ["EQ_PLASTIC_STRAIN"]
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
ColorBy(d, ("CELLS", "EQ_PLASTIC_STRAIN"))
lut = GetColorTransferFunction("EQ_PLASTIC_STRAIN")
lut.RescaleTransferFunction(0.0, 3.0)
bar = GetScalarBar(lut, view)
bar.Title = "equivalent plastic strain"
bar.ComponentTitle = ""
d.SetScalarBarVisibility(view, True)
view.CameraPosition = [0, 0.011, 0.09]
view.CameraFocalPoint = [0, 0.011, 0]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.013
Render(view)
SaveScreenshot(png, view, ImageResolution=[700, 900])
