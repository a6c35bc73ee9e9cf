"""Run by pvpython (tests/test_output3d_contact.py, tests/test_view3d.py): opens a 3D contact
scene's XDMF file as a user would (OpenDataFile, which picks Xdmf3ReaderS:
the grids read as pieces of one dataset), keeps the contact surface (the
points with a weight, which is NaN on the bodies: a Threshold on it), warps
it by its displacement (with load stages, at the last time step, the
final state: the earlier steps have the bodies alone), and writes to out.json its cell count, cell types
and point arrays; then renders it seen from below (-z), coloured by
pressure rescaled to its range, to <png>. Each further FIELD (a point
array: pressure, stick; a vector's magnitude: shear, slip) renders the same
view coloured by it, rescaled to its range, to <png>'s name with -FIELD
before its suffix (view-shear.png).

    xvfb-run -a pvpython tests/paraview_contact3d.py out/ball.xdmf out.json view.png [FIELD ...]
"""
import json
import sys

import numpy as np
from paraview import servermanager, simple
from vtkmodules.numpy_interface import dataset_adapter as dsa

from paraview_solid import leaves  # this script's folder is on pvpython's path


def render(view, shown, field, vector, png):
    """The view coloured by a point field (a vector by its magnitude), to png."""
    simple.ColorBy(shown, ("POINTS", field, "Magnitude") if vector else ("POINTS", field))
    shown.RescaleTransferFunctionToDataRange(True, False)
    simple.Render(view)
    simple.SaveScreenshot(png, view, ImageResolution=[400, 400])


def main(xdmf, out_json, png, fields=()):
    src = simple.OpenDataFile(xdmf)
    surf = simple.Threshold(Input=src)
    surf.Scalars = ["POINTS", "weight"]
    surf.LowerThreshold = 0.0
    surf.UpperThreshold = 1e300
    surf.AllScalars = 1
    warp = simple.WarpByVector(Input=surf)
    warp.Vectors = ["POINTS", "displacement"]
    times = src.TimestepValues  # with -load_stages, one per stage: the contact surface is the last one's
    last = (times[-1] if len(times) else None) if isinstance(times, (list, tuple)) or hasattr(times, "__len__") else times
    warp.UpdatePipeline(last) if last is not None else warp.UpdatePipeline()
    result = {"reader": src.GetXMLName(), "grids": []}
    vectors = {}  # each point array: whether it has several components
    for g in leaves(servermanager.Fetch(warp)):
        if g.GetNumberOfCells() == 0:
            continue
        w = dsa.WrapDataObject(g)
        vectors.update({n: np.asarray(w.PointData[n]).ndim > 1 for n in w.PointData.keys()})
        result["grids"].append({"cells": g.GetNumberOfCells(), "points": g.GetNumberOfPoints(),
                                "cell_types": sorted({g.GetCellType(i) for i in range(g.GetNumberOfCells())}),
                                "arrays": {n: np.asarray(w.PointData[n]).tolist() for n in w.PointData.keys()},
                                "xyz": np.asarray(w.Points).tolist()})
    view = simple.CreateRenderView()
    view.ViewSize = [400, 400]
    view.OrientationAxesVisibility = 0
    if last is not None:
        view.ViewTime = last
    shown = simple.Show(warp, view)
    view.CameraPosition = [0.0, 0.0, -3.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0, 1, 0]
    view.ResetCamera()
    render(view, shown, "pressure", False, png)
    stem, dot, suffix = png.rpartition(".")
    for field in fields:
        render(view, shown, field, vectors.get(field, False), f"{stem}-{field}.{suffix}" if dot else f"{png}-{field}")
    with open(out_json, "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:])
