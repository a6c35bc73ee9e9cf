"""The BLAS kernel (src/driver/blaskernel.c): OpenBLAS falls back to its
Prescott kernels on a CPU newer than itself; the program then starts again on
the best kernel the CPU's features allow, says which in the JSON and in
-log_view's header line, keeps a kernel the user sets in OPENBLAS_CORETYPE,
and takes -blas_kernel NAME (auto by default). The fallback is made here
with OPENBLAS_CORETYPE=Prescott and -blas_kernel auto, which asks the
program to choose from the CPU whatever is loaded."""
import json
import subprocess

import pytest

from conftest import BIN, ENV, ROOT, run_contact

SCENE = ["-options_file", "meshes/hertz/hertz.opts", "-mesh_size", "0.2"]


def cpu_best():
    """The best kernel the CPU runs, from /proc/cpuinfo's flags (as the
    program reads them from CPUID), by the program's table."""
    flags = set()
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("flags"):
                flags = set(line.split(":", 1)[1].split())
                break
    if {"avx512f", "avx512cd", "avx512bw", "avx512dq", "avx512vl"} <= flags:
        return "SkylakeX"
    if {"avx2", "fma"} <= flags:
        return "Haswell"
    if "avx" in flags:
        return "Sandybridge"
    if "sse4_2" in flags:
        return "Nehalem"
    return "Prescott"


def kernel_of(r):
    return r.summary["blas_kernel"]


def test_fallback_replaced_by_cpu_best(tmp_path):
    """Prescott loaded (OPENBLAS_CORETYPE) and -blas_kernel auto: the program
    runs on the CPU's best kernel, names the one it replaced, and prints it
    in -log_view's header line; on 2 ranks too."""
    best = cpu_best()
    for ranks in (1, 2):
        r = run_contact(SCENE + ["-blas_kernel", "auto", "-log_view"], tmp_path, ranks=ranks, name=f"auto{ranks}",
                        env={"OPENBLAS_CORETYPE": "Prescott"})
        k = kernel_of(r)
        print(ranks, k)
        assert k["name"] == best and k["source"] == "cpu" and k["replaced"] == "Prescott", k
        assert f"BLAS: OpenBLAS kernel {best} (the CPU's features, in place of Prescott)" in r.stdout
        assert r.stdout.index("BLAS: OpenBLAS kernel") < r.stdout.index("Performance Summary")


def test_user_kernel_kept(tmp_path):
    """OPENBLAS_CORETYPE set by the user is the kernel run (not replaced)."""
    r = run_contact(SCENE, tmp_path, env={"OPENBLAS_CORETYPE": "Nehalem"})
    assert kernel_of(r) == {"name": "Nehalem", "source": "OPENBLAS_CORETYPE", "replaced": None}


def test_default_not_below_cpu(tmp_path):
    """Without settings the kernel is OpenBLAS's choice or the CPU's best,
    never one of a lower family than the CPU's features allow."""
    order = ["Prescott", "Core2", "Penryn", "Nehalem", "Sandybridge", "Haswell", "Zen", "SkylakeX", "Cooperlake"]
    rank = {"Prescott": 1, "Core2": 1, "Penryn": 1, "Nehalem": 2, "Sandybridge": 3, "Haswell": 4, "Zen": 4,
            "SkylakeX": 5, "Cooperlake": 5}
    env = {k: v for k, v in ENV.items() if k != "OPENBLAS_CORETYPE"}
    proc = subprocess.run([str(BIN)] + SCENE + ["-output", "none", "-summary", str(tmp_path / "s.json")],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    k = json.loads((tmp_path / "s.json").read_text())["blas_kernel"]
    print(k)
    assert k["name"] in order and rank[k["name"]] >= rank[cpu_best()], k


def test_option_names_kernel(tmp_path):
    """-blas_kernel Nehalem overrides OPENBLAS_CORETYPE, and the answer is
    the machine's own to what the stop guarantees (a tight stop)."""
    tight = SCENE + ["-tao_gttol", "1e-12"]
    a = run_contact(tight + ["-blas_kernel", "Nehalem"], tmp_path, name="n", env={"OPENBLAS_CORETYPE": "Haswell"})
    b = run_contact(tight, tmp_path, name="d")
    assert kernel_of(a)["name"] == "Nehalem" and kernel_of(a)["source"] == "-blas_kernel"
    assert kernel_of(a)["replaced"] == "Haswell"
    dP = abs(a.summary["contact_force"] / b.summary["contact_force"] - 1)
    print(f"P apart {dP:.2e}")
    assert dP <= 1e-10


@pytest.mark.parametrize("value,needle", [("Bogus", "-blas_kernel Bogus: not a kernel"),
                                          ("SapphireRapids", "-blas_kernel SapphireRapids: not a kernel")])
def test_bad_kernel(value, needle, tmp_path):
    """An unknown kernel is one line naming it and the known ones, status 1,
    nothing written."""
    r = run_contact(SCENE + ["-blas_kernel", value], tmp_path, check=False)
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    assert r.returncode == 1 and len(lines) == 1 and needle in lines[0] and "SkylakeX" in lines[0], r.stderr
    assert not r.summary_path.exists() and not r.output_path.exists()


def test_help_lists_it():
    proc = subprocess.run([str(BIN), "-help"], cwd=ROOT, env=ENV, capture_output=True, text=True, timeout=60)
    assert "-blas_kernel <now auto" in proc.stdout
