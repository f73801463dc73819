#!/usr/bin/env bash
# Renders the Brown/Tufts files of the wild corpus (scene-format.md §9.4) and puts each beside the
# screenshot of its course's own renderer that ships next to it, for docs/dialects.md.
# The screenshots are 504 × 530 windows: a 25-pixel title bar over a 504 × 504 canvas (with a
# one-pixel frame at the bottom); the canvas is cropped out and ours is rendered at 504 × 504.
# Usage: scripts/dialect-comparison.sh [OUT_DIR]     (default docs/dialects)
# Environment: WHITTED_BUILD (build directory, default build-release), WHITTED_SHARED_DIR.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/docs/dialects}"
build="${WHITTED_BUILD:-$root/build-release}"
shared="${WHITTED_SHARED_DIR:-$root/../shared}"
tests="$shared/scenes/wild/spanut01__Graphics/homework/5/data/tests"
command -v convert >/dev/null || { echo "needs ImageMagick's convert (apt-get install imagemagick)" >&2; exit 1; }
[[ -x "$build/apps/cli/whitted" ]] || { echo "build whitted first (cmake --build $build --target whitted)" >&2; exit 1; }
mkdir -p "$out"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
for name in all all_effects all_objects mirror_test shadow_test; do
    # mirror_test.sc's image/ballz5.bmp does not ship: drawn as the checkerboard of §8.
    "$build/apps/cli/whitted" "$tests/$name.sc" -o "$tmp/ours.png" --width 504 --height 504 -q \
        --missing-textures checker 2>/dev/null
    convert "$tests/$name.png" -crop 504x504+0+25 +repage "$tmp/theirs.png"
    convert "$tmp/theirs.png" -size 8x504 xc:white "$tmp/ours.png" +append -quality 88 "$out/$name.jpg"
    echo "wrote $out/$name.jpg"
done

# all_effects' sun cube: their screenshot (left) beside whitted's render of the same file with the
# cube's `blend 1.0` changed to `blend 0.1` over `diffuse 1 1 1` (right): docs/dialects.md explains.
mkdir -p "$tmp/edited"
cp -r "$tests/image" "$tmp/edited/"
sed 's/blend 1\.0/blend 0.1\n    diffuse 1 1 1/' "$tests/all_effects.sc" > "$tmp/edited/all_effects.sc"
"$build/apps/cli/whitted" "$tmp/edited/all_effects.sc" -o "$tmp/ours.png" --width 504 --height 504 -q 2>/dev/null
convert "$tests/all_effects.png" -crop 504x504+0+25 +repage -crop 220x180+120+60 +repage "$tmp/theirs.png"
convert "$tmp/theirs.png" -size 8x180 xc:white \( "$tmp/ours.png" -crop 220x180+120+60 +repage \) +append \
    -quality 88 "$out/all_effects_sun_cube.jpg"
echo "wrote $out/all_effects_sun_cube.jpg"
