#!/bin/sh
# Install what `contact` needs on Debian 12, skipping what is already there.
# Debian: PETSc (with TAO, HDF5, MUMPS), METIS, Gmsh, Open MPI, HDF5, pkg-config,
# ParaView, xvfb, GetFEM's Python module.
# Python: h5py, numpy, matplotlib, pytest, pytest-xdist (pip, or Debian packages as
# a fallback).
set -eu

# libopenblas0-serial replaces the reference BLAS under PETSc's factorisations
# (CHOLMOD and MUMPS factor about twice as fast with it; serial, to share the
# cores with MPI ranks rather than with BLAS threads).
# ParaView (pvpython is in python3-paraview) and xvfb-run (with xauth): the test
# that opens the XDMF output with ParaView's readers, headless.
# libmumps-dev, liblapack-dev, libblas-dev: the substructured Newton step calls MUMPS
# (condensation and expansion, which PETSc does not expose) and LAPACK directly.
# python3-getfem (about 30 MB with its libraries, for the system's /usr/bin/python3):
# the independent code tests/test_squeeze.py compares the rubber squeeze with.
DEB_PKGS="petsc-dev libmetis-dev libmumps-dev liblapack-dev libblas-dev gmsh openmpi-bin libhdf5-openmpi-dev pkg-config make gcc libopenblas0-serial paraview python3-paraview xvfb xauth python3-getfem"
# Each Python module as module:pip-name where the names differ (pytest-xdist,
# which runs `make test` on every core, is imported as xdist; Debian ships it as
# python3-pytest-xdist).
PY_MODS="h5py numpy matplotlib pytest xdist:pytest-xdist"

missing=""
for p in $DEB_PKGS; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing="$missing $p"
  fi
done
if [ -n "$missing" ]; then
  echo "install-deps: installing Debian packages:$missing"
  SUDO=""
  if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends $missing
fi

PY="${PYTHON:-python3}"
pymissing=""
for spec in $PY_MODS; do
  if ! "$PY" -c "import ${spec%%:*}" >/dev/null 2>&1; then pymissing="$pymissing ${spec#*:}"; fi
done
if [ -n "$pymissing" ]; then
  echo "install-deps: installing Python modules:$pymissing"
  if ! "$PY" -m pip install -q $pymissing 2>/dev/null; then
    if ! "$PY" -m pip install -q --break-system-packages $pymissing 2>/dev/null; then
      debs=""
      for m in $pymissing; do debs="$debs python3-$m"; done
      SUDO=""
      if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
      $SUDO apt-get install -y -qq --no-install-recommends $debs
    fi
  fi
fi
for spec in $PY_MODS; do
  "$PY" -c "import ${spec%%:*}" || { echo "install-deps: Python module ${spec%%:*} (${spec#*:}) still missing" >&2; exit 1; }
done
