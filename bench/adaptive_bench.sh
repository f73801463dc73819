#!/usr/bin/env bash
# Adaptive sampling (--noise-threshold) against uniform sampling at equal error. For each scene:
# two independent references of REF samples per pixel (--seed 1 and --seed 2: a reference that
# shares the renders' sample values would hide their noise), uniform renders at 16, 64 and 256
# samples, then adaptive renders at the noise thresholds in THRESHOLDS (at most MAX samples, from
# 16). Each run's error against the first reference is the relative MSE rendering papers report
# (mean of (x - ref)^2 / (ref^2 + 0.01) over pixels and channels), less the reference's own share
# (half the error between the two references, the references being independent). Cost: rays traced
# (from --stats: the work, whatever else the machine does) and CPU seconds (user + system).
# Uniform sampling's error falls as 1/samples, so the uniform rays for an adaptive run's error are
# the fitted c / error × rays per sample; their ratio to the adaptive run's rays is its speed-up.
# EXTRA: more options for every run (e.g. EXTRA="--photons 0": path mode's photon caustics are a
# consistent but biased estimate whose error does not fall as c / samples, which the fit assumes).
# Usage: bench/adaptive_bench.sh [BUILD_DIR]   (Release; writes a table to stdout)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cli="${1:-$root/build-release}/apps/cli/whitted"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
REF=${REF:-2048}
MAX=${MAX:-1024}
THRESHOLDS=${THRESHOLDS:-"0.8 0.4 0.2 0.1"}
SCENES=${SCENES:-"showcase features/cornell_box"}
SIZE=(--width "${WIDTH:-160}" --height "${HEIGHT:-120}" --mode path --threads 2 -q --stats ${EXTRA:-})

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

for scene in $SCENES; do
    s="$root/scenes/$scene.sc"
    run ref1 "$s" --spp "$REF" --seed 1 >/dev/null
    run ref2 "$s" --spp "$REF" --seed 2 >/dev/null
    ref_err=$(python3 -c "print($(relmse "$out/ref1.pfm" "$out/ref2.pfm") / 2)")
    rows="$out/rows.txt"
    : >"$rows"
    for spp in 16 64 256; do
        read -r cpu rays < <(run "u$spp" "$s" --spp "$spp")
        echo "uniform $spp $(relmse "$out/u$spp.pfm" "$out/ref1.pfm") $cpu $rays" >>"$rows"
    done
    for t in $THRESHOLDS; do
        read -r cpu rays < <(run "a$t" "$s" --spp "$MAX" --noise-threshold "$t")
        echo "adaptive $t $(relmse "$out/a$t.pfm" "$out/ref1.pfm") $cpu $rays" >>"$rows"
    done
    echo "== $scene (${SIZE[*]:0:6}), references: 2 x $REF spp (seeds 1, 2), their own relMSE $ref_err subtracted"
    python3 - "$rows" "$ref_err" <<'PY'
import sys
ref_err = float(sys.argv[2])
rows = [l.split() for l in open(sys.argv[1])]
uni = [(int(r[1]), float(r[2]) - ref_err, float(r[4])) for r in rows if r[0] == 'uniform']
# error = c / spp: c fitted in the log domain over the uniform runs; rays per sample from them too
import math
c = math.exp(sum(math.log(e * n) for n, e, _ in uni) / len(uni))
rays_per_spp = sum(r / n for n, _, r in uni) / len(uni)
print('method | spp / threshold | relMSE | CPU s | rays (M) | uniform rays at this error (M) | speed-up')
print('--- | --- | --- | --- | --- | --- | ---')
for r in rows:
    err = float(r[2]) - ref_err
    rays = float(r[4])
    equal = c / err * rays_per_spp if err > 0 else float('inf')
    print('%s | %s | %.3g | %s | %.1f | %.1f | %.2f' % (r[0], r[1], err, r[3], rays / 1e6, equal / 1e6, equal / rays))
print('uniform fit: relMSE = %.4g / spp' % c)
PY
done
