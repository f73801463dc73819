#!/usr/bin/env bash
# Re-renders the reference images of the image regression test (tests/regression/) from every
# scene under scenes/, and the crops of reference/crops/crops.txt, with the command-line renderer
# of a Release build. Run it only after a change meant to alter pictures, then LOOK at every image it wrote (git diff shows which) before
# committing them: a reference is only worth what its inspection was.
# Usage: scripts/update-reference-images.sh [BUILD_DIR]      (default build-release)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath "${1:-$root/build-release}")"
cli="$build/apps/cli/whitted"
[[ -x "$cli" ]] || { echo "no $cli: build Release first (scripts/test.sh does)" >&2; exit 1; }
out="$root/tests/regression/reference"
mkdir -p "$out"
cd "$root/scenes"
find . -name '*.sc' | sort | while read -r scene; do
    name="${scene#./}"; name="${name%.sc}"; name="${name//\//__}"
    "$cli" "$scene" -o "$out/$name.png" --width 160 --height 120 -q
    echo "$out/$name.png"
done
"$cli" showcase.sc -o "$out/showcase__aa3.png" --width 160 --height 120 --aa 3 -q
echo "$out/showcase__aa3.png"
for scene in features/soft_shadows features/depth_of_field features/glossy showcase; do
    name="${scene//\//__}__spp16"
    "$cli" "$scene.sc" -o "$out/$name.png" --width 160 --height 120 --spp 16 -q
    echo "$out/$name.png"
done
# The full-resolution crops listed in crops/crops.txt (ImageMagick's convert cuts them out).
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
grep -v '^#' "$out/crops/crops.txt" | while read -r name scene width height x y w h; do
    [[ -n "$name" ]] || continue
    full="$tmp/${scene%.sc}_${width}x${height}.png"
    [[ -f "$full" ]] || "$cli" "$scene" -o "$full" --width "$width" --height "$height" -q
    convert "$full" -crop "${w}x${h}+${x}+${y}" +repage "$out/crops/$name.png"
    echo "$out/crops/$name.png"
done
