# SPDX-License-Identifier: BSD-2-Clause
"""Open an fsi_app XDMF series in ParaView and render its last frame, warped by the
displacement, to a PNG; prints what ParaView read (frames, points, cells, the displacement
range) so a test can check it.   pvbatch scripts/render_xdmf.py <file.xdmf> <out.png> [warp]"""
import os
import sys

from paraview.simple import ColorBy, GetActiveViewOrCreate, OpenDataFile, SaveScreenshot, Show, WarpByVector

series = OpenDataFile(os.path.abspath(sys.argv[1]))  # the reader resolves the .h5 beside an absolute path only
times = list(series.TimestepValues) or [0.0]
series.UpdatePipeline(times[-1])
info = series.GetDataInformation()
low, high = series.PointData["displacement"].GetRange(-1)
print(f"frames {len(times)} last time {times[-1]:.6g} points {info.GetNumberOfPoints()} cells {info.GetNumberOfCells()} "
      f"displacement magnitude {low:.6e} {high:.6e}")
warp = WarpByVector(Input=series, Vectors=["POINTS", "displacement"], ScaleFactor=float(sys.argv[3]) if len(sys.argv) > 3 else 1.0)
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [1000, 500]
view.ViewTime = times[-1]
shown = Show(warp, view)
ColorBy(shown, ("POINTS", "displacement", "Magnitude"))
shown.SetScalarBarVisibility(view, True)
view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [4, 2, 2], [0, 0, 1], [0, 0, 1]
view.ResetCamera()
SaveScreenshot(sys.argv[2], view)
