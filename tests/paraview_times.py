"""Run by pvpython (tests/test_load_stages.py): opens an XDMF file with
ParaView's legacy reader (XDMFReader) and its Xdmf3 readers (Xdmf3ReaderS,
Xdmf3ReaderT), and writes per reader its time steps and, at each, the
largest |component| of the displacement over every block, to a JSON file.

    xvfb-run -a pvpython tests/paraview_times.py out/hertz.xdmf times.json
"""
import json
import sys

import numpy as np
from paraview import servermanager as sm
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from paraview_probe import leaves


def largest_displacement(data):
    m = 0.0
    for _, block in leaves(data):
        a = block.GetPointData().GetArray("displacement")
        if a is not None and a.GetNumberOfTuples():
            m = max(m, float(np.nanmax(np.abs(vtk_to_numpy(a)))))
    return m


def main(xdmf, out):
    result = {}
    for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT"):
        src = simple.XDMFReader(FileNames=[xdmf]) if reader == "XDMFReader" else getattr(simple, reader)(FileName=[xdmf])
        src.UpdatePipelineInformation()
        times = [float(t) for t in (src.TimestepValues or [])]
        umax = []
        for t in times:
            src.UpdatePipeline(t)
            umax.append(largest_displacement(sm.Fetch(src)))
        result[reader] = {"times": times, "umax": umax}
        simple.Delete(src)
    with open(out, "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
