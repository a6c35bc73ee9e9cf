# contact: 2D frictionless penalty contact with PETSc/TAO.
#   make run    install what is missing, build, mesh, solve the hertz scene
#   make test   the same set-up, then the test suite
SHELL := /bin/bash
CC      = mpicc
# recursive (=) so that pkg-config runs after install-deps has put PETSc in place
PETSC_CFLAGS = $(shell pkg-config --cflags petsc hdf5-openmpi)
PETSC_LIBS   = $(shell pkg-config --libs petsc hdf5-openmpi)
CFLAGS  = -O2 -g -std=gnu11 -Wall -Wextra -Werror -Iinclude $(PETSC_CFLAGS)
LDLIBS  = $(PETSC_LIBS) -ldmumps -lscalapack-openmpi -llapack -lblas -lmetis -lm
SRCS    = $(wildcard src/*.c src/*/*.c)
OBJS    = $(patsubst src/%.c,build/obj/%.o,$(SRCS))
DEPS_STAMP = build/.deps-installed
PYTHON ?= python3
NP ?= 1
SCENE ?= hertz
export OMPI_ALLOW_RUN_AS_ROOT = 1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM = 1
export OMPI_MCA_rmaps_base_oversubscribe = 1
MPIEXEC = mpiexec --oversubscribe -n $(NP)
# the sources compile on every core (a clean clone's make test builds 41 files
# first: 14 s instead of 23 s on 2 cores)
MAKEFLAGS += -j$(shell nproc 2>/dev/null || echo 2)

.PHONY: all deps meshes run test test-kernels check-figures check-sanitize stress bench bench-quick bench-formulations bench-parallel bench-accuracy bench-solid3d bench-contact3d clean
all: bin/contact

$(DEPS_STAMP): scripts/install-deps.sh
	@mkdir -p build
	sh scripts/install-deps.sh
	@touch $@
deps: $(DEPS_STAMP)

build/obj/%.o: src/%.c $(wildcard include/*.h src/body/*.h) $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

bin/contact: $(OBJS)
	@mkdir -p bin
	$(CC) -o $@ $(OBJS) $(LDLIBS)

# the materials' kernels checked at random 3D states (tests/test_material_kernels.py)
MATERIAL_OBJS = build/obj/body/elasticity.o build/obj/body/neohookean.o build/obj/body/mooneyrivlin.o build/obj/body/plasticity.o build/obj/body/material.o build/obj/io/options.o
bin/material-check: tests/kernels/material_check.c tests/kernels/checkutil.h $(MATERIAL_OBJS)
	@mkdir -p bin
	$(CC) $(CFLAGS) -o $@ $< $(MATERIAL_OBJS) $(LDLIBS)
# and the element loop on one 3D cell (Hex27, Tet10), on a body it fills in
# itself: it reads the body's private header (src/body/bodyimpl.h)
bin/element-check: tests/kernels/element_check.c tests/kernels/checkutil.h src/body/bodyimpl.h build/obj/body/element.o $(MATERIAL_OBJS)
	@mkdir -p bin
	$(CC) $(CFLAGS) -Isrc/body -o $@ $< build/obj/body/element.o $(MATERIAL_OBJS) $(LDLIBS)
# and the 3D mortar kernels: faces, clipping, segments, the tree (tests/test_mortar3d_kernels.py)
MORTAR3D_OBJS = build/obj/contact/face3d.o build/obj/contact/clip.o build/obj/contact/segment3d.o build/obj/contact/bvh.o
bin/mortar3d-check: tests/kernels/mortar3d_check.c tests/kernels/checkutil.h $(MORTAR3D_OBJS)
	@mkdir -p bin
	$(CC) $(CFLAGS) -o $@ $< $(MORTAR3D_OBJS) $(LDLIBS)

meshes: bin/contact
	./bin/contact -options_file meshes/hertz/hertz.opts -mesh_only

# ARGS: options added to the scene's (make run SCENE=cattaneo ARGS="-load_steps 1")
# the figures listed are those this run wrote (a scene without contact has no
# pressure plot, one without friction no shear plot, skipped without a line
# (--quiet: only a scene with friction has one to draw); an earlier one would
# be stale)
FIGURES = out/$(SCENE)-pressure.png out/$(SCENE)-shear.png out/$(SCENE)-vonmises.png
run: bin/contact meshes
	$(MPIEXEC) ./bin/contact -options_file meshes/$(SCENE)/$(SCENE).opts $(ARGS)
	@rm -f $(FIGURES)
	$(PYTHON) scripts/plot_hertz.py out/$(SCENE).h5 -o out/$(SCENE)-pressure.png
	@$(PYTHON) scripts/plot_hertz.py out/$(SCENE).h5 --shear --quiet -o out/$(SCENE)-shear.png
	$(PYTHON) scripts/plot_hertz.py out/$(SCENE).h5 --field -o out/$(SCENE)-vonmises.png
	@figs=""; for f in $(FIGURES); do if [ -f "$$f" ]; then figs="$$figs $$f"; fi; done; \
	echo "Figures:$${figs:- none}; data: out/$(SCENE).h5 (ParaView: out/$(SCENE).xdmf), out/$(SCENE).json"

# the suite runs on TEST_JOBS workers (pytest-xdist; TEST_JOBS=0: serially).
# 3 on 2 cores: a worker waits part of its time (Gmsh, pvpython, a 2-rank
# run's start), and a third worker fills it; a fourth now costs more than it
# fills (the processes' start-up is cheap since the suite's Open MPI uses ob1,
# tests/conftest.py, and 2-rank runs on 4 workers oversubscribe the cores):
# 777 tests in clean clones of 07a0451 on the quiet machine, make test on 4
# workers 6 min 26 s (674 s of CPU), on 3 6 min 10 s (634 s); 896 tests in
# clean clones of d5cd858 and f362485 on 3, 5 min 32 s and 5 min 56 s
# (docs/testing.md).
# --dist loadgroup
# keeps the tests that share a module- or session-scoped fixture on one worker
# (tests/conftest.py), so each shared run is made once.
TEST_JOBS ?= 3
PYTEST_PARALLEL = -n $(TEST_JOBS) --dist loadgroup
test: bin/contact meshes
	$(PYTHON) -m pytest -q --durations=10 -m "not stress and not kernels" $(PYTEST_PARALLEL) tests

# the tests whose figures depend on round-off (pytest's roundoff mark) under
# each of OpenBLAS's kernels Prescott, Nehalem, Sandybridge, Haswell and
# SkylakeX (OPENBLAS_CORETYPE): a table of verdicts and of the figures' ranges
# (out/test-kernels/table.md), and the docstrings' quoted figures checked
# against them (docs/testing.md, "The same verdict under every kernel")
test-kernels: bin/contact meshes
	$(PYTHON) scripts/test_kernels.py -n $(TEST_JOBS)

# the suite on this machine's kernel, recording every figure the tests
# measure, then each figure a docstring quotes checked against them (a factor
# over 3 is flagged)
check-figures: bin/contact meshes
	@mkdir -p out/figures; rm -f out/figures/suite.jsonl
	CONTACT_FIGURES=$(CURDIR)/out/figures/suite.jsonl $(PYTHON) -m pytest -q -m "not stress" $(PYTEST_PARALLEL) tests || true
	$(PYTHON) scripts/check_figures.py out/figures/suite.jsonl

# the same sources built with AddressSanitizer and UndefinedBehaviorSanitizer
# (build/san, bin/contact-sanitize), then a fast subset of the suite run with
# it: any invalid access, overflow or undefined operation aborts the run with a
# report and fails its test (leaks are not counted: MPI's own allocations)
SAN_FLAGS = -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined
SAN_OBJS  = $(patsubst src/%.c,build/san/%.o,$(SRCS))
build/san/%.o: src/%.c $(wildcard include/*.h) $(DEPS_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(SAN_FLAGS) -std=gnu11 -Wall -Wextra -Werror -Iinclude $(PETSC_CFLAGS) -c $< -o $@
bin/contact-sanitize: $(SAN_OBJS)
	@mkdir -p bin
	$(CC) $(SAN_FLAGS) -o $@ $(SAN_OBJS) $(LDLIBS)
SAN_TESTS = tests/test_patch_contact.py tests/test_master_pressure.py tests/test_cases.py tests/test_bad_input.py tests/test_robustness.py \
            tests/test_loads.py tests/test_force_control.py tests/test_held_by_contact.py tests/test_penalty_auto.py \
             tests/test_axisymmetric.py tests/test_setup_checks.py tests/test_missing_value.py tests/test_write_faults.py \
             tests/test_neohookean.py tests/test_force_stop.py tests/test_slide_watch.py tests/test_slide_off.py tests/test_solid.py
check-sanitize: bin/contact-sanitize meshes
	CONTACT_BIN=$(CURDIR)/bin/contact-sanitize ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
	  $(PYTHON) -m pytest -q -m "not stress" $(PYTEST_PARALLEL) $(wildcard $(SAN_TESTS))

# the long extremes (k_p up to 1e12 without continuation, h = 0.01), 500
# mutated meshes through the mesh reader, and the robustness sweep (h x k_p x
# push, both formulations, 1 and 2 ranks: 180 runs, about 30 minutes):
# bench/stress/results.json and RESULTS.md, bench/README.md's table
stress: bin/contact meshes
	$(PYTHON) -m pytest -q -m stress tests
	$(PYTHON) tests/fuzz_msh.py --cases 500 --seed 1 --jobs 2
	$(PYTHON) scripts/stress_sweep.py --out bench/stress

# the speed-accuracy sweep: bench/results.csv, bench/RESULTS.md, PNG plots
# (the full sweep takes hours; bench-quick covers the main points in minutes)
bench: bin/contact meshes
	$(PYTHON) scripts/bench.py --out bench
	$(PYTHON) scripts/bench_parallel.py --out bench/parallel
	$(PYTHON) scripts/accuracy_study.py --out bench/accuracy
# -accuracy: its estimate against the true error, its cost (about 4 minutes):
# bench/accuracy/RESULTS.md, and the curve of bench.py's error-against-time plot
bench-accuracy: bin/contact meshes
	$(PYTHON) scripts/accuracy_study.py --out bench/accuracy
# 1 against 2 ranks, interleaved, median of 3 (about 5 minutes)
bench-parallel: bin/contact meshes
	$(PYTHON) scripts/bench_parallel.py --out bench/parallel
# 3D elastic blocks of 1e4 to 1e6 dofs, the Newton step's solvers, 1 and 2
# ranks, and Lame's octant beside GetFEM (about 15 minutes; the cases not yet
# in bench/solid3d/results.json): bench/solid3d/RESULTS.md
bench-solid3d: bin/contact
	$(PYTHON) scripts/bench_solid3d.py --out bench/solid3d --getfem
# the quarter Hertz ball beside GetFEM (3 rounds interleaved), L-BFGS against
# Newton on the 3D scenes, the cost of a Newton step against the linear
# solve's by size (about 40 minutes): bench/contact3d/RESULTS.md
bench-contact3d: bin/contact
	$(PYTHON) scripts/bench_contact3d.py --side-by-side 3 --lmvm 3 --cost
bench-quick: bin/contact meshes
	$(PYTHON) scripts/bench.py --quick --out bench
# mortar / gpts solve time at h = 0.06 and 0.0065 (1.07e6 dofs), interleaved,
# median of 3 (about 10 minutes): bench/formulations.md
bench-formulations: bin/contact meshes
	$(PYTHON) scripts/bench.py --formulations-cost --out bench

clean:
	rm -rf build bin
