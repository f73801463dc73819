#!/usr/bin/env bash
# Time to a given caustic error, whitted against Blender Cycles, on the emissive-sphere variant of the
# caustic scene (bench/scenes/caustic_ball_emissive.sc: a glass ball under an emissive sphere over a
# white floor; Cycles has no photons, its caustic is found by paths that refract onto the emitter).
# Each renderer renders its runs (the two alternating) and its own reference with 64 times the
# samples of its longest run and another seed; bench/caustic_error.py measures each run's relative
# RMS error over the caustic's box against its renderer's reference and the time (render seconds:
# whitted's --stats without the parse, Cycles' render call) each needs to reach Cycles' error at its
# most samples.
#
#   bench/caustics_cycles.sh [-w "WHITTED_SPP ..."] [-c "CYCLES_SPP ..."] [-t THREADS] [-W WIDTH]
#                            [-H HEIGHT] [-d DEPTH] [-b BUILD_DIR] [-k KEEP_DIR]
#
# Defaults: whitted spp "1 2 4 8 16", Cycles spp "16 64 256", 2 threads, 160x120, depth 16, build/.
# Blender 3.4 (Debian's blender) is a benchmark anchor only, installed by bench/compare_cycles.sh's
# rule when missing, never a dependency of whitted.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
wspps="1 2 4 8 16" cspps="16 64 256" threads=2 width=160 height=120 depth=16 build="$here/../build" keep=""
while getopts "w:c:t:W:H:d:b:k:" opt; do
  case "$opt" in
    w) wspps="$OPTARG" ;; c) cspps="$OPTARG" ;; t) threads="$OPTARG" ;; W) width="$OPTARG" ;;
    H) height="$OPTARG" ;; d) depth="$OPTARG" ;; b) build="$OPTARG" ;; k) keep="$OPTARG" ;;
    *) sed -n '2,17p' "$0"; exit 1 ;;
  esac
done
scene="$here/scenes/caustic_ball_emissive.sc"
box="0.25 0.75 0.36 0.80"  # the caustic under the ball, fractions of width and height
whitted="$build/apps/cli/whitted"
[ -x "$whitted" ] || { echo "caustics_cycles: no $whitted (build it, or pass -b BUILD_DIR)" >&2; exit 1; }
need=()
command -v blender >/dev/null || need+=(blender)
command -v bc >/dev/null || need+=(bc)
/usr/bin/python3 -c 'import numpy' 2>/dev/null || need+=(python3-numpy)
if ((${#need[@]})); then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "caustics_cycles: installing ${need[*]}" >&2
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >&2
fi
out="$(mktemp -d)"; [ -z "$keep" ] || { out="$keep"; mkdir -p "$out"; }
[ -n "$keep" ] || trap 'rm -rf "$out"' EXIT
now() { date +%s.%N; }
bl() { blender -b --factory-startup --python-exit-code 1 --python "$@"; }

# cycles OUT.exr SPP SEED / whitted OUT.pfm SPP SEED: render; set wall and render (seconds).
cycles() {
  local t0; t0=$(now)
  bl "$here/sc_to_blender.py" -- "$scene" -o "$1" --width "$width" --height "$height" --spp "$2" \
    --max-depth "$depth" --threads "$threads" --seed "$3" > "$out/cycles.log" 2>&1 ||
    { echo "caustics_cycles: Cycles failed:" >&2; tail -20 "$out/cycles.log" >&2; exit 1; }
  wall=$(echo "$(now) - $t0" | bc -l)
  render=$(awk '/^cycles_render_seconds/ { print $2 }' "$out/cycles.log")
}
whitted() {
  local t0; t0=$(now)
  "$whitted" "$scene" -o "$1" --mode path --width "$width" --height "$height" --spp "$2" --seed "$3" \
    --max-depth "$depth" --threads "$threads" --stats -q > "$out/whitted.log" 2>&1 ||
    { echo "caustics_cycles: whitted failed:" >&2; tail -20 "$out/whitted.log" >&2; exit 1; }
  wall=$(echo "$(now) - $t0" | bc -l)
  render=$(awk '{ for (i = 1; i < NF; i++) if ($i ~ /^(flatten|textures|meshes|build|render)$/ && $(i + 1) ~ /^[0-9.]+s,?$/) {
                    v = $(i + 1); gsub(/[s,]/, "", v); t += v; n++ } }
                END { if (n) printf "%.3f\n", t }' "$out/whitted.log")
}

echo "$(blender --version 2>/dev/null | grep -m1 -o 'Blender [0-9.]*') (Cycles, CPU) and whitted $(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo '?')"
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) hardware threads; $(date -u '+%Y-%m-%d %H:%M') UTC; load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "${width}x${height}, max depth $depth, $threads threads; whitted spp $wspps, Cycles spp $cspps; references 64x the longest run"
runs="$out/runs.tsv"; : > "$runs"
wmax=$(echo $wspps | tr ' ' '\n' | sort -n | tail -1); cmax=$(echo $cspps | tr ' ' '\n' | sort -n | tail -1)
wlist=($wspps); clist=($cspps)
for ((i = 0; i < ${#wlist[@]} || i < ${#clist[@]}; i++)); do  # the two alternating
  if ((i < ${#wlist[@]})); then
    whitted "$out/whitted_${wlist[i]}.pfm" "${wlist[i]}" 0
    printf 'whitted\trun\t%s\t%s\t%s\t%s\n' "${wlist[i]}" "$wall" "$render" "$out/whitted_${wlist[i]}.pfm" >> "$runs"
  fi
  if ((i < ${#clist[@]})); then
    cycles "$out/cycles_${clist[i]}.exr" "${clist[i]}" 0
    printf 'cycles\trun\t%s\t%s\t%s\t%s\n' "${clist[i]}" "$wall" "$render" "$out/cycles_${clist[i]}.exr" >> "$runs"
  fi
done
echo "(runs done at $(date -u +%H:%M) UTC, load $(cut -d' ' -f1 /proc/loadavg); references next)"
whitted "$out/whitted_ref.pfm" "$((64 * wmax))" 1
printf 'whitted\tref\t%s\t%s\t%s\t%s\n' "$((64 * wmax))" "$wall" "$render" "$out/whitted_ref.pfm" >> "$runs"
cycles "$out/cycles_ref.exr" "$((64 * cmax))" 1
printf 'cycles\tref\t%s\t%s\t%s\t%s\n' "$((64 * cmax))" "$wall" "$render" "$out/cycles_ref.exr" >> "$runs"
bl "$here/caustic_error.py" -- "$runs" $box 2> "$out/error.log" | grep -v '^Blender \|^Read prefs\|^Blender quit' ||
  { echo "caustics_cycles: caustic_error.py failed:" >&2; tail -20 "$out/error.log" >&2; exit 1; }
echo "(load after: $(cut -d' ' -f1-3 /proc/loadavg))"
