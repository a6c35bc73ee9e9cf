"""Run by pvpython (tests/test_paraview.py): opens an XDMF file of a scene
with friction with ParaView's legacy reader (XDMFReader), its Xdmf3 readers
(Xdmf3ReaderS, Xdmf3ReaderT) and what OpenDataFile picks, at the last time
step, and writes per reader its time steps, every leaf block's friction
arrays (shear, slip, stick: their values, or null where the block has none),
the shear's range as ParaView's data information gives it, and the range of
the colour map after colouring a view by the shear and rescaling it to the
data, to a JSON file.

    xvfb-run -a pvpython tests/paraview_shear.py out/cattaneo.xdmf shear.json
"""
import json
import sys

from paraview import servermanager as sm
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from paraview_probe import leaves
from paraview_render import open_with

FIELDS = ("shear", "slip", "stick")


def main(xdmf, out):
    result = {}
    for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT", "OpenDataFile"):
        src = open_with(reader, xdmf)
        src.UpdatePipelineInformation()
        times = [float(t) for t in (src.TimestepValues or [])]
        t = times[-1] if times else 0.0
        src.UpdatePipeline(t)
        blocks = []
        for name, block in leaves(sm.Fetch(src)):
            pd = block.GetPointData()
            blocks.append({"name": name, "points": block.GetNumberOfPoints(),
                           "arrays": {f: (vtk_to_numpy(pd.GetArray(f)).tolist() if pd.GetArray(f) is not None else None)
                                      for f in FIELDS}})
        info = src.PointData["shear"]
        view = simple.CreateRenderView()
        view.ViewTime = t
        shown = simple.Show(src, view)
        simple.ColorBy(shown, ("POINTS", "shear"))
        shown.RescaleTransferFunctionToDataRange(True, False)
        rgb = list(simple.GetColorTransferFunction("shear").RGBPoints)
        result[reader] = {"times": times, "blocks": blocks,
                          "range": list(info.GetRange()) if info is not None else None,
                          "colour_range": [rgb[0], rgb[-4]]}
        simple.Delete(shown)
        simple.Delete(view)
        simple.Delete(src)
    with open(out, "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
