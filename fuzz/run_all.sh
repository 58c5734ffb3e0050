#!/usr/bin/env bash
# fuzz/run_all.sh [SECONDS_PER_TARGET] [BUILD_DIR]
#
# Builds every libFuzzer target (fuzz/CMakeLists.txt, target `fuzzers`) with
# clang in BUILD_DIR (default build-fuzz; configured here with CC=clang
# CXX=clang++ when it has no CMakeCache.txt yet) and runs each for
# SECONDS_PER_TARGET seconds (default 60) on its seed corpus fuzz/corpus/<name>,
# FUZZ_PARALLEL (default nproc) targets at a time (a libFuzzer run is one
# thread; fuzz_kernels' TBB/OpenMP workers sleep between calls). Prints
# executions and exec/s per target; exits non-zero when any target crashed,
# hung (-timeout), ran out of memory (-rss_limit_mb) or found a property
# violation.
#
# Per target, under BUILD_DIR/fuzz-runs/<name>/: corpus/ (new inputs libFuzzer
# found; the repository corpus is only read), artifacts/ (crash reproducers),
# log.txt. To keep a reproducer, copy it into fuzz/corpus/<name>/: ctest
# (fuzz_<name>_replay) then replays it on every run.
#
# Environment: FUZZ_TARGETS (space-separated names: run only these),
# FUZZ_PARALLEL (targets run at once, default nproc), FUZZ_TIMEOUT (seconds
# per input, default 30), FUZZ_RSS_MB (default 2048), FUZZ_JOBS (build
# parallelism, default nproc), ASAN_OPTIONS (default malloc_context_size=0:
# allocation stacks are not recorded, which doubles the speed of the
# allocation-heavy exact predicates; rerun a reproducer with ASAN_OPTIONS= for
# full ASan reports).
set -uo pipefail

SECONDS_PER_TARGET=${1:-60}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${2:-build-fuzz}
case "$BUILD" in /*) ;; *) BUILD="$ROOT/$BUILD" ;; esac
TIMEOUT=${FUZZ_TIMEOUT:-30}
RSS_MB=${FUZZ_RSS_MB:-2048}
JOBS=${FUZZ_JOBS:-$(nproc)}
PARALLEL=${FUZZ_PARALLEL:-$(nproc)}

if ! [[ "$SECONDS_PER_TARGET" =~ ^[0-9]+$ ]] || [ "$SECONDS_PER_TARGET" -lt 1 ]; then
  echo "usage: fuzz/run_all.sh [SECONDS_PER_TARGET] [BUILD_DIR]" >&2
  exit 2
fi

start=$(date +%s)
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  echo "run_all: configuring $BUILD with clang"
  # the CCCL headers make deps fetched where no CUDA toolkit has them (Makefile: CCCL_DIR)
  cccl=()
  [ -d "$ROOT/build-deps/cccl/nvidia/cuda_cccl/include/thrust" ] &&
    cccl=(-DFLIPFLOP_CCCL_INCLUDE="$ROOT/build-deps/cccl/nvidia/cuda_cccl/include")
  # Ninja where installed (make deps installs it): the Makefile generator left
  # one of 2 cores idle behind the library order (519 -> 383 s here, stop 65)
  gen=()
  command -v ninja > /dev/null && gen=(-G Ninja)
  CC=clang CXX=clang++ cmake "${gen[@]}" -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release "${cccl[@]}" \
    -DFLIPFLOP_TESTS=OFF -DFLIPFLOP_CUDA=OFF -DFLIPFLOP_FUZZ=ON > "$BUILD.configure.log" 2>&1 ||
    { cat "$BUILD.configure.log"; exit 1; }
fi
echo "run_all: building the fuzz targets in $BUILD"
if ! cmake --build "$BUILD" -j "$JOBS" --target fuzzers > "$BUILD/fuzzers.build.log" 2>&1; then
  tail -n 40 "$BUILD/fuzzers.build.log"
  echo "run_all: build failed (is $BUILD configured with clang++? see $BUILD/fuzzers.build.log)" >&2
  exit 1
fi
built=$(date +%s)
echo "run_all: build took $((built - start)) s; ${SECONDS_PER_TARGET} s per target"

export ASAN_OPTIONS=${ASAN_OPTIONS-malloc_context_size=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
# OpenMP / TBB threads of fuzz_kernels: sleep instead of spinning between calls.
export OMP_WAIT_POLICY=passive KMP_BLOCKTIME=0

# One target: its run folder's log.txt and a one-line summary.txt (its row of
# the table) and failed marker; run in the background, PARALLEL at a time.
run_target() {
  local name=$1 dir=$2 exe=$3 run=$4 rc execs rate added rss status
  timeout --kill-after=10 $((SECONDS_PER_TARGET + TIMEOUT + 120)) \
    "$exe" -max_total_time="$SECONDS_PER_TARGET" -timeout="$TIMEOUT" -rss_limit_mb="$RSS_MB" \
    -print_final_stats=1 -artifact_prefix="$run/artifacts/" "$run/corpus" "$dir" > "$run/log.txt" 2>&1
  rc=$?
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$run/log.txt" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$run/log.txt" | tail -n 1)
  added=$(sed -n 's/^stat::new_units_added: *//p' "$run/log.txt" | tail -n 1)
  rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$run/log.txt" | tail -n 1)
  if [ "$rc" -eq 0 ]; then
    status="ok (${added:-0} new inputs, peak ${rss:-?} MB)"
  else
    status="FAILED (exit $rc)"
    touch "$run/failed"
  fi
  printf '%-14s %12s %10s  %s\n' "$name" "${execs:-?}" "${rate:-?}" "$status" > "$run/summary.txt"
}

failed=()
summary=()
names=()
for dir in "$ROOT"/fuzz/corpus/*/; do
  name=$(basename "$dir")
  if [ -n "${FUZZ_TARGETS:-}" ] && [[ " $FUZZ_TARGETS " != *" $name "* ]]; then
    continue
  fi
  exe="$BUILD/fuzz/fuzz_$name"
  run="$BUILD/fuzz-runs/$name"
  mkdir -p "$run/corpus" "$run/artifacts"
  rm -f "$run/summary.txt" "$run/failed"
  if [ ! -x "$exe" ]; then
    printf '%-14s %12s %10s  %s\n' "$name" "-" "-" "not built (see fuzz/CMakeLists.txt)" > "$run/summary.txt"
  else
    # each libFuzzer run is one thread: PARALLEL of them share the cores
    while [ "$(jobs -rp | wc -l)" -ge "$PARALLEL" ]; do wait -n; done
    run_target "$name" "$dir" "$exe" "$run" &
  fi
  names+=("$name")
done
wait
for name in "${names[@]}"; do
  run="$BUILD/fuzz-runs/$name"
  summary+=("$(cat "$run/summary.txt")")
  if [ -f "$run/failed" ]; then
    failed+=("$name")
    echo "---- fuzz_$name failed; last lines of $run/log.txt:"
    tail -n 40 "$run/log.txt"
    ls "$run/artifacts" 2>/dev/null | sed "s|^|  artifact: $run/artifacts/|"
  fi
done

echo
printf '%-14s %12s %10s  %s\n' target executions exec/s status
printf '%s\n' "${summary[@]}"
echo "run_all: total $(( $(date +%s) - start )) s (build $((built - start)) s)"
if [ ${#failed[@]} -gt 0 ]; then
  echo "run_all: FAILED: ${failed[*]}" >&2
  exit 1
fi
