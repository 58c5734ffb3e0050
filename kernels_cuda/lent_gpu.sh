#!/usr/bin/env bash
# lent_gpu.sh — the GPU validation of kernels_cuda/ on a lent machine, in one
# short call (the workplace's device tool: 15 minutes of device time, nvcc's
# sm_90 build of the algorithm kernels takes 30+ minutes on the 2-core VM, so
# everything is compiled here and carried).
#
#   kernels_cuda/lent_gpu.sh bundle BUILD   (here) copy the CUDA build's test
#       programs and flipflop, stripped, and every shared library they load
#       except glibc's and the driver's into .devrun/ (ignored by git through
#       .git/info/exclude; carried with the call). BUILD was configured with
#       -DFLIPFLOP_CUDA_ALGORITHMS=ON (make cuda).
#   kernels_cuda/lent_gpu.sh check [all|tests|bench]   (there, in the repository
#       root; all: the four steps, tests: 1-3, bench: 1 and 4)
#       1. the device, the CPU;
#       2. the GPU test programs (kernels_cuda/*_cuda_test.cpp): byte-identical
#          to the reference over the generator families, degenerate ones too;
#       3. compute-sanitizer memcheck, racecheck, synccheck on flipflop
#          hull2|hull3|rt2 --backend cuda over small generated inputs;
#       4. flipflop bench hull3|hull2|rt2|dt2 on 10^7 points:
#          flipflop:cuda (with and without transfers) next to flipflop:cpu,
#          Qhull and CGAL on that machine's CPU, medians of 3 (CSV); then
#          flipflop:cpu on 10^6 points pinned to 1, 2, 4, 8 and 16 cores.
#       Logs and CSV under $OUT; one summary line per step on stdout.
set -u
mode=${1:-check}
here=$(pwd)
B=$here/.devrun

if [ "$mode" = bundle ]; then
  build=${2:?usage: lent_gpu.sh bundle BUILD}
  rm -rf "$B" && mkdir -p "$B/lib"
  progs="flipflop"
  for t in classify predicates hull2 rt2 hull3; do progs="$progs ${t}_cuda_test"; done
  for p in $progs; do
    f=$(find "$build" -name "$p" -type f -perm -u+x | head -1)
    [ -n "$f" ] || { echo "lent_gpu.sh: $p not built in $build" >&2; exit 1; }
    strip -o "$B/$p" "$f"
    ldd "$f" | awk '$3 ~ /^\// {print $3}' | while read -r lib; do
      case $(basename "$lib") in
        libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|ld-linux*|libcuda.so*) ;;
        *) cp -L -n "$lib" "$B/lib/" ;;
      esac
    done
  done
  grep -qx '/.devrun/' .git/info/exclude 2>/dev/null || echo '/.devrun/' >> .git/info/exclude
  du -sh "$B"
  exit 0
fi

: "${OUT:=/tmp/lent_gpu_out}"
mkdir -p "$OUT"
export PATH=$PATH:/usr/local/cuda/bin
export LD_LIBRARY_PATH=$B/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
ff=$B/flipflop
step() { printf '%-58s %s\n' "$1" "$2"; }

echo "== device"
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv,noheader
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2) x $(nproc)"
if ! "$ff" --help > /dev/null 2> "$OUT/start.log"; then
  echo "flipflop does not start here:"; cat "$OUT/start.log"; ldd "$ff"; exit 1
fi

what=${2:-all}
if [ "$what" != bench ]; then
echo "== GPU test programs (byte-identical to the reference)"
for t in classify predicates hull2 rt2 hull3; do
  s=$(date +%s%N)
  timeout 150 "$B/${t}_cuda_test" > "$OUT/test_$t.log" 2>&1
  rc=$?
  e=$(( ($(date +%s%N) - s) / 1000000 ))
  step "${t}_cuda_test" "rc=$rc  $(grep -c '^ok' "$OUT/test_$t.log") ok, $(grep -c '^FAIL' "$OUT/test_$t.log") FAIL, $e ms"
  grep -m5 -E '^FAIL|rror|what\(\)' "$OUT/test_$t.log"
done
cat "$OUT"/test_*.log > "$OUT/tests.log" && rm -f "$OUT"/test_*.log

echo "== compute-sanitizer (flipflop --backend cuda, small inputs)"
tmp=$(mktemp -d)
"$ff" gen disk 1000 --seed 5 -o "$tmp/p2.xyz"
"$ff" gen ball 1000 --seed 5 -o "$tmp/p3.xyz"
"$ff" gen square 1000 --seed 5 --weights 0,1e-5 -o "$tmp/w2.xyz"
: > "$OUT/sanitizer.log"
for tool in memcheck racecheck synccheck; do
  for job in "hull2 $tmp/p2.xyz" "hull3 $tmp/p3.xyz" "rt2 $tmp/w2.xyz"; do
    set -- $job
    timeout 100 compute-sanitizer --tool "$tool" --error-exitcode 9 "$ff" "$1" "$2" --backend cuda -o "$tmp/out" \
      >> "$OUT/sanitizer.log" 2>&1
    rc=$?
    step "compute-sanitizer --tool $tool: $1" "rc=$rc $(tail -1 "$OUT/sanitizer.log")"
    "$ff" "$1" "$2" --backend reference -o "$tmp/ref" 2>/dev/null
    cmp -s "$tmp/out" "$tmp/ref" || step "  output of $1 under $tool" "differs from --backend reference"
  done
done
rm -rf "$tmp"
fi
[ "$what" = tests ] && exit 0

echo "== benchmarks (medians of 3; CSV in \$OUT/bench.csv)"
: > "$OUT/bench.csv"
bench() {
  echo "# flipflop bench $*" >> "$OUT/bench.csv"
  timeout 200 "$ff" bench "$@" --reps 3 --csv >> "$OUT/bench.csv" 2>> "$OUT/bench.err"
  echo "rc=$? flipflop bench $*"
}
bench hull3 --dist ball --n 10000000 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,qhull'
bench hull2 --dist disk --n 10000000 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,qhull,cgal'
bench rt2 --dist square --n 10000000 --weights 0,1e-5 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,cgal'
bench dt2 --dist square --n 10000000 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,cgal'
echo "== flipflop:cpu scaling with cores (taskset; CSV in \$OUT/scaling.csv)"
: > "$OUT/scaling.csv"
for job in "hull3 --dist ball" "rt2 --dist square --weights 0,1e-5" "dt2 --dist square"; do
  for cores in 0 0-1 0-3 0-7 0-15; do
    echo "# $job --n 1000000, cores $cores" >> "$OUT/scaling.csv"
    timeout 60 taskset -c $cores "$ff" bench $job --n 1000000 --reps 3 --csv --run 'flipflop:cpu$' \
      2>> "$OUT/bench.err" | tail -1 >> "$OUT/scaling.csv"
  done
done
cat "$OUT/bench.csv" "$OUT/scaling.csv"
