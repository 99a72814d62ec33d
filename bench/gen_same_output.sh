#!/usr/bin/env bash
# Two builds of fieldcodec-gen write the same bytes: every output (header, EDS export, compact
# header, configuration list of a DCF), the diagnostics and the exit status, for every file of
# the shared EDS corpus, the dictionaries, the generator's test fixtures and fuzz corpus, and any
# FILE given (e.g. the benchmark DCFs of fieldcodec_gen_bench). For changes that must not change
# a result (issue 18: the generator's speed-ups).
#
#   bench/gen_same_output.sh OLD_GEN NEW_GEN [FILE...]
#
# Exit status 0 when everything is the same, 1 with the differences listed otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
[[ $# -ge 2 ]] || { echo "usage: $0 OLD_GEN NEW_GEN [FILE...]" >&2; exit 2; }
old="$(realpath "$1")"
new="$(realpath "$2")"
shift 2

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# The fuzz corpus files have no extension: the generator reads them by their prefix's format.
mkdir -p "$work/fuzz"
for f in fuzz/corpus/codegen/*; do
  b="$(basename "$f")"
  case "$b" in
  csv_*) cp "$f" "$work/fuzz/$b.csv" ;;
  eds_*) cp "$f" "$work/fuzz/$b.eds" ;;
  dcf_*) cp "$f" "$work/fuzz/$b.dcf" ;;
  esac
done

inputs=()
for f in ../shared/eds-corpus/*.eds ../shared/eds-corpus/*.dcf include/fieldcodec/dictionaries/*.csv \
  "$work"/fuzz/*; do
  [[ -f "$f" ]] && inputs+=("$f")
done
while IFS= read -r f; do inputs+=("$f"); done < <(find tests/codegen -name '*.eds' -o -name '*.dcf' -o -name '*.csv' | sort)
inputs+=("$@")

run() { # GEN OUTDIR FILE
  local gen="$1" out="$2" f="$3" b
  b="$(echo "$f" | tr '/' '_')"
  {
    "$gen" --name x -o "$out/$b.hpp" --eds "$out/$b.eds" "$f" >"$out/$b.out" 2>"$out/$b.err"
    echo $?
    "$gen" --name x --compact-arrays -o "$out/$b.compact.hpp" "$f" >/dev/null 2>"$out/$b.compact.err"
    echo $?
    "$gen" --quiet --name x -o - "$f" >"$out/$b.stdout.hpp" 2>/dev/null
    echo $?
    case "$f" in
    *.dcf)
      "$gen" --name x --config-list "$out/$b.cl" "$f" >/dev/null 2>"$out/$b.cl.err"
      echo $?
      ;;
    esac
  } >"$out/$b.rc" || true
}

mkdir -p "$work/old" "$work/new"
for f in "${inputs[@]}"; do
  run "$old" "$work/old" "$f"
  run "$new" "$work/new" "$f"
done
if diff -r "$work/old" "$work/new"; then
  echo "same output for ${#inputs[@]} input files ($(find "$work/new" -type f | wc -l) outputs each)"
else
  echo "outputs differ" >&2
  exit 1
fi
