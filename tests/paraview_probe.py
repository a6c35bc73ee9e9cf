"""Run by pvpython (tests/test_paraview.py): opens an XDMF file with ParaView's
legacy reader (XDMFReader) and its Xdmf3 readers (Xdmf3ReaderS, Xdmf3ReaderT)
and writes, per reader, every leaf block as ParaView holds it (points, cell
types, point arrays with their component counts and values), then the points
of the bodies warped by their displacement (Warp By Vector), to a JSON file.

    xvfb-run -a pvpython tests/paraview_probe.py out/hertz.xdmf probe.json
"""
import json
import sys

from paraview import servermanager as sm
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkDataObjectTreeIterator


def leaves(data):
    """(name or None, dataset) of every leaf block, in order."""
    it = vtkDataObjectTreeIterator()
    it.SetDataSet(data)
    it.VisitOnlyLeavesOn()
    it.InitTraversal()
    out = []
    while not it.IsDoneWithTraversal():
        meta = it.GetCurrentMetaData()
        name = meta.Get(data.NAME()) if meta is not None and meta.Has(data.NAME()) else None
        out.append((name, it.GetCurrentDataObject()))
        it.GoToNextItem()
    return out


def describe(block):
    pd = block.GetPointData()
    arrays = {}
    for i in range(pd.GetNumberOfArrays()):
        a = pd.GetArray(i)
        arrays[a.GetName()] = {"components": a.GetNumberOfComponents(), "tuples": a.GetNumberOfTuples(),
                               "values": vtk_to_numpy(a).tolist()}
    points = vtk_to_numpy(block.GetPoints().GetData()).tolist() if block.GetNumberOfPoints() else []
    return {"points": points, "cells": block.GetNumberOfCells(),
            "cell_types": sorted({block.GetCellType(c) for c in range(block.GetNumberOfCells())}),
            "arrays": arrays}


def main(xdmf, out):
    result = {}
    for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT"):
        if reader == "XDMFReader":
            src = simple.XDMFReader(FileNames=[xdmf])
        else:
            src = getattr(simple, reader)(FileName=[xdmf])
        src.UpdatePipeline()
        blocks = [dict(describe(b), name=n) for n, b in leaves(sm.Fetch(src))]
        warp = simple.WarpByVector(Input=src, Vectors=["POINTS", "displacement"], ScaleFactor=1.0)
        warp.UpdatePipeline()
        warped = [vtk_to_numpy(b.GetPoints().GetData()).tolist() if b.GetNumberOfPoints() else []
                  for _, b in leaves(sm.Fetch(warp))]
        result[reader] = {"blocks": blocks, "warped_points": warped}
        simple.Delete(warp)
        simple.Delete(src)
    with open(out, "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
