#!/usr/bin/env bash
# Cortex-M4 builds: the firmware example and one size probe per module, compiled with
# arm-none-eabi-g++ -Os -fno-exceptions -fno-rtti and linked with newlib-nano.
# Fails if an image references the heap or exceptions, or if a module exceeds its budget
# (examples/firmware/budgets.txt, bytes of flash above the baseline probe).
set -euo pipefail
cd "$(dirname "$0")/../.."
.ci/deps cross-arm

out=build-ci-cortex-m
mkdir -p "$out"
flags=(-std=c++20 -mcpu=cortex-m4 -mthumb -mfloat-abi=soft -Os -fno-exceptions -fno-rtti
       -ffunction-sections -fdata-sections -Wall -Wextra -Wpedantic -Werror -Wconversion
       -Wsign-conversion -Wno-array-bounds -Wno-stringop-overflow -Wno-stringop-overread
       -Iinclude -Iexamples/firmware
       -Wl,--gc-sections --specs=nano.specs --specs=nosys.specs)

flash() { arm-none-eabi-size -A "$1" | awk '$1 ~ /^\.(text|rodata|data|ARM\.exidx|init_array)/ {s += $2} END {print s}'; }

forbidden='(operator new|operator delete|malloc|calloc|realloc|free|__cxa_throw|__cxa_allocate_exception|__gxx_personality)'
check_symbols() {
  local elf=$1
  if arm-none-eabi-nm -C "$elf" | grep -E " [TtUuWw] .*\b$forbidden\b" | grep -v "_free_r\|__malloc_lock\|__malloc_unlock" ; then
    echo "FAIL: $elf references the heap or exceptions (symbols above)" >&2
    return 1
  fi
}

status=0
for src in examples/firmware/*.cpp; do
  name="$(basename "$src" .cpp)"
  arm-none-eabi-g++ "${flags[@]}" "$src" -o "$out/$name.elf"
  check_symbols "$out/$name.elf" || status=1
done

base=$(flash "$out/size_baseline.elf")
printf '%-16s %8s %8s\n' module bytes budget
while read -r module budget; do
  [[ -z "$module" || "$module" == \#* ]] && continue
  elf="$out/size_$module.elf"
  if [ ! -f "$elf" ]; then echo "FAIL: no size probe for $module" >&2; status=1; continue; fi
  bytes=$(( $(flash "$elf") - base ))
  printf '%-16s %8d %8d\n' "$module" "$bytes" "$budget"
  if (( bytes > budget )); then echo "FAIL: $module is over its budget" >&2; status=1; fi
done < examples/firmware/budgets.txt
if [ -f "$out/firmware.elf" ]; then
  printf '%-16s %8d\n' firmware "$(( $(flash "$out/firmware.elf") - base ))"
fi
exit $status
