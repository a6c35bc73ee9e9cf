"""Reading and writing Gmsh 2.2 ASCII meshes for the tests that build or
distort meshes: physical names (their lines), nodes {id: xyz} and elements as
Gmsh lists [id, type, ntags, tags..., nodes...]."""
import numpy as np


def read(path):
    lines = path.read_text().splitlines()
    i = lines.index("$PhysicalNames")
    names = lines[i + 2:i + 2 + int(lines[i + 1])]
    j = lines.index("$Nodes")
    nodes = {int(l.split()[0]): np.array([float(v) for v in l.split()[1:4]]) for l in lines[j + 2:j + 2 + int(lines[j + 1])]}
    k = lines.index("$Elements")
    elems = [list(map(int, l.split())) for l in lines[k + 2:k + 2 + int(lines[k + 1])]]
    return names, nodes, elems


def write(path, names, nodes, elems):
    """Elements are renumbered 1, 2, ... in the order given."""
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n%s\n$EndPhysicalNames\n" % (len(names), "\n".join(names)))
        f.write("$Nodes\n%d\n" % len(nodes))
        for i in sorted(nodes):
            x = nodes[i]
            f.write(f"{i} {x[0]:.17g} {x[1]:.17g} 0\n")
        f.write("$EndNodes\n$Elements\n%d\n" % len(elems))
        for k, e in enumerate(elems, 1):
            f.write(" ".join(map(str, [k] + list(e[1:]))) + "\n")
        f.write("$EndElements\n")
