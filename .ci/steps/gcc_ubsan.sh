#!/usr/bin/env bash
# The test suite built with g++ under AddressSanitizer + UndefinedBehaviorSanitizer, beside the
# clang++ sanitizer run of .ci/run step 3. g++ instruments differently from clang++ (it once
# refused to evaluate a constexpr PDO mapping under -fsanitize=undefined, issue 12 #13), so
# both compilers' sanitizer builds must compile and pass.
set -euo pipefail
cd "$(dirname "$0")/../.."

CXX=g++ BUILD_DIR=build-ci-gcc-asan \
  CXXFLAGS="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
  UBSAN_OPTIONS=print_stacktrace=1 bash .ci/test
