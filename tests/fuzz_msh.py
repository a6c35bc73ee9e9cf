"""Fuzz test of the mesh-reading path: corrupted Gmsh files given to bin/contact.

Seed meshes of the hertz scene are made at run time (MSH 2.2 by `bin/contact
-mesh_only`, MSH 4.1 by Gmsh), for both bodies (Tri6 indenter, Quad9 block).
Each case mutates one seed with a fixed random generator (byte flips,
truncation, deleted, duplicated or swapped lines, numbers replaced by huge,
negative, NaN, inf or garbage values, altered counts, removed or mangled
section markers, node references out of range, changed element types,
inserted random bytes, empty files, binary junk, moved nodes, ...) and runs

    bin/contact -options_file meshes/hertz/hertz.opts -<body>_mesh MUTATED
                -<other>_mesh SEED -output none -summary none -tao_type nls ...

with a timeout. A case passes if the program exits 0, or exits 1 with exactly
one non-empty line on stderr starting with "contact: error:", or exits 2 (a
valid but badly shaped mesh) with the line "contact: the solve did not
converge ..." after nothing but "contact: warning: ..." lines. A signal, a
traceback, several lines, any other status or a timeout is a failure; the
failing inputs are saved for reproduction.

    python3 tests/fuzz_msh.py --cases 500 --seed 1 --jobs 2 [--bin PATH]
"""
import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BIN = ROOT / "bin" / "contact"
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
SCENE = "meshes/hertz/hertz.opts"
MESH_SIZE = 0.3
SOLVER = ["-tao_type", "nls", "-tao_nls_ksp_type", "preonly", "-tao_nls_pc_type", "cholesky", "-tao_max_it", "50"]

# Replacement values for one number: too large for an int, negative, NaN, inf,
# overflowing, not a number, a real where an int is expected, empty.
BAD_VALUES = ["2147483648", "-2147483649", "9223372036854775808", "99999999999999999999", "1e18", "100000001",
              "-1", "0", "-0", "1", "2", "7", "65536", "nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e999",
              "-1e999", "1e-999", "1e300", "-1e300", "1e30", "abc", "1.2.3", "0x", "0x10", "--1", "1e", "+", "",
              "1.5", "1,5", "\x01", "4294967297", "00000000000000000000000000000001", "3.0"]
ELEMENT_TYPES = [-1, 0, 1, 2, 3, 4, 5, 8, 9, 10, 11, 15, 16, 17, 20, 21, 36, 46, 51, 66, 67, 99, 137, 255, 2 ** 31]


def opts_file_values(path):
    """Options of a PETSc options file as {name: value}."""
    values = {}
    for line in Path(path).read_text().splitlines():
        parts = line.split("#", 1)[0].split()
        if parts and parts[0].startswith("-"):
            values[parts[0][1:]] = parts[1] if len(parts) > 1 else ""
    return values


def make_seeds(workdir, bin_path=BIN):
    """Seed meshes {(body, fmt): path} of the hertz scene at mesh size MESH_SIZE:
    MSH 2.2 from bin/contact -mesh_only, MSH 4.1 from Gmsh with the same .geo."""
    workdir = Path(workdir)
    d22 = workdir / "seeds22"
    subprocess.run([str(bin_path), "-options_file", SCENE, "-mesh_only", "-mesh_size", str(MESH_SIZE), "-mesh_dir", str(d22)],
                   cwd=ROOT, env=ENV, check=True, capture_output=True, timeout=300)
    opts = opts_file_values(ROOT / SCENE)
    seeds = {}
    for body in opts["bodies"].split(","):
        found = sorted(d22.glob(f"{body}-*.msh"))
        assert len(found) == 1, f"expected one {body} mesh in {d22}, found {found}"
        seeds[(body, "2.2")] = found[0]
        wrapper = workdir / f"{body}41.geo"
        geo = (ROOT / SCENE).parent / opts[body + "_geo"]  # relative to the options file
        wrapper.write_text(f'Include "{geo}";\nMesh.MshFileVersion = 4.1;\n')
        cmd = ["gmsh", "-2", "-v", "0", str(wrapper), "-setnumber", "h", str(MESH_SIZE), "-o", str(workdir / f"{body}41.msh")]
        for p in filter(None, opts.get(body + "_geo_params", "").split(",")):
            name, value = p.split("=")
            cmd += ["-setnumber", name, value]
        subprocess.run(cmd, check=True, capture_output=True, timeout=300)
        seeds[(body, "4.1")] = workdir / f"{body}41.msh"
    return seeds


@dataclass
class Layout:
    """Where the fields of a valid seed are: lists of (line index, token index)."""
    fmt: str
    counts: list = field(default_factory=list)     # counts and block sizes
    node_ids: list = field(default_factory=list)
    coords: list = field(default_factory=list)     # the x of each node; y follows
    node_refs: list = field(default_factory=list)  # (line, first node token) of each element
    types: list = field(default_factory=list)
    ntags: list = field(default_factory=list)
    markers: list = field(default_factory=list)    # line indices
    names: list = field(default_factory=list)      # $PhysicalNames entries
    max_node: int = 0


def analyse(data):
    """The Layout of a valid MSH 2.2 or 4.1 ASCII file."""
    lines = data.decode().split("\n")
    tok = [l.split() for l in lines]
    fmt = tok[1][0]
    lay = Layout(fmt)
    lay.markers = [i for i, l in enumerate(lines) if l.startswith("$")]
    sec = {lines[i]: i for i in lay.markers}
    p = sec.get("$PhysicalNames")
    if p is not None:
        lay.counts.append((p + 1, 0))
        lay.names = list(range(p + 2, p + 2 + int(tok[p + 1][0])))
    n, e = sec["$Nodes"], sec["$Elements"]
    if fmt == "2.2":
        lay.counts += [(n + 1, 0), (e + 1, 0)]
        for i in range(n + 2, n + 2 + int(tok[n + 1][0])):
            lay.node_ids.append((i, 0))
            lay.coords.append((i, 1))
        for i in range(e + 2, e + 2 + int(tok[e + 1][0])):
            lay.types.append((i, 1))
            lay.ntags.append((i, 2))
            lay.node_refs.append((i, 3 + int(tok[i][2])))
    else:
        lay.counts += [(n + 1, k) for k in range(4)] + [(e + 1, k) for k in range(4)]
        i = n + 2
        for _ in range(int(tok[n + 1][0])):
            nb = int(tok[i][3])
            lay.counts.append((i, 3))
            lay.node_ids += [(i + 1 + k, 0) for k in range(nb)]
            lay.coords += [(i + 1 + nb + k, 0) for k in range(nb)]
            i += 1 + 2 * nb
        i = e + 2
        for _ in range(int(tok[e + 1][0])):
            nb = int(tok[i][3])
            lay.counts.append((i, 3))
            lay.types.append((i, 2))
            lay.node_refs += [(i + 1 + k, 1) for k in range(nb)]
            i += 1 + nb
    lay.max_node = max(int(tok[i][j]) for i, j in lay.node_ids)
    return lay


def _set_token(lines, i, j, value):
    """Replaces token j of line i (a list of bytes lines); returns the old token."""
    t = lines[i].split()
    old = t[j].decode(errors="replace")
    t[j] = value.encode() if isinstance(value, str) else value
    lines[i] = b" ".join(t)
    return old


def m_flip_bytes(rng, data, lay):
    b = bytearray(data)
    n = rng.randint(1, 8)
    for _ in range(n):
        b[rng.randrange(len(b))] ^= 1 << rng.randrange(8)
    return bytes(b), f"{n} bit flips"


def m_truncate(rng, data, lay):
    k = rng.randrange(len(data))
    return data[:k], f"truncated at byte {k} of {len(data)}"


def m_delete_lines(rng, data, lay):
    lines = data.split(b"\n")
    i, n = rng.randrange(len(lines)), rng.randint(1, 3)
    del lines[i:i + n]
    return b"\n".join(lines), f"deleted lines {i + 1}-{i + n}"


def m_duplicate_line(rng, data, lay):
    lines = data.split(b"\n")
    i = rng.randrange(len(lines))
    lines.insert(i, lines[i])
    return b"\n".join(lines), f"duplicated line {i + 1}"


def m_swap_lines(rng, data, lay):
    lines = data.split(b"\n")
    i = rng.randrange(len(lines))
    j = min(i + 1, len(lines) - 1) if rng.random() < 0.5 else rng.randrange(len(lines))
    lines[i], lines[j] = lines[j], lines[i]
    return b"\n".join(lines), f"swapped lines {i + 1} and {j + 1}"


def m_replace_number(rng, data, lay):
    lines = data.split(b"\n")
    cands = [i for i, l in enumerate(lines) if l.split() and not l.startswith(b"$")]
    i = rng.choice(cands)
    j = rng.randrange(len(lines[i].split()))
    v = rng.choice(BAD_VALUES)
    old = _set_token(lines, i, j, v)
    return b"\n".join(lines), f"line {i + 1} token {j + 1}: {old!r} -> {v!r}"


def m_alter_count(rng, data, lay):
    lines = data.split(b"\n")
    i, j = rng.choice(lay.counts)
    old = int(lines[i].split()[j])
    v = str(rng.choice([old + 1, old - 1, old + rng.randint(2, 1000), max(old - rng.randint(2, 50), 0), 0, -old,
                        old * 10, 2 ** 31, 10 ** 8, 10 ** 8 + 1]))
    _set_token(lines, i, j, v)
    return b"\n".join(lines), f"count at line {i + 1}: {old} -> {v}"


def m_remove_marker(rng, data, lay):
    lines = data.split(b"\n")
    i = rng.choice(lay.markers)
    old = lines[i].decode()
    del lines[i]
    return b"\n".join(lines), f"removed {old} (line {i + 1})"


def m_mangle_marker(rng, data, lay):
    lines = data.split(b"\n")
    i = rng.choice(lay.markers)
    old = lines[i]
    new = rng.choice([old[:-1], old.lower(), old + b" x", b" " + old, old.replace(b"$", b""), b"$" + old,
                      b"$Comments", b"$EndComments", b"$Periodic", b"$Nodes", b"$Elements", b"$EndElements"])
    lines[i] = new
    return b"\n".join(lines), f"marker line {i + 1}: {old.decode()!r} -> {new.decode()!r}"


def m_bad_node_ref(rng, data, lay):
    lines = data.split(b"\n")
    i, j0 = rng.choice(lay.node_refs)
    j = rng.randrange(j0, len(lines[i].split()))
    v = str(rng.choice([0, -1, lay.max_node + 1, lay.max_node + rng.randint(2, 10 ** 6), 2 ** 31 - 1, 10 ** 8 + 1, 2 ** 32 + 1]))
    old = _set_token(lines, i, j, v)
    return b"\n".join(lines), f"element line {i + 1}: node {old} -> {v}"


def m_existing_node_ref(rng, data, lay):
    lines = data.split(b"\n")
    i, j0 = rng.choice(lay.node_refs)
    j = rng.randrange(j0, len(lines[i].split()))
    v = str(rng.randint(1, lay.max_node))
    old = _set_token(lines, i, j, v)
    return b"\n".join(lines), f"element line {i + 1}: node {old} -> existing node {v}"


def m_change_type(rng, data, lay):
    lines = data.split(b"\n")
    i, j = rng.choice(lay.types)
    v = str(rng.choice(ELEMENT_TYPES))
    old = _set_token(lines, i, j, v)
    return b"\n".join(lines), f"element type at line {i + 1}: {old} -> {v}"


def m_change_ntags(rng, data, lay):
    if not lay.ntags:
        return m_change_type(rng, data, lay)
    lines = data.split(b"\n")
    i, j = rng.choice(lay.ntags)
    v = str(rng.choice([0, 1, 3, 4, 17, 65, 1000, -1, 2 ** 31]))
    old = _set_token(lines, i, j, v)
    return b"\n".join(lines), f"number of tags at line {i + 1}: {old} -> {v}"


def m_insert_bytes(rng, data, lay):
    k = rng.randrange(len(data) + 1)
    junk = bytes(rng.randrange(256) for _ in range(rng.randint(1, 64)))
    return data[:k] + junk + data[k:], f"{len(junk)} random bytes inserted at byte {k}"


def m_empty(rng, data, lay):
    return rng.choice([b"", b"\n", b"   \n\n", b"$MeshFormat\n", b"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"]), "empty or header-only file"


def m_binary_junk(rng, data, lay):
    n = rng.choice([1, 100, 5000, 100000])
    junk = bytes(rng.randrange(256) for _ in range(n))
    if rng.random() < 0.5:
        return data[:data.index(b"$EndMeshFormat")].replace(b" 0 8", b" 1 8") + b"$EndMeshFormat\n" + junk, f"binary header and {n} random bytes"
    return junk, f"{n} random bytes"


def m_move_node(rng, data, lay):
    lines = data.split(b"\n")
    i, j = rng.choice(lay.coords)
    j += rng.randrange(2)
    x = float(lines[i].split()[j])
    v = rng.choice([x + rng.uniform(-2, 2), -x, x * 1e6, 1e10, 0.0, x + 1e-9])
    old = _set_token(lines, i, j, repr(v))
    return b"\n".join(lines), f"coordinate at line {i + 1}: {old} -> {v!r}"


def m_transform(rng, data, lay):
    """A valid file: every node scaled, shifted, stretched or mirrored."""
    lines = data.split(b"\n")
    name, f = rng.choice([("scaled by 1e-12", lambda x, y: (x * 1e-12, y * 1e-12)), ("scaled by 1e12", lambda x, y: (x * 1e12, y * 1e12)),
                          ("shifted by 1e6", lambda x, y: (x + 1e6, y)), ("shifted by 1e15", lambda x, y: (x + 1e15, y)),
                          ("stretched by 1e8 in x", lambda x, y: (x * 1e8, y)), ("squashed by 1e-12 in y", lambda x, y: (x, y * 1e-12)),
                          ("mirrored", lambda x, y: (-x, y)), ("rotated by 90 degrees", lambda x, y: (-y, x))])
    for i, j in lay.coords:
        t = lines[i].split()
        t[j], t[j + 1] = (repr(v).encode() for v in f(float(t[j]), float(t[j + 1])))
        lines[i] = b" ".join(t)
    return b"\n".join(lines), f"every node {name}"


def m_swap_element_nodes(rng, data, lay):
    lines = data.split(b"\n")
    i, j0 = rng.choice(lay.node_refs)
    t = lines[i].split()
    if len(t) - j0 < 2:
        return m_existing_node_ref(rng, data, lay)
    a, b = rng.sample(range(j0, len(t)), 2)
    t[a], t[b] = t[b], t[a]
    lines[i] = b" ".join(t)
    return b"\n".join(lines), f"element line {i + 1}: nodes {a - j0 + 1} and {b - j0 + 1} swapped"


def m_duplicate_node_id(rng, data, lay):
    lines = data.split(b"\n")
    (i, j), (k, l) = rng.sample(lay.node_ids, 2)
    v = lines[k].split()[l].decode()
    old = _set_token(lines, i, j, v)
    return b"\n".join(lines), f"node tag at line {i + 1}: {old} -> {v} (the tag of line {k + 1})"


def m_mangle_name(rng, data, lay):
    if not lay.names:
        return m_replace_number(rng, data, lay)
    lines = data.split(b"\n")
    i = rng.choice(lay.names)
    old = lines[i]
    d, t, name = old.split(b" ", 2)
    new = rng.choice([d + b" " + t + b"  " + name, d + b" " + t + b" " + name[:-1], d + b" " + t + b" " + name[1:],
                      d + b" " + t + b' "' + b"x" * 300 + b'"', d + b" " + t + b' ""', d + b" " + t,
                      d + b" " + t + b' "a\x07b"', b"9 " + t + b" " + name, d + b" 0 " + name, d + b" " + t + b" " + name + b" extra",
                      d + b" " + t + b' "a:b"', d + b" " + t + b"\t" + name])
    lines[i] = new
    return b"\n".join(lines), f"physical name line {i + 1}: {old!r} -> {new!r}"


def m_long_line(rng, data, lay):
    lines = data.split(b"\n")
    i = rng.randrange(len(lines))
    n = rng.choice([4096, 5000, 100000])
    lines.insert(i, rng.choice([b"1" * n, b"$" + b"A" * n, b"1 " * (n // 2)]))
    return b"\n".join(lines), f"{n}-character line inserted at line {i + 1}"


def m_line_endings(rng, data, lay):
    k = rng.randrange(3)
    if k == 0:
        return data.replace(b"\n", b"\r\n"), "CRLF line endings"
    if k == 1:
        return data.rstrip(b"\n"), "no final newline"
    return data.replace(b"\n", b"\n\n"), "blank line after every line"


MUTATORS = [m_flip_bytes, m_truncate, m_delete_lines, m_duplicate_line, m_swap_lines, m_replace_number, m_alter_count,
            m_remove_marker, m_mangle_marker, m_bad_node_ref, m_existing_node_ref, m_change_type, m_change_ntags,
            m_insert_bytes, m_empty, m_binary_junk, m_move_node, m_transform, m_swap_element_nodes, m_duplicate_node_id, m_mangle_name,
            m_long_line, m_line_endings]
# mutations that keep the layout of the seed valid enough for a second one
GENERIC = [m_flip_bytes, m_truncate, m_delete_lines, m_duplicate_line, m_swap_lines, m_replace_number, m_insert_bytes]


def mutate(rng, data, lay):
    """One mutated file and its description; one case in eight combines two or three mutations."""
    if rng.random() < 0.125:
        f = rng.choice([m for m in MUTATORS if m not in (m_empty, m_binary_junk)])
        data, desc = f(rng, data, lay)
        descs = [f.__name__[2:] + ": " + desc]
        for _ in range(rng.randint(1, 2)):
            if not data:
                break
            g = rng.choice(GENERIC)
            data, desc = g(rng, data, lay)
            descs.append(g.__name__[2:] + ": " + desc)
        return data, "combo(" + "; ".join(descs) + ")", "combo"
    f = rng.choice(MUTATORS)
    data, desc = f(rng, data, lay)
    return data, f.__name__[2:] + ": " + desc, f.__name__[2:]


@dataclass
class Case:
    index: int
    body: str
    fmt: str
    kind: str
    desc: str
    path: Path
    verdict: str = ""
    detail: str = ""
    returncode: int = 0
    stderr: str = ""
    seconds: float = 0.0
    command: str = ""
    saved: Path = None


def strip_mpiexec(stderr):
    """stderr without Open MPI's notices (blocks between lines of dashes)."""
    out, inside = [], False
    for line in stderr.split("\n"):
        if line.startswith("-----") and not line.strip("-"):
            inside = not inside
        elif not inside:
            out.append(line)
    return "\n".join(out)


def classify(returncode, stderr, timed_out):
    """(verdict, detail): verdict "accepted", "rejected", "not converged" or "FAIL"."""
    if timed_out:
        return "FAIL", "timeout (hang)"
    lines = [l for l in stderr.split("\n") if l.strip()]
    if returncode < 0 or returncode >= 128:
        return "FAIL", f"killed by a signal (status {returncode})"
    if returncode == 0:
        return "accepted", ""
    if (returncode == 2 and lines and lines[-1].startswith("contact: the solve did not converge")
            and all(l.startswith("contact: warning:") for l in lines[:-1])):
        return "not converged", "; ".join(lines)
    if len(lines) != 1:
        return "FAIL", f"exit {returncode} with {len(lines)} lines on stderr"
    if returncode == 1 and lines[0].startswith("contact: error:"):
        return "rejected", lines[0]
    return "FAIL", f"exit {returncode}: {lines[0]}"


def run_case(case, seeds, bin_path, timeout, ranks):
    other = [b for (b, f) in seeds if b != case.body and f == case.fmt]
    cmd = [str(bin_path), "-options_file", SCENE, "-mesh_size", str(MESH_SIZE), f"-{case.body}_mesh", str(case.path)]
    for b in other:
        cmd += [f"-{b}_mesh", str(seeds[(b, case.fmt)])]
    cmd += ["-output", "none", "-summary", "none"] + SOLVER
    if ranks > 1:
        cmd = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + cmd
    t0 = time.time()
    try:
        proc = subprocess.run(cmd, cwd=ROOT, env=ENV, capture_output=True, timeout=timeout)
        case.returncode, case.stderr, timed_out = proc.returncode, proc.stderr.decode(errors="replace"), False
    except subprocess.TimeoutExpired as exc:
        case.returncode, timed_out = -1, True
        case.stderr = (exc.stderr or b"").decode(errors="replace")
    case.seconds = time.time() - t0
    case.verdict, case.detail = classify(case.returncode, strip_mpiexec(case.stderr) if ranks > 1 else case.stderr, timed_out)
    case.command = " ".join(cmd)
    return case


@dataclass
class FuzzResult:
    cases: list
    seconds: float

    @property
    def failures(self):
        return [c for c in self.cases if c.verdict == "FAIL"]

    def summary(self):
        out = []
        verdicts = ["accepted", "rejected", "not converged", "FAIL"]
        for v in verdicts:
            out.append(f"  {v:14s} {sum(c.verdict == v for c in self.cases):5d}")
        out.append("  by mutation:    " + "  ".join(f"{v[:8]:>8s}" for v in verdicts))
        for kind in sorted({c.kind for c in self.cases}):
            sel = [c for c in self.cases if c.kind == kind]
            out.append(f"    {kind:20s}" + "  ".join(f"{sum(c.verdict == v for c in sel):8d}" for v in verdicts))
        return "\n".join(out)


def run_fuzz(cases=500, seed=1, jobs=2, bin_path=BIN, out_dir=None, timeout=20.0, ranks=1, log=print, verbose=False):
    """Runs cases mutated inputs; failing inputs are copied to out_dir (default
    build/fuzz-failures) with a .txt beside each that gives the command and stderr."""
    bin_path = Path(bin_path).resolve()
    out_dir = Path(out_dir) if out_dir else ROOT / "build" / "fuzz-failures"
    t0 = time.time()
    with tempfile.TemporaryDirectory(prefix="fuzz_msh") as tmp:
        tmp = Path(tmp)
        seeds = make_seeds(tmp, bin_path)
        layouts = {k: analyse(p.read_bytes()) for k, p in seeds.items()}
        for key in sorted(seeds):
            c = run_case(Case(-1, key[0], key[1], "seed", "unmodified seed", seeds[key]), seeds, bin_path, timeout, ranks)
            if c.verdict != "accepted":
                raise RuntimeError(f"seed {seeds[key]} is not accepted: {c.detail}\n{c.stderr[-2000:]}")
        rng = random.Random(seed)
        keys = sorted(seeds)
        todo = []
        for i in range(cases):
            body, fmt = rng.choice(keys)
            data, desc, kind = mutate(rng, seeds[(body, fmt)].read_bytes(), layouts[(body, fmt)])
            path = tmp / f"case-{i:04d}.msh"
            path.write_bytes(data)
            todo.append(Case(i, body, fmt, kind, desc, path))
        with ThreadPoolExecutor(max_workers=jobs) as pool:
            done = list(pool.map(lambda c: run_case(c, seeds, bin_path, timeout, ranks), todo))
        if verbose:
            for c in done:
                log(f"case {c.index:4d} {c.body}/{c.fmt} {c.verdict:13s} {c.seconds:5.1f}s [{c.desc}] {c.detail}")
        fails = [c for c in done if c.verdict == "FAIL"]
        if fails:
            out_dir.mkdir(parents=True, exist_ok=True)
            for c in fails:
                keep = out_dir / f"seed{seed}-case-{c.index:04d}-{c.body}.msh"
                shutil.copy(c.path, keep)
                command = c.command.replace(str(c.path), str(keep))
                for (b, f), p in seeds.items():
                    if b != c.body and f == c.fmt:
                        shutil.copy(p, out_dir / f"{b}-{f}.msh")
                        command = command.replace(str(p), str(out_dir / f"{b}-{f}.msh"))
                keep.with_suffix(".txt").write_text(f"{c.desc}\n{c.detail}\n(cd {ROOT} && {command})\n{c.stderr}")
                c.saved = keep
    return FuzzResult(done, time.time() - t0)


def report(res, seed, jobs, log=print):
    log(f"fuzz_msh: {len(res.cases)} cases, seed {seed}, {jobs} jobs, {res.seconds:.1f} s")
    log(res.summary())
    for c in res.failures:
        log(f"FAIL case {c.index} ({c.body}, MSH {c.fmt}) [{c.desc}]: {c.detail}; input saved to {c.saved}")
        for line in c.stderr.strip().split("\n")[:12]:
            log("    | " + line)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cases", type=int, default=500)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--bin", default=str(BIN), help="the contact binary (default: bin/contact)")
    ap.add_argument("--timeout", type=float, default=20.0, help="seconds per case")
    ap.add_argument("--ranks", type=int, default=1, help="MPI ranks per case")
    ap.add_argument("--out", default=None, help="directory for failing inputs (default: build/fuzz-failures)")
    ap.add_argument("--verbose", action="store_true", help="print every case")
    args = ap.parse_args(argv)
    res = run_fuzz(args.cases, args.seed, args.jobs, args.bin, args.out, args.timeout, args.ranks, verbose=args.verbose)
    report(res, args.seed, args.jobs)
    return 1 if res.failures else 0


if __name__ == "__main__":
    sys.exit(main())
