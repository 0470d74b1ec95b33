# choc top-level entry points. Each target does the whole set-up on a fresh Debian 12
# machine: install the missing packages, configure, build, then act.
BUILD ?= build
JOBS  ?= $(shell nproc)
CTEST_ARGS ?=
# Debian's Python (matplotlib, netCDF4 and ParaView come from Debian packages).
PYTHON ?= /usr/bin/python3
# Open MPI's waiting ranks give up their core (sched_yield) instead of spinning: with two 2-rank
# tests at once on 2 cores, spinning ranks wait a time slice per message (a 2 s run measured at
# 93 s; 4.3 s yielding; no cost alone). Every mpirun under make (tests, studies, benchmarks).
export OMPI_MCA_mpi_yield_when_idle = 1

.PHONY: all deps configure build run test verify study study-contact-mass bench-block-on-slab study-plastic bench bench-kept bench-direct bench-multigrid bench-bracket bench-oblique bench-finite bench-plastic bench-inputs bench-mesh bench-modal bench-explicit bench-peer study-modal study-bar study-modal-direct study-friction study-finite study-saint-venant docs clean

all: build

deps:
	@tools/build/install-deps.sh --with-viz

$(BUILD)/Makefile: CMakeLists.txt | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=mpicxx -DCMAKE_C_COMPILER=mpicc

configure: deps $(BUILD)/Makefile

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The SDNL111 suite: every benchmark input, then the report. Builds only what it runs: the
# launcher and the engine (the report's tools are Python), not the unit tests.
run: configure
	cmake --build $(BUILD) -j $(JOBS) --target choc choc-engine
	tools/build/run-suite.sh $(BUILD)

# The test suite (unit tests, regression cases, restarts, error messages, the shorter scenes):
# every test but the verification tier, under 30 minutes from a clean clone on 2 cores.
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -LE verify $(CTEST_ARGS)

# The verification tier (label 'verify'): the scene tests over 40 s each, the sanitizer build and
# the fuzzers. `.ci/run` runs it after `make test`; together they are every test.
verify: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L verify $(CTEST_ARGS)

# The scale benchmark: input/scale-3d.xml (300,300 unknowns) on 1 and 2 MPI ranks, then smaller
# sizes of the same scene (docs/performance/scale.md); generates meshes/scale_3d.exo when missing. Then the
# same input with the linear solver 'auto' (CG + Jacobi, adaptive tolerance). Each as the median
# of 3 runs per rank count, np = 1 and np = 2 alternating. Every benchmark writes its figures to
# results/bench/<bench>.json (the performance pages of `make docs`).
bench: build
	$(PYTHON) tools/bench/bench_scale.py --build $(BUILD) --sizes --repeat 3 $(BENCH_ARGS)
	$(PYTHON) tools/bench/bench_scale.py --build $(BUILD) --solver auto --repeat 3
	$(PYTHON) tools/bench/bench_scale.py --build $(BUILD) --contact lagrange --repeat 3
	$(PYTHON) tools/bench/bench_scale.py --build $(BUILD) --contact lagrange --solver auto --repeat 3
	$(PYTHON) tools/bench/bench_scale.py --build $(BUILD) --contact lagrange --solver auto --friction 0.1 --repeat 3
	$(PYTHON) tools/bench/bench_modal_direct.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_explicit.py --build $(BUILD) --end-time 2e-5
	$(PYTHON) tools/bench/bench_explicit.py --build $(BUILD) --end-time 2e-5 --mesh 18 560 --ranks 2 --contact lagrange
	$(PYTHON) tools/bench/bench_kept_factorization.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_direct_packages.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_block_drop.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_projected_gram.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_multigrid.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_bracket.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_oblique_sphere.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_finite_strain.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_plastic.py --build $(BUILD)

# The direct packages on contact scenes: KLU2 on rank 0 against MUMPS on every rank, 1 and 2
# ranks; the scale scene's bars, then a compact block (against penalty contact too); the Gram
# matrix of many active constraints between meshed bodies, dense or sparse (stacked plates).
bench-direct: build
	$(PYTHON) tools/bench/bench_direct_packages.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_block_drop.py --build $(BUILD)
	$(PYTHON) tools/bench/bench_projected_gram.py --build $(BUILD)

# The bracket drop with friction: implicit and explicit, 1 and 2 ranks, against an implicit run at
# a small step (--sizes 1.5e-3 for about 200,000 unknowns).
bench-bracket: build
	$(PYTHON) tools/bench/bench_bracket.py --build $(BUILD)

# The oblique sphere's frictional Newton: the status after each correction against after converged
# solves, at 6k and 17k unknowns, 1 and 2 ranks.
bench-oblique: build
	$(PYTHON) tools/bench/bench_oblique_sphere.py --build $(BUILD)

# The cost of finite strain: element-by-element internal force against the assembled product,
# explicit and implicit, HEX8 and TET10, 1 and 2 ranks.
bench-finite: build
	$(PYTHON) tools/bench/bench_finite_strain.py --build $(BUILD)

# Explicit J2 per element-cycle: the 3D Taylor bar's first 10 us, HEX8 F-bar and standard, TET10,
# 1 and 2 ranks.
bench-plastic: build
	$(PYTHON) tools/bench/bench_plastic.py --build $(BUILD)

# CG's preconditioners on stiffness-dominated steps (153,792 unknowns): Multigrid, Schwarz, Jacobi.
bench-multigrid: build
	$(PYTHON) tools/bench/bench_multigrid.py --build $(BUILD)

# Contact status changes on a kept factorisation (Update Budget) against refactoring at each.
bench-kept: build
	$(PYTHON) tools/bench/bench_kept_factorization.py --build $(BUILD)

# The implicit contact mass's trade (issue 73): every 'Contact Mass' treatment on the Taylor bars,
# the copper bar, example 03, SDNV100 and SDNL111 E2, each against its reference, with its cost
# (docs/verification/contact-mass.md).
study-contact-mass: build
	$(PYTHON) tools/study/contact_mass_study.py --build $(BUILD) --out results/study/contact-mass

# Issue 73's friction scene: a compact block dropped flat on a meshed slab (58,041 unknowns), with
# and without friction, at the contact masses auto, normal and velocity update: Newton corrections
# per step and the time against the frictionless run (docs/verification/contact-mass.md).
bench-block-on-slab: build
	$(PYTHON) tools/bench/bench_block_on_slab.py --build $(BUILD) --repeat 1 --masses auto normal "velocity update"

# SDND100's friction: stick stiffness and dt against the rows and the exact motion.
# Saint-Venant's problem: the rigid striker's error against h and dt, and the striker meshed elastic.
study-saint-venant: build
	$(PYTHON) tools/study/saint_venant_study.py --build $(BUILD) --out results/study/saint-venant

study-friction: build
	$(PYTHON) tools/study/sdnd100_study.py --build $(BUILD)

# SDNL32 by the modal transient on 4 to 31 modes and by the direct transient (docs/verification/modal-and-direct.md).
study-modal-direct: build
	$(PYTHON) tools/study/modal_direct_study.py --build $(BUILD)

# Explicit central differences on the scale scene, np = 1 and 2, penalty and Lagrange
# contact; then the 1.2M-unknown scene (18 x 18 x 560 HEX8 per bar) on 2 ranks.
bench-explicit: build
	$(PYTHON) tools/bench/bench_explicit.py --build $(BUILD) --end-time 2e-5
	$(PYTHON) tools/bench/bench_explicit.py --build $(BUILD) --end-time 2e-5 --mesh 18 560 --ranks 2 --contact lagrange

# choc against CalculiX on the same deck: installs calculix-ccx, then runs both on
# SDNL111's bars in 3D at growing sizes (tools/bench/peer_calculix.py; PEER_ARGS, e.g. --sizes 3x100).
PEER_ARGS ?=
bench-peer: build
	@tools/build/install-deps.sh --with-viz --with-peer
	$(PYTHON) tools/bench/peer_calculix.py --build $(BUILD) $(PEER_ARGS)

# The same 3D scene direct and reduced to 40 modes with shock links (docs/performance/modal-vs-direct.md).
bench-modal: build
	$(PYTHON) tools/bench/bench_modal_direct.py --build $(BUILD)

# The speed-accuracy study: sweeps, results/study/study.csv, Pareto plots and README.md.
study: build
	$(PYTHON) tools/study/study.py --build $(BUILD) --out results/study
	$(PYTHON) tools/study/study_report.py results/study
	$(PYTHON) tools/study/modal_direct_study.py --build $(BUILD) --out results/study/modal-direct
	$(PYTHON) tools/study/sdnd100_study.py --build $(BUILD) --out results/study/sdnd100
	$(PYTHON) tools/study/sdnv100_explicit_study.py --build $(BUILD) --out results/study/sdnv100-explicit
	$(PYTHON) tools/study/hertz_3d_study.py --build $(BUILD) --out results/study/hertz-3d
	$(PYTHON) tools/study/explicit_implicit_study.py --build $(BUILD) --out results/study/explicit-implicit
	$(PYTHON) tools/study/small_vs_finite_study.py --build $(BUILD) --out results/study/small-vs-finite
	$(PYTHON) tools/study/taylor_bar_study.py --build $(BUILD) --out results/study/taylor-bar
	$(PYTHON) tools/study/taylor_bar_study.py --build $(BUILD) --law johnson-cook --out results/study/taylor-bar-jc
	$(PYTHON) tools/study/plastic_impact_study.py --build $(BUILD) --out results/study/plastic-impact
	$(PYTHON) tools/study/contact_mass_study.py --build $(BUILD) --out results/study/contact-mass

# The Taylor bar's mesh convergence, QUAD4 F-bar against standard QUAD4 and QUAD8
# (docs/verification/taylor-bar.md; about 15 minutes), and the elastic-plastic sphere's restitution
# against speed (docs/verification/plastic-impact.md; about 20 minutes).
study-plastic: build
	$(PYTHON) tools/study/taylor_bar_study.py --build $(BUILD) --out results/study/taylor-bar
	$(PYTHON) tools/study/taylor_bar_study.py --build $(BUILD) --law johnson-cook --out results/study/taylor-bar-jc
	$(PYTHON) tools/study/plastic_impact_study.py --build $(BUILD) --out results/study/plastic-impact

# Small against finite strain: the rubber ball at rising speeds (docs/verification/rubber-ball.md).
study-finite: build
	$(PYTHON) tools/study/small_vs_finite_study.py --build $(BUILD) --out results/study/small-vs-finite

# A ~1M-unknown TET10 gmsh mesh read, partitioned and assembled on 2 ranks (time, memory per phase).
bench-mesh: build
	$(PYTHON) tools/bench/bench_large_mesh.py --build $(BUILD) --n 20

# The first 10 frequencies of a cantilever block in HEX20 and TET10 against mesh refinement.
study-modal: build
	$(PYTHON) tools/study/modal_convergence.py --build $(BUILD) --out results/modal_convergence

# The SDNL111 bar wave per element type at 4 mesh levels (about 2 minutes; gmsh meshes).
study-bar: build
	$(PYTHON) tools/study/bar_convergence.py --build $(BUILD) --out results/bar_convergence --levels 25 50 100 200

# Wall time of every SDNL111 input, start-up included (not a test).
bench-inputs: build
	$(PYTHON) tools/bench/bench_inputs.py --build $(BUILD) --repeat 5

# The generated documentation: the parameters' reference (when its script exists), the
# verification pages' results (docs/verification/generated/) from the last `make test`'s
# regression results (it does not rerun the suite: tools/docs/verification_pages.py --run does),
# and the performance tables (docs/performance/generated/) from the benchmarks' JSON files in
# results/bench/ (a benchmark whose JSON is absent is skipped, saying so; `make bench...` writes them).
docs: build
	[ ! -x tools/docs/parameters_reference.sh ] || tools/docs/parameters_reference.sh $(BUILD) docs/reference/parameters.md
	$(PYTHON) tools/docs/verification_pages.py --build $(BUILD) --out docs/verification/generated
	$(PYTHON) tools/docs/performance_pages.py --results results/bench --out docs/performance/generated

clean:
	rm -rf $(BUILD) results
