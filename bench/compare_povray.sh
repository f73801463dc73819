#!/usr/bin/env bash
# Renders each scene with whitted and with POV-Ray 3.7 at the same size, recursion depth and
# thread count, alternating the two renderers run by run, and prints the median wall time of the
# whole process (parse + build + render + write) of each and their ratio.
#
#   bench/compare_povray.sh [-n RUNS] [-t THREADS] [-W WIDTH] [-H HEIGHT] [-d DEPTH] [-b BUILD_DIR]
#                           [-a N [-T THRESHOLD]] [SCENE.sc ...]
#
# Defaults: 5 runs, all hardware threads, 640×480, depth 5, build/ (needs build/apps/cli/whitted),
# scenes bench/scenes/small.sc, grid10k.sc and mirrors.sc. Every SCENE.sc needs a SCENE.pov next
# to it. Depth: whitted's --max-depth D traces the camera ray plus D bounces; POV-Ray counts the
# camera ray as level 1, so it gets max_trace_level D+1 (patched into a temporary copy). No
# anti-aliasing in either unless -a N (N >= 2): whitted --aa N (N x N rays per pixel on a regular
# grid of sub-pixel centres) against POV-Ray's non-recursive method +AM1 +RN -J (N x N rays on the
# same grid plus the centre ray, no jitter), every pixel (whitted threshold 0, POV-Ray +A0.0), or
# with -T T adaptive: whitted --aa-threshold T, POV-Ray +AT (not the same test: whitted compares the
# largest channel difference with the 4 neighbours, POV-Ray the sum over the channels, gamma-encoded,
# with the left and upper neighbours; see bench/RESULTS.md for how many pixels each supersamples).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
runs=5 threads="$(nproc)" width=640 height=480 depth=5 build="$here/../build" aa=1 aa_threshold=0
while getopts "n:t:W:H:d:b:a:T:" opt; do
  case "$opt" in
    n) runs="$OPTARG" ;; t) threads="$OPTARG" ;; W) width="$OPTARG" ;; H) height="$OPTARG" ;;
    d) depth="$OPTARG" ;; b) build="$OPTARG" ;; a) aa="$OPTARG" ;; T) aa_threshold="$OPTARG" ;;
    *) sed -n '2,18p' "$0"; exit 1 ;;
  esac
done
shift $((OPTIND - 1))
w_aa=() p_aa=(-A) aa_desc="no AA"
if ((aa > 1)); then
  w_aa=(--aa "$aa" --aa-threshold "$aa_threshold")
  p_threshold="$aa_threshold"; [[ "$p_threshold" == *.* ]] || p_threshold="$p_threshold.0"  # POV-Ray rejects +A0
  p_aa=(+AM1 +A"$p_threshold" +R"$aa" -J)
  aa_desc="AA ${aa}x${aa} (whitted --aa $aa --aa-threshold $aa_threshold; POV-Ray ${p_aa[*]})"
fi
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=("$here/scenes/small.sc" "$here/scenes/grid10k.sc" "$here/scenes/mirrors.sc")
whitted="$build/apps/cli/whitted"
[ -x "$whitted" ] || { echo "compare_povray: no $whitted (build it, or pass -b BUILD_DIR)" >&2; exit 1; }
# POV-Ray 3.7 (Debian's povray) and bc (the arithmetic below), installed when missing.
need=()
command -v povray >/dev/null || need+=(povray)
command -v bc >/dev/null || need+=(bc)
if ((${#need[@]})); then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "compare_povray: installing ${need[*]}" >&2
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >&2
fi
povray_version="$(povray --version 2>&1 | grep -o -m1 'POV-Ray [0-9.]*' || true)"
case "$povray_version" in
  "POV-Ray 3.7"*) ;;
  *) echo "compare_povray: need POV-Ray 3.7, found '${povray_version:-nothing}'" >&2; exit 1 ;;
esac

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

now() { date +%s.%N; }
median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

echo "$povray_version; machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) hardware threads; load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "size ${width}x${height}, depth $depth (POV-Ray max_trace_level $((depth + 1))), $threads threads, $aa_desc, $runs alternating runs each, median wall time of the whole process"
printf "%-14s %12s %12s %9s\n" scene whitted_s povray_s ratio
for sc in "${scenes[@]}"; do
  pov="${sc%.sc}.pov"
  [ -f "$pov" ] || { echo "compare_povray: no $pov for $sc" >&2; exit 1; }
  sed -E "s/max_trace_level [0-9]+/max_trace_level $((depth + 1))/" "$pov" > "$tmp/scene.pov"
  : > "$tmp/w.times"; : > "$tmp/p.times"
  for ((i = 0; i < runs; i++)); do
    t0=$(now)
    "$whitted" "$sc" -o "$tmp/w.png" --width "$width" --height "$height" --max-depth "$depth" --threads "$threads" "${w_aa[@]}" -q
    t1=$(now)
    povray +I"$tmp/scene.pov" +O"$tmp/p.png" +W"$width" +H"$height" "${p_aa[@]}" -D -V -GA +WT"$threads" 2>"$tmp/povray.log" ||
      { echo "compare_povray: POV-Ray failed on $pov:" >&2; cat "$tmp/povray.log" >&2; exit 1; }
    t2=$(now)
    echo "$t1 - $t0" | bc -l >> "$tmp/w.times"
    echo "$t2 - $t1" | bc -l >> "$tmp/p.times"
  done
  w=$(median < "$tmp/w.times"); p=$(median < "$tmp/p.times")
  printf "%-14s %12.3f %12.3f %8.1fx\n" "$(basename "$sc" .sc)" "$w" "$p" "$(echo "$p / $w" | bc -l)"
done
