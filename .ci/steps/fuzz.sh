#!/usr/bin/env bash
# Builds every fuzz harness with libFuzzer + ASan + UBSan (clang) and runs each for a bounded
# time, starting from its committed seed corpus. New inputs go to a scratch directory, never
# into the repository. FUZZ_SECONDS (default 20) is the time per harness. The mutation seed is
# fixed (FUZZ_SEED, default 1) so that a CI run repeats the sequence that was checked before
# submitting instead of gambling on a new one; long exploratory runs use other seeds
# (fuzz/FINDINGS.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
.ci/deps base clang

seconds="${FUZZ_SECONDS:-20}"
build=build-ci-fuzz
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DFIELDCODEC_FUZZ_ENGINE=libfuzzer -DFIELDCODEC_BUILD_TESTS=OFF \
  -DFIELDCODEC_BUILD_EXAMPLES=OFF -DFIELDCODEC_BUILD_CODEGEN=OFF >/dev/null
cmake --build "$build" -j"$(nproc)"

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
status=0
for harness in "$build"/fuzz/fuzz_*; do
  [ -x "$harness" ] || continue
  name="$(basename "$harness")"
  short="${name#fuzz_}"
  mkdir -p "$scratch/$short"
  echo "--- $name (${seconds}s)"
  if ! "$harness" -seed="${FUZZ_SEED:-1}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$scratch/$short-" \
      "$scratch/$short" "fuzz/corpus/$short" >"$scratch/$short.log" 2>&1; then
    echo "FAILED: $name"; tail -40 "$scratch/$short.log"; status=1
  else
    grep -E "stat::number_of_executed_units|stat::new_units_added" "$scratch/$short.log" | tr '\n' ' '
    echo
  fi
done
exit $status
