# SPDX-License-Identifier: BSD-2-Clause
"""Render one node field of one part of a coupled fsi_app XDMF series on that part's outer
surface at one time, the vessel seen from +y (its centre lines in the x-z plane), warped by the
displacement times a factor; prints what ParaView read so a caller can check it.
    pvbatch scripts/render_vessel.py <file.xdmf> <out.png> <time> <part> <field> [warp] [title]
part is fluid or wall; the fluid's surface is the lumen, where wss, tawss and osi live.
The part is read from a copy of the series that holds only it (scripts/xdmf_part.py)."""
import os
import sys

from xdmf_part import part_copy
from paraview.simple import (ColorBy, ExtractSurface, GetActiveViewOrCreate, GetColorTransferFunction, OpenDataFile, SaveScreenshot, Show,
                             Text, WarpByVector)

path, png, when, name, field = os.path.abspath(sys.argv[1]), sys.argv[2], float(sys.argv[3]), sys.argv[4], sys.argv[5]
warp = float(sys.argv[6]) if len(sys.argv) > 6 else 1.0

copy = part_copy(path, name)

series = OpenDataFile(copy)
steps = series.TimestepValues  # a float for a series of one frame
times = list(steps) if hasattr(steps, "__len__") else [steps or 0.0]
t = min(times, key=lambda s: abs(s - when))
series.UpdatePipeline(t)
info = series.GetDataInformation()
low, high = series.PointData[field].GetRange(-1)
print(f"{name}: frames {len(times)} time {t:.6g} points {info.GetNumberOfPoints()} cells {info.GetNumberOfCells()} {field} magnitude {low:.6e} {high:.6e}")

view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [900, 700]
view.OrientationAxesVisibility = 0
view.ViewTime = t
surface = ExtractSurface(Input=WarpByVector(Input=series, Vectors=["POINTS", "displacement"], ScaleFactor=warp))
shown = Show(surface, view)
ColorBy(shown, ("POINTS", field, "Magnitude"))
GetColorTransferFunction(field).RescaleTransferFunction(low, high)
shown.SetScalarBarVisibility(view, True)
if len(sys.argv) > 7:
    Show(Text(Text=sys.argv[7]), view)
b = info.GetBounds()
mid, size = [(b[2 * k] + b[2 * k + 1]) / 2 for k in range(3)], max(b[1] - b[0], b[5] - b[4])
view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [mid[0], mid[1] + 3 * size, mid[2]], mid, [0, 0, 1]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.55 * size
SaveScreenshot(png, view)
os.remove(copy)
