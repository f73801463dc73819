#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang, AddressSanitizer and UBSan, and runs each.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]   (default: 60 seconds, every target)
#   FUZZ_BUILD=DIR   build directory (default: build-fuzz); its corpus/<target>/ keeps what was found
#   FUZZ_SEED=N      libFuzzer's random seed (default 0: a new one each run, printed in the log as
#                    "Seed: N"); scripts/test.sh fixes it, so that CI tries the same inputs in the
#                    same order every run (how many of them depends on the machine's speed)
# Exits non-zero on the first target that finds a crash, a leak, a timeout or memory above the
# limit; the input that did it is left in the build directory as crash-*/timeout-*/oom-* (reproduce
# with `BUILD/fuzz/TARGET FILE`).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
build="${FUZZ_BUILD:-$root/build-fuzz}"
shared="${WHITTED_SHARED_DIR:-$root/../shared}"

"$root/scripts/install-deps.sh"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWHITTED_FUZZ=ON \
    -DWHITTED_BUILD_TESTS=OFF -DWHITTED_BUILD_VIEWER=OFF >/dev/null
targets=("$@")
if ((${#targets[@]} == 0)); then
    for f in "$root"/fuzz/*_fuzzer.cpp; do targets+=("$(basename "$f" .cpp)"); done
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}"

# Seeds: every scene of scenes/ and of the wild corpus for the scene targets, the CSCI 1230 JSON
# scenes for cs1230_fuzzer, every image for the texture target (copied flat, so that libFuzzer reads nothing else from those folders).
# Meshes: every OBJ file of both (and fuzz/obj_seeds/) for the OBJ target; scenes with a mesh after
# their mark (fuzz/mesh_scene_seeds/, see load_render_fuzzer.cpp) for the scene targets.
seeds="$build/seeds"
rm -rf "$seeds" && mkdir -p "$seeds/scenes" "$seeds/images" "$seeds/objs"
find "$root/scenes" "$shared/scenes/wild" "$root/fuzz/mesh_scene_seeds" -type f -iname '*.sc' 2>/dev/null |
    while read -r f; do cp "$f" "$seeds/scenes/$(echo "$f" | md5sum | cut -c1-12).sc"; done
find "$root/scenes" "$shared/scenes" "$root/fuzz/obj_seeds" -type f -iname '*.obj' 2>/dev/null |
    while read -r f; do cp "$f" "$seeds/objs/$(echo "$f" | md5sum | cut -c1-12).obj"; done
mkdir -p "$seeds/json"
find "$shared/scenes/cs1230" -type f -iname '*.json' -size -60k 2>/dev/null |
    while read -r f; do cp "$f" "$seeds/json/$(echo "$f" | md5sum | cut -c1-12).json"; done
find "$root/scenes" "$shared/scenes/wild" "$shared/scenes/cs1230" -type f -size -400k \
    \( -iname '*.png' -o -iname '*.bmp' -o -iname '*.ppm' -o -iname '*.jpg' -o -iname '*.tga' -o -iname '*.gif' \) 2>/dev/null |
    while read -r f; do cp "$f" "$seeds/images/$(echo "$f" | md5sum | cut -c1-12)"; done

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
for t in "${targets[@]}"; do
    corpus="$build/corpus/$t"
    mkdir -p "$corpus"
    case "$t" in
        texture_fuzzer) seed="$seeds/images" max_len=400000 dict=() ;;
        compare_image_fuzzer) seed="$root/fuzz/seeds/compare_image" max_len=400000 dict=() ;;
        cs1230_fuzzer) seed="$seeds/json" max_len=65536 dict=(-dict="$root/fuzz/cs1230.dict") ;;
        obj_fuzzer) seed="$seeds/objs" max_len=65536 dict=(-dict="$root/fuzz/obj.dict") ;;
        *) seed="$seeds/scenes" max_len=65536 dict=(-dict="$root/fuzz/scene.dict") ;;
    esac
    echo "== $t: ${seconds}s"
    (cd "$build" && "$build/fuzz/$t" "$corpus" "$seed" "${dict[@]}" -max_len="$max_len" \
        -seed="${FUZZ_SEED:-0}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 2>"$build/$t.log") || {
        tail -n 60 "$build/$t.log"
        echo "fuzz: $t found a problem; see $build/$t.log and the crash-/timeout-/oom- file in $build" >&2
        exit 1
    }
    grep -E '^#[0-9]+ +DONE|stat::number_of_executed_units|stat::peak_rss_mb' "$build/$t.log" || true
done
