#!/usr/bin/env bash
# Installs the Debian packages whitted builds and tests with. Safe to run again.
# Usage: scripts/install-deps.sh [--viewer-test]   (--viewer-test adds Xvfb and tools for the viewer's screen test)
set -euo pipefail
# fluid: Debian's FLTK CMake package config names /usr/bin/fluid and stops find_package(FLTK) without it,
# although whitted never runs fluid; libfltk1.3-dev only recommends it.
# openmpi-bin, libopenmpi-dev: whitted-mpi (one image rendered across a cluster) and its tests run mpirun.
# zlib1g-dev: PNG compression (stb's encoder is single-threaded, slow, and overflows past 1.4 GB).
# libjpeg-dev: JPEG textures (Debian's stb aborts on an assertion with a corrupt Huffman table).
# clang, libclang-rt-dev: the libFuzzer targets of fuzz/ (scripts/fuzz.sh); libFuzzer and clang's
# sanitizer runtimes are in libclang-rt-dev, which clang only recommends.
# libtinyobjloader-dev: the reference the tests hold whitted's OBJ line parser to (scene-format.md §9.3).
# nlohmann-json3-dev: reads Brown CSCI 1230's JSON scene files (scene-format.md §9.5).
# chromium: only to test `whitted grade`'s HTML report (a headless screenshot of the page); whitted never runs it.
packages=(build-essential cmake pkg-config libglm-dev libstb-dev libcli11-dev libgtest-dev libgmock-dev
          libbenchmark-dev libfltk1.3-dev fluid libopenexr-dev openmpi-bin libopenmpi-dev
          clang libclang-rt-dev zlib1g-dev libjpeg-dev libtinyobjloader-dev nlohmann-json3-dev chromium)
if [[ "${1:-}" == "--viewer-test" ]]; then packages+=(xvfb x11-apps imagemagick xdotool tesseract-ocr); fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then exit 0; fi

sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
echo "Installing: ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
