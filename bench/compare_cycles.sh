#!/usr/bin/env bash
# Renders each scene with `whitted --mode path` and with Blender Cycles (bench/sc_to_blender.py) at
# the same size, samples per pixel, bounce limit and thread count, and prints, per scene, the time
# and the error against a converged Cycles reference of each at each spp, the time each needs to
# reach the other's error, and whether the two converged images agree within noise (bench/image_error.py
# says how each number is computed).
#
#   bench/compare_cycles.sh [-s "SPP ..."] [-R REF_SPP] [-w WHITTED_REF_SPP] [-t THREADS] [-W WIDTH]
#                           [-H HEIGHT] [-d DEPTH] [-b BUILD_DIR] [-k KEEP_DIR] [SCENE.sc ...]
#
# Defaults: spp "16 64 256", reference 4096 spp, 2 threads, 128x128, depth 64, build/ (needs
# build/apps/cli/whitted), scenes bench/scenes/cornell.sc and bench/scenes/quadrics.sc.
# The reference is Cycles': two renders of REF_SPP/2 with different seeds (seed 1 and 2; the
# low-spp Cycles runs use seed 0, so they are independent of it), averaged; the pair also gives
# the reference's own noise. whitted renders W/2 and W spp (W = WHITTED_REF_SPP, default REF_SPP)
# for the agreement check of the converged images (whitted has no seed; its sample sequence is
# nested, which gives its noise the same way). Images go to
# KEEP_DIR/SCENE/ when -k is given (else a temporary directory, removed at the end); a Cycles reference
# found there is reused while the scene, the converter, Blender and the settings are unchanged.
# Blender 3.4 (Debian's blender) and numpy are installed when missing; they are a benchmark anchor
# only, not dependencies of whitted (so not in scripts/install-deps.sh).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
spps="16 64 256" ref_spp=4096 wref_spp="" threads=2 width=128 height=128 depth=64 build="$here/../build" keep=""
while getopts "s:R:w:t:W:H:d:b:k:" opt; do
  case "$opt" in
    s) spps="$OPTARG" ;; R) ref_spp="$OPTARG" ;; w) wref_spp="$OPTARG" ;; t) threads="$OPTARG" ;; W) width="$OPTARG" ;;
    H) height="$OPTARG" ;; d) depth="$OPTARG" ;; b) build="$OPTARG" ;; k) keep="$OPTARG" ;;
    *) sed -n '2,21p' "$0"; exit 1 ;;
  esac
done
shift $((OPTIND - 1))
wref_spp="${wref_spp:-$ref_spp}"
((ref_spp % 2 == 0 && wref_spp % 2 == 0)) || { echo "compare_cycles: -R and -w must be even (two halves)" >&2; exit 1; }
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=("$here/scenes/cornell.sc" "$here/scenes/quadrics.sc")
whitted="$build/apps/cli/whitted"
[ -x "$whitted" ] || { echo "compare_cycles: no $whitted (build it, or pass -b BUILD_DIR)" >&2; exit 1; }
# Blender (Debian's blender, 3.4), bc (the arithmetic below) and numpy (bench/image_error.py, run by
# Blender's Python), installed when missing.
need=()
command -v blender >/dev/null || need+=(blender)
command -v bc >/dev/null || need+=(bc)
/usr/bin/python3 -c 'import numpy' 2>/dev/null || need+=(python3-numpy)  # Blender's Python is the system's
if ((${#need[@]})); then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "compare_cycles: installing ${need[*]}" >&2
  $sudo apt-get update -qq && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >&2
fi
blender_version="$(blender --version 2>/dev/null | grep -o -m1 'Blender [0-9.]*' || true)"
case "$blender_version" in
  "Blender 3."* | "Blender 4."*) ;;
  *) echo "compare_cycles: need Blender 3.4 or later, found '${blender_version:-nothing}'" >&2; exit 1 ;;
esac

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

now() { date +%s.%N; }
bl() { blender -b --factory-startup --python-exit-code 1 --python "$@"; }

# cycles OUT.exr SCENE SPP SEED: renders, sets wall and render (seconds).
cycles() {
  local t0 t1
  t0=$(now)
  bl "$here/sc_to_blender.py" -- "$2" -o "$1" --width "$width" --height "$height" --spp "$3" \
    --max-depth "$depth" --threads "$threads" --seed "$4" > "$tmp/cycles.log" 2>&1 ||
    { echo "compare_cycles: Cycles failed on $2:" >&2; tail -20 "$tmp/cycles.log" >&2; exit 1; }
  t1=$(now)
  wall=$(echo "$t1 - $t0" | bc -l)
  render=$(awk '/^cycles_render_seconds/ { print $2 }' "$tmp/cycles.log")
}

# whitted OUT.pfm SCENE SPP: renders, sets wall and render (seconds: --stats' render time).
whitted() {
  local t0 t1
  t0=$(now)
  "$whitted" "$2" -o "$1" --mode path --width "$width" --height "$height" --spp "$3" \
    --max-depth "$depth" --threads "$threads" --stats -q > "$tmp/whitted.log" 2>&1 ||
    { echo "compare_cycles: whitted failed on $2:" >&2; tail -20 "$tmp/whitted.log" >&2; exit 1; }
  t1=$(now)
  wall=$(echo "$t1 - $t0" | bc -l)
  # --stats: "parse 0.001s, flatten 0.000s, textures 0.000s, meshes 0.000s, build 0.000s, render 0.010s (2 threads)";
  # everything but the parse, as Cycles' time has its scene sync and BVH build but not our converter.
  render=$(awk '{ for (i = 1; i < NF; i++) if ($i ~ /^(flatten|textures|meshes|build|render)$/ && $(i + 1) ~ /^[0-9.]+s,?$/) {
                    v = $(i + 1); gsub(/[s,]/, "", v); t += v; n++ } }
                END { if (n) printf "%.3f\n", t }' "$tmp/whitted.log")
  [ -n "$render" ] || { echo "compare_cycles: no render time in whitted --stats:" >&2; cat "$tmp/whitted.log" >&2; exit 1; }
  awk '/^samples rejected/ && $NF != 0 { print "compare_cycles: whitted: " $0 }' "$tmp/whitted.log" >&2
}

echo "$blender_version (Cycles, CPU); machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) hardware threads; load: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "size ${width}x${height}, max depth $depth bounces, $threads threads; spp $spps; reference Cycles $ref_spp spp; whitted converged $wref_spp spp"
for sc in "${scenes[@]}"; do
  name="$(basename "$sc" .sc)"
  out="$tmp/$name"; [ -z "$keep" ] || out="$keep/$name"
  mkdir -p "$out"
  runs="$out/runs.tsv"; : > "$runs"
  echo
  echo "== $name ($(date -u +%H:%M:%S) UTC, load $(cut -d' ' -f1 /proc/loadavg))"
  half=$((ref_spp / 2))
  # The Cycles reference is kept in KEEP_DIR and reused while the scene, the converter, Blender and
  # the settings are the same (its render time is then the one measured when it was made).
  stamp="$(cat "$sc" "$here/sc_to_blender.py" | sha256sum | cut -c1-16) ${width}x$height spp $half x2 depth $depth $blender_version"
  if [ -n "$keep" ] && [ -f "$out/cycles_ref.stamp" ] && [ "$(cat "$out/cycles_ref.stamp")" = "$stamp" ] &&
     [ -f "$out/cycles_ref.tsv" ]; then
    echo "(Cycles reference reused from $out: $stamp)"
    cat "$out/cycles_ref.tsv" >> "$runs"
  else
    rm -f "$out/cycles_ref.stamp"; : > "$out/cycles_ref.tsv"
    for seed in 1 2; do
      cycles "$out/cycles_ref$seed.exr" "$sc" "$half" "$seed"
      role=ref_a; [ "$seed" = 1 ] || role=ref_b
      printf '%s\tcycles\t%s\t%s\t%s\t%s\n' "$role" "$half" "$wall" "$render" "$out/cycles_ref$seed.exr" >> "$out/cycles_ref.tsv"
    done
    echo "$stamp" > "$out/cycles_ref.stamp"
    cat "$out/cycles_ref.tsv" >> "$runs"
  fi
  whitted "$out/whitted_ref_half.pfm" "$sc" "$((wref_spp / 2))"
  printf 'wref_half\twhitted\t%s\t%s\t%s\t%s\n' "$((wref_spp / 2))" "$wall" "$render" "$out/whitted_ref_half.pfm" >> "$runs"
  whitted "$out/whitted_ref.pfm" "$sc" "$wref_spp"
  printf 'wref\twhitted\t%s\t%s\t%s\t%s\n' "$wref_spp" "$wall" "$render" "$out/whitted_ref.pfm" >> "$runs"
  # The low-spp runs, the two renderers alternating.
  for spp in $spps; do
    whitted "$out/whitted_$spp.pfm" "$sc" "$spp"
    printf 'run\twhitted\t%s\t%s\t%s\t%s\n' "$spp" "$wall" "$render" "$out/whitted_$spp.pfm" >> "$runs"
    cycles "$out/cycles_$spp.exr" "$sc" "$spp" 0
    printf 'run\tcycles\t%s\t%s\t%s\t%s\n' "$spp" "$wall" "$render" "$out/cycles_$spp.exr" >> "$runs"
  done
  bl "$here/image_error.py" -- "$runs" 2> "$tmp/error.log" | grep -v '^Blender \|^Read prefs\|^Blender quit' ||
    { echo "compare_cycles: image_error.py failed:" >&2; tail -20 "$tmp/error.log" >&2; exit 1; }
done
echo
echo "(load after: $(cut -d' ' -f1-3 /proc/loadavg))"
