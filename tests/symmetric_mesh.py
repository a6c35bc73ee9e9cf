"""Builds an exactly mirror-symmetric Tri6 disc mesh: Gmsh meshes the upper half
(tests/meshes/half_indenter.geo) and this script reflects it about y = yc,
sharing the nodes on the axis. Usage: symmetric_mesh.py OUT.msh h [yc]"""
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

import msh22

HERE = Path(__file__).resolve().parent


def mirror(half, out, yc=0.0):
    names, nodes, elems = msh22.read(half)
    mirror_id, nmax = {}, max(nodes)
    for i, x in sorted(nodes.items()):
        if abs(x[1] - yc) < 1e-12:
            x[1] = yc
            mirror_id[i] = i
        else:
            nmax += 1
            mirror_id[i] = nmax
    all_nodes = dict(nodes)
    for i, m in mirror_id.items():
        if m != i:
            all_nodes[m] = nodes[i] * np.array([1.0, -1.0, 1.0]) + np.array([0.0, 2 * yc, 0.0])
    out_elems = []
    for e in elems:
        head, conn = e[:3 + e[2]], e[3 + e[2]:]
        out_elems.append(e)
        out_elems.append(head + [mirror_id[c] for c in conn])  # reflection: clockwise copy
    msh22.write(out, names, all_nodes, out_elems)


def build(out, h, yc=0.0):
    with tempfile.TemporaryDirectory() as d:
        half = Path(d) / "half.msh"
        subprocess.run(["gmsh", "-2", "-v", "0", "-format", "msh22", str(HERE / "meshes/half_indenter.geo"),
                        "-setnumber", "h", str(h), "-setnumber", "yc", str(yc), "-o", str(half)], check=True)
        mirror(half, out, yc)


if __name__ == "__main__":
    build(sys.argv[1], float(sys.argv[2]), float(sys.argv[3]) if len(sys.argv) > 3 else 0.0)
