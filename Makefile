# Thin wrapper around CMake. `make run` and `make test` work on a fresh Debian machine: they install the
# missing Debian packages (scripts/setup-deps.sh), configure, build, then run the default study / the
# test suite. See README.md.
BUILD  ?= build
PYTHON ?= /usr/bin/python3
JOBS   ?= $(shell nproc)
GRANMC := $(BUILD)/bin/granmc
MPI_BUILD ?= build-mpi

.PHONY: all setup configure build run test lint format output-format-page thread-test sanitize-test portable-test bench clean mpi-setup mpi-configure mpi mpi-test hcs-alpha08 hcs-disks-alpha08 rough-disks-noise rough-mixture fig-shear-disks fig-mixture-disks fig-000-1 fig-000-2 fig-000-3 fig-000-4 fig-000-5 fig-000-6 fig-000-7 fig-000-8 fig-000-9 fig-000-10 fig-000-12 fig-000-7-shear-rate fig-000-8-shear-rate fig-000-sec5 fig-000-6-elastic fig-003 evolution-003 relaxation-bias-003 figures-000 fig-002-1 fig-002-3 fig-002-4 fig-002-5 fig-002-7 fig-002-8 figures-002 \
	table-001-1 table-001-2 fig-001-3 relaxation-001 tails-001 tails-001-full tails-001-full-float tails-001-weighted tails-disks-weighted intruder-cost accuracy-cost bench-effects bench-threads bench-naive bench-models stability

all: build

setup:
	@bash scripts/setup-deps.sh

$(BUILD)/CMakeCache.txt: | setup
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DGRANMC_WERROR=ON

configure: setup $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# The default study: a monodisperse homogeneous cooling state (alpha = 0.8) against Haff's law and Sonine a2.
run: build
	$(GRANMC) run drivers/scenes/default.toml --out results/default.h5 --summary results/default.json
	$(PYTHON) drivers/plot_cooling.py results/default.h5 results/default.png
	@echo "results: results/default.h5 results/default.json results/default.png"

# Precision check of the cooling state at alpha = 0.8 (docs/methods/validation.md).
hcs-alpha08: build
	$(GRANMC) run drivers/scenes/hcs_alpha08.toml --out results/hcs_alpha08.h5 --summary results/hcs_alpha08.json
	$(PYTHON) drivers/plot_cooling.py results/hcs_alpha08.h5 results/hcs_alpha08.png
	$(PYTHON) drivers/cooling_table.py results/hcs_alpha08.h5

hcs-disks-alpha08: build
	$(GRANMC) run drivers/scenes/hcs_disks_alpha08.toml --out results/hcs_disks_alpha08.h5 --summary results/hcs_disks_alpha08.json
	$(PYTHON) drivers/plot_cooling.py results/hcs_disks_alpha08.h5 results/hcs_disks_alpha08.png
	$(PYTHON) drivers/cooling_table.py results/hcs_disks_alpha08.h5

# Rough hard disks under split white noise against the published DSMC/EDMD (docs/methods/validation/disks-and-rough.md, "Rough particles").
rough-disks-noise: build
	$(PYTHON) drivers/rough_split_noise.py --granmc $(GRANMC)

# A rough binary mixture's cooling state against the Maxwellian theory (docs/methods/validation/disks-and-rough.md, "Rough particles").
rough-mixture: build
	$(PYTHON) drivers/rough_mixture.py --granmc $(GRANMC)

# Paper 000's figures (drivers/figure.py; results/000_fig<k>/figure.png, table.md). Runs are cached per
# point: a second call only redoes the theory and the plot. Runtimes in docs/methods/validation.md.
fig-000-1 fig-000-3 fig-000-4 fig-000-5 fig-000-6 fig-000-7 fig-000-8 fig-000-9 fig-000-10 fig-000-12: fig-000-%: build
	$(PYTHON) drivers/figure.py drivers/scenes/000_fig$*/figure.toml --granmc $(GRANMC)

fig-000-2: build
	$(GRANMC) run drivers/scenes/000_fig2/fig2.toml --out results/000_fig2/fig2.h5 --summary results/000_fig2/fig2.json
	$(GRANMC) theory drivers/scenes/000_fig2/fig2.toml > results/000_fig2/theory.json
	$(PYTHON) drivers/plot_delta.py results/000_fig2/fig2.h5 results/000_fig2/figure.png \
	  --theory-json results/000_fig2/theory.json --table results/000_fig2/table.md

# 000 Fig. 6 at alpha = 1 with a CI below 0.005: the converged Chapman-Enskog 1.016 against the first-Sonine 1.
fig-000-6-elastic: build
	$(PYTHON) drivers/figure.py drivers/scenes/000_fig6_elastic/figure.toml --granmc $(GRANMC)

# 000 sec. 5: the steady shear flow without a thermostat, a* and eta* against alpha with Grad's solution.
fig-000-sec5: build
	$(PYTHON) drivers/figure.py drivers/scenes/000_sec5/figure.toml --granmc $(GRANMC)

# The same in d = 2: the steady shear flow of hard disks with Grad's solution in d = 2.
fig-shear-disks: build
	$(PYTHON) drivers/figure.py drivers/scenes/shear_disks/figure.toml --granmc $(GRANMC)

# 000 Fig. 3 in d = 2: the temperature ratio of a mixture of hard disks with their Maxwellian theory.
fig-mixture-disks: build
	$(PYTHON) drivers/figure.py drivers/scenes/mixture_disks/figure.toml --granmc $(GRANMC)

figures-000: fig-000-1 fig-000-2 fig-000-3 fig-000-4 fig-000-5 fig-000-6 fig-000-7 fig-000-8 fig-000-9 fig-000-10 fig-000-12 fig-000-sec5

# Paper 003: eta^k/eta0 and eta/eta0 against phi in the modified shear flow (results/003_viscosity/).
fig-003: build
	$(PYTHON) drivers/figure.py drivers/scenes/003_viscosity/figure.toml --granmc $(GRANMC)

# 003's evolution (drivers/evolution_003.py): eta*(t), a*(t) and T(t) of the modified shear flow from the
# start to the approach to the cooling state, dilute, alpha = 0.8 and 0.6, t in [0, 250] (about 3 min).
evolution-003: build
	$(PYTHON) drivers/evolution_003.py drivers/scenes/003_viscosity/base.toml --restitution 0.8 0.6 --t-end 250

# 003's relaxation term: how the choice of f^(0) moves eta (results/003_f0_bias/table.md, about 4 min).
relaxation-bias-003: build
	$(PYTHON) drivers/relaxation_bias.py --granmc $(GRANMC)

# 000 Fig. 8 at omega = 0.5 and 1: eta* against the shear rate, extrapolated to a* -> 0 (about 60 min; resumes).
fig-000-8-shear-rate: build
	$(PYTHON) drivers/shear_rate_extrapolation.py drivers/scenes/000_fig8_shear_rate/omega0.5.toml \
		drivers/scenes/000_fig8_shear_rate/omega1.toml --granmc $(GRANMC)

# 000 Fig. 7 at mu = 10, alpha = 1, 0.9, 0.8, 0.7: the same extrapolation, against 000's "around 2 % at
# alpha = 0.7" (results/000_fig7_shear_rate/; resumes).
fig-000-7-shear-rate: build
	$(PYTHON) drivers/shear_rate_extrapolation.py drivers/scenes/000_fig7_shear_rate/mu10.toml \
		--granmc $(GRANMC) --out results/000_fig7_shear_rate --target fig-000-7-shear-rate

# Paper 002 Figs. 1-2: the Gaussian bath's collision flux and the law of the colliding velocities, from
# `granmc bath` against 002 eqs. 14, 19-20 (drivers/plot_bath.py; results/002_fig1/, a few seconds).
fig-002-1: build
	$(PYTHON) drivers/plot_bath.py drivers/scenes/002_fig1/bath.toml --granmc $(GRANMC)

# Paper 002's figures (1D Gillespie intruder).
fig-002-3 fig-002-4 fig-002-5: fig-002-%: build
	$(PYTHON) drivers/figure.py drivers/scenes/002_fig$*/figure.toml --granmc $(GRANMC)
	@if [ $* = 5 ]; then $(PYTHON) drivers/plot_intruder_tails.py results/002_fig5; fi

# The 2D needle: Fig. 7 (R against alpha) and Fig. 8 (angular-velocity distribution).
fig-002-7: build
	$(PYTHON) drivers/figure.py drivers/scenes/002_fig7/figure.toml --granmc $(GRANMC)

fig-002-8: build
	@mkdir -p results/002_fig8
	$(GRANMC) run drivers/scenes/002_fig8/needle.toml --out results/002_fig8/needle.h5 --summary results/002_fig8/needle.json
	$(PYTHON) drivers/plot_needle_angular.py results/002_fig8/needle.h5 results/002_fig8

figures-002: fig-002-1 fig-002-3 fig-002-4 fig-002-5 fig-002-7 fig-002-8

# Work-precision (docs/user-guide/accuracy-cost.md): 001 Example 3 against particles, replicas, dt, method and storage;
# the early-time Haff slope against particles and dt; the recommendation table.
accuracy-cost: build
	$(PYTHON) drivers/accuracy_cost.py --granmc $(GRANMC)

# Gillespie against the DSMC alternative for the 1D intruder (docs/user-guide/accuracy-cost.md).
intruder-cost: build
	$(PYTHON) drivers/intruder_cost.py --granmc $(GRANMC)

# Paper 001 sec. 5.2: temperature relaxation against n (drivers/relaxation.py; results/001_example<k>/).
RELAXATION = $(PYTHON) drivers/relaxation.py --granmc $(GRANMC)
table-001-1: build
	$(RELAXATION) drivers/scenes/001_relaxation/example3.toml --particles 64 256 1024 4096 16384 \
	  --plot-particles 64 256 1024 4096 --window 2 8 --paper-table 1
table-001-2: build
	$(RELAXATION) drivers/scenes/001_relaxation/example4.toml --particles 64 256 1024 4096 16384 \
	  --plot-particles 64 256 1024 4096 --window 2 8 --paper-table 2
fig-001-3: build
	$(RELAXATION) drivers/scenes/001_relaxation/example5.toml --particles 64 256 1024 4096

relaxation-001: table-001-1 table-001-2 fig-001-3

# Paper 001 sec. 5.3: tail exponents (drivers/tails.py, drivers/tail_fit.py). tails-001 runs Examples 7-9 at
# n = 10^6, N = 10 (half a minute); tails-001-full at the paper's n = 10^7, N = 100 (on 2 cores, 640 MB; last
# measured: Example 7 8 min and 9 13 min, both before later speed-ups, 8 28 min); tails-001-full-float the same with
# 16-byte particles (330 MB: Examples 7, 8 and 9 in 7, 22 and 8 min). Measured runs in docs/developer-guide/performance.md.
TAILS = $(PYTHON) drivers/tails.py --granmc $(GRANMC)
tails-001: build
	$(TAILS) drivers/scenes/001_tails/example7.toml --particles 1000000 --replicas 10
	$(TAILS) drivers/scenes/001_tails/example8.toml --particles 1000000 --replicas 10
	$(TAILS) drivers/scenes/001_tails/example9.toml --particles 1000000 --replicas 10
tails-001-full: build
	$(TAILS) drivers/scenes/001_tails/example7.toml
	$(TAILS) drivers/scenes/001_tails/example8.toml
	$(TAILS) drivers/scenes/001_tails/example9.toml

# The same with 16-byte particles (run.storage = "float"): half the memory, a little faster at 10^7.
tails-001-full-float: build
	$(TAILS) drivers/scenes/001_tails/example7.toml --storage float
	$(TAILS) drivers/scenes/001_tails/example8.toml --storage float
	$(TAILS) drivers/scenes/001_tails/example9.toml --storage float

# The same tails with weighted particles (docs/methods/derivations/swpm-inelastic.md): granmc fits b itself (the
# summary's tail.exponent); drivers/tails_weighted.py writes results/001_tails_weighted/table.md and a figure
# per scene (f(|v|) and b against the fit window's inner edge). Any scene: the same script with its path.
tails-001-weighted: build
	$(PYTHON) drivers/tails_weighted.py --granmc $(GRANMC) drivers/scenes/001_tails_weighted/example7.toml \
	  drivers/scenes/001_tails_weighted/example8.toml drivers/scenes/001_tails_weighted/example9.toml \
	  drivers/scenes/001_tails_weighted/vhs_lambda025.toml drivers/scenes/001_tails_weighted/hcs_hard_spheres.toml

# The same four laws in the plane (run.dimension = 2): Maxwell, hard and variable hard disks heated by white
# noise, and freely cooling hard disks; results/tails_disks_weighted/{table.md, NAME.png}.
tails-disks-weighted: build
	$(PYTHON) drivers/tails_weighted.py --granmc $(GRANMC) --out results/tails_disks_weighted \
	  drivers/scenes/tails_disks_weighted/maxwell.toml drivers/scenes/tails_disks_weighted/hard_disks.toml \
	  drivers/scenes/tails_disks_weighted/vhs.toml drivers/scenes/tails_disks_weighted/hcs_hard_disks.toml

# The habits CI holds the tree to (docs/developer-guide/architecture.md, "Rules"): the lint (clang-format,
# pyflakes), the suite (built with warnings as errors) at 2 OpenMP threads, its unit and cli tests again at 1 and
# 4, the fast tests under the address and undefined-behaviour sanitizers, the SIMD tests for plain x86-64,
# then the MPI test in $(MPI_BUILD) (replicas over ranks against one process, docs/developer-guide/scaling.md;
# installs OpenMPI if missing and builds only granmc and test_mpi there).
test: build
	$(MAKE) --no-print-directory lint
	OMP_NUM_THREADS=2 ctest --test-dir $(BUILD) --output-on-failure
	$(MAKE) --no-print-directory thread-test
	$(MAKE) --no-print-directory sanitize-test
	$(MAKE) --no-print-directory portable-test
	$(MAKE) --no-print-directory mpi-test

# Every C++ file as .clang-format writes it, every Python file clean under pyflakes. `make format` rewrites the
# C++ files in place.
CXX_SOURCES = $(shell git ls-files '*.cpp' '*.hpp' 2>/dev/null)
PY_SOURCES = $(shell git ls-files '*.py' 2>/dev/null)
lint: setup
	clang-format --dry-run --Werror $(CXX_SOURCES)
	$(PYTHON) -m pyflakes $(PY_SOURCES)
	@echo "lint: $(words $(CXX_SOURCES)) C++ and $(words $(PY_SOURCES)) Python files clean"

format: setup
	clang-format -i $(CXX_SOURCES)

# docs/formats/output-format.md, generated from the output schema (io/output_schema.cpp); test_output_format fails while
# it is stale.
output-format-page: build
	$(GRANMC) output-format > docs/formats/output-format.md

# The unit and cli tests again at 1 and 4 OpenMP threads (4: more threads than cores, replicas over threads and
# threads inside a replica). Results do not depend on the count, and test_threads, test_cli and test_checkpoint compare
# the bits of runs on different counts directly, so the validation tests would repeat the 2-thread run's numbers.
thread-test: build
	OMP_NUM_THREADS=1 ctest --test-dir $(BUILD) --output-on-failure -L 'unit|cli'
	OMP_NUM_THREADS=4 ctest --test-dir $(BUILD) --output-on-failure -L 'unit|cli'

# The fast tests (labels unit and cli, not heavy: the target fast_tests, tests/CMakeLists.txt) built with
# AddressSanitizer and UndefinedBehaviorSanitizer in $(SANITIZE_BUILD), at -O1 (about a third less compile time
# than -O2): any finding fails the test. test_spread is heavy (2 minutes under the sanitizers); test_cli runs
# the rank-wave backend through granmc.
SANITIZE_BUILD ?= build-sanitize
sanitize-test: setup
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DGRANMC_WERROR=ON \
	  -DGRANMC_BENCH=OFF -DGRANMC_SANITIZE=address,undefined
	cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target granmc fast_tests
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --test-dir $(SANITIZE_BUILD) --output-on-failure -L 'unit|cli' -LE heavy

# The build above is for this machine's widest registers (AVX-512 here). The SIMD code has other branches,
# for narrower registers: the tests that hold them to the scalar code (numerics, the store, the event
# scheme's registers) built again for plain x86-64 (GRANMC_NATIVE=OFF: SSE2, two doubles a register) in
# $(PORTABLE_BUILD), so that a build for another machine cannot break unseen.
PORTABLE_BUILD ?= build-portable
portable-test: setup
	cmake -S . -B $(PORTABLE_BUILD) -DCMAKE_BUILD_TYPE=Release -DGRANMC_NATIVE=OFF -DGRANMC_WERROR=ON
	cmake --build $(PORTABLE_BUILD) -j $(JOBS) --target test_core test_numerics test_event_scheme
	ctest --test-dir $(PORTABLE_BUILD) --output-on-failure -R '^(test_core|test_numerics|test_event_scheme)$$'

# Replicas over MPI ranks (docs/user-guide/parallel-runs.md), built apart in $(MPI_BUILD) with GRANMC_MPI=ON: `make mpi`, then
# `mpirun -np R $(MPI_BUILD)/bin/granmc run SCENE ...`. The default set-up does not install MPI.
mpi-setup:
	@bash scripts/setup-deps.sh --mpi

$(MPI_BUILD)/CMakeCache.txt: | mpi-setup
	cmake -S . -B $(MPI_BUILD) -DCMAKE_BUILD_TYPE=Release -DGRANMC_MPI=ON -DGRANMC_WERROR=ON

mpi-configure: mpi-setup $(MPI_BUILD)/CMakeCache.txt

mpi: mpi-configure
	cmake --build $(MPI_BUILD) -j $(JOBS)

mpi-test: mpi-configure
	cmake --build $(MPI_BUILD) -j $(JOBS) --target granmc test_mpi
	ctest --test-dir $(MPI_BUILD) -L mpi --output-on-failure

bench: build
	cmake --build $(BUILD) --target bench

# Cost of each effect (perf/bench_effects.cpp): ratios to the plain scene, about 90 s.
bench-effects: build
	cmake --build $(BUILD) --target bench-effects

# Threads: one replica with its threads inside it, and replicas on threads; `granmc run` wall time, one thread
# against two (perf/thread_scaling.py, docs/developer-guide/scaling.md). About 3 minutes.
bench-threads: build
	$(PYTHON) perf/thread_scaling.py --granmc $(GRANMC)

# Whole-run collisions per second on one thread against a plain scalar DSMC (perf/naive_run.cpp, Bird's scheme),
# 10^6 and 10^7 particles, set-up included (perf/naive_ratio.py, docs/developer-guide/performance.md; about 12 minutes).
bench-naive: build
	$(PYTHON) perf/naive_ratio.py --granmc $(GRANMC) --naive $(BUILD)/bin/naive_run

# What a collision costs in each model: smooth and rough spheres and disks, 10^7 particles, one thread, `granmc
# run` wall time per collision, paired runs (perf/model_cost.py, docs/developer-guide/performance.md). About 4 minutes.
bench-models: build
	$(PYTHON) perf/model_cost.py --granmc $(GRANMC)

# Regression benchmarks (perf/bench_compare.py, docs/developer-guide/performance.md): the ratios granmc / naive,
# granmc / packed gather-scatter limit (DSMC stage and event scheme) and effect / plain, compared with
# perf/baselines/baseline.json; fails if one moved the wrong way by more than its threshold (10 %, or the
# floor for that ratio in the baseline).
# BENCH_ROUNDS rounds of about 3 min each.
# bench-baseline records a new baseline instead. JSON in $(BUILD)/bench-json.
BENCH_ROUNDS ?= 3
.PHONY: bench-compare bench-baseline
bench-compare: build
	$(PYTHON) perf/bench_compare.py --bin $(BUILD)/bin --rounds $(BENCH_ROUNDS)

bench-baseline: build
	$(PYTHON) perf/bench_compare.py --bin $(BUILD)/bin --rounds $(BENCH_ROUNDS) --save

clean:
	rm -rf $(BUILD) $(MPI_BUILD) $(PORTABLE_BUILD) $(SANITIZE_BUILD)

# The stability study: the fast hard cases (ctest -L stability), then the long versions at full size
# (drivers/scenes/stability/, checks and table in results/stability/table.md; about 4 min), then checkpoints under
# SIGKILL and a full disk (tests/fault_injection.py, about 40 s).
stability: build
	cd $(BUILD) && ctest -L stability --output-on-failure
	$(PYTHON) drivers/stability.py --granmc $(GRANMC)
	$(PYTHON) tests/fault_injection.py --granmc $(GRANMC)
