#!/usr/bin/env bash
# The public headers in users' optimised builds: programs that use fieldcodec — the host
# examples, the interop bridges (a CiA 301 node and a CiA 402 master on the host adapters) and
# one translation unit that includes every public header — compiled as a user compiles them:
# only their own flags, `-std=c++20 -O2|-O3|-Os -Wall -Wextra -Werror -DNDEBUG`, no project
# warning options (the project turns off some of g++'s optimiser-only false positives for its
# own targets, cmake/FieldcodecWarnings.cmake; users do not). With g++ and clang++. Compiled,
# not linked or run: the test builds do that. g++ at -O2, -O3 and -Os: its flow-based warnings
# (-Wmaybe-uninitialized, -Warray-bounds, -Wstringop-*, -Wrestrict) depend on what the
# optimiser inlines. clang++ at -O2 and -Os: its diagnostics come from the front end and do not
# change with the level.
#   USERS_BUILD_LEVELS="-O2 -Os"  USERS_BUILD_COMPILERS="g++"  .ci/steps/users_build.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
.ci/deps base clang

compilers="${USERS_BUILD_COMPILERS:-g++ clang++}"
levels_of() {
  if [ -n "${USERS_BUILD_LEVELS:-}" ]; then echo "$USERS_BUILD_LEVELS"
  elif [ "$1" = g++ ]; then echo "-O2 -O3 -Os"
  else echo "-O2 -Os"; fi
}
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT

# one translation unit with every public header (each header alone is the header check's job)
all="$out/all_headers.cpp"
while IFS= read -r h; do
  echo "#include <${h#include/}>"
done < <(git ls-files 'include/fieldcodec/*.hpp' | sort) >"$all"
echo 'int main() { return 0; }' >>"$all"

sources=(examples/example_*.cpp tests/interop/bridge/interop_node.cpp
         tests/interop/bridge/interop_master.cpp "$all")
jobs=()
for cxx in $compilers; do
  for level in $(levels_of "$cxx"); do
    for src in "${sources[@]}"; do
      jobs+=("$cxx $level $src")
    done
  done
done

compile() {
  local cxx=$1 level=$2 src=$3
  local log
  log="$(mktemp "$out/log.XXXXXX")"
  if "$cxx" -std=c++20 "$level" -DNDEBUG -Wall -Wextra -Werror -Iinclude -c "$src" \
      -o /dev/null >"$log" 2>&1; then
    echo "ok     $cxx $level $src"
  else
    echo "FAILED $cxx $level $src"
    head -60 "$log"
    return 1
  fi
}
export -f compile
export out
printf '%s\n' "${jobs[@]}" | xargs -P "$(nproc)" -I{} bash -c 'compile {}'
