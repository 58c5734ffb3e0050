# flipflop — the two commands of the README.
#   make demo   set up, build (Release, build/), run the demo job
#   make test   set up, build, run the whole test suite through ctest
BUILD ?= build
JOBS  ?= $(shell nproc)
PKGS  := cmake g++ make clang lld libomp-14-dev libgmp-dev libmpfr-dev libcgal-dev libeigen3-dev libtbb-dev \
         libqhull-dev qhull-bin catch2 librapidcheck-dev libcli11-dev python3-meshio python3-numpy \
         python3-venv python3-pip python3-scipy python3-pytest python3-hypothesis python3-matplotlib ccache ninja-build libtet1.5-dev \
         libopenmpi-dev openmpi-bin python3-dask python3-distributed

.PHONY: all deps configure build demo test python sanitize asan asan-full tsan clean cuda

all: build

# thrust, CUB and libcu++ (CCCL) for the GPU kernels' OpenMP build, whose
# *_cuda_omp tests are the GPU code's coverage without a GPU: from the CUDA
# toolkit where one is installed, otherwise make deps fetches PyPI's
# nvidia-cuda-cccl-cu12 (headers only, 3 MB) into build-deps/cccl and every
# configure below passes it (kernels_cuda/CMakeLists.txt: FLIPFLOP_CCCL_INCLUDE).
CCCL_DIR   := $(CURDIR)/build-deps/cccl
CCCL_INC   := $(CCCL_DIR)/nvidia/cuda_cccl/include
CCCL_WHEEL := nvidia-cuda-cccl-cu12==12.9.27
CCCL_ARG    = $(shell test -d $(CCCL_INC)/thrust && echo -DFLIPFLOP_CCCL_INCLUDE=$(CCCL_INC))

deps:
	@missing=""; for p in $(PKGS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "flipflop: installing missing Debian packages:$$missing"; \
	  if [ "$$(id -u)" -ne 0 ]; then SUDO=sudo; else SUDO=; fi; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi
	@if ! ls -d /usr/local/cuda*/include/thrust /usr/local/cuda*/include/cccl/thrust 2>/dev/null | grep -q . && \
	    [ ! -d $(CCCL_INC)/thrust ]; then \
	  echo "flipflop: no CUDA toolkit headers: fetching thrust/CUB/libcu++ ($(CCCL_WHEEL), PyPI) into $(CCCL_DIR)"; \
	  rm -rf $(CCCL_DIR) && mkdir -p $(CCCL_DIR) && \
	  /usr/bin/python3 -m pip download -q --disable-pip-version-check --no-deps --only-binary=:all: \
	    -d $(CCCL_DIR) "$(CCCL_WHEEL)" && \
	  /usr/bin/python3 -m zipfile -e $(CCCL_DIR)/*.whl $(CCCL_DIR) && test -d $(CCCL_INC)/thrust; \
	fi

# Ninja (make deps installs it) for every build folder this Makefile
# configures: with CMake's Makefile generator a library's objects wait until
# the libraries it links are built, and one of 2 cores idled behind the last
# long files (the fuzz stage's build: 519 s wall for 803 s of compilation; with
# Ninja 383 s, 99 % of both cores; 2026-12-02, stop 65). A folder already
# configured keeps its generator (CMake refuses another): `make clean` first
# to switch an old one.
generator = $(if $(wildcard $(1)/CMakeCache.txt),,$(if $(shell command -v ninja),-G Ninja))

# ccache (when installed; make deps installs it): the Python package's build
# (make python) compiles the same library sources with the same flags as
# $(BUILD); through ccache it reuses $(BUILD)'s objects instead of compiling
# them a second time. Cache in $(BUILD)/ccache.
export CCACHE_DIR ?= $(abspath $(BUILD))/ccache
WITH_CCACHE = cc=$$(command -v ccache || true); \
  export CMAKE_C_COMPILER_LAUNCHER=$$cc CMAKE_CXX_COMPILER_LAUNCHER=$$cc;

# The test drivers (proptests/*_test.cpp, 55 % of the build's compile time) at
# -O1, the libraries they test at Release's -O3: measured on two drivers, -O1
# compiles in 50-70 % of -O3's time (-O2: 90-100 %); the tests that inline the
# predicates run up to 30 % longer, the rest as fast.
configure: deps
	@$(WITH_CCACHE) cmake $(call generator,$(BUILD)) -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DFLIPFLOP_PYTHON_TESTS=ON $(CCCL_ARG) \
	  -DFLIPFLOP_TESTS_OPT=-O1 > $(BUILD).configure.log 2>&1 || \
	  { cat $(BUILD).configure.log; exit 1; }

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/flipflop demo

# cuda: the CUDA algorithm kernels (kernels_cuda/hull2, hull3, rt2) built with
#       nvcc for sm_90 even without a GPU (a compile check; minutes per file),
#       with their device tests (skipped without a device)
cuda: configure
	cmake -S . -B $(BUILD) -DFLIPFLOP_CUDA_ALGORITHMS=ON > /dev/null
	cmake --build $(BUILD) -j $(JOBS)

test: build python
	cd $(BUILD) && ctest --output-on-failure --no-tests=error -j $(JOBS)

# python: the Python package (python/, scikit-build-core + nanobind from PyPI)
#         installed into a virtual environment on Debian's interpreter (with
#         its numpy, scipy, pytest, hypothesis), where ctest's python.pytest
#         runs its test suite. The package's CMake build folder persists
#         (python/build/), so a second install rebuilds only what changed.
#         CC and CXX: the compilers CMake chose for $(BUILD) (its defaults cc
#         and c++ unless the caller set them), not the ones scikit-build-core
#         would take from Python's sysconfig (x86_64-linux-gnu-g++): ccache
#         hashes the compiler's name, and with another name every library
#         object missed the cache and was compiled twice (measured: 256 of
#         273 misses, about 160 s of a 2-core make test).
PYVENV := $(BUILD)/python-venv
python: build
	@test -x $(PYVENV)/bin/python || /usr/bin/python3 -m venv --system-site-packages $(PYVENV)
	@$(PYVENV)/bin/python -c "import nanobind, scikit_build_core" 2>/dev/null || \
	  $(PYVENV)/bin/python -m pip install -q --disable-pip-version-check "nanobind>=2.0" "scikit-build-core>=0.8"
	$(WITH_CCACHE) CC=$${CC:-cc} CXX=$${CXX:-c++} CMAKE_BUILD_PARALLEL_LEVEL=$(JOBS) CMAKE_ARGS="$(CCCL_ARG)" \
	  $(PYVENV)/bin/python -m pip install -q --disable-pip-version-check --no-build-isolation ./python

# ---- sanitizers (run by .ci/run) ---------------------------------------------
# asan: one clang build (build-asan) of the libraries with AddressSanitizer,
#       UBSan's arithmetic and control checks and libFuzzer's coverage
#       (-fsanitize=fuzzer-no-link), shared by two jobs: a selection of the
#       test suite (ASAN_TESTS, below; its [long] cases and the full
#       RapidCheck count are make test's) and the libFuzzer targets, which
#       link the same libraries (FLIPFLOP_FUZZ_SHARED_LIBS) and which .ci/run
#       then runs (fuzz/run_all.sh SECONDS build-asan). Until stop 77 the
#       ASan suite was a gcc build of its own (now make asan-full, below) and
#       the fuzz stage compiled instrumented copies of every library again with
#       clang: on the 2-core "AMD EPYC" VM (L3 8 MiB) the two stages were
#       1433 + 664 s of .ci/run's 4543 s (stop 76), and CI stopped stop 75's run
#       at 5400 s. What this build leaves out and where it runs instead:
#       the other test drivers and the [long] cases (make test, in Release;
#       make asan-full runs every driver under gcc's ASan + UBSan), UBSan's
#       checks other than the arithmetic and control ones (make asan-full),
#       the thrust/OpenMP kernels' tests (make tsan, make test; the fuzz
#       targets hull2, kernels, rt2, hull3 and rt3 run those kernels here),
#       the corpus replays (each fuzz target runs its corpus first), the
#       checked reference, the example, flipflop-mpi. The CGAL/Qhull peers and
#       Catch2's main are compiled uninstrumented (FLIPFLOP_SANITIZE_THIRD_PARTY=OFF),
#       the peers at -O1 (the reference and CLI drivers use CGAL as an
#       oracle on small inputs).
#       The libraries at -O2 with their assertions (CMAKE_BUILD_TYPE=None:
#       no NDEBUG, where the fuzz stage's own build is Release), the test
#       drivers at -O0 with ASan only (no UBSan, no coverage).
SAN_CASES ?= 100
# UBSan's checks in make asan: the fuzz targets' set (.ci/fuzz_ubsan_checks;
# fuzz/CMakeLists.txt gives the measured cost of the others).
ASAN_UBSAN := $(shell grep '^[a-z]' .ci/fuzz_ubsan_checks)
ASAN_FLAGS := -O2 -g1 -fno-omit-frame-pointer -fsanitize=address,$(ASAN_UBSAN) -fno-sanitize-recover=undefined \
              -fsanitize-ignorelist=$(CURDIR)/.ci/ubsan.ignorelist -fsanitize=fuzzer-no-link
# The test drivers make asan builds and runs (FLIPFLOP_TESTS_ONLY): the input
# layer and the command line, the predicates' composed path, the certifiers,
# every reference algorithm and every CPU kernel, one driver each where
# several test the same code (the orders, invariance, oracle, strict-view and
# checked drivers are make test's).
ASAN_TESTS := io_test cli_test gen_test gen_planes_test values_test regression_test inner_ball_test \
              predicates_mixed_test sos_test certify_test rtd_certify_test \
              hull2_reference_test ffhull_reference_test splay_reference_test splay_stars_test \
              twist_flip_hull_test twist_flip_precondition_test twist_flip_stages_test \
              rt2_reference_test rt2_strict_test rtd_reference_test rtd_strict_test \
              instant_flip_insert_test instant_flip_dynamic_test instant_flip_timeline_test instant_flip_rebuild_test \
              instant_flip_perturbation_order_test instant_flip_rt_plus_2_test instant_flip_cli_test \
              kernels_test hull2_cpu_test hull3_cpu_test hull3_witness_test rt2_cpu_test certify_rt2_cpu_test \
              rt2_witness_test rt3_cpu_test certify_rt3_cpu_test rtd_hull_d_test rtd_cavity_test rtd_flips_test \
              rtd_lattice_quotient_test \
              distributed_test
asan_space := $(subst ,, )
ASAN_TESTS_LIST = $(subst $(asan_space),;,$(strip $(ASAN_TESTS)))

asan: deps
	@CC=clang CXX=clang++ cmake $(call generator,build-asan) -S . -B build-asan -DCMAKE_BUILD_TYPE=None -DFLIPFLOP_CUDA=OFF \
	  -DFLIPFLOP_RC_CASES=$(SAN_CASES) -DFLIPFLOP_LONG_TESTS=OFF -DFLIPFLOP_TESTS_ONLY="$(ASAN_TESTS_LIST)" \
	  -DFLIPFLOP_FUZZ=ON -DFLIPFLOP_FUZZ_SHARED_LIBS=ON -DFLIPFLOP_EXAMPLES=OFF -DFLIPFLOP_FUZZ_REPLAYS=OFF \
	  -DFLIPFLOP_SANITIZE_THIRD_PARTY=OFF -DFLIPFLOP_PEERS_FLAGS=-O1 -DFLIPFLOP_MPI=OFF -DFLIPFLOP_CHECKED_TESTS=OFF \
	  -DFLIPFLOP_TESTS_OPT=-O0 -DFLIPFLOP_TESTS_FLAGS="-fno-sanitize=undefined,fuzzer-no-link" $(CCCL_ARG) \
	  -DCMAKE_CXX_FLAGS="$(ASAN_FLAGS)" -DCMAKE_C_FLAGS="$(ASAN_FLAGS)" \
	  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" > build-asan.configure.log 2>&1 || \
	  { cat build-asan.configure.log; exit 1; }
	cmake --build build-asan -j $(JOBS)
	cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure --no-tests=error -j $(JOBS) \
	  -E '^(bench\.|cli\.progress_line$$|cli\.demo$$)'

# asan-full: (not run by .ci/run since stop 77; make asan was this until then)
#       AddressSanitizer + UndefinedBehaviorSanitizer build of the whole test
#       suite but the test cases tagged [long] (the deterministic sweeps and the
#       large inputs, FLIPFLOP_LONG_TESTS=OFF), with fewer RapidCheck cases per
#       property: the sanitizers multiply run time; the Release suite (make
#       test) runs the [long] cases and the full count. Not built here (CI
#       time; measured: 2040 s of compilation on 2 cores before these cuts):
#       the thrust/OpenMP kernels and their tests (the fuzz stage runs them
#       under clang's ASan + UBSan, make tsan under TSan, make test in full),
#       the corpus replays (the fuzz stage replays the corpus first), the
#       example, the checked twin of the reference and its 14 *_checked_test
#       cases (FLIPFLOP_CHECKED_TESTS=OFF: 165 s of compile for 12 s of
#       tests; make test runs them); the CGAL/Qhull peer wrappers and
#       Catch2's main are compiled uninstrumented (FLIPFLOP_SANITIZE_THIRD_PARTY=OFF, 330 s of compile),
#       the peers with make test's Release flags through its ccache, whose
#       objects they then are (150 s of compile; peers/CMakeLists.txt),
#       the test drivers at -O0 (FLIPFLOP_TESTS_OPT; the libraries at -O1) and
#       without UBSan (FLIPFLOP_TESTS_FLAGS, stop 76; until then without its
#       null and alignment checks only): ASan still checks the drivers' memory
#       accesses, and every library keeps every UBSan check but vptr;
#       the benchmarks (ctest bench.*) are not run, nor cli.progress_line (the
#       terminal protocol of a 3*10^6-point reference run: 61 s under ASan;
#       make test runs it), nor cli.demo (make demo's job: 10^5-10^6-point
#       reference runs and peers, about 6 s in Release; make test runs it),
#       nor flipflop-mpi (FLIPFLOP_MPI=OFF: LeakSanitizer reports Open MPI's
#       own allocations at exit; the MPI-free steps of a distributed run, in
#       distributed_test, run here). Measured from a fresh clone
#       after these cuts: build about 615 s, ctest 341 s, make asan 956 s.
SAN_CASES ?= 100
# Compile time dominates this stage in CI; measured on one test file (g++ 12,
# -O1, ASan + UBSan): 58 s with -g, 37 s with -g1 (line tables: reports keep
# file:line), 28 s with -g1 and without UBSan's `vptr` check (dynamic-type
# checks on polymorphic objects: mostly CGAL's and Boost's; flipflop has one
# interface, ref::KernelPoint, whose misuse after destruction ASan reports).
# Every other UBSan check stays on.
# -fno-tree-pta: GCC's points-to analysis, whose time grows with the
# addressable variables ASan makes of every stack array, was 272 of the 595 s
# that predicates.cpp took to compile here (-ftime-report, the 2-core "AMD
# EPYC" VM, stop 76); without it 266 s. The tests run ASan's checks either
# way; only alias-based optimisations of -O1 are lost.
ASAN_FULL_FLAGS := -O1 -g1 -fno-omit-frame-pointer -fno-tree-pta -fsanitize=address,undefined -fno-sanitize=vptr -fno-sanitize-recover=undefined -fsanitize-recover=null
# Drivers make asan does not build (FLIPFLOP_TESTS_SKIP): the predicates'
# own arithmetic, whose run time is the test side's GMP oracle and whose
# compile time the heaviest (ASan stage, this VM: oracle_sos_test 45 s of
# compile + 134 s of tests, predicates_int_lattice_test 116 + 11,
# predicates_stages_test 71 + 34, filter_sensitivity_test 27 s for no case
# outside [long]). make test runs them in full; the fuzz stage runs the
# predicates (fuzz_predicates) under clang's ASan and UBSan's arithmetic checks.
ASAN_FULL_SKIP := oracle_sos_test;predicates_int_lattice_test;predicates_stages_test;filter_sensitivity_test

asan-full: deps
	@cmake $(call generator,build-asan-full) -S . -B build-asan-full -DCMAKE_BUILD_TYPE=None -DFLIPFLOP_CUDA=OFF -DFLIPFLOP_RC_CASES=$(SAN_CASES) -DFLIPFLOP_LONG_TESTS=OFF \
	  -DFLIPFLOP_OMP_KERNELS=OFF -DFLIPFLOP_EXAMPLES=OFF -DFLIPFLOP_FUZZ_REPLAYS=OFF -DFLIPFLOP_SANITIZE_THIRD_PARTY=OFF \
	  -DFLIPFLOP_TESTS_OPT=-O0 -DFLIPFLOP_TESTS_FLAGS="-fno-sanitize=undefined" -DFLIPFLOP_MPI=OFF \
	  -DFLIPFLOP_CHECKED_TESTS=OFF -DFLIPFLOP_TESTS_SKIP="$(ASAN_FULL_SKIP)" \
	  -DCMAKE_CXX_FLAGS="$(ASAN_FULL_FLAGS)" -DCMAKE_C_FLAGS="$(ASAN_FULL_FLAGS)" \
	  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" > build-asan-full.configure.log 2>&1 || \
	  { cat build-asan-full.configure.log; exit 1; }
	cmake --build build-asan-full -j $(JOBS)
	cd build-asan-full && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=$(CURDIR)/.ci/ubsan.supp ctest --output-on-failure --no-tests=error -j $(JOBS) \
	  -E '^(bench\.|cli\.progress_line$$|cli\.demo$$)' 

# tsan: ThreadSanitizer build (clang) of the multithreaded tests (TSAN_TESTS):
#       the TBB kernels (fork/join declared to TSan by kernels_cpu/tsan.hpp,
#       since Debian's libtbb is not instrumented) and the thrust/OpenMP kernels
#       built against LLVM's libomp, whose synchronisation TSan learns through
#       the Archer OMPT tool (libarcher.so, loaded by OMP_TOOL_LIBRARIES).
#       The [long] cases stay in: their large inputs reach the parallel paths;
#       but the cuda-omp deterministic sweeps (hull2 125 s, hull3 310 s under
#       TSan here; make test runs them) — their property, large-input and
#       rejection tests run the same OpenMP kernels here. The CGAL/Qhull peers
#       and Catch2's main uninstrumented, the peers at -O0: no selected case
#       calls a peer (peers/CMakeLists.txt). The test drivers at -O0
#       (FLIPFLOP_TESTS_OPT; the libraries they test at -O1): the selected
#       cases spend their time in the kernels, and the drivers were 514 of
#       the stage's 1372 s of compilation at -O1 (2-core "AMD EPYC" VM, stop 76).
TSAN_FLAGS := -O1 -g1 -fno-omit-frame-pointer -fsanitize=thread -fsanitize-ignorelist=$(CURDIR)/.ci/tsan.ignorelist
TSAN_TESTS := kernels_test predicates_device_test hull3_cpu_test hull3_witness_test hull2_cpu_test rt2_cpu_test certify_rt2_cpu_test rt2_witness_test \
              rt3_cpu_test certify_rt3_cpu_test distributed_test rtd_hull_d_test rtd_cavity_test \
              hull2_cuda_omp_test hull3_cuda_omp_test rt2_cuda_omp_test rt3_cuda_omp_test ghull_cuda_omp_test \
              ghull_voronoi_cuda_omp_test
# The TSan stage's test cases, one alternation (ctest's regular expressions
# allow at most nine groups: a nested selection compiled to nothing and the
# stage ran no test, which --no-tests=error now makes a failure).
TSAN_SELECT := ^(kernels|device predicates|hull2 cuda-omp: degenerate|hull2 cuda-omp: 16 OpenMP|hull2 cuda-omp: input|hull3 cuda-omp: degenerate|hull3 cuda-omp: every generator|hull3 cuda-omp: large|hull3 cuda-omp: 16 OpenMP|hull3 cuda-omp: an almost|hull3 cuda-omp: input|rt2 cuda-omp: degenerate|rt2 cuda-omp: every generator|rt2 cuda-omp: 20000|rt2 cuda-omp: 16 OpenMP|rt2 cuda-omp: input|rt3 cuda-omp: degenerate|rt3 cuda-omp: 1, 2 and 16|rt3 cuda-omp: input|ghull cuda-omp: degenerate|ghull cuda-omp: 1, 2 and 16|ghull cuda-omp: the verification|ghull stage 1: |hull[23] cpu: degenerate|hull[23] cpu: every generator|hull[23] cpu: large|hull[23] cpu: input|hull[23] cpu: the parallel certifier|hull3 witness: degenerate|hull3 witness: every generator|hull3 witness: flip-flop in rounds|hull3 witness: an? |rt2 cpu: degenerate|rt2 cpu: every generator|rt2 cpu: input|rt2 cpu: 20000|rt2 cpu: parallel insertion|rt2 cpu certify: many missing points|rt2 witness: degenerate|rt2 witness: every generator|rt2 witness: wrong|rt2 witness: stage 2b|rt3 cpu: degenerate|rt3 cpu: every 3D|rt3 cpu: lattices|rt3 cpu: 20000|rt3 cpu: parallel rounds|rt3 cpu: input|certify_rt3: small|certify_rt3: every 3D|distributed: |hull_d: the parallel|rtd cavity: integer grids|rtd cavity: degenerate and random|rtd cavity: in-place insertion in batches)
ARCHER     := $(firstword $(wildcard /usr/lib/llvm-14/lib/libarcher.so /usr/lib/llvm-*/lib/libarcher.so))

tsan: deps
	@test -n "$(ARCHER)" || { echo "tsan: libarcher.so (libomp-14-dev) not found"; exit 1; }
	@CC=clang CXX=clang++ cmake $(call generator,build-tsan) -S . -B build-tsan -DCMAKE_BUILD_TYPE=None -DFLIPFLOP_CUDA=OFF -DFLIPFLOP_TSAN=ON -DFLIPFLOP_LONG_TESTS=ON \
	  -DFLIPFLOP_SANITIZE_THIRD_PARTY=OFF -DFLIPFLOP_PEERS_FLAGS=-O0 -DFLIPFLOP_TESTS_OPT=-O0 \
	  -DFLIPFLOP_RC_CASES=$(SAN_CASES) -DCMAKE_CXX_FLAGS="$(TSAN_FLAGS)" -DCMAKE_C_FLAGS="$(TSAN_FLAGS)" $(CCCL_ARG) \
	  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" > build-tsan.configure.log 2>&1 || \
	  { cat build-tsan.configure.log; exit 1; }
	cmake --build build-tsan -j $(JOBS) --target $(TSAN_TESTS)
	cd build-tsan && OMP_TOOL_LIBRARIES=$(ARCHER) ARCHER_OPTIONS=verbose=1 \
	  TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$(CURDIR)/.ci/tsan.supp \
	  ctest --output-on-failure --no-tests=error -j $(JOBS) -R '$(TSAN_SELECT)'

sanitize: asan tsan

clean:
	rm -rf python/build $(BUILD) $(BUILD).configure.log build-asan build-asan.configure.log build-asan-full build-asan-full.configure.log build-tsan build-tsan.configure.log
