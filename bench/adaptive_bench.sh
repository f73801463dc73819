#!/usr/bin/env bash
# Adaptive sampling (--noise-threshold) against uniform sampling at equal error: for each scene, a
# reference of REF samples per pixel, uniform renders at 16, 64 and 256 samples, then adaptive
# renders at the noise thresholds in THRESHOLDS; each run's error against the reference (relative
# MSE, as rendering papers report it: mean of (x - ref)^2 / (ref^2 + 0.01) over pixels and channels)
# and its cost: CPU seconds (user + system, less disturbed by other load than wall time) and rays
# traced (from --stats: a count of the work that no load changes).
# Usage: bench/adaptive_bench.sh [BUILD_DIR]   (Release; writes a table to stdout)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cli="${1:-$root/build-release}/apps/cli/whitted"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
REF=${REF:-4096}
THRESHOLDS=${THRESHOLDS:-"0.1 0.05 0.025 0.0125 0.00625"}
SIZE=(--width "${WIDTH:-160}" --height "${HEIGHT:-120}" --mode path --threads 2 -q --stats)

# run NAME ARGS...: renders to $out/NAME.pfm; prints "cpu_seconds rays"
run() {
    local name=$1
    shift
    /usr/bin/time -f "%U %S" -o "$out/$name.time" "$cli" "$@" "${SIZE[@]}" -o "$out/$name.pfm" 2>"$out/$name.log"
    local rays
    rays=$(grep -o "camera [0-9]*, reflected [0-9]*, refracted [0-9]*, shadow [0-9]*" "$out/$name.log" |
           awk '{gsub(",",""); print $2+$4+$6+$8}')
    echo "$(awk '{print $1+$2}' "$out/$name.time") $rays"
}

relmse() {
    python3 - "$1" "$2" <<'PY'
import struct, sys
def pfm(p):
    f = open(p, 'rb')
    assert f.readline().strip() == b'PF'
    w, h = map(int, f.readline().split())
    scale = float(f.readline())
    fmt = ('<' if scale < 0 else '>') + 'f' * (3 * w * h)
    return struct.unpack(fmt, f.read(12 * w * h))
a, r = pfm(sys.argv[1]), pfm(sys.argv[2])
print('%.6g' % (sum((x - y) ** 2 / (y * y + 0.01) for x, y in zip(a, r)) / len(a)))
PY
}

for scene in showcase features/cornell_box; do
    s="$root/scenes/$scene.sc"
    run ref "$s" --spp "$REF" >/dev/null
    echo "== $scene (${SIZE[*]:0:4}), reference $REF spp"
    echo "method | spp / threshold | relMSE | CPU s | rays"
    for spp in 16 64 256; do
        read -r cpu rays < <(run "u$spp" "$s" --spp "$spp")
        echo "uniform | $spp | $(relmse "$out/u$spp.pfm" "$out/ref.pfm") | $cpu | $rays"
    done
    for t in $THRESHOLDS; do
        read -r cpu rays < <(run "a$t" "$s" --spp 1024 --noise-threshold "$t")
        echo "adaptive | $t (max 1024, min 16) | $(relmse "$out/a$t.pfm" "$out/ref.pfm") | $cpu | $rays"
    done
done
