"""Builds an exactly mirror-symmetric Tri6 disc mesh: Gmsh meshes the upper half
(tests/meshes/half_indenter.geo) and this script reflects it about y = yc,
sharing the nodes on the axis. Usage: symmetric_mesh.py OUT.msh h [yc]"""
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent


def read(path):
    lines = path.read_text().splitlines()
    i = lines.index("$PhysicalNames")
    names = lines[i + 2:i + 2 + int(lines[i + 1])]
    j = lines.index("$Nodes")
    nodes = {int(l.split()[0]): np.array([float(v) for v in l.split()[1:4]]) for l in lines[j + 2:j + 2 + int(lines[j + 1])]}
    k = lines.index("$Elements")
    elems = [list(map(int, l.split())) for l in lines[k + 2:k + 2 + int(lines[k + 1])]]
    return names, nodes, elems


def mirror(half, out, yc=0.0):
    names, nodes, elems = read(half)
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
        t, ntags = e[1], e[2]
        tags, conn = e[3:3 + ntags], e[3 + ntags:]
        out_elems.append((t, tags, conn))
        out_elems.append((t, tags, [mirror_id[c] for c in conn]))  # reflection: clockwise copy
    with open(out, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n%s\n$EndPhysicalNames\n" % (len(names), "\n".join(names)))
        f.write("$Nodes\n%d\n" % len(all_nodes))
        for i in sorted(all_nodes):
            x = all_nodes[i]
            f.write(f"{i} {x[0]:.17g} {x[1]:.17g} 0\n")
        f.write("$EndNodes\n$Elements\n%d\n" % len(out_elems))
        for k, (t, tags, conn) in enumerate(out_elems, 1):
            f.write(" ".join(map(str, [k, t, len(tags)] + tags + conn)) + "\n")
        f.write("$EndElements\n")


def build(out, h, yc=0.0):
    with tempfile.TemporaryDirectory() as d:
        half = Path(d) / "half.msh"
        subprocess.run(["gmsh", "-2", "-v", "0", "-format", "msh22", str(HERE / "meshes/half_indenter.geo"),
                        "-setnumber", "h", str(h), "-setnumber", "yc", str(yc), "-o", str(half)], check=True)
        mirror(half, out, yc)


if __name__ == "__main__":
    build(sys.argv[1], float(sys.argv[2]), float(sys.argv[3]) if len(sys.argv) > 3 else 0.0)
