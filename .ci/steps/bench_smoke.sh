#!/usr/bin/env bash
# Benchmark smoke test: builds the codec benchmarks in Release and runs each one briefly.
# Every run first checks that fieldcodec and the hand-written baseline agree on all inputs
# (a mismatch fails the step); the timings of this short run are printed but not judged.
# Then one operation per executable goes through bench/callgrind.sh's exact-iteration mode
# when valgrind is installed. Full numbers: docs/performance.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
.ci/deps base

build=build-ci-bench
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="${CXX:-g++}" \
  -DFIELDCODEC_BUILD_BENCH=ON -DFIELDCODEC_BUILD_TESTS=OFF -DFIELDCODEC_BUILD_EXAMPLES=OFF \
  -DFIELDCODEC_BUILD_FUZZERS=OFF -DFIELDCODEC_BUILD_CODEGEN=OFF >/dev/null
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

if command -v valgrind >/dev/null; then
  echo "--- callgrind (one operation)"
  N=200 bench/callgrind.sh "$build" "bytes/load_unsigned w=4 le"
fi
