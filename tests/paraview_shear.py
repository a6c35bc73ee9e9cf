"""Run by pvpython (tests/test_paraview.py): opens an XDMF file of a scene
with friction with ParaView's legacy reader (XDMFReader), its Xdmf3 readers
(Xdmf3ReaderS, Xdmf3ReaderT) and what OpenDataFile picks, at the last time
step, and writes per reader its time steps, every leaf block's friction
arrays (shear, slip, stick: their values, or null where the block has none),
the shear's range as ParaView's data information gives it, and the range of
the colour map after colouring a view by the shear and rescaling it to the
data, and the points and cells that Threshold on the shear keeps (the NaN
dropped: the contact lines alone), to a JSON file. Given a directory, it
also saves those lines as a user sees them, framed from +z on their loaded
part, in one solid colour and coloured by the shear:
<dir>/<reader>-{solid,shear}.png.

    xvfb-run -a pvpython tests/paraview_shear.py out/cattaneo.xdmf shear.json [pngdir]
"""
import json
import os
import sys

from paraview import servermanager as sm
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from paraview_probe import leaves
from paraview_render import open_with

FIELDS = ("shear", "slip", "stick")


def loaded_box(data):
    """The box (x0, x1, y0, y1) of the points whose shear is a number other than 0."""
    import numpy as np
    on = []
    for _, block in leaves(data):
        q = block.GetPointData().GetArray("shear")
        if q is not None and block.GetNumberOfPoints():
            q = vtk_to_numpy(q)
            on.append(vtk_to_numpy(block.GetPoints().GetData())[:, :2][np.isfinite(q) & (q != 0)])
    on = np.concatenate(on)
    return on[:, 0].min(), on[:, 0].max(), on[:, 1].min(), on[:, 1].max()


def render_line(line, t, box, pngdir, reader):
    """The thresholded lines, 6 pixels wide, from +z, framed on their loaded
    part (its box enlarged 1.3 times)."""
    view = simple.CreateRenderView()
    view.ViewTime = t
    view.ViewSize = [400, 400]
    view.OrientationAxesVisibility = 0
    shown = simple.Show(line, view)
    shown.LineWidth = 6.0
    simple.Render(view)   # the session's first render resets the camera: before it is set
    x0, x1, y0, y1 = box
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = [cx, cy, 10.0], [cx, cy, 0.0], [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.65 * max(x1 - x0, y1 - y0)
    for field in ("solid", "shear"):
        if field == "solid":
            simple.ColorBy(shown, None)
        else:
            simple.ColorBy(shown, ("POINTS", "shear"))
            shown.RescaleTransferFunctionToDataRange(True, False)
        simple.Render(view)
        simple.SaveScreenshot(os.path.join(pngdir, f"{reader}-{field}.png"), view, ImageResolution=[400, 400])
    simple.Delete(shown)
    simple.Delete(view)


def main(xdmf, out, pngdir=None):
    result = {}
    for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT", "OpenDataFile"):
        src = open_with(reader, xdmf)
        src.UpdatePipelineInformation()
        times = [float(t) for t in (src.TimestepValues or [])]
        t = times[-1] if times else 0.0
        src.UpdatePipeline(t)
        blocks, data = [], sm.Fetch(src)
        for name, block in leaves(data):
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
        simple.Delete(shown)
        simple.Delete(view)
        line = simple.Threshold(Input=src, Scalars=["POINTS", "shear"], LowerThreshold=-1e300, UpperThreshold=1e300)
        line.UpdatePipeline(t)
        kept = line.GetDataInformation()
        result[reader] = {"times": times, "blocks": blocks,
                          "range": list(info.GetRange()) if info is not None else None,
                          "colour_range": [rgb[0], rgb[-4]],
                          "threshold": [kept.GetNumberOfPoints(), kept.GetNumberOfCells()]}
        if pngdir:
            os.makedirs(pngdir, exist_ok=True)
            render_line(line, t, loaded_box(data), pngdir, reader)
        simple.Delete(line)
        simple.Delete(src)
    with open(out, "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main(*sys.argv[1:4])
