"""Run by pvpython (tests/test_paraview.py): renders an XDMF file as a user
would see it, with each reader ParaView offers for it (the legacy
XDMFReader, Xdmf3ReaderS, Xdmf3ReaderT, and whatever OpenDataFile picks),
first in one solid colour and then coloured by each field given, rescaled to
its range, and saves each view as <out>/<reader>-<field>.png (field "solid"
for the first).

    xvfb-run -a pvpython tests/paraview_render.py out/hertz.xdmf outdir von_mises stress_xx displacement
"""
import os
import sys

from paraview import simple


def open_with(reader, xdmf):
    if reader == "OpenDataFile":
        return simple.OpenDataFile(xdmf)
    if reader == "XDMFReader":
        return simple.XDMFReader(FileNames=[xdmf])
    return getattr(simple, reader)(FileName=[xdmf])


def main(xdmf, out, fields):
    os.makedirs(out, exist_ok=True)
    for reader in ("XDMFReader", "Xdmf3ReaderS", "Xdmf3ReaderT", "OpenDataFile"):
        src = open_with(reader, xdmf)
        view = simple.CreateRenderView()
        view.ViewSize = [400, 400]
        view.OrientationAxesVisibility = 0
        shown = simple.Show(src, view)
        view.ResetCamera()
        for field in ["solid"] + fields:
            if field == "solid":
                simple.ColorBy(shown, None)
            else:
                simple.ColorBy(shown, ("POINTS", field))
                shown.RescaleTransferFunctionToDataRange(True, False)
            simple.Render(view)
            simple.SaveScreenshot(os.path.join(out, f"{reader}-{field}.png"), view, ImageResolution=[400, 400])
        simple.Delete(shown)
        simple.Delete(view)
        simple.Delete(src)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
