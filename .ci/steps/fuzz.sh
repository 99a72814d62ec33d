#!/usr/bin/env bash
# Builds every fuzz harness with libFuzzer + ASan + UBSan (clang) and runs each from its
# committed seed corpus. New inputs go to a scratch directory, never into the repository.
#
# The same run every time: the mutation seed is fixed (FUZZ_SEED, default 1) and each harness
# runs a fixed number of executions (fuzz/runs.txt, about 10 s each on CI's machine) instead of
# a time, with address randomisation off, so a tree that passed before submitting passes in CI
# and a finding reproduces (libFuzzer's sequence then depends on the seed, the corpus and the
# count, not on the clock; corpus reloading is off). A harness not in fuzz/runs.txt runs for a time: FUZZ_TOTAL_SECONDS (default
# 150 s of wall time) shared by such harnesses, as many at a time as there are cores, at least
# 10 s each (FUZZ_SECONDS sets it directly). FUZZ_RUNS_SCALE (default 1) multiplies the counts
# for a longer run; exploration with other seeds: fuzz/FINDINGS.md.
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
echo "fuzz: ${#harnesses[@]} harnesses, ${jobs} at a time; counts from fuzz/runs.txt (x${FUZZ_RUNS_SCALE:-1}), else ${seconds} s"

# Address randomisation off (setarch -R): the harnesses' comparisons of addresses feed
# libFuzzer's coverage, so with it on two runs of one count and seed diverge. Where the machine
# forbids it (a container's seccomp may), the runs are not repeatable: said, not hidden.
norandom=()
if setarch "$(uname -m)" -R true 2>/dev/null; then
  norandom=(setarch "$(uname -m)" -R)
else
  echo "fuzz: note: address randomisation cannot be turned off here: runs are not repeatable"
fi
export norandom_cmd="${norandom[*]}"

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
run_one() {
  local harness=$1 name short
  name="$(basename "$harness")"
  short="${name#fuzz_}"
  mkdir -p "$scratch/$short"
  local runs budget
  runs="$(awk -v h="$name" '$1 == h {print $2}' fuzz/runs.txt)"
  if [ -n "$runs" ]; then
    # a count: the same sequence every time (a cap of 60 s only against a runaway harness)
    budget=(-runs="$(( runs * ${FUZZ_RUNS_SCALE:-1} ))" -max_total_time=$(( 60 * ${FUZZ_RUNS_SCALE:-1} )))
  else
    echo "--- note: $name is not in fuzz/runs.txt: it runs for ${seconds} s (not repeatable)"
    budget=(-max_total_time="$seconds")
  fi
  # shellcheck disable=SC2086 # norandom_cmd: a command and its arguments, or nothing
  if $norandom_cmd "$harness" -seed="${FUZZ_SEED:-1}" "${budget[@]}" -reload=0 -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$scratch/$short-" \
      "$scratch/$short" "fuzz/corpus/$short" >"$scratch/$short.log" 2>&1; then
    echo "--- $name: $(grep -E 'stat::number_of_executed_units|stat::new_units_added' \
      "$scratch/$short.log" | tr '\n' ' ')"
    local done
    done="$(awk '/stat::number_of_executed_units/ {print $2}' "$scratch/$short.log")"
    if [ -n "$runs" ] && [ "${done:-0}" -lt "$(( runs * ${FUZZ_RUNS_SCALE:-1} ))" ]; then
      echo "--- note: $name stopped at its time cap after ${done:-0} runs (not repeatable;" \
        "fuzz/runs.txt asks too many for this machine)"
    fi
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
