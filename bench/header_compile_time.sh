#!/usr/bin/env bash
# Compile time of generated headers (issue 18): `-std=c++20 -fsyntax-only` user CPU time of
# g++ and clang++, the minimum of RUNS runs (the machine is shared; the minimum is the least
# disturbed run). Headers measured:
#   bench700        the header of a ~700 kB DCF written by fieldcodec_gen_bench (4574 entries)
#   bench700_views  the same with --no-sub-descriptors (no standalone descriptor per named
#                   ARRAY/RECORD sub-object)
#   <checked-in>    include/fieldcodec/dictionaries/{compax_objects,xenax_canopen,dpq_parameters}
#   (od includes)   only the od/ headers a generated header includes: the floor of every row
#
#   bench/header_compile_time.sh [BUILD_DIR]      (default build-bench; RUNS=5, CXXS="g++ clang++")
#   INSTRUCTIONS=1 bench/header_compile_time.sh   instructions (millions) of one run under
#                                                 valgrind --tool=callgrind --trace-children=yes
#                                                 instead of seconds: the load does not change them
#
# BUILD_DIR must have (or gets) the targets fieldcodec-gen and fieldcodec_gen_bench; configure it
# with -DCMAKE_BUILD_TYPE=Release.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-bench}
runs=${RUNS:-5}
cxxs=${CXXS:-"g++ clang++"}
[ -f "$build/build.ninja" ] || cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target fieldcodec-gen fieldcodec_gen_bench -j2 >/dev/null

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/h/fieldcodec/dictionaries"
"$build/codegen/fieldcodec_gen_bench" 700000 --dcf "$work/bench700.dcf" >/dev/null
"$build/codegen/fieldcodec-gen" --quiet --name bench700 \
  -o "$work/h/fieldcodec/dictionaries/bench700.hpp" "$work/bench700.dcf"
"$build/codegen/fieldcodec-gen" --quiet --no-sub-descriptors --name bench700_views \
  -o "$work/h/fieldcodec/dictionaries/bench700_views.hpp" "$work/bench700.dcf"

# The od/ includes of a generated header, nothing else.
grep '^#include <fieldcodec/' "$work/h/fieldcodec/dictionaries/bench700.hpp" > "$work/od_includes.cpp"

best() { # best CXX FILE -> minimum user seconds over $runs runs (or instructions, see above)
  local cxx=$1 src=$2 b=
  if [ "${INSTRUCTIONS:-0}" = 1 ]; then
    rm -f "$work"/cg.*
    valgrind --tool=callgrind --trace-children=yes --callgrind-out-file="$work/cg.%p" \
      "$cxx" -std=c++20 -I"$work/h" -Iinclude -fsyntax-only "$src" 2>/dev/null
    awk '/^summary:/ {n += $2} END {printf "%.0fM\n", n / 1e6}' "$work"/cg.*
    return
  fi
  for _ in $(seq "$runs"); do
    /usr/bin/time -o "$work/t" -f '%U' "$cxx" -std=c++20 -I"$work/h" -Iinclude -fsyntax-only "$src"
    b=$(awk -v b="$b" '{print (b == "" || $1 < b) ? $1 : b}' "$work/t")
  done
  echo "$b"
}

printf '| header | size | entries |'
unit='user s'; [ "${INSTRUCTIONS:-0}" = 1 ] && unit=instructions
for c in $cxxs; do printf ' %s %s |' "$c" "$unit"; done
printf '\n|---|---:|---:|'
for c in $cxxs; do printf -- '---:|'; done
printf '\n'
row() { # row NAME HEADER-or-SOURCE BYTES ENTRIES
  local name=$1 src=$2
  printf '| %s | %s | %s |' "$name" "$3" "$4"
  for c in $cxxs; do printf ' %s |' "$(best "$c" "$src")"; done
  printf '\n'
}
entries() { grep -o 'od::entry, [0-9]*>' "$1" | grep -o '[0-9]*>' | tr -d '>'; }
row "(od includes only)" "$work/od_includes.cpp" - -
for name in bench700 bench700_views compax_objects xenax_canopen dpq_parameters; do
  hdr=include/fieldcodec/dictionaries/$name.hpp
  case $name in bench700*) hdr=$work/h/fieldcodec/dictionaries/$name.hpp ;; esac
  echo "#include <fieldcodec/dictionaries/$name.hpp>" > "$work/$name.cpp"
  row "$name" "$work/$name.cpp" "$(( $(wc -c < "$hdr") / 1024 )) kB" "$(entries "$hdr")"
done
