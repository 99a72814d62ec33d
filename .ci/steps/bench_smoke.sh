#!/usr/bin/env bash
# Benchmark smoke test: runs each codec benchmark of a Release build briefly. Every run first
# checks that fieldcodec and the hand-written baseline agree on all inputs (a mismatch fails the
# step); the timings of this short run are printed but not judged. Then one operation per
# executable goes through bench/callgrind.sh's exact-iteration mode under valgrind. Full
# numbers: docs/performance.md.
#   BENCH_BUILD_DIR=build .ci/steps/bench_smoke.sh   reuse a Release build of the whole tree
#                                                    (.ci/run: the one of its first step)
# Without BENCH_BUILD_DIR it configures and builds the benchmarks alone in build-ci-bench.
set -euo pipefail
cd "$(dirname "$0")/../.."
.ci/deps base valgrind

if [ -n "${BENCH_BUILD_DIR:-}" ]; then
  build="$BENCH_BUILD_DIR"
  if ! grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$build/CMakeCache.txt"; then
    echo "bench_smoke: $build is not a Release build" >&2
    exit 1
  fi
else
  build=build-ci-bench
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="${CXX:-g++}" \
    -DFIELDCODEC_BUILD_BENCH=ON -DFIELDCODEC_BUILD_TESTS=OFF -DFIELDCODEC_BUILD_EXAMPLES=OFF \
    -DFIELDCODEC_BUILD_FUZZERS=OFF -DFIELDCODEC_BUILD_CODEGEN=OFF -DFIELDCODEC_WERROR=ON >/dev/null
fi
cmake --build "$build" --target fieldcodec_bench -j"$(nproc)"

shopt -s nullglob
ran=0
for exe in "$build"/bench/codec_*; do
  [ -f "$exe" ] && [ -x "$exe" ] || continue
  echo "--- $(basename "$exe") --quick"
  "$exe" --quick
  "$exe" --run "harness/empty loop" --impl fieldcodec --iterations 1000
  ran=$((ran + 1))
done
if [ "$ran" -eq 0 ]; then echo "bench_smoke: no bench executables built" >&2; exit 1; fi

echo "--- callgrind (one operation)"
N=200 bench/callgrind.sh "$build" "bytes/load_unsigned w=4 le"
