#!/usr/bin/env bash
# Instructions per operation, measured with valgrind --tool=callgrind (repeatable on a noisy
# machine, unlike wall-clock time).
#
# For every operation of every bench executable, and for both implementations (fieldcodec and
# the hand-written baseline), the executable runs exactly N and exactly 2N iterations of that
# one operation under callgrind; (instructions(2N) − instructions(N)) / N is the number of
# instructions per operation, without start-up, registration and input-generation costs.
# Each operation's loop is also run empty (--impl empty: the same loop over the same inputs,
# only the barrier): h. The ratio is taken net of it, (fieldcodec − h) / (baseline − h), so a
# small operation is not flattered by the loop. The Ir/op columns include the loop.
#
# Usage: bench/callgrind.sh [BUILD_DIR] [FILTER]
#   BUILD_DIR  a Release build with FIELDCODEC_BUILD_BENCH=ON (default: build-bench)
#   FILTER     only operations whose name contains FILTER
# Environment: N (iterations, default 2000), FORMAT=markdown for a Markdown table.
set -euo pipefail
cd "$(dirname "$0")/.."

build="${1:-build-bench}"
filter="${2:-}"
n="${N:-2000}"
format="${FORMAT:-text}"

command -v valgrind >/dev/null || { echo "callgrind.sh: valgrind is not installed" >&2; exit 2; }

instructions() { # exe name impl iterations -> total instructions of the run
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" --run "$2" --impl "$3" \
    --iterations "$4" 2>&1 >/dev/null | awk '/Collected :/ {print $NF}'
}

per_op() { # exe name impl -> instructions per operation (one decimal)
  local a b
  a=$(instructions "$1" "$2" "$3" "$n")
  b=$(instructions "$1" "$2" "$3" $((2 * n)))
  awk -v a="$a" -v b="$b" -v n="$n" 'BEGIN {printf "%.1f", (b - a) / n}'
}

if [ "$format" = markdown ]; then
  echo "| operation | fieldcodec Ir/op | baseline Ir/op | loop Ir | ratio (net of loop) |"
  echo "|---|---:|---:|---:|---:|"
else
  printf '%-52s %10s %10s %6s %7s\n' operation fieldcodec baseline loop ratio
fi

shopt -s nullglob
found=0
for exe in "$build"/bench/codec_*; do
  [ -x "$exe" ] && [ -f "$exe" ] || continue
  found=1
  while IFS= read -r name; do
    [ -n "$name" ] || continue
    if [ -n "$filter" ] && [[ "$name" != *"$filter"* ]]; then continue; fi
    [[ "$name" == harness/* ]] && continue # the loop alone: the "loop" column of every row
    h=$(per_op "$exe" "$name" empty)
    f=$(per_op "$exe" "$name" fieldcodec)
    b=$(per_op "$exe" "$name" baseline)
    ratio=$(awk -v f="$f" -v b="$b" -v h="$h" \
      'BEGIN {if (b - h > 0.5) printf "%.2f", (f - h) / (b - h); else print "-"}')
    if [ "$format" = markdown ]; then
      echo "| $(basename "$exe" | sed 's/^codec_//') · $name | $f | $b | $h | $ratio |"
    else
      printf '%-52s %10s %10s %6s %7s\n' "$(basename "$exe" | sed 's/^codec_//'):$name" "$f" "$b" "$h" "$ratio"
    fi
  done < <("$exe" --list)
done
if [ "$found" = 0 ]; then
  echo "callgrind.sh: no bench executables in $build/bench (configure with -DFIELDCODEC_BUILD_BENCH=ON -DCMAKE_BUILD_TYPE=Release)" >&2
  exit 2
fi
