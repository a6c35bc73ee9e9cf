"""Run by pvpython (tests/test_output3d.py): reads a 3D body's XDMF file
as a user would, with each reader ParaView offers for it (the legacy
XDMFReader, Xdmf3ReaderS, Xdmf3ReaderT), and writes to out.json per reader
the cell types and counts, the points, the point arrays, the volume
IntegrateVariables finds, and the volume through each cell's own
interpolation (VTK's shape functions' derivatives, InterpolateDerivs, at
Gauss points: a node out of VTK's order moves the cell's geometry and so
its volume); then renders the first reader's body in one solid colour and
coloured by von Mises stress, rescaled to its range, to <png>-solid.png and
<png>-von_mises.png.

    xvfb-run -a pvpython tests/paraview_solid.py out/block.xdmf out.json png-prefix
"""
import json
import sys

import numpy as np
from paraview import servermanager, simple
from vtkmodules.numpy_interface import dataset_adapter as dsa


def leaves(data):
    """The unstructured grids of a reader's output (one, or a composite's blocks)."""
    if data.IsA("vtkCompositeDataSet"):
        it = data.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            yield it.GetCurrentDataObject()
            it.GoToNextItem()
    else:
        yield data


def gauss(n):
    """Gauss-Legendre points and weights on [0, 1]."""
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (x + 1), 0.5 * w


def cell_volume(cell, X):
    """The volume of one cell through VTK's own interpolation: the integral
    of det J, J = sum_a X_a (dN_a / dr)^T, J of VTK's derivatives of its
    shape functions. A hexahedron's triquadratic map (J of degree 5 a
    direction at most): 4 Gauss points a direction, exact; a tetrahedron's
    quadratic map (det J of degree 3) by the collapsed (Duffy) product rule,
    r = a (1 - b)(1 - c), s = b (1 - c), t = c, weight (1 - b)(1 - c)^2,
    4 points a direction: exact to degree 5 in c."""
    n = cell.GetNumberOfPoints()
    g, w = gauss(4)
    d = [0.0] * (3 * n)
    vol = 0.0
    for i, a in enumerate(g):
        for j, b in enumerate(g):
            for k, c in enumerate(g):
                if cell.GetCellType() == 24:  # VTK_QUADRATIC_TETRA
                    p, wt = (a * (1 - b) * (1 - c), b * (1 - c), c), w[i] * w[j] * w[k] * (1 - b) * (1 - c) ** 2
                else:
                    p, wt = (a, b, c), w[i] * w[j] * w[k]
                cell.InterpolateDerivs(p, d)
                J = np.asarray(d).reshape(3, n) @ X
                vol += wt * np.linalg.det(J)
    return vol


def describe(src):
    src.UpdatePipeline()
    data = servermanager.Fetch(src)
    grids = []
    for g in leaves(data):
        w = dsa.WrapDataObject(g)
        arrays = {name: np.asarray(w.PointData[name]).tolist() for name in w.PointData.keys()}
        pts = np.asarray(w.Points)
        vol = 0.0
        for i in range(g.GetNumberOfCells()):
            cell = g.GetCell(i)
            ids = [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())]
            vol += cell_volume(cell, pts[ids])
        grids.append({"points": pts.tolist(), "cells": g.GetNumberOfCells(),
                      "cell_types": sorted({g.GetCellType(i) for i in range(g.GetNumberOfCells())}),
                      "arrays": arrays, "interpolated_volume": vol})
    integ = simple.IntegrateVariables(Input=src)
    integ.DivideCellDataByVolume = 0
    integ.UpdatePipeline()
    out = dsa.WrapDataObject(servermanager.Fetch(integ))
    volume = float(out.CellData["Volume"][0])
    simple.Delete(integ)
    return {"grids": grids, "volume": volume}


def main(xdmf, out_json, png):
    result = {}
    for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT"):
        src = simple.XDMFReader(FileNames=[xdmf]) if reader == "XDMFReader" else getattr(simple, reader)(FileName=[xdmf])
        result[reader] = describe(src)
        if reader == "XDMFReader":
            view = simple.CreateRenderView()
            view.ViewSize = [400, 400]
            view.OrientationAxesVisibility = 0
            shown = simple.Show(src, view)
            view.CameraPosition = [2.5, -1.8, 2.2]
            view.CameraFocalPoint = [0.5, 0.5, 0.5]
            view.CameraViewUp = [0, 0, 1]
            view.ResetCamera()
            for field in ("solid", "von_mises"):
                if field == "solid":
                    simple.ColorBy(shown, None)
                else:
                    simple.ColorBy(shown, ("POINTS", field))
                    shown.RescaleTransferFunctionToDataRange(True, False)
                simple.Render(view)
                simple.SaveScreenshot(f"{png}-{field}.png", view, ImageResolution=[400, 400])
            simple.Delete(shown)
            simple.Delete(view)
        simple.Delete(src)
    with open(out_json, "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3])
