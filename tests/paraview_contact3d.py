"""Run by pvpython (tests/test_output3d_contact.py): opens a 3D contact
scene's XDMF file as a user would (OpenDataFile, which picks Xdmf3ReaderS:
the grids read as pieces of one dataset), keeps the contact surface (the
points with a weight, which is NaN on the bodies: a Threshold on it), warps
it by its displacement, and writes to out.json its cell count, cell types
and point arrays; then renders it seen from below (-z), coloured by
pressure rescaled to its range, to <png>.

    xvfb-run -a pvpython tests/paraview_contact3d.py out/ball.xdmf out.json view.png
"""
import json
import sys

import numpy as np
from paraview import servermanager, simple
from vtkmodules.numpy_interface import dataset_adapter as dsa

from paraview_solid import leaves  # this script's folder is on pvpython's path


def main(xdmf, out_json, png):
    src = simple.OpenDataFile(xdmf)
    surf = simple.Threshold(Input=src)
    surf.Scalars = ["POINTS", "weight"]
    surf.LowerThreshold = 0.0
    surf.UpperThreshold = 1e300
    surf.AllScalars = 1
    warp = simple.WarpByVector(Input=surf)
    warp.Vectors = ["POINTS", "displacement"]
    warp.UpdatePipeline()
    result = {"reader": src.GetXMLName(), "grids": []}
    for g in leaves(servermanager.Fetch(warp)):
        if g.GetNumberOfCells() == 0:
            continue
        w = dsa.WrapDataObject(g)
        result["grids"].append({"cells": g.GetNumberOfCells(), "points": g.GetNumberOfPoints(),
                                "cell_types": sorted({g.GetCellType(i) for i in range(g.GetNumberOfCells())}),
                                "arrays": {n: np.asarray(w.PointData[n]).tolist() for n in w.PointData.keys()},
                                "xyz": np.asarray(w.Points).tolist()})
    view = simple.CreateRenderView()
    view.ViewSize = [400, 400]
    view.OrientationAxesVisibility = 0
    shown = simple.Show(warp, view)
    simple.ColorBy(shown, ("POINTS", "pressure"))
    shown.RescaleTransferFunctionToDataRange(True, False)
    view.CameraPosition = [0.0, 0.0, -3.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0, 1, 0]
    view.ResetCamera()
    simple.Render(view)
    simple.SaveScreenshot(png, view, ImageResolution=[400, 400])
    with open(out_json, "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3])
