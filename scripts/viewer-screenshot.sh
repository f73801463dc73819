#!/usr/bin/env bash
# Takes a real screenshot of whitted-view (the FLTK viewer) under Xvfb, for the README: starts a
# private X server, opens the scene, waits until the render is finished and on screen, grabs the
# screen with xwd and crops it to the viewer's window with ImageMagick.
# Usage: scripts/viewer-screenshot.sh [SCENE] [OUT.png]     (defaults: scenes/showcase.sc, docs/viewer.png)
# Environment: WHITTED_BUILD (build directory, default build-release), VIEWER_ARGS (extra viewer options).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scene="${1:-$root/scenes/showcase.sc}"
out="${2:-$root/docs/viewer.png}"
build="${WHITTED_BUILD:-$root/build-release}"

"$root/scripts/install-deps.sh" --viewer-test
if [[ ! -x "$build/apps/viewer/whitted-view" ]]; then
    cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DWHITTED_BUILD_TESTS=OFF >/dev/null
fi
cmake --build "$build" -j"$(nproc)" --target whitted-view
viewer="$build/apps/viewer/whitted-view"

tmp="$(mktemp -d)"
xvfb_pid="" viewer_pid=""
cleanup() {
    if [[ -n "$viewer_pid" ]]; then kill "$viewer_pid" 2>/dev/null || true; wait "$viewer_pid" 2>/dev/null || true; fi
    if [[ -n "$xvfb_pid" ]]; then kill "$xvfb_pid" 2>/dev/null || true; wait "$xvfb_pid" 2>/dev/null || true; fi
    rm -rf "$tmp"
}
trap cleanup EXIT

# Xvfb picks a free display number and writes it to fd 3 once it accepts connections.
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb_pid=$!
for _ in $(seq 100); do [[ -s "$tmp/display" ]] && break; sleep 0.1; done
[[ -s "$tmp/display" ]] || { echo "viewer-screenshot: Xvfb did not start:" >&2; cat "$tmp/xvfb.log" >&2; exit 1; }
display=":$(head -n1 "$tmp/display")"

# shellcheck disable=SC2086  # VIEWER_ARGS is a list of options
# A HOME of its own: the window remembers recent files and its size there (Fl_Preferences).
HOME="$tmp" DISPLAY="$display" "$viewer" "$scene" --window-size 1000x720 --fit --missing-textures checker \
    --ready-file "$tmp/ready" ${VIEWER_ARGS:-} 2>"$tmp/viewer.log" &
viewer_pid=$!
for _ in $(seq 1200); do [[ -f "$tmp/ready" ]] && break; sleep 0.1; done
[[ -f "$tmp/ready" ]] || { echo "viewer-screenshot: the render did not finish:" >&2; cat "$tmp/viewer.log" >&2; exit 1; }

# "window X Y W H" in root coordinates.
read -r _ wx wy ww wh < <(grep '^window ' "$tmp/ready")
mkdir -p "$(dirname "$out")"
xwd -root -silent -display "$display" | convert xwd:- -crop "${ww}x${wh}+${wx}+${wy}" +repage "$out"
echo "wrote $out ($(grep '^state ' "$tmp/ready"))"
