#!/usr/bin/env bash
# Parse speed of two builds side by side, on the 10,000-object file and a ~100 MB one, and what
# the scene load does after the parse on a million instances (flatten, build).
#
#   bench/parse_speed.sh [-n RUNS] [-d DIR] OLD_PARSE_BENCH NEW_PARSE_BENCH OLD_WHITTED NEW_WHITTED
#
# 1. gen_scene (next to NEW_PARSE_BENCH) writes flat10k.sc (10,000 objects, each written out),
#    flat100m.sc (576,000 objects, about 100 MB) and grid1m.sc (a million instances of one block)
#    into DIR (default: a temporary folder, removed at the end).
# 2. The parser alone, one thread, the file in memory: bench/compare_parse.sh (both builds must read
#    both files the same, strict and lenient; then alternating runs, wall and thread CPU time).
# 3. The whole process, alternating old and new: `whitted --stats --threads 1` on the two flat files
#    (its "parse" includes reading the file) and `--threads 2` on grid1m.sc (flatten and build);
#    user and system CPU of each process from GNU time. Medians of RUNS (default 5).
set -euo pipefail
runs=5
dir=""
while getopts "n:d:" opt; do
  case "$opt" in
    n) runs="$OPTARG" ;;
    d) dir="$OPTARG" ;;
    *) sed -n '2,14p' "$0"; exit 1 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -eq 4 ] || { sed -n '2,14p' "$0"; exit 1; }
old_pb="$1" new_pb="$2" old_w="$3" new_w="$4"
here="$(cd "$(dirname "$0")" && pwd)"
gen="$(dirname "$new_pb")/gen_scene"
[ -x "$gen" ] || { echo "parse_speed: no gen_scene next to $new_pb" >&2; exit 1; }
if [ -z "$dir" ]; then
  dir="$(mktemp -d)"
  trap 'rm -rf "$dir"' EXIT
fi
mkdir -p "$dir"
[ -f "$dir/flat10k.sc" ] || "$gen" --count 10000 --flat -o "$dir/flat10k.sc" > /dev/null
[ -f "$dir/flat100m.sc" ] || "$gen" --count 576000 --flat -o "$dir/flat100m.sc" > /dev/null
[ -f "$dir/grid1m.sc" ] || "$gen" --count 1000000 -o "$dir/grid1m.sc" > /dev/null

echo "== parser alone (parse_bench, one thread, file in memory), $runs alternating runs"
"$here/compare_parse.sh" -n "$runs" "$old_pb" "$new_pb" "$dir/flat10k.sc" "$dir/flat100m.sc"

median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
# One whitted run: "FIELD SECONDS ..." from --stats, then the process's user and system CPU.
one_run() {  # BIN FILE THREADS
  local out
  out="$( { /usr/bin/time -f 'cpu %U %S' "$1" --stats --threads "$3" --width 64 --height 48 "$2" \
             -o "$dir/out.png" > /dev/null; } 2>&1 )"
  echo "$out" | grep -o -E '(parse|flatten|build) [0-9.]+' | tr '\n' ' '
  echo "$out" | grep -E '^cpu ' | tr '\n' ' '
  echo
}
echo
echo "== whole process (whitted --stats, 64x48), $runs alternating runs; load: $(cut -d' ' -f1-3 /proc/loadavg)"
printf "%-14s %-4s | %-9s %-9s %-9s | %-9s %-9s | %s\n" file bin parse flatten build user sys "parse MB/s (median)"
for spec in "flat10k.sc 1" "flat100m.sc 1" "grid1m.sc 2"; do
  set -- $spec
  f="$dir/$1" threads="$2"
  for which in old new; do : > "$dir/$which.runs"; done
  for ((i = 0; i < runs; i++)); do
    one_run "$old_w" "$f" "$threads" >> "$dir/old.runs"
    one_run "$new_w" "$f" "$threads" >> "$dir/new.runs"
  done
  mb="$(stat -c %s "$f" | awk '{ printf "%.3f", $1 / 1e6 }')"
  for which in old new; do
    field() { awk -v k="$1" '{ for (i = 1; i < NF; ++i) if ($i == k) print $(i + 1) }' "$dir/$which.runs" | median; }
    user="$(awk '{ print $(NF - 1) }' "$dir/$which.runs" | median)"
    sys="$(awk '{ print $NF }' "$dir/$which.runs" | median)"
    parse="$(field parse)"
    printf "%-14s %-4s | %-9s %-9s %-9s | %-9s %-9s | %.1f\n" "$1" "$which" "$parse" "$(field flatten)" \
      "$(field build)" "$user" "$sys" "$(awk -v m="$mb" -v s="$parse" 'BEGIN { print (s > 0) ? m / s : 0 }')"
  done
done
