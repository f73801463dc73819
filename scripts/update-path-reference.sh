#!/usr/bin/env bash
# Re-renders the converged path-tracing reference of tests/integrator/path_reference_test.cpp (the
# Cornell box at 4096 samples per pixel, 24×24, linear PFM) with a Release build. Run it only after
# a change meant to alter path-traced pictures, and compare the new reference with Blender Cycles
# (bench/compare_cycles.sh) before committing it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cli="$(realpath "${1:-$root/build-release}")/apps/cli/whitted"
[[ -x "$cli" ]] || { echo "no $cli: build Release first" >&2; exit 1; }
"$cli" "$root/scenes/features/cornell_box.sc" --mode path --spp 4096 --width 24 --height 24 -q \
    -o "$root/tests/integrator/reference/cornell_box_4096spp.pfm"
