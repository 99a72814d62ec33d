#!/usr/bin/env bash
# The test suite on a big-endian host: s390x, cross-compiled and run under qemu-user. Not the
# benchmarks (nothing runs them here) nor the per-header checks (FIELDCODEC_HEADER_CHECK=OFF:
# self-containment does not depend on the target; .ci/run's g++ build compiles them, and the
# headers with byte-order branches - core/bytes.hpp, canopen/sdo_transfer.hpp, compax/nx.hpp -
# are compiled and run here by their tests).
set -euo pipefail
cd "$(dirname "$0")/../.."
.ci/deps base cross-s390x

# The cross compiler must not see the host's /usr/include; give it doctest alone.
inc="$(mktemp -d)"
ln -s /usr/include/doctest "$inc/doctest"

build=build-ci-s390x
# Optimised at -O1, not Release's -O3: this step is about byte order, which the optimiser does
# not change, and -O1 compiles the suite in about two thirds of the time (g++ 12 for s390x, a
# node test: 4.5 s against 7.0 s); g++'s -O3 build is .ci/run's step 1.
# FIELDCODEC_TEST_SHORT_RUNS: the randomised and sweeping tests run a tenth of their counts
# (tests/short_runs.hpp); under qemu their full counts took most of this step's test time.
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG -DFIELDCODEC_TEST_SHORT_RUNS" \
  -DFIELDCODEC_TEST_PCH=ON \
  -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/s390x-linux-gnu.cmake \
  -DDOCTEST_INCLUDE_DIR="$inc" \
  -DFIELDCODEC_BUILD_CODEGEN=OFF -DFIELDCODEC_BUILD_EXAMPLES=OFF -DFIELDCODEC_BUILD_BENCH=OFF \
  -DFIELDCODEC_HEADER_CHECK=OFF -DFIELDCODEC_WERROR=ON >/dev/null
cmake --build "$build" -j"$(nproc)"
# Prove the binaries really are big-endian s390x before trusting a green run.
file_out="$(od -An -tx1 -j5 -N1 "$build"/tests/test_core | tr -d ' ')"
if [ "$file_out" != "02" ]; then echo "test_core is not a big-endian ELF" >&2; exit 1; fi
junit="$(cd "$build" && pwd)/ctest-junit.xml"
ctest --test-dir "$build" -j"$(nproc)" --output-on-failure --output-junit "$junit"
python3 tests/skip_report.py "$junit"
