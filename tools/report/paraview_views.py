#!/usr/bin/env pvbatch
"""Renders every transient Exodus result of a results directory with ParaView.

usage: xvfb-run -a pvbatch tools/report/paraview_views.py RESULTS_DIR [--times 2e-4,4e-4,6e-4,8e-4]
                                                   [--scale 1000] [--output DIR]

RESULTS_DIR is the suite's results directory (RESULTS_DIR/<input>/*.exo) or one run's
directory. A transient result is an <analysis>.exo (or <analysis>.incomplete.exo) with an
<analysis>.history*.csv beside it (modal results, one step per mode, are skipped). For each,
the mesh is warped by DISP times --scale (the displacements are ~1e-4 m on 1 m bars) and
coloured by the displacement along the bar axis (the mesh's longest direction: DISP_X for the
1D models, DISP_Z for the 3D ones) and, when present, by CONTACT_PRESSURE, at each of --times
(the nearest stored step; times after the last step are dropped). One PNG per run and field,
the chosen times stacked top to bottom with one colour scale: OUTPUT/<input>_<analysis>_<field>.png
(OUTPUT defaults to RESULTS_DIR/paraview). Exit 1 when a file could not be rendered.
"""
import argparse
import glob
import math
import os
import sys

from paraview.simple import (ColorBy, CreateView, Delete, ExtractSurface, GetColorTransferFunction,
                             GetScalarBar, OpenDataFile, Render, SaveScreenshot, Show, Text, Transform, Tube,
                             WarpByVector)
import vtk

PANEL = (1600, 200)       # one time, whole bars
PANEL_ZOOM = (1600, 320)  # one time, zoom on the contact


def transient_results(results):
    dirs = [results] if glob.glob(os.path.join(results, "*.exo")) else \
        sorted(d for d in glob.glob(os.path.join(results, "*")) if os.path.isdir(d))
    out = []
    for d in dirs:
        for exo in sorted(glob.glob(os.path.join(d, "*.exo"))):
            base = os.path.basename(exo)[:-len(".exo")]
            analysis = base[:-len(".incomplete")] if base.endswith(".incomplete") else base
            if glob.glob(os.path.join(d, analysis + ".history*.csv")):
                out.append((os.path.basename(os.path.normpath(d)), analysis, exo,
                            base.endswith(".incomplete")))
    return out


def timesteps(reader):
    tv = reader.TimestepValues
    try:
        return [float(x) for x in tv]
    except TypeError:  # a single step may come back as a number
        return [float(tv)] if tv is not None else []


def bar_axis(reader):
    b = reader.GetDataInformation().GetBounds()
    ext = [b[1] - b[0], b[3] - b[2], b[5] - b[4]]
    return ext.index(max(ext)), b


def range_over(reader, array, comp, times):
    lo, hi = float("inf"), float("-inf")
    for t in times:
        reader.UpdatePipeline(t)
        info = reader.PointData[array]
        r = info.GetRange(comp)
        lo, hi = min(lo, r[0]), max(hi, r[1])
    return lo, hi


def stitch(pngs, out):
    app = vtk.vtkImageAppend()
    app.SetAppendAxis(1)  # vertical: VTK images start at the bottom, so add the last first
    readers = []
    for p in reversed(pngs):
        r = vtk.vtkPNGReader()
        r.SetFileName(p)
        r.Update()
        readers.append(r)
        app.AddInputConnection(r.GetOutputPort())
    w = vtk.vtkPNGWriter()
    w.SetFileName(out)
    w.SetInputConnection(app.GetOutputPort())
    w.Write()
    for p in pngs:
        os.remove(p)


def render(label, exo, incomplete, times_wanted, scale, outdir):
    reader = OpenDataFile(exo)
    if reader is None:
        raise RuntimeError("ParaView cannot open it")
    if "ApplyDisplacements" in reader.ListProperties():
        reader.ApplyDisplacements = 0  # IOSS reader: warp ourselves, with a known factor
    reader.UpdatePipelineInformation()
    steps = timesteps(reader) or [0.0]
    reader.UpdatePipeline(steps[0])
    axis, b = bar_axis(reader)
    names = reader.PointData.keys()
    disp = "DISP" if "DISP" in names else ("DISP_" if "DISP_" in names else None)
    if disp is None:
        raise RuntimeError(f"no displacement field (point arrays: {', '.join(names)})")
    chosen = []
    for t in times_wanted:
        if t <= steps[-1] * (1 + 1e-9):
            chosen.append(min(steps, key=lambda s: abs(s - t)))
    if not chosen:
        chosen = [steps[-1]]
    chosen = sorted(set(chosen))
    xyz = "XYZ"[axis]
    fields = [(disp, axis, f"DISP_{xyz}", "m", False)]
    pressure = next((n for n in names if n.upper() == "CONTACT_PRESSURE"), None)
    if pressure:  # non-zero at the contact faces only: zoom on the contact
        fields.append((pressure, -1, "CONTACT_PRESSURE", "Pa", True))

    warp = WarpByVector(Input=reader, Vectors=["POINTS", disp], ScaleFactor=scale)
    lateral = [b[2 * k + 1] - b[2 * k] for k in range(3) if k != axis]
    if max(lateral) < 1e-12:  # 1D line elements: a round tube of the bars' section (S = 4e-4)
        surf = Tube(Input=ExtractSurface(Input=warp), Radius=math.sqrt(4e-4 / math.pi),
                    NumberofSides=16, Capping=1)
    else:
        surf = ExtractSurface(Input=warp)
    view = CreateView("RenderView")
    view.ViewSize = list(PANEL)
    view.OrientationAxesVisibility = 0
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    disp_rep = Show(surf, view)
    title = Text()
    trep = Show(title, view)
    trep.WindowLocation = "Any Location"
    trep.Position = [0.01, 0.84]
    trep.FontSize = 15
    trep.Color = [0, 0, 0]
    note = Text(Text="grey: undeformed mesh (shifted sideways)")
    nrep = Show(note, view)
    nrep.WindowLocation = "Any Location"
    nrep.Position = [0.01, 0.04]
    nrep.FontSize = 12
    nrep.Color = [0.4, 0.4, 0.4]

    # the undeformed mesh, shifted sideways by 2.5 bar widths, as a reference for the warp
    look = 2 if axis != 2 else 0  # 1D bars on x: look along z; 3D bars on z: look along x
    up = [0, 1, 0] if axis != 1 else [0, 0, 1]
    side = up.index(1)
    width = max(b[2 * side + 1] - b[2 * side], 0.02)
    shift = [0.0, 0.0, 0.0]
    shift[side] = 2.5 * width
    refsurf = ExtractSurface(Input=reader)
    ref = Transform(Input=refsurf)
    ref.Transform.Translate = shift
    rrep = Show(ref, view)
    rrep.ColorArrayName = ["POINTS", ""]
    rrep.AmbientColor = rrep.DiffuseColor = [0.6, 0.6, 0.6]
    rrep.LineWidth = 4.0

    # camera: parallel projection, bar axis horizontal with the moving bar (the +axis side)
    # on the right, looking along a lateral axis; the whole length, or a zoom on the contact
    centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
    centre[side] += shift[side] / 2
    pos = list(centre)
    pos[look] += 10.0 if look == 2 else -10.0
    length = b[2 * axis + 1] - b[2 * axis]

    def camera(half_width, size):
        view.ViewSize = list(size)
        view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = pos, centre, up
        view.CameraParallelProjection = 1
        # the bar and its undeformed copy within the middle half of the height
        view.CameraParallelScale = max(half_width * size[1] / size[0], shift[side] + width)

    written = []
    for array, comp, fname, unit, zoom in fields:
        size = PANEL_ZOOM if zoom else PANEL
        disp_rep.SetRepresentationType("Surface With Edges" if zoom else "Surface")
        disp_rep.EdgeColor = [0.3, 0.3, 0.3]
        camera(0.34 if zoom else 0.62 * length, size)
        ColorBy(disp_rep, ("POINTS", array, xyz) if comp >= 0 else ("POINTS", array))
        lut = GetColorTransferFunction(array)
        lo, hi = range_over(reader, array, max(comp, 0), chosen)
        if comp >= 0:  # signed displacement: symmetric range, diverging map, 0 is white
            m = max(abs(lo), abs(hi)) or 1e-12
            lut.ApplyPreset("Cool to Warm", True)
            lut.RescaleTransferFunction(-m, m)
        else:
            lut.ApplyPreset("Viridis (matplotlib)", True)
            lut.RescaleTransferFunction(min(lo, 0.0), hi if hi > 0 else 1.0)
        lut.AutomaticRescaleRangeMode = "Never"
        bar = GetScalarBar(lut, view)
        bar.Title, bar.ComponentTitle = f"{fname} [{unit}]", ""
        bar.Orientation = "Horizontal"
        bar.WindowLocation = "Any Location"
        bar.Position = [0.70, 0.03]
        bar.ScalarBarLength = 0.28
        bar.TitleColor = bar.LabelColor = [0, 0, 0]
        bar.TitleFontSize = bar.LabelFontSize = 13
        bar.AddRangeLabels = 0
        bar.UseCustomLabels = 1
        cmin, cmax = lut.RGBPoints[0], lut.RGBPoints[-4]
        bar.CustomLabels = [cmin, 0.5 * (cmin + cmax), cmax]
        bar.AutomaticLabelFormat = 0
        bar.LabelFormat = "%-#.3g"
        bar.Visibility = 1
        parts = []
        for i, t in enumerate(chosen):
            view.ViewTime = t
            title.Text = (f"{label}{' (INCOMPLETE run)' if incomplete else ''}: {fname} at "
                          f"t = {t * 1e3:.3g} ms; shape warped by displacement x {scale:g}"
                          f"{'; zoom on the contact' if zoom else ''}")
            Render(view)
            png = os.path.join(outdir, f".{label.replace('/', '_')}_{fname}_{i}.png")
            SaveScreenshot(png, view, ImageResolution=list(size))
            parts.append(png)
        out = os.path.join(outdir, f"{label.replace('/', '_')}_{fname}.png")
        stitch(parts, out)
        written.append(out)
        bar.Visibility = 0
    for p in (title, note, ref, refsurf, surf, warp, reader):
        Delete(p)
    Delete(view)
    return written


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results")
    ap.add_argument("--times", default="2e-4,4e-4,6e-4,8e-4")
    ap.add_argument("--scale", type=float, default=1000.0)
    ap.add_argument("--output")
    a = ap.parse_args()
    times = [float(x) for x in a.times.split(",") if x]
    outdir = a.output or os.path.join(a.results, "paraview")
    os.makedirs(outdir, exist_ok=True)
    runs = transient_results(a.results)
    if not runs:
        print(f"paraview_views: no transient Exodus result in {a.results}")
        return 0
    failed = 0
    for name, analysis, exo, incomplete in runs:
        try:
            for p in render(f"{name}/{analysis}", exo, incomplete, times, a.scale, outdir):
                print(f"paraview_views: {p}")
        except Exception as e:  # noqa: BLE001
            failed += 1
            print(f"paraview_views: {exo}: {type(e).__name__}: {e}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
