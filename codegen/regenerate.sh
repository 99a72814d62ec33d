#!/bin/sh
# Regenerate include/fieldcodec/dictionaries/<name>.hpp from every dictionaries/*.eds, *.dcf
# and *.csv, the EDS exports in dictionaries/export/ (DPQ), the XDD and ESI exports there
# (XENAX CANopen, POWERLINK, EtherCAT), the PDO layouts headers <name>_pdos.hpp (XENAX CANopen,
# EtherCAT) and the dictionary of the firmware
# example (examples/firmware/io_node_dictionary.hpp from io_node.eds). With --check nothing is
# written: the script fails (exit 1) when a checked-in header differs from what the generator
# writes, is missing, or has no source any more.
#
# usage: codegen/regenerate.sh [--check] [--gen PATH/TO/fieldcodec-gen]
#
# Without --gen (or $FIELDCODEC_GEN) the generator is built in build-regenerate/ first.
# Output depends only on the input files: same inputs, same bytes.
set -eu
cd "$(dirname "$0")/.."
check=
gen=${FIELDCODEC_GEN:-}
while [ $# -gt 0 ]; do
  case "$1" in
    --check) check=--check ;;
    --gen) gen=$2; shift ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "regenerate.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done
if [ -z "$gen" ]; then
  cmake -S . -B build-regenerate -DFIELDCODEC_BUILD_TESTS=OFF -DFIELDCODEC_BUILD_EXAMPLES=OFF \
    -DFIELDCODEC_BUILD_FUZZERS=OFF -DFIELDCODEC_INSTALL=OFF >/dev/null
  cmake --build build-regenerate --target fieldcodec-gen >/dev/null
  gen=build-regenerate/codegen/fieldcodec-gen
fi
out=include/fieldcodec/dictionaries
# CSV tables of CANopen devices that are also exported as EDS to dictionaries/export/
eds_exports="dpq_parameters"
# The DPQ maps its PDOs in BODAC's Bus Manager and documents no mapping parameters (1A00h..):
# its Tx-PDO communication parameters (1800h..1803h, the event timers) stay out of the EDS,
# because CiA 301 tools refuse a communication parameter without its mapping parameter
# (docs/dpq.md "EDS export").
export_only_dpq_parameters="0x0000-0x17FF,0x1A00-0xFFFF"
# XML device descriptions of the XENAX dictionaries (manual 2.4 lists Xenax_CANopen.xdd and
# Xenax_Powerlink.xdd): name:profile, written to dictionaries/export/<name>.xdd
xdd_exports="xenax_canopen:canopen xenax_powerlink:powerlink"
# ESI (ETG.2000) of the XENAX EtherCAT dictionary (the manual lists Xenax_EtherCAT.xml), written
# to dictionaries/export/<name>.xml
esi_exports="xenax_ethercat"
# Dictionaries whose PDO layouts are generated beside their header (<name>_pdos.hpp: the default
# PDO mappings as compile-time layouts checked against the dictionary)
pdo_headers="xenax_canopen xenax_ethercat"
mkdir -p "$out"
status=0
expected=
for src in dictionaries/*.eds dictionaries/*.dcf dictionaries/*.csv; do
  [ -e "$src" ] || continue
  # a CSV without an index or code column is not a dictionary table (e.g. a helper table)
  case "$src" in
    *.csv)
      header=$(grep -v '^#' "$src" | grep -v '^[[:space:]]*$' | head -n 1)
      case ",$header," in
        *,index,*|*,code,*) ;;
        *) echo "regenerate.sh: warning: $src has no 'index' or 'code' column; skipped" >&2
           continue ;;
      esac ;;
  esac
  base=$(basename "$src")
  stem=$(echo "${base%.*}" | tr 'A-Z' 'a-z' | sed -e 's/[^a-z0-9][^a-z0-9]*/_/g' -e 's/^_//' -e 's/_$//')
  expected="$expected $stem.hpp"
  if ! "$gen" $check --quiet --name "$stem" -o "$out/$stem.hpp" "$src"; then
    status=1
  fi
  # CiA 306 exports of the CSV parameter tables of CANopen devices, for standard CANopen tools
  case " $eds_exports " in
    *" $stem "*)
      mkdir -p dictionaries/export
      only=$(eval "echo \${export_only_$stem:-}")
      if ! "$gen" $check --quiet --name "$stem" ${only:+--only "$only"} --eds "dictionaries/export/$stem.eds" "$src"; then
        status=1
      fi ;;
  esac
  case " $esi_exports " in
    *" $stem "*)
      mkdir -p dictionaries/export
      if ! "$gen" $check --quiet --esi "dictionaries/export/$stem.xml" "$src"; then
        status=1
      fi ;;
  esac
  case " $pdo_headers " in
    *" $stem "*)
      expected="$expected ${stem}_pdos.hpp"
      if ! "$gen" $check --quiet --name "$stem" --pdo-header "$out/${stem}_pdos.hpp" "$src"; then
        status=1
      fi ;;
  esac
  for x in $xdd_exports; do
    [ "${x%%:*}" = "$stem" ] || continue
    mkdir -p dictionaries/export
    if ! "$gen" $check --quiet --xdd-profile "${x#*:}" --xdd "dictionaries/export/$stem.xdd" "$src"; then
      status=1
    fi
  done
done
# Example dictionaries generated from an EDS beside the example that uses them (the header says
# "Regenerate with codegen/regenerate.sh"): source:name:output
for ex in examples/firmware/io_node.eds:io_node:examples/firmware/io_node_dictionary.hpp; do
  src=${ex%%:*}; rest=${ex#*:}; name=${rest%%:*}; dst=${rest#*:}
  if ! "$gen" $check --quiet --name "$name" -o "$dst" "$src"; then
    status=1
  fi
done
if [ -n "$check" ]; then
  for h in "$out"/*.hpp; do
    [ -e "$h" ] || continue
    case " $expected " in
      *" $(basename "$h") "*) ;;
      *) echo "$h: error: no source in dictionaries/ (stale generated header)" >&2; status=1 ;;
    esac
  done
fi
exit $status
