#!/usr/bin/env bash
# Peak memory and time of loading a 1M-triangle OBJ, whole process, side by side:
#   bench/obj_load_bench.sh OLD_WHITTED NEW_WHITTED [RUNS]
# Writes three 1,000,000-triangle tori with bench/gen_obj.py (positions only; with vn; with vt and vn),
# renders each at 64x48 (so the film does not count) with both binaries alternately, RUNS times
# (default 3), and prints per binary and file the median wall time and the largest maximum
# resident set size (/usr/bin/time -v), in bytes per triangle. The images must be the same bytes.
set -euo pipefail
old="$1"; new="$2"; runs="${3:-3}"
here="$(cd "$(dirname "$0")" && pwd)"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
tris=1000000
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) CPUs; $(date -u +%FT%TZ)"
printf "%-6s %9s | %-24s | %-24s\n" file MB "old: s med, B/tri max" "new: s med, B/tri max"
for attrs in v vn vtvn; do
  python3 "$here/gen_obj.py" "$tmp/torus.obj" --attrs "$attrs"
  cat > "$tmp/torus.sc" <<SC
camera [ eye 0 2.5 3 focus 0 0 0 up 0 1 0 angle 45 ]
light [ type point position 3 5 4 color 1 1 1 ]
mastersubgraph root [ trans [ object mesh [ file torus.obj diffuse 0.8 0.6 0.4 specular 0.3 0.3 0.3 shine 30 ] ] ]
SC
  : > "$tmp/old.txt"; : > "$tmp/new.txt"
  for ((i = 0; i < runs; ++i)); do
    for which in old new; do
      bin="$old"; [ "$which" = new ] && bin="$new"
      /usr/bin/time -v -o "$tmp/time" "$bin" "$tmp/torus.sc" --width 64 --height 48 -q -o "$tmp/$which.png"
      awk '/Elapsed \(wall clock\)/ { n = split($NF, a, ":"); s = a[n] + (n > 1 ? 60 * a[n - 1] : 0) }
           /Maximum resident set size/ { kb = $NF } END { print s, kb }' "$tmp/time" >> "$tmp/$which.txt"
    done
    cmp -s "$tmp/old.png" "$tmp/new.png" || { echo "images differ for $attrs" >&2; exit 1; }
  done
  summary() { sort -n "$1" | awk -v t="$tris" '{ s[NR] = $1; if ($2 > kb) kb = $2 }
              END { printf "%6.2f s, %5.1f B/tri", s[int((NR + 1) / 2)], kb * 1024 / t }'; }
  printf "%-6s %9.1f | %-24s | %-24s\n" "$attrs" "$(stat -c %s "$tmp/torus.obj" | awk '{ print $1 / 1e6 }')" \
    "$(summary "$tmp/old.txt")" "$(summary "$tmp/new.txt")"
done
