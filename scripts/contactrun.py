"""Running bin/contact from the scripts, and reading what it leaves: the one
place that builds its command line (options, MPI ranks, each rank's peak
memory), runs it from the repository root (the environment for MPI as root, a
time limit, the JSON summary and the HDF5 output), parses its -log_view and
its TAO line, takes medians, and describes the machine and the git state of
the tree.

    run(args, ranks, ...)             one run, every file named by the caller: a Run
    run_case(args, tmp, name, ...)    one run, its summary and HDF5 in tmp under name
    run_checked(args, tmp, name, ...) run_case, or stop the script if it fails
    mesh_only(args)                   generate a scene's meshes (kept out of the timed runs)
    copy_program(tmp)                 a copy of bin/contact, so that a rebuild meanwhile does not mix versions
    parse_log_view(path)              per stage, its time and each event's count and time
    event_totals(log_view)            each event's count and time summed over the stages
    parse_tao_line(text)              the program's `TAO ...` line: reason, iterations, evaluations
    median(values)                    the median of the finite numbers
    write_results(out, res, lines)    a study's JSON at out and its markdown table beside it
    machine_info(), nproc(), load_average(), git(...), git_info(out)

Used by bench.py and its modules (bench_run.py, bench_analysis.py, ...),
bench_parallel.py, formulation_study.py, accuracy_study.py, stress_sweep.py,
oscillation_floor.py and readme_figures.py.
"""
import hashlib
import json
import math
import os
import platform
import re
import shutil
import signal
import statistics
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "bin", "contact")
# MPI as root, and more ranks than cores (mpiexec is also given --oversubscribe)
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
# each rank under GNU time, its peak resident set (kB) written to <prefix>.<rank>
PEAK_MEMORY = 'exec /usr/bin/time -f %M -o "$0.${OMPI_COMM_WORLD_RANK:-0}" "$@"'


class Run:
    """What one run left. cmd: the command line; returncode: the exit status
    (None when the time limit stopped it: timed_out); stdout, stderr (None
    when merged into stdout); wall: seconds, start to exit; summary: the JSON
    summary it wrote, or None; peaks: each rank's peak resident memory in MB
    (None for a rank whose figure was not read; [] when not measured); h5:
    the HDF5 output's path (run_case), or None."""

    def __init__(self, cmd, returncode, stdout, stderr, wall, summary, peaks, h5=None):
        self.cmd, self.returncode, self.stdout, self.stderr = cmd, returncode, stdout, stderr
        self.wall, self.summary, self.peaks, self.h5 = wall, summary, peaks, h5
        self.timed_out = returncode is None


def command(args, ranks=1, binary=None, peak_memory=None):
    """The command line of one run: binary (default bin/contact) with args;
    each rank under GNU time writing its peak memory to
    <peak_memory>.<rank> where peak_memory is given; under mpiexec from 2
    ranks."""
    cmd = [binary or BIN] + [str(a) for a in args]
    if peak_memory:
        cmd = ["sh", "-c", PEAK_MEMORY, peak_memory] + cmd
    if ranks > 1:
        cmd = ["mpiexec", "--oversubscribe", "-n", str(ranks)] + cmd
    return cmd


def remove(*paths):
    for f in paths:
        if f and os.path.isfile(f):
            os.remove(f)


def stop(p):
    """Ends a run's process group (SIGTERM, then SIGKILL 10 s later); its
    output so far."""
    try:
        os.killpg(p.pid, signal.SIGTERM)
        return p.communicate(timeout=10)
    except (subprocess.TimeoutExpired, ProcessLookupError):
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        return p.communicate()


def options_file(path):
    """{option: value} of a PETSc options file (comments dropped; the option
    without its '-'; a flag's value '')."""
    opts = {}
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("-"):
                key, _, val = line.partition(" ")
                opts[key[1:]] = val.strip()
    return opts


def read_summary(path):
    """The JSON summary at path, or None where there is none (or it does not
    parse)."""
    if not path or not os.path.exists(path):
        return None
    try:
        with open(path) as fh:
            return json.load(fh)
    except (OSError, ValueError):
        return None


def read_peaks(prefix, ranks):
    """Each rank's peak resident memory in MB from <prefix>.<rank> (the last
    line GNU time wrote, kB), None where it cannot be read; the files
    removed."""
    if not prefix:
        return []
    peaks = []
    for r in range(ranks):
        try:
            with open("%s.%d" % (prefix, r)) as fh:
                peaks.append(int([ln for ln in fh.read().split("\n") if ln.strip()][-1]) / 1024.0)
            os.remove("%s.%d" % (prefix, r))
        except (OSError, ValueError, IndexError):
            peaks.append(None)
    return peaks


def run(args, ranks=1, binary=None, summary=None, output=None, log_view=None, peak_memory=None, timeout=None,
        merge_stderr=False):
    """Runs the program from the repository root: args, then `-output
    output` (a path or "none"), `-summary summary` and `-log_view
    :log_view` where given, each of these files removed first so that none
    is left from an earlier run. Past timeout seconds the run's process group
    is ended and the Run says timed_out (an interrupt of the script ends it
    too). merge_stderr: stderr into stdout, in the order written. Returns a
    Run."""
    extra = (["-output", output] if output else []) + (["-summary", summary] if summary else []) \
        + (["-log_view", ":" + log_view] if log_view else [])
    remove(summary, log_view, output if output != "none" else None)
    cmd = command(list(args) + extra, ranks, binary, peak_memory)
    t = time.perf_counter()
    p = subprocess.Popen(cmd, cwd=ROOT, env=ENV, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT if merge_stderr else subprocess.PIPE, text=True,
                         start_new_session=True)
    try:
        out, err = p.communicate(timeout=timeout)
        rc = p.returncode
    except subprocess.TimeoutExpired:
        out, err = stop(p)
        rc = None
    except BaseException:
        stop(p)
        raise
    wall = time.perf_counter() - t
    return Run(cmd, rc, out, err, wall, read_summary(summary), read_peaks(peak_memory, ranks))


def run_case(args, tmp, name, ranks=1, h5=True, binary=None, timeout=None):
    """run() with its JSON summary at <tmp>/<name>.json and its HDF5 output
    at <tmp>/<name>.h5 (h5=False: -output none); the Run's h5 is that path
    (or None)."""
    out = os.path.join(tmp, name + ".h5") if h5 else "none"
    res = run(args, ranks, binary, summary=os.path.join(tmp, name + ".json"), output=out, timeout=timeout)
    res.h5 = out if h5 else None
    return res


def run_checked(args, tmp, name, ok=(0,), binary=None):
    """run_case on one rank, its HDF5 output written; an exit status not in
    ok stops the script with the command line and the end of its output.
    Returns the Run."""
    res = run_case(args, tmp, name, binary=binary)
    if res.returncode not in ok:
        raise SystemExit(f"{' '.join(res.cmd)} failed:\n{res.stdout[-2000:]}{res.stderr[-2000:]}")
    return res


def mesh_only(args, binary=None):
    """Generates a scene's meshes (args + -mesh_only; cached in build/meshes),
    so that no timed run includes Gmsh; the Run."""
    return run(list(args) + ["-mesh_only"], binary=binary)


def copy_program(tmp, binary=None):
    """A copy of the program (default bin/contact) in tmp, so that a rebuild
    during a study does not mix versions; its path."""
    path = os.path.join(tmp, "contact")
    shutil.copy2(binary or BIN, path)
    return path


def program_sha(path):
    """The first 12 hex digits of the program's sha256, naming the build a
    study ran."""
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()[:12]


def power(x):
    """A power of ten as the pages write it: 1e3, 2e6, 1e10, 1e-8."""
    return f"{x:.0e}".replace("e+0", "e").replace("e+", "e").replace("e-0", "e-")


def parse_log_view(path):
    """A -log_view file as {"stages": {stage: time}, "events": {stage:
    {event: (count, time)}}}: each stage's time from the Summary of Stages
    (the average over ranks, which the ranks share up to the barrier at the
    stage's end), each event's count and time (the max over ranks) per
    stage, from the first table only (the per-event one: it ends where the
    object summary starts). Empty where the file cannot be read."""
    out = {"stages": {}, "events": {}}
    try:
        with open(path) as fh:
            text = fh.read()
    except OSError:
        return out
    summary = text.partition("Summary of Stages")[2].partition("Event Stage")[0]
    for line in summary.split("\n"):
        m = re.match(r"\s*\d+:\s+(.+?):\s+(\S+)", line)
        if m:
            try:
                out["stages"][m.group(1)] = float(m.group(2))
            except ValueError:
                pass
    stage = None
    for line in text.split("Memory usage is given in bytes")[0].split("\n"):
        m = re.match(r"--- Event Stage \d+: (.+)", line)
        if m:
            stage = out["events"].setdefault(m.group(1).strip(), {})
            continue
        parts = line.split()
        if stage is None or len(parts) < 5:
            continue
        try:
            count, t = int(parts[1]), float(parts[3])
        except ValueError:
            continue
        c0, t0 = stage.get(parts[0], (0, 0.0))
        stage[parts[0]] = (c0 + count, t0 + t)
    return out


def event_totals(lv):
    """{event: (count, time)} of a parsed -log_view, summed over the
    stages."""
    out = {}
    for events in lv["events"].values():
        for name, (count, t) in events.items():
            c0, t0 = out.get(name, (0, 0.0))
            out[name] = (c0 + count, t0 + t)
    return out


TAO_LINE = re.compile(r"TAO (\S+): (\S+) after (\d+) iterations, (\d+) energy evaluations, (\d+) Hessian")


def parse_tao_line(text):
    """The program's last `TAO <type>: <reason> after N iterations, M energy
    evaluations, K Hessian evaluations` line as {type, reason, iterations,
    evals, hessians}, or None."""
    m = None
    for m in TAO_LINE.finditer(text or ""):
        pass
    if not m:
        return None
    return {"type": m.group(1), "reason": m.group(2), "iterations": int(m.group(3)),
            "evals": int(m.group(4)), "hessians": int(m.group(5))}


def finite(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def median(values):
    """The median of the finite numbers among values; NaN where there are
    none."""
    v = [x for x in values if finite(x)]
    return statistics.median(v) if v else float("nan")


def write_results(out, res, lines):
    """A study's results: res as JSON at out, lines (a markdown table and its
    caption) at out with the ending .md, printed too."""
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as fp:
        json.dump(res, fp, indent=1)
    md = os.path.splitext(out)[0] + ".md"
    with open(md, "w") as fp:
        fp.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"Wrote {out} and {md}")


def nproc():
    """The number of cores this process may use (nproc)."""
    return subprocess.run(["nproc"], capture_output=True, text=True).stdout.strip()


def load_average():
    """The machine's load average over the last minute."""
    return os.getloadavg()[0]


def machine_info():
    """{nproc, cpu, mem, blas, petsc, os}: what the figures of a benchmark
    were measured on."""
    info = {"nproc": nproc()}
    cpu = ""
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    info["cpu"] = cpu
    try:
        with open("/proc/meminfo") as fh:
            info["mem"] = "%.1f GB" % (int(fh.readline().split()[1]) / 1024 ** 2)
    except (OSError, ValueError, IndexError):
        info["mem"] = "?"
    p = subprocess.run(["update-alternatives", "--display", "libblas.so.3-x86_64-linux-gnu"],
                       capture_output=True, text=True)
    blas = [ln.strip() for ln in p.stdout.split("\n") if "currently points" in ln]
    info["blas"] = blas[0] if blas else (p.stdout.strip().split("\n")[0] if p.stdout else "unknown")
    p = subprocess.run(["pkg-config", "--modversion", "petsc"], capture_output=True, text=True)
    info["petsc"] = p.stdout.strip() or "?"
    info["os"] = platform.platform()
    return info


def git(*args):
    """The output of a git command in the repository, stripped."""
    return subprocess.run(["git"] + list(args), cwd=ROOT, capture_output=True, text=True).stdout.strip()


def git_info(out=None):
    """HEAD and whether the tree differs from it, the output directory (the
    study's own files, rewritten by this run) left out."""
    skip = []
    if out and os.path.abspath(out).startswith(ROOT + os.sep):
        skip = ["--", ".", ":(exclude)" + os.path.relpath(os.path.abspath(out), ROOT)]
    dirty = git("status", "--short", "--untracked-files=no", *skip)
    return git("rev-parse", "--short", "HEAD") + (" (with uncommitted changes)" if dirty else "")
