#!/usr/bin/env bash
# Cortex-M4 builds: the firmware example and one size probe per module, compiled with
# arm-none-eabi-g++ -Os -fno-exceptions -fno-rtti and linked with newlib-nano.
# Fails if an image references the heap or exceptions, or if a module exceeds its budget
# (examples/firmware/budgets.txt, bytes of flash above the baseline probe).
# Then the node side by side with CANopenNode v4 built from the same EDS (see the end).
set -euo pipefail
cd "$(dirname "$0")/../.."
.ci/deps cross-arm peer-build

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

# ---------------------------------------------------------------------------------------------
# size_node next to CANopenNode v4 with the same services and dictionary (docs/performance.md
# "Cortex-M"). CANopenNode's source and the recipe (its CO_CONFIG choices, the driver patch, a
# main(), an EDS-to-OD script) are in ../shared/peers/canopennode (README.md there): the
# sources are copied into the build directory and patched there, never into the repository.
# Same compiler and flags as its README gives (C, no -std=c++20 and no warnings of ours).
peer="${FIELDCODEC_CANOPENNODE:-../shared/peers/canopennode}"
echo
if [ ! -d "$peer/source" ] || [ ! -d "$peer/compare" ]; then
  if [ "${CI:-}" = true ]; then
    echo "FAIL: CANopenNode peer not found at $peer (CI=true: the side-by-side size is required)" >&2
    exit 1
  fi
  echo "SKIPPED: side by side with CANopenNode (peer not found at $peer; set FIELDCODEC_CANOPENNODE)"
  exit $status
fi
co="$out/canopennode"
rm -rf "$co"
mkdir -p "$co/obj"
cp -r "$peer/source/." "$co/"
cp "$peer"/compare/{co_config.h,io.h,regs.h,regs.c,node.c,baseline.c} "$co/"
patch -s -d "$co/example" -p0 < "$peer/compare/driver.patch"
python3 "$peer/compare/eds2co_od.py" examples/firmware/io_node.eds "$co/od" >/dev/null
cflags=(-mcpu=cortex-m4 -mthumb -mfloat-abi=soft -Os -ffunction-sections -fdata-sections
        -I"$co/od" -I"$co" -I"$co/example")
lflags=(-Wl,--gc-sections --specs=nano.specs --specs=nosys.specs)
co_sources=(CANopen.c 301/CO_ODinterface.c 301/CO_NMT_Heartbeat.c 301/CO_HBconsumer.c
            301/CO_Node_Guarding.c 301/CO_Emergency.c 301/CO_SDOserver.c 301/CO_SYNC.c
            301/CO_PDO.c 301/crc16-ccitt.c example/CO_driver_blank.c od/OD.c node.c regs.c)
for src in "${co_sources[@]}"; do
  arm-none-eabi-gcc "${cflags[@]}" -c "$co/$src" -o "$co/obj/$(basename "$src" .c).o"
done
arm-none-eabi-gcc "${cflags[@]}" "$co"/obj/*.o "${lflags[@]}" -o "$co/node.elf"
arm-none-eabi-gcc "${cflags[@]}" "$co/baseline.c" "$co/regs.c" "${lflags[@]}" -o "$co/baseline.elf"
o="$co/obj"
echo "size_node next to CANopenNode v4 (bytes above each one's baseline; io_node.eds):"
# parts by symbol (.ci/size_parts.py; FIELDCODEC_SIZE_LIST=1 lists every symbol); CANopenNode's
# driver counts as services: it routes received frames to them, as device::on_frame does
python3 .ci/size_parts.py \
  --ours "$out/size_node.elf" "$out/size_baseline.elf" \
  --peer "$co/node.elf" "$co/baseline.elf" \
  --libgcc "$(arm-none-eabi-gcc "${cflags[@]}" -print-libgcc-file-name)" \
  --peer-object "OD data=$o/OD.o" --peer-object "OD access=$o/CO_ODinterface.o" \
  --peer-object "services=$o/CANopen.o" --peer-object "services=$o/CO_NMT_Heartbeat.o" \
  --peer-object "services=$o/CO_HBconsumer.o" --peer-object "services=$o/CO_Node_Guarding.o" \
  --peer-object "services=$o/CO_Emergency.o" --peer-object "services=$o/CO_SYNC.o" \
  --peer-object "services=$o/CO_driver_blank.o" \
  --peer-object "SDO=$o/CO_SDOserver.o" --peer-object "SDO=$o/crc16-ccitt.o" \
  --peer-object "PDO=$o/CO_PDO.o" ${FIELDCODEC_SIZE_LIST:+--list} \
  --warn-only || status=1 # issue 27: --warn-only goes once the node is no larger
exit $status
