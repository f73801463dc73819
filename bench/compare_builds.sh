#!/usr/bin/env bash
# Two builds of whitted side by side on the same scenes: runs A and B alternately, run after run,
# and prints the median of each phase --stats reports (build and render wall seconds) and of the
# whole process's CPU time (user + system: steadier than wall time on a shared machine), with B's
# ratios to A. For changes that must not slow the hot paths.
#
#   bench/compare_builds.sh -a WHITTED_A -b WHITTED_B [-n RUNS] [-x "EXTRA ARGS"] SCENE.sc ...
#
# Default: 9 runs; EXTRA ARGS go to both (default: --width 640 --height 480 --threads 2).
set -euo pipefail
runs=9 a="" b="" extra_text="--width 640 --height 480 --threads 2"
while getopts "a:b:n:x:" opt; do
  case "$opt" in
    a) a="$OPTARG" ;; b) b="$OPTARG" ;; n) runs="$OPTARG" ;; x) extra_text="$OPTARG" ;;
    *) sed -n '2,8p' "$0"; exit 1 ;;
  esac
done
shift $((OPTIND - 1))
read -r -a extra <<<"$extra_text"
scenes=("$@")
[[ -x "$a" && -x "$b" && ${#scenes[@]} -gt 0 ]] || { sed -n '2,8p' "$0"; exit 1; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
printf '%-14s %9s %9s %9s %9s %9s %9s %10s %8s\n' scene A_build B_build A_render B_render A_cpu B_cpu B/A_render B/A_cpu
for scene in "${scenes[@]}"; do
  name="$(basename "$scene" .sc)"
  for r in $(seq "$runs"); do
    for which in A B; do
      bin="$a"; [[ $which == B ]] && bin="$b"
      /usr/bin/time -f "cpu %U %S" -o "$tmp/time" "$bin" "$scene" -o "$tmp/o.png" -q --stats "${extra[@]}" 2>"$tmp/stats"
      awk '/^cpu/ { print $2 + $3 }' "$tmp/time" >>"$tmp/$which.cpu"
      sed -n 's/.*build \([0-9.]*\)s, render \([0-9.]*\)s.*/\1 \2/p' "$tmp/stats" >>"$tmp/$which.phases"
    done
  done
  ab=$(awk '{print $1}' "$tmp/A.phases" | median) bb=$(awk '{print $1}' "$tmp/B.phases" | median)
  ar=$(awk '{print $2}' "$tmp/A.phases" | median) br=$(awk '{print $2}' "$tmp/B.phases" | median)
  ac=$(median <"$tmp/A.cpu") bc_=$(median <"$tmp/B.cpu")
  printf '%-14s %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %10.3f %8.3f\n' "$name" "$ab" "$bb" "$ar" "$br" "$ac" "$bc_" \
    "$(echo "$br / $ar" | bc -l)" "$(echo "$bc_ / $ac" | bc -l)"
  rm -f "$tmp"/A.* "$tmp"/B.*
done
