#!/usr/bin/env bash
# whitted-mpi on one machine: protocol cost (1 rank × 2 threads against 2 ranks × 1 thread),
# set-up, master service time, bytes per tile, idle time; oversubscribed runs for overhead only.
# Usage: bench/mpi_bench.sh [BUILD_DIR]   (a Release build with whitted and whitted-mpi)
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
whitted=$build/apps/cli/whitted
mpi=$build/apps/mpi/whitted-mpi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# --bind-to none: Open MPI binds each rank to one core when there are at most two ranks, so one
# rank's two threads would share a core (half speed: not the protocol's cost).
mpirun=(mpirun --oversubscribe --bind-to none --allow-run-as-root --mca btl self,vader)

run() {  # label, then the arguments after the scene
    local label=$1 n=$2 threads=$3 scene=$4
    shift 4
    local t0=$(date +%s.%N)
    "${mpirun[@]}" -np "$n" "$mpi" "$scene" -o "$out/mpi.png" -q --stats --threads "$threads" "$@" 2>"$out/log"
    local t1=$(date +%s.%N)
    cmp -s "$out/mpi.png" "$out/ref.png" || { echo "$label: differs from whitted"; exit 1; }
    printf '%s: %d ranks x %d threads, wall %.2fs\n' "$label" "$n" "$threads" "$(echo "$t1 - $t0" | bc)"
    grep -E "^(ranks|master|rank [0-9])" "$out/log" | sed 's/^/    /'
}

job() {  # label, scene, whitted options
    local label=$1 scene=$2
    shift 2
    local t0=$(date +%s.%N)
    "$whitted" "$scene" -o "$out/ref.png" -q --stats "$@" 2>"$out/log"
    local t1=$(date +%s.%N)
    printf '%s: whitted, 2 threads, wall %.2fs; %s\n' "$label" "$(echo "$t1 - $t0" | bc)" "$(grep -o 'render [0-9.]*s' "$out/log")"
    run "$label" 1 2 "$scene" "$@"
    run "$label" 2 1 "$scene" "$@"
    run "$label" 4 1 "$scene" "$@"   # oversubscribed: 4 ranks on 2 cores
    run "$label" 8 1 "$scene" "$@"   # oversubscribed: 8 ranks on 2 cores
}

job "1080p Whitted (showcase)" "$root/scenes/showcase.sc" --width 1920 --height 1080
job "effects --spp 64 (640x360)" "$root/tests/mpi/effects.sc" --width 640 --height 360 --spp 64
