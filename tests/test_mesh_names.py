"""Generated meshes are named after their parameters, each number in the
shortest decimal form that reads back as the same double: no float noise
(hc0.0050000000000000001), and no two values sharing a name (h%g made 0.3 and
0.1 + 0.2 the same mesh)."""
import re
import subprocess

from conftest import BIN, ENV, ROOT

SCENE = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_only"]


def test_mesh_names_shortest_round_trip(tmp_path):
    hs = [0.3, 0.1 + 0.2, 0.25]
    for h in hs:
        proc = subprocess.run([str(BIN)] + SCENE + [
            "-mesh_size", repr(h), "-mesh_dir", str(tmp_path),
            "-indenter_geo_params", "R=1,xc=-1,yc=0,xclamp=-1.8,xcontact=-0.5,hc=0.005,dc=1.6",
            "-block_geo_params", "x0=0,W=1,H=2,hc=0.1"], cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=300)
        assert proc.returncode == 0, proc.stderr
    names = sorted(p.name for p in tmp_path.glob("*.msh"))
    assert len(names) == 2 * len(hs), names
    assert "indenter-h0.3_R1_xc-1_yc0_xclamp-1.8_xcontact-0.5_hc0.005_dc1.6.msh" in names
    assert "block-h0.30000000000000004_x00_W1_H2_hc0.1.msh" in names
    assert "block-h0.25_x00_W1_H2_hc0.1.msh" in names
    params = ("h", "R", "xc", "yc", "xclamp", "xcontact", "hc", "dc", "x0", "W", "H")
    for n in names:
        for part in n[:-len(".msh")].split("-", 1)[1].split("_"):
            name = max((p for p in params if part.startswith(p)), key=len)
            num = part[len(name):]
            assert num == repr(float(num)).removesuffix(".0"), f"{part} in {n} is not in the shortest round-trip form"
    found = sorted({float(re.match(r"block-h([^_]+)_", n).group(1)) for n in names if n.startswith("block")})
    assert found == sorted(hs)
