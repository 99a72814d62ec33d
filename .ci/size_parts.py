#!/usr/bin/env python3
"""Flash and RAM of fieldcodec's node next to CANopenNode's, split by part.

    size_parts.py --ours NODE.elf BASELINE.elf \
                  --peer NODE.elf BASELINE.elf [--peer-object PART=FILE.o ...] [--tool-prefix P]

Flash is .text + .rodata + .data + .ARM.exidx + .init_array, RAM is .data + .bss, each above
the image's baseline (the same scaffolding without a stack). The parts:

  OD data    the dictionary's tables and default values
  OD access  finding entries, reading and writing values, their checks (od/, the store, core/)
  libgcc     the compiler's run-time helpers (soft-float, 64-bit division), by library
  services   NMT, heartbeat, guarding, EMCY, SYNC, the device that routes frames to them and
             (CANopenNode) the driver that does that routing
  SDO        the SDO server and its channels, block CRC
  PDO        the PDO engine and mapping checks
  rest       what is left above the baseline (the probe's own main, libc, alignment)

fieldcodec's symbols are given their part by their qualified name (template arguments and
parameters removed; see RULES); CANopenNode's by the object file that defines them
(--peer-object, e.g. SDO=CO_SDOserver.o), libgcc's by libgcc.a. Exit status 1 when fieldcodec's
flash above its baseline is larger than CANopenNode's.
"""
import argparse
import re
import subprocess
import sys

PARTS = ["OD data", "OD access", "libgcc", "services", "SDO", "PDO"]
FLASH = (".text", ".rodata", ".data", ".ARM.exidx", ".init_array")
RAM = (".data", ".bss")

# fieldcodec: the first rule whose pattern matches the start of the stripped name decides
RULES = [
    (r"fieldcodec::dictionaries::", "OD data"),
    (r"\(anonymous namespace\)::(layout|storage)\b", "OD data"),
    (r"fieldcodec::canopen::node::(pdo_engine|pdo_config|mapping_abort)\b", "PDO"),
    (r"fieldcodec::canopen::pdo::", "PDO"),
    (r"fieldcodec::canopen::node::sdo_channels\b", "SDO"),
    (r"fieldcodec::canopen::(sdo::)?(dictionary_store|object_store|layout|make_layout)\b",
     "OD access"),
    (r"fieldcodec::canopen::sdo::", "SDO"),
    (r"fieldcodec::canopen::frames::segments?\b", "SDO"),
    (r"fieldcodec::crc::", "SDO"),
    (r"fieldcodec::canopen::", "services"),
    (r"_GLOBAL__sub_I_", "services"),
    (r"fieldcodec::", "OD access"),
]


def run(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def strip_name(name):
    """The qualified name without template arguments, function parameters and clone suffixes."""
    name = re.sub(r" \[clone [^\]]*\]", "", name)
    out, depth = [], 0
    for i, ch in enumerate(name):
        if ch == "<" and not name.endswith("operator", 0, i):
            depth += 1
        elif ch == ">" and depth:
            depth -= 1
        elif depth == 0:
            if ch == "(" and "(anonymous namespace)" not in name[i:i + 21]:
                break
            out.append(ch)
    # a function template's name starts with its return type: keep the qualified name alone
    name = "".join(out).strip().replace("(anonymous namespace)", "{anon}")
    return name.split(" ")[-1].replace("{anon}", "(anonymous namespace)")


def sections(prefix, elf):
    sizes = {}
    for line in run([prefix + "size", "-A", elf]).splitlines():
        f = line.split()
        if len(f) >= 2 and f[0].startswith(".") and f[1].isdigit():
            sizes[f[0]] = int(f[1])
    return sizes


def symbols(prefix, elf):
    """(name, size, section) of every sized symbol in a flash section, aliases once."""
    seen, out = set(), []
    for line in run([prefix + "objdump", "-t", "-C", elf]).splitlines():
        m = re.match(r"^([0-9a-f]{8}) (.{7}) (\S+)\t([0-9a-f]{8}) (.*)$", line)
        if not m:
            continue
        addr, section, size = int(m[1], 16), m[3], int(m[4], 16)
        name = re.sub(r"^\.hidden ", "", m[5].strip())
        if size == 0 or section not in FLASH or (addr, size) in seen:
            continue
        seen.add((addr, size))
        out.append((name, size, section))
    return out


def defined_in(prefix, path):
    names = set()
    for line in run([prefix + "nm", "-C", "--defined-only", path]).splitlines():
        f = line.split(maxsplit=2)
        if len(f) == 3:
            names.add(f[2])
        elif len(f) == 2:
            names.add(f[1])
    return names


def split(prefix, elf, base, libgcc, objects, listing=None):
    """{part: bytes} of elf's flash above base, 'rest' included, and the RAM above base;
    `listing` (a list) receives (part, size, name) of every symbol."""
    s, b = sections(prefix, elf), sections(prefix, base)
    flash = sum(s.get(k, 0) for k in FLASH) - sum(b.get(k, 0) for k in FLASH)
    ram = sum(s.get(k, 0) for k in RAM) - sum(b.get(k, 0) for k in RAM)
    parts = dict.fromkeys(PARTS, 0)
    for name, size, _ in symbols(prefix, elf):
        part = None
        if name in libgcc:
            part = "libgcc"
        else:
            for p, names in objects:
                if name in names:
                    part = p
                    break
        if part is None and not objects:
            stripped = strip_name(name)
            for pattern, p in RULES:
                if re.match(pattern, stripped):
                    part = p
                    break
        if part is not None:
            parts[part] += size
        if listing is not None:
            listing.append((part or "rest", size, name))
    parts["rest"] = flash - sum(parts.values())
    return flash, ram, parts


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ours", nargs=2, required=True, metavar=("NODE", "BASELINE"))
    ap.add_argument("--peer", nargs=2, required=True, metavar=("NODE", "BASELINE"))
    ap.add_argument("--peer-object", action="append", default=[], metavar="PART=FILE.o")
    ap.add_argument("--tool-prefix", default="arm-none-eabi-")
    ap.add_argument("--libgcc", required=True, help="libgcc.a the images were linked with")
    ap.add_argument("--list", action="store_true", help="also list every symbol by part")
    ap.add_argument("--warn-only", action="store_true",
                    help="say when fieldcodec's node is larger, but exit 0")
    a = ap.parse_args()

    libgcc = defined_in(a.tool_prefix, a.libgcc)
    objects = []
    for spec in a.peer_object:
        part, path = spec.split("=", 1)
        if part not in PARTS:
            sys.exit("size_parts: unknown part %r (one of %s)" % (part, ", ".join(PARTS)))
        objects.append((part, defined_in(a.tool_prefix, path)))

    ours_list, peer_list = [], []
    ours = split(a.tool_prefix, a.ours[0], a.ours[1], libgcc, [], ours_list)
    peer = split(a.tool_prefix, a.peer[0], a.peer[1], libgcc, objects, peer_list)
    if a.list:
        for title, listing in (("fieldcodec", ours_list), ("CANopenNode", peer_list)):
            for part, size, name in sorted(listing, key=lambda t: (t[0], -t[1])):
                print("%-11s %-9s %6d %s" % (title, part, size, name))

    print("%-12s %10s %12s %7s" % ("", "fieldcodec", "CANopenNode", "ratio"))
    for part in PARTS + ["rest"]:
        o, p = ours[2][part], peer[2][part]
        ratio = "%.2f" % (o / p) if p > 0 else "-"
        print("%-12s %10d %12d %7s" % (part, o, p, ratio))
    print("%-12s %10d %12d %7.2f" % ("flash", ours[0], peer[0], ours[0] / peer[0]))
    print("%-12s %10d %12d %7.2f" % ("RAM", ours[1], peer[1], ours[1] / peer[1]))
    if ours[0] > peer[0]:
        print("%s: fieldcodec's node takes %d bytes of flash more than CANopenNode's"
              % ("NOTE" if a.warn_only else "FAIL", ours[0] - peer[0]), file=sys.stderr)
        return 0 if a.warn_only else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
