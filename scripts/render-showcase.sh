#!/usr/bin/env bash
# Installs what is needed, builds whitted in Release and renders the bundled showcase to showcase.png.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$root/build-release" -DCMAKE_BUILD_TYPE=Release -DWHITTED_BUILD_TESTS=OFF >/dev/null
cmake --build "$root/build-release" -j"$(nproc)"
"$root/build-release/apps/cli/whitted" "$root/scenes/showcase.sc" -o "${1:-showcase.png}" --width 1024 --height 768 --spp 16
