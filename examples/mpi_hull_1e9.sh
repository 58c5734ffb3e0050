#!/bin/bash
# mpi_hull_1e9.sh — the exact 3D hull of 10^9 points (24 GB of coordinates in
# 20 .npy shards) with `mpirun -n 2 flipflop-mpi` on a machine with less
# memory than the points (issue 37; measured in docs/distributed_mpi.md).
#
#   examples/mpi_hull_1e9.sh [DIR] [OUT]
#
# Generates the missing shards DIR/ball_01.npy .. ball_20.npy (flipflop gen
# ball, 5*10^7 points each, seeds 1..20: 24 GB on disk), then computes their
# hull with RANKS ranks (default 2) of one thread each, certified; OUT
# (default hull_1e9.txt) holds the triangles in global rows (shard-name order).
# Each rank maps only its own rows and gives the pages back block by block:
# its resident memory stays near one block (4 * 10^6 points, 96 MB) plus the
# hull vertices it keeps. Environment: BUILD (default build), SHARDS (20),
# ROWS (50000000), RANKS (2), THREADS (1).
set -euo pipefail
DIR=${1:-shards_1e9}
OUT=${2:-hull_1e9.txt}
BUILD=${BUILD:-build}
SHARDS=${SHARDS:-20}
ROWS=${ROWS:-50000000}
RANKS=${RANKS:-2}
THREADS=${THREADS:-1}
root=()
[ "$(id -u)" -eq 0 ] && root=(--allow-run-as-root)  # Open MPI refuses root without it

mkdir -p "$DIR"
for k in $(seq 1 "$SHARDS"); do
  f=$(printf "%s/ball_%02d.npy" "$DIR" "$k")
  [ -f "$f" ] || "$BUILD/flipflop" gen ball "$ROWS" --seed "$k" -o "$f"
done
echo "$(ls "$DIR"/*.npy | wc -l) shards, $(du -shL "$DIR" | cut -f1) in $DIR"
/usr/bin/time -f "mpirun: %e s wall" \
  mpirun "${root[@]}" -q -n "$RANKS" "$BUILD/flipflop-mpi" hull3 "$DIR" -o "$OUT" --threads "$THREADS" --stats
echo "$(wc -l < "$OUT") triangles in $OUT (certified on every rank before it was written)"
