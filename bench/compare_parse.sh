#!/usr/bin/env bash
# The parser of two builds side by side: parse_bench of each (bench/parse_bench.cpp; build the
# older one from its own tree with the same parse_bench.cpp), alternating run by run, on the same
# files, then each one's median and best, wall clock and CPU time, and the median of the user time
# alone (when the parse_bench of both prints it). Before timing, both dump what they read from
# every file (--dump, strict and lenient) and the dumps must be identical.
#
#   bench/compare_parse.sh [-n RUNS] OLD_PARSE_BENCH NEW_PARSE_BENCH FILE...
#
# Default 5 alternating runs. Each run is one process parsing the file once (so a run pays for
# its first touch of memory as a real load does).
set -euo pipefail
runs=5
while getopts "n:" opt; do
  case "$opt" in
    n) runs="$OPTARG" ;;
    *) sed -n '2,11p' "$0"; exit 1 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 3 ] || { sed -n '2,11p' "$0"; exit 1; }
old="$1" new="$2"
shift 2
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

for mode in "" --lenient; do
  "$old" --dump $mode "$@" > "$tmp/old.txt"
  "$new" --dump $mode "$@" > "$tmp/new.txt"
  cmp -s "$tmp/old.txt" "$tmp/new.txt" || { echo "compare_parse: the two read the files differently ($mode):" >&2;
                                               diff "$tmp/old.txt" "$tmp/new.txt" | head -20 >&2; exit 1; }
done
echo "same diagnostics and descriptions from both (strict and lenient)"

median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) hardware threads; load: $(cut -d' ' -f1-3 /proc/loadavg); $(date -u '+%Y-%m-%d %H:%M UTC')"
printf "%-24s %9s | %-30s | %-30s | %-24s | %s\n" file MB "old: wall MB/s med (best)" "new: wall MB/s med (best)" \
  "cpu MB/s med: old new" "user MB/s med: old new"
for f in "$@"; do
  : > "$tmp/ow"; : > "$tmp/oc"; : > "$tmp/ou"; : > "$tmp/nw"; : > "$tmp/nc"; : > "$tmp/nu"
  for ((i = 0; i < runs; i++)); do
    for which in o n; do
      bin="$old"; [ "$which" = n ] && bin="$new"
      line="$("$bin" --runs 1 "$f")"
      # "...; wall: median S (R MB/s), best ...; cpu: median S (R MB/s), ..."
      echo "$line" | sed -E 's/.*wall: median [0-9.]+ s \(([0-9.]+) MB\/s\).*/\1/' >> "$tmp/${which}w"
      echo "$line" | sed -E 's/.*cpu: median [0-9.]+ s \(([0-9.]+) MB\/s\).*/\1/' >> "$tmp/${which}c"
      echo "$line" | sed -n -E 's/.*user: median [0-9.]+ s \(([0-9.]+) MB\/s\).*/\1/p' >> "$tmp/${which}u"
    done
  done
  mb="$(stat -c %s "$f" | awk '{ printf "%.2f", $1 / 1e6 }')"
  best() { sort -g | tail -1; }
  user="-"
  [ -s "$tmp/ou" ] && [ -s "$tmp/nu" ] && user="$(median < "$tmp/ou") $(median < "$tmp/nu")"
  printf "%-24s %9s | %12.1f (%12.1f) | %12.1f (%12.1f) | %-24s | %s\n" "$(basename "$f")" "$mb" \
    "$(median < "$tmp/ow")" "$(best < "$tmp/ow")" "$(median < "$tmp/nw")" "$(best < "$tmp/nw")" \
    "$(median < "$tmp/oc") $(median < "$tmp/nc")" "$user"
done
