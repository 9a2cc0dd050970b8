# SPDX-License-Identifier: BSD-2-Clause
"""Render a coupled fsi_app XDMF series (fluid and wall parts) at one time, like Fig. 5 of
Heinlein, Klawonn, Rheinbach (2016): the tube cut along its axis, warped by the displacement
times a factor, the fluid coloured by pressure and the wall grey; prints what ParaView read so a test can check it.
    pvbatch scripts/render_fsi.py <file.xdmf> <out.png> <time> [warp] [title]
ParaView 5.11's XDMF reader leaves the parts of a spatial collection unnamed, so each part is
read from a copy of the series that holds only it (written beside the file, then removed)."""
import os
import sys

from xdmf_part import part_copy
from paraview.simple import (Clip, ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, OpenDataFile, SaveScreenshot, Show, Text,
                             WarpByVector)

path = os.path.abspath(sys.argv[1])  # the reader resolves the .h5 beside an absolute path only
warp = float(sys.argv[4]) if len(sys.argv) > 4 else 10.0




view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1200, 300]
view.OrientationAxesVisibility = 0
files, bounds = [part_copy(path, "fluid"), part_copy(path, "wall")], None
for name, copy in zip(("fluid", "wall"), files):
    series = OpenDataFile(copy)
    times = list(series.TimestepValues) or [0.0]
    t = min(times, key=lambda s: abs(s - float(sys.argv[3])))
    series.UpdatePipeline(t)
    info = series.GetDataInformation()
    bounds = bounds or info.GetBounds()
    dlow, dhigh = series.PointData["displacement"].GetRange(-1)
    line = f"{name}: frames {len(times)} time {t:.6g} points {info.GetNumberOfPoints()} cells {info.GetNumberOfCells()} displacement magnitude {dlow:.6e} {dhigh:.6e}"
    cut = Clip(Input=WarpByVector(Input=series, Vectors=["POINTS", "displacement"], ScaleFactor=warp), ClipType="Plane")
    cut.ClipType.Normal = [0, 1, 0]
    shown = Show(cut, view)
    if name == "fluid":
        low, high = series.PointData["pressure"].GetRange(-1)
        line += f" pressure {low:.6e} {high:.6e}"
        ColorBy(shown, ("POINTS", "pressure"))
        GetColorTransferFunction("pressure").RescaleTransferFunction(min(low, 0.0), max(high, 1.0))
        shown.SetScalarBarVisibility(view, True)
    else:
        shown.ColorArrayName = [None, ""]
        shown.AmbientColor = shown.DiffuseColor = [0.75, 0.75, 0.75]
    print(line)
view.ViewTime = t
if len(sys.argv) > 5:
    Show(Text(Text=sys.argv[5]), view)
mid, length = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)], bounds[5] - bounds[4]  # the tube along z, seen from +y
view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [mid[0], mid[1] + 3 * length, mid[2]], mid, [1, 0, 0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.6 * length * view.ViewSize[1] / view.ViewSize[0]
SaveScreenshot(sys.argv[2], view)
for copy in files:
    os.remove(copy)
