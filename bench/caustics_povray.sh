#!/usr/bin/env bash
# The caustic of a glass ball (bench/scenes/caustic_ball.sc) rendered by whitted's path mode and by
# POV-Ray 3.7 with photons (caustic_ball.pov), compared on what both models agree on, not pixel for
# pixel: where the caustic is (its brightness-weighted centroid), how big (RMS radius, radius of half
# its light), how bright (the sum of its pixels; the floor is lit by the caustic alone) and its peak,
# with the wall time of each. Also whitted at a series of sample counts against its own long render:
# the caustic's error falling as the samples grow.
#
#   bench/caustics_povray.sh [-W WIDTH] [-H HEIGHT] [-s SPP] [-t THREADS] [-b BUILD_DIR]
#
# Defaults: 480×360, 64 samples per pixel, all hardware threads, build/ (needs build/apps/cli/whitted).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
width=480 height=360 spp=64 threads="$(nproc)" build="$here/../build"
while getopts "W:H:s:t:b:" opt; do
  case "$opt" in
    W) width="$OPTARG" ;; H) height="$OPTARG" ;; s) spp="$OPTARG" ;; t) threads="$OPTARG" ;; b) build="$OPTARG" ;;
    *) sed -n '2,11p' "$0"; exit 1 ;;
  esac
done
whitted="$build/apps/cli/whitted"
[ -x "$whitted" ] || { echo "caustics_povray: no $whitted (build it, or pass -b BUILD_DIR)" >&2; exit 1; }
if ! command -v povray >/dev/null; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "caustics_povray: installing povray" >&2
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends povray >&2
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
stats() { python3 "$here/caustic_stats.py" "$1"; }
now() { date +%s.%N; }

echo "# $(uname -n), $(nproc) cores, $(date -u '+%Y-%m-%d %H:%M UTC'), ${width}x${height}, $threads threads"
t0=$(now)
"$whitted" "$here/scenes/caustic_ball.sc" -o "$out/w.pfm" --mode path --spp "$spp" --width "$width" --height "$height" \
  --threads "$threads" >/dev/null
t1=$(now)
(cd "$out" && povray +I"$here/scenes/caustic_ball.pov" +O"$out/p.hdr" +FH +W"$width" +H"$height" -A +WT"$threads" -D -V \
  >/dev/null 2>&1)
t2=$(now)
printf 'whitted --mode path --spp %s\t%.1f s\t%s\n' "$spp" "$(echo "$t1 - $t0" | bc)" "$(stats "$out/w.pfm")"
printf 'POV-Ray photons (4M)\t%.1f s\t%s\n' "$(echo "$t2 - $t1" | bc)" "$(stats "$out/p.hdr")"

# Convergence: whitted at 4, spp/4 and spp samples against itself at 4 × spp. The reference shares its first
# passes (photons and samples) with each image, at most a quarter of it: the error is understated by
# up to that much for the largest image.
ref="$out/ref.pfm"
"$whitted" "$here/scenes/caustic_ball.sc" -o "$ref" --mode path --spp $((4 * spp)) --width "$width" \
  --height "$height" --threads "$threads" >/dev/null
for n in 4 $((spp / 4)) "$spp"; do
  t0=$(now)
  "$whitted" "$here/scenes/caustic_ball.sc" -o "$out/n.pfm" --mode path --spp "$n" --width "$width" --height "$height" \
    --threads "$threads" >/dev/null
  t1=$(now)
  printf 'whitted spp %s\t%.1f s\trelative RMS error against spp %s: %s\n' "$n" "$(echo "$t1 - $t0" | bc)" \
    $((4 * spp)) "$(python3 "$here/caustic_stats.py" --error "$out/n.pfm" "$ref")"
done
