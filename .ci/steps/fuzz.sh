#!/usr/bin/env bash
# Builds every fuzz harness with libFuzzer + ASan + UBSan (clang) and runs each for a bounded
# time, starting from its committed seed corpus. New inputs go to a scratch directory, never
# into the repository. The mutation seed is fixed (FUZZ_SEED, default 1) so that a CI run repeats
# the sequence that was checked before submitting instead of gambling on a new one; long
# exploratory runs use other seeds (fuzz/FINDINGS.md).
#
# Time: the harnesses share a total budget, FUZZ_TOTAL_SECONDS (default 150 s of wall time),
# run as many at a time as there are cores (a libFuzzer process uses one); each gets
# budget × cores / harnesses seconds, at least 10 (FUZZ_SECONDS sets it directly). So adding a
# harness shortens the others' runs instead of lengthening CI.
set -euo pipefail
cd "$(dirname "$0")/../.."
.ci/deps base clang

build=build-ci-fuzz
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DFIELDCODEC_FUZZ_ENGINE=libfuzzer -DFIELDCODEC_BUILD_TESTS=OFF -DFIELDCODEC_WERROR=ON \
  -DFIELDCODEC_BUILD_EXAMPLES=OFF -DFIELDCODEC_BUILD_CODEGEN=OFF -DFIELDCODEC_BUILD_BENCH=OFF \
  >/dev/null
cmake --build "$build" -j"$(nproc)"

harnesses=()
for h in "$build"/fuzz/fuzz_*; do
  [ -f "$h" ] && [ -x "$h" ] && harnesses+=("$h")
done
if [ "${#harnesses[@]}" -eq 0 ]; then echo "fuzz: no harness built" >&2; exit 1; fi
jobs="$(nproc)"
seconds="${FUZZ_SECONDS:-$(( ${FUZZ_TOTAL_SECONDS:-150} * jobs / ${#harnesses[@]} ))}"
if [ "$seconds" -lt 10 ]; then seconds=10; fi
echo "fuzz: ${#harnesses[@]} harnesses, ${seconds} s each, ${jobs} at a time"

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
run_one() {
  local harness=$1 name short
  name="$(basename "$harness")"
  short="${name#fuzz_}"
  mkdir -p "$scratch/$short"
  if "$harness" -seed="${FUZZ_SEED:-1}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$scratch/$short-" \
      "$scratch/$short" "fuzz/corpus/$short" >"$scratch/$short.log" 2>&1; then
    echo "--- $name: $(grep -E 'stat::number_of_executed_units|stat::new_units_added' \
      "$scratch/$short.log" | tr '\n' ' ')"
  else
    echo "--- FAILED: $name"
    tail -40 "$scratch/$short.log"
    # the input itself, whatever its size (libFuzzer prints it only when small; the scratch
    # directory goes with the run): replay it with the harness of a replay build
    local a
    for a in "$scratch/$short"-*; do
      [ -f "$a" ] && echo "input $(basename "$a") (base64): $(base64 -w0 "$a")"
    done
    return 1
  fi
}
export -f run_one
export scratch seconds
printf '%s\n' "${harnesses[@]}" | xargs -P "$jobs" -I{} bash -c 'run_one {}'
