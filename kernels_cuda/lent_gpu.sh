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
#   kernels_cuda/lent_gpu.sh bundle BUILD BASE   as above, and BASE (another
#       build's flipflop, e.g. before a change) as .devrun/flipflop_base for
#       the step ab.
#   kernels_cuda/lent_gpu.sh check [STEPS]   (there, in the repository root;
#       STEPS: comma-separated, of tests,bench,sanitizer,scaling,stages,ab,
#       profile,firstcall;
#       the first four by default, in that order — most wanted first, should
#       the call's time run out)
#       1. the device, the CPU;
#       2. the GPU test programs (kernels_cuda/*_cuda_test.cpp): byte-identical
#          to the reference over the generator families, degenerate ones too;
#       3. compute-sanitizer memcheck, racecheck, synccheck on flipflop
#          hull2|hull3|rt2|rt3 --backend cuda over small generated inputs;
#       4. flipflop bench hull3|hull2|rt2|dt2|dt3|rt3 on 10^7 points:
#          flipflop:cuda (with and without transfers) next to flipflop:cpu,
#          Qhull and CGAL on that machine's CPU, medians of 3 (CSV); then
#          flipflop:cpu on 10^6 points pinned to 1, 2, 4, 8 and 16 cores
#          (rt2/dt2 with the parallel insertions' rows).
#       5. (stages) the GPU kernels' time by stage on 10^7 points.
#       6. (ab) hull3 on 10^7 ball points, this build's flipflop:cuda rows
#          against flipflop_base's, runs alternating; then the time by step
#          of each (FLIPFLOP_GPU_STEPS=1 --stats, which times a second run).
#       7. (profile) Nsight Compute: the GPU time per kernel of one hull3
#          run on 10^6 ball points (ncu --print-summary per-kernel).
#       8. (firstcall) where a process's first call goes (0.35-0.47 s on an
#          H200 for a 10^7 hull3, 0.06 s for the next ones): the --stats
#          stages of the first call of fresh processes, hull3 then hull2 on
#          10^7 points, with lazy module loading (the default) and eager
#          (every kernel loaded when the context is made, inside "upload"):
#          the context's creation shows in "upload", a kernel's first launch
#          (module loading, the exact passes' stack) in the stage that makes it.
#       Logs and CSV under $OUT; one summary line per step on stdout. LG_TESTS,
#       LG_SANITIZE, LG_BENCH (space-separated names) narrow steps 2-4.
set -u
mode=${1:-check}
here=$(pwd)
B=$here/.devrun

if [ "$mode" = bundle ]; then
  build=${2:?usage: lent_gpu.sh bundle BUILD [BASE]}
  rm -rf "$B" && mkdir -p "$B/lib"
  [ -z "${3:-}" ] || strip -o "$B/flipflop_base" "$3" || exit 1
  progs="flipflop"
  for t in classify predicates hull2 rt2 hull3 rt3; do progs="$progs ${t}_cuda_test"; done
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
  # one compressed archive: the call's working tree is limited to 64 MiB
  (cd "$B" && tar cJf ../devrun.tar.xz . && rm -rf ./* && mv ../devrun.tar.xz .)
  grep -qx '/.devrun/' .git/info/exclude 2>/dev/null || echo '/.devrun/' >> .git/info/exclude
  du -sh "$B"
  exit 0
fi
[ -f "$B/devrun.tar.xz" ] && (cd "$B" && tar xJf devrun.tar.xz && rm devrun.tar.xz)

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

run_tests() {
echo "== GPU test programs (byte-identical to the reference)"
for t in ${LG_TESTS:-classify predicates hull2 rt2 hull3 rt3}; do
  s=$(date +%s%N)
  timeout "${LG_TEST_TIMEOUT:-100}" "$B/${t}_cuda_test" > "$OUT/test_$t.log" 2>&1
  rc=$?
  e=$(( ($(date +%s%N) - s) / 1000000 ))
  step "${t}_cuda_test" "rc=$rc  $(grep -c '^ok' "$OUT/test_$t.log") ok, $(grep -c '^FAIL' "$OUT/test_$t.log") FAIL, $e ms"
  grep -m5 -E '^FAIL|rror|what\(\)' "$OUT/test_$t.log"
  grep 'per-thread stack limit' "$OUT/test_$t.log" | sed 's/^/  /'
  # a program the device killed: its last announced case ("case FAMILY N ...")
  # again, alone, under memcheck, for the kernel and the fault
  last=$(grep '^case ' "$OUT/test_$t.log" | tail -1)
  if [ $rc -ne 0 ] && [ $rc -ne 1 ] && [ $rc -ne 77 ] && [ -n "$last" ]; then
    set -- $last
    echo "  last case: $last; under compute-sanitizer memcheck:"
    timeout 120 compute-sanitizer --tool memcheck --show-backtrace device "$B/${t}_cuda_test" "$2" "$3" \
      > "$OUT/memcheck_$t.log" 2>&1
    grep -m12 -E 'Invalid|Illegal|illegal|Error|at 0x|in .*\(|Program hit|Saved host' "$OUT/memcheck_$t.log" | cut -c1-300
  fi
done
cat "$OUT"/test_*.log > "$OUT/tests.log" && rm -f "$OUT"/test_*.log
cat "$OUT"/memcheck_*.log > "$OUT/memcheck.log" 2>/dev/null; rm -f "$OUT"/memcheck_*.log
}

run_sanitizer() {
echo "== compute-sanitizer (flipflop --backend cuda, small inputs)"
tmp=$(mktemp -d)
"$ff" gen disk 1000 --seed 5 -o "$tmp/p2.xyz"
"$ff" gen ball 1000 --seed 5 -o "$tmp/p3.xyz"
"$ff" gen square 1000 --seed 5 --weights 0,1e-5 -o "$tmp/w2.xyz"
"$ff" gen cube 1000 --seed 5 --weights 0,1e-3 -o "$tmp/w3.xyz"
"$ff" gen tiny2 50000 --seed 5 -o "$tmp/t2.xyz"  # subnormals: the exact stage inside the throw-away
: > "$OUT/sanitizer.log"
for tool in memcheck racecheck synccheck; do
  for job in "hull2 $tmp/p2.xyz" "hull2 $tmp/t2.xyz" "hull3 $tmp/p3.xyz" "hull3 $tmp/p3.xyz --algo ghull" \
             "rt2 $tmp/w2.xyz" "rt3 $tmp/w3.xyz"; do
    set -- $job
    case " ${LG_SANITIZE:-hull2 hull3 rt2 rt3} " in *" $1 "*) ;; *) continue ;; esac
    timeout 60 compute-sanitizer --tool "$tool" --error-exitcode 9 "$ff" "$@" --backend cuda -o "$tmp/out" \
      >> "$OUT/sanitizer.log" 2>&1
    rc=$?
    step "compute-sanitizer --tool $tool: $1 $(basename "$2") ${3:-} ${4:-}" "rc=$rc $(tail -1 "$OUT/sanitizer.log")"
    if [ $rc -eq 0 ]; then
      "$ff" "$1" "$2" --backend reference -o "$tmp/ref" 2>/dev/null
      cmp -s "$tmp/out" "$tmp/ref" || step "  output of $1 under $tool" "differs from --backend reference"
    fi
  done
done
rm -rf "$tmp"
}

run_bench() {
echo "== benchmarks (medians of 3; CSV in \$OUT/bench.csv)"
: > "$OUT/bench.csv"
bench() {
  case " ${LG_BENCH:-hull3 hull2 rt2 dt2 dt3 rt3} " in *" $1 "*) ;; *) return ;; esac
  echo "# flipflop bench $*" >> "$OUT/bench.csv"
  timeout 200 "$ff" bench "$@" --reps 3 --csv >> "$OUT/bench.csv" 2>> "$OUT/bench.err"
  echo "rc=$? flipflop bench $*"
}
bench hull3 --dist ball --n 10000000 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,qhull'
# gHull beside the GPU ffHull on §7.4's four distributions (issue 36 item 2)
for d in cube ball box sphere; do
  bench hull3 --dist $d --n 10000000 --run 'flipflop:cuda$,flipflop:cuda:,qhull'
done
bench hull2 --dist disk --n 10000000 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,qhull,cgal'
bench rt2 --dist square --n 10000000 --weights 0,1e-5 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,cgal'
bench dt2 --dist square --n 10000000 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,cgal'
bench dt3 --dist cube --n 10000000 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,cgal:delaunay_triangulation_3:parallel$'
bench rt3 --dist cube --n 10000000 --weights 0,1e-4 --run 'flipflop:cuda$,flipflop:cuda:,flipflop:cpu$,cgal:regular_triangulation_3:parallel$'
cat "$OUT/bench.csv"
}

run_stages() {
echo "== the GPU kernels' stages (flipflop ... --backend cuda --stats, the second of two runs)"
tmp=$(mktemp -d)
for job in "hull3 ball" "hull2 disk" "rt2 square --weights 0,1e-5"; do
  set -- $job
  kind=$1; shift
  "$ff" gen "$@" 10000000 --seed 1 -o "$tmp/in.npy" 2>> "$OUT/bench.err" || continue
  for rep in 1 2; do timeout 60 "$ff" "$kind" "$tmp/in.npy" --backend cuda --stats -o "$tmp/out" 2> "$tmp/stats"; done
  cat "$tmp/stats" | tee -a "$OUT/stages.log"
done
rm -rf "$tmp"
}

run_scaling() {
echo "== flipflop:cpu scaling with cores (taskset; CSV in \$OUT/scaling.csv)"
: > "$OUT/scaling.csv"
for job in "hull3 --dist ball" "rt2 --dist square --weights 0,1e-5" "dt2 --dist square"; do
  for cores in 0 0-1 0-3 0-7 0-15; do
    echo "# $job --n 1000000, cores $cores" >> "$OUT/scaling.csv"
    # rt2/dt2: the parallel insertions (territories, batches) next to the
    # default sequential one — which of them to make the default on many
    # cores is what this measures
    rows='flipflop:cpu$'
    case $job in rt2*|dt2*) rows='flipflop:cpu$,flipflop:territories,flipflop:batches' ;; esac
    timeout 120 taskset -c $cores "$ff" bench $job --n 1000000 --reps 3 --csv --run "$rows" \
      2>> "$OUT/bench.err" | tail -n +2 >> "$OUT/scaling.csv"
  done
done
cat "$OUT/scaling.csv"
}

run_ab() {
echo "== hull3, 10^7 ball: flipflop:cuda of this build (new) and of flipflop_base (base), alternating"
# without a flipflop_base in the bundle: this build's rows and steps alone
versions="new"
[ -x "$B/flipflop_base" ] && versions="new base" || echo "no flipflop_base in the bundle: this build alone"
tmp=$(mktemp -d)
"$ff" gen ball 10000000 --seed 1 -o "$tmp/in.npy"
: > "$OUT/ab.csv"
for rep in 1 2; do
  for v in $versions; do
    bin=$ff; [ $v = base ] && bin=$B/flipflop_base
    echo "# $v, pass $rep" >> "$OUT/ab.csv"
    timeout 60 "$bin" bench hull3 --dist ball --n 10000000 --reps 5 --csv --run 'flipflop:cuda$,flipflop:cuda:' \
      2>> "$OUT/bench.err" >> "$OUT/ab.csv"
  done
done
echo "# the CPU peers on this machine, the same input" >> "$OUT/ab.csv"
timeout 90 "$ff" bench hull3 --dist ball --n 10000000 --reps 3 --csv --run 'flipflop:cpu$,qhull' \
  2>> "$OUT/bench.err" >> "$OUT/ab.csv"
cat "$OUT/ab.csv"
for v in $versions; do
  bin=$ff; [ $v = base ] && bin=$B/flipflop_base
  # every kernel loaded at the context's start (in "upload"); the steps are
  # those of a second, timed run in the process (hull3.cuh)
  CUDA_MODULE_LOADING=EAGER FLIPFLOP_GPU_STEPS=1 timeout 60 "$bin" hull3 "$tmp/in.npy" --backend cuda --stats \
    -o "$tmp/out_$v" 2> "$tmp/stats"
  echo "$v: $(cat "$tmp/stats")" | tee -a "$OUT/stages.log"
done
if [ "$versions" != new ]; then
  cmp -s "$tmp/out_new" "$tmp/out_base" && echo "outputs of new and base identical" || echo "OUTPUTS OF NEW AND BASE DIFFER"
fi
rm -rf "$tmp"
}

run_profile() {
echo "== Nsight Compute: GPU time per kernel, flipflop hull3 --backend cuda, 10^6 ball"
tmp=$(mktemp -d)
"$ff" gen ball 1000000 --seed 1 -o "$tmp/in.npy"
ncu=$(command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | tail -1)
[ -n "$ncu" ] || { echo "no ncu here"; return; }
timeout 150 "$ncu" --metrics gpu__time_duration.sum --print-summary per-kernel \
  "$ff" hull3 "$tmp/in.npy" --backend cuda -o "$tmp/out" > "$OUT/ncu.txt" 2>&1
echo "rc=$? (ncu.txt: $(wc -l < "$OUT/ncu.txt") lines)"
rm -rf "$tmp"
}

run_firstcall() {
echo "== the first call of a process: --stats stages of fresh processes (lazy, then eager module loading)"
tmp=$(mktemp -d)
"$ff" gen ball 10000000 --seed 1 -o "$tmp/p3.npy"
"$ff" gen disk 10000000 --seed 1 -o "$tmp/p2.npy"
for loading in LAZY EAGER LAZY EAGER; do
  for job in "hull3 $tmp/p3.npy" "hull2 $tmp/p2.npy"; do
    set -- $job
    s=$(date +%s%N)
    CUDA_MODULE_LOADING=$loading timeout 60 "$ff" "$1" "$2" --backend cuda --stats -o "$tmp/out" 2> "$tmp/stats"
    e=$(( ($(date +%s%N) - s) / 1000000 ))
    echo "$1 $loading, process $e ms: $(grep -h 'stages' "$tmp/stats")" | tee -a "$OUT/firstcall.log"
  done
done
rm -rf "$tmp"
}

steps=${2:-tests,bench,sanitizer,scaling}
for step_name in ${steps//,/ }; do "run_$step_name"; done
