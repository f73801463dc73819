#!/usr/bin/env bash
# Installs what is needed, then builds and runs the whole test suite twice: a Release build,
# and a build under AddressSanitizer + UndefinedBehaviorSanitizer; then fuzzes each target of fuzz/
# for FUZZ_SECONDS (default 60) under the same sanitizers, from the seed FUZZ_SEED (default 1)
# (scripts/fuzz.sh; FUZZ_SECONDS=0 skips it).
#
# No silent green: tests that need ../shared or the viewer fail when it is missing, unless
# WHITTED_SKIP_SHARED_TESTS or WHITTED_SKIP_VIEWER_TESTS gives the reason to skip them; and this
# script fails when ctest reports any skipped test while neither variable is set.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh" --viewer-test
jobs="$(nproc)"

# ctest on build dir $1 (environment as given), then the check for skipped tests.
run_ctest() {
    local log
    log="$(mktemp)"
    ctest --test-dir "$1" --output-on-failure -j"$jobs" 2>&1 | tee "$log"
    local skipped
    skipped="$(grep -E '^[[:space:]]*[0-9]+ - .*\((Skipped|Disabled|Not Run)\)' "$log" || true)"
    rm -f "$log"
    [[ -z "$skipped" ]] && return 0
    if [[ -n "${WHITTED_SKIP_SHARED_TESTS:-}${WHITTED_SKIP_VIEWER_TESTS:-}" ]]; then
        echo "== skipped as asked (WHITTED_SKIP_SHARED_TESTS='${WHITTED_SKIP_SHARED_TESTS:-}'," \
             "WHITTED_SKIP_VIEWER_TESTS='${WHITTED_SKIP_VIEWER_TESTS:-}'):"
        echo "$skipped"
        return 0
    fi
    echo "error: these tests did not run, and no WHITTED_SKIP_SHARED_TESTS or WHITTED_SKIP_VIEWER_TESTS" \
         "says why:" >&2
    echo "$skipped" >&2
    return 1
}

echo "== Release build and tests"
cmake -S "$root" -B "$root/build-release" -DCMAKE_BUILD_TYPE=Release -DWHITTED_BUILD_TESTS=ON >/dev/null
cmake --build "$root/build-release" -j"$jobs"
run_ctest "$root/build-release"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
cmake -S "$root" -B "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DWHITTED_SANITIZE=ON \
      -DWHITTED_BUILD_TESTS=ON >/dev/null
cmake --build "$root/build-asan" -j"$jobs"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    run_ctest "$root/build-asan"

if [[ "${FUZZ_SECONDS:-60}" != 0 ]]; then
    echo "== libFuzzer targets, ${FUZZ_SECONDS:-60} s each (ASan + UBSan)"
    # A fixed seed: the same inputs in the same order every run, so a finding is not a matter of luck
    # and reproduces (FUZZ_SEED to vary it).
    FUZZ_SEED="${FUZZ_SEED:-1}" "$root/scripts/fuzz.sh" "${FUZZ_SECONDS:-60}"
fi
