#!/usr/bin/env bash
# Installs what is needed, then builds and runs the whole test suite twice: a Release build,
# and a build under AddressSanitizer + UndefinedBehaviorSanitizer; then fuzzes each target of fuzz/
# for FUZZ_SECONDS (default 60) under the same sanitizers (scripts/fuzz.sh; FUZZ_SECONDS=0 skips it).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh" --viewer-test
jobs="$(nproc)"

echo "== Release build and tests"
cmake -S "$root" -B "$root/build-release" -DCMAKE_BUILD_TYPE=Release -DWHITTED_BUILD_TESTS=ON >/dev/null
cmake --build "$root/build-release" -j"$jobs"
ctest --test-dir "$root/build-release" --output-on-failure -j"$jobs"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
cmake -S "$root" -B "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWHITTED_SANITIZE=ON \
      -DWHITTED_BUILD_TESTS=ON >/dev/null
cmake --build "$root/build-asan" -j"$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir "$root/build-asan" --output-on-failure -j"$jobs"

if [[ "${FUZZ_SECONDS:-60}" != 0 ]]; then
    echo "== libFuzzer targets, ${FUZZ_SECONDS:-60} s each (ASan + UBSan)"
    "$root/scripts/fuzz.sh" "${FUZZ_SECONDS:-60}"
fi
