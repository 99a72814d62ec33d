#!/usr/bin/env python3
"""Every XDD/XDC/XPD of the XML corpus is read by fieldcodec-gen, or refused with a diagnostic
naming the construct; what it reads is checked against an independent reading with xml.etree.

For each file of CORPUS/xdd/ the generator writes the dictionary as an EDS (--eds), which this
script reads back with its own INI parsing. Against its own reading of the XML it checks:
  * the objects: every Object/CANopenObject is an EDS object, and there are no others;
  * every entry (a VAR object, or a SubObject): it exists, with the data type code the XML
    gives (the dataType attribute, or the IEC type of the parameter its uniqueIDRef names);
  * every default value (defaultValue attribute, else the parameter's <defaultValue>) and every
    XDC actualValue (the EDS ParameterValue), compared as numbers, node-ID expressions, text or
    bytes as the type says;
  * every PDO mapping entry: the defaults of the sub-objects of the mapping objects
    (1600h-17FFh, 1A00h-1BFFh) — counted and reported.
A file the generator refuses must be one this script finds the defect in on its own (a
duplicate object or sub-object, an entry without any data type) and the generator's
diagnostic must name it.

usage: xml_corpus.py GEN CORPUS_DIR WORK_DIR
Exit status 0 when every file passes, 1 otherwise.
"""
import configparser
import os
import re
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET

IEC = {"BOOL": 0x01, "SINT": 0x02, "INT": 0x03, "DINT": 0x04, "USINT": 0x05, "UINT": 0x06,
       "UDINT": 0x07, "REAL": 0x08, "STRING": 0x09, "BITSTRING": 0x0A, "WSTRING": 0x0B,
       "LREAL": 0x11, "LINT": 0x15, "ULINT": 0x1B, "BYTE": 0x05, "WORD": 0x06, "DWORD": 0x07,
       "LWORD": 0x1B, "CHAR": 0x05}
BYTE_STRINGS = {0x09, 0x0A, 0x0B, 0x0F}
REALS = {0x08, 0x11}


def local(tag):
    return tag.rsplit("}", 1)[-1]


def children(el, name):
    return [c for c in el if local(c.tag) == name]


def read_eds(path):
    cp = configparser.ConfigParser(strict=False, interpolation=None, delimiters=("=",),
                                   comment_prefixes=(";",), inline_comment_prefixes=None)
    cp.optionxform = str
    with open(path, encoding="utf-8") as f:
        cp.read_file(f)
    return cp


def number(text):
    """An XML or EDS number: ('node', n) for $NODEID+n, an int, or a float."""
    t = text.strip()
    m = re.fullmatch(r"\$NODEID\s*\+\s*(.+)|(.+?)\s*\+\s*\$NODEID|\$NODEID", t, re.I)
    if m:
        operand = m.group(1) or m.group(2) or "0"
        return ("node", number(operand))
    low = t.lower()
    if low in ("true", "false"):
        return 1 if low == "true" else 0
    neg = low.startswith("-")
    body = low.lstrip("+-")
    if body.startswith("0x") or body.startswith("#x"):
        v = int(body[2:], 16)
    elif re.fullmatch(r"[0-9]+", body):
        v = int(body, 10)
    else:
        return float(t)
    return -v if neg else v


def real_value(text, code):
    t = text.strip()
    if t.lower().startswith("0x"):
        bits = int(t, 16)
        return struct.unpack("<f" if code == 0x08 else "<d",
                             bits.to_bytes(4 if code == 0x08 else 8, "little"))[0]
    return float(t)


def same_value(xml_text, eds_text, code):
    """Whether the XML value and the generator's EDS value are the same value of type `code`."""
    if code == 0x0401:  # MAC_ADDRESS: bytes
        return bytes(int(p, 16) for p in xml_text.split(":")).hex().upper() == eds_text
    if code == 0x0402:  # IP_ADDRESS
        return bytes(int(p) for p in xml_text.split(".")).hex().upper() == eds_text
    if code == 0x09:
        return xml_text == eds_text or '"' + xml_text + '"' == eds_text
    if code in (0x0A, 0x0F) or (code >= 0x20 and code not in REALS):
        return re.sub(r"\s", "", xml_text).upper() == eds_text.upper()
    if code == 0x0B:
        return xml_text == eds_text
    if code in REALS:
        a = number(xml_text)
        if isinstance(a, tuple):
            return False
        return real_value(xml_text, code) == real_value(eds_text, code)
    a = number(xml_text)
    b = number(eds_text)
    if isinstance(a, int) and isinstance(b, int) and not isinstance(a, bool):
        width = {0x02: 8, 0x03: 16, 0x04: 32, 0x10: 24, 0x12: 40, 0x13: 48, 0x14: 56,
                 0x15: 64}.get(code)
        if width and a >= 0 and a >= 1 << (width - 1) and a < 1 << width:
            a -= 1 << width  # a signed type written as its bit pattern
    return a == b


def ignored_byte_string(text, code):
    """The generator ignores (with a warning) an OCTET_STRING/DOMAIN value that is not hex."""
    return code in (0x0A, 0x0F) and not re.fullmatch(r"(\s*[0-9A-Fa-f]{2})*\s*", text)


class xdd_file:
    """The independent reading of one XDD."""

    def __init__(self, path):
        self.root = ET.parse(path).getroot()
        self.params = {}
        for el in self.root.iter():
            if local(el.tag) == "parameter" and el.get("uniqueID"):
                self.params[el.get("uniqueID")] = el
        self.objects = [el for el in self.root.iter()
                        if local(el.tag) in ("Object", "CANopenObject")]

    def param(self, el):
        ref = el.get("uniqueIDRef")
        return self.params.get(ref) if ref else None

    def type_code(self, el):
        if el.get("dataType"):
            return int(el.get("dataType"), 16)
        p = self.param(el)
        if p is None:
            return None
        for c in p:
            if local(c.tag) in IEC:
                return IEC[local(c.tag)]
        if children(p, "dataTypeIDRef"):
            return 0x0F  # a VAR typed by a structure: a DOMAIN
        return None

    def value(self, el, attr, child):
        if el.get(attr) is not None:
            return el.get(attr)
        p = self.param(el)
        if p is not None:
            for c in children(p, child):
                return c.get("value")
        return None

    def entries(self):
        """(index, sub, element) of every entry."""
        out = []
        for o in self.objects:
            index = int(o.get("index"), 16)
            code = int(o.get("objectType"), 0)
            subs = [c for c in o if local(c.tag) in ("SubObject", "CANopenSubObject")]
            if code in (6, 8, 9):
                for s in subs:
                    out.append((index, int(s.get("subIndex"), 16), s))
            else:
                out.append((index, 0, o))
        return out

    def defects(self):
        """What the generator must refuse, found independently."""
        found = []
        seen = set()
        for o in self.objects:
            index = int(o.get("index"), 16)
            if index in seen:
                found.append(f"duplicate object 0x{index:04X}")
            seen.add(index)
            subs = set()
            for s in o:
                if local(s.tag) not in ("SubObject", "CANopenSubObject"):
                    continue
                sub = int(s.get("subIndex"), 16)
                if sub in subs:
                    found.append(f"duplicate sub-object 0x{index:04X} sub-index 0x{sub:02X}")
                subs.add(sub)
        for index, sub, el in self.entries():
            if self.type_code(el) is None:
                where = f"object 0x{index:04X}" + (f" sub 0x{sub:02X}" if el is not None and
                                                   local(el.tag).endswith("SubObject") else "")
                found.append(f"no data type for {where}")
        return found


def eds_section(eds, index, sub, single):
    name = f"{index:04X}" if single else f"{index:04X}sub{sub:X}"
    return eds[name] if eds.has_section(name) else None


def check_xdd(gen, path, work):
    name = os.path.basename(path)
    out = os.path.join(work, name + ".eds")
    run = subprocess.run([gen, "-q", path, "--eds", out], capture_output=True, text=True)
    x = xdd_file(path)
    defects = x.defects()
    if run.returncode != 0:
        if not defects:
            return [f"refused, but no defect found independently:\n{run.stderr}"]
        missing = [d for d in defects[:3] if d not in run.stderr]
        if missing:
            return [f"refused without naming {missing}:\n{run.stderr}"]
        return "refused: " + defects[0] + (f" (+{len(defects) - 1} more)" if len(defects) > 1 else "")
    if defects:
        return [f"read although {defects[0]}"]
    eds = read_eds(out)
    problems = []
    objects = {s for s in eds.sections() if re.fullmatch(r"[0-9A-F]{4}", s)}
    xml_objects = {f"{int(o.get('index'), 16):04X}" for o in x.objects}
    if objects != xml_objects:
        problems.append(f"objects differ: only EDS {sorted(objects - xml_objects)[:5]}, "
                        f"only XML {sorted(xml_objects - objects)[:5]}")
    entries = x.entries()
    singles = {int(o.get("index"), 16) for o in x.objects
               if int(o.get("objectType"), 0) not in (6, 8, 9)}
    defaults = actuals = pdo_entries = 0
    for index, sub, el in entries:
        sec = eds_section(eds, index, sub, index in singles)
        where = f"0x{index:04X} sub {sub}"
        if sec is None:
            problems.append(f"{where}: no EDS section")
            continue
        code = x.type_code(el)
        if int(sec.get("DataType"), 16) != code:
            problems.append(f"{where}: data type {sec.get('DataType')}, XML 0x{code:04X}")
            continue
        for attr, child, key in (("defaultValue", "defaultValue", "DefaultValue"),
                                 ("actualValue", "actualValue", "ParameterValue")):
            v = x.value(el, attr, child)
            if v is None or (v == "" and code not in BYTE_STRINGS) or v == "":
                continue
            if ignored_byte_string(v, code):
                if sec.get(key) is not None:
                    problems.append(f"{where}: {key} {sec.get(key)} of ignored '{v}'")
                continue
            e = sec.get(key)
            if e is None or not same_value(v, e, code):
                problems.append(f"{where}: {key} {e!r}, XML {v!r}")
                continue
            if key == "DefaultValue":
                defaults += 1
                if (0x1600 <= index <= 0x17FF or 0x1A00 <= index <= 0x1BFF) and sub > 0:
                    pdo_entries += 1 if number(v) != 0 else 0
            else:
                actuals += 1
    if problems:
        return problems
    return (f"{len(xml_objects)} objects, {len(entries)} entries, {defaults} defaults, "
            f"{actuals} actual values, {pdo_entries} PDO mapping entries")


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    gen, corpus, work = sys.argv[1:]
    os.makedirs(work, exist_ok=True)
    files = sorted(os.path.join(corpus, "xdd", f) for f in os.listdir(os.path.join(corpus, "xdd")))
    failed = 0
    read = refused = 0
    for path in files:
        result = check_xdd(gen, path, work)
        name = os.path.basename(path)
        if isinstance(result, list):
            failed += 1
            print(f"FAIL {name}")
            for p in result[:10]:
                print(f"     {p}")
        else:
            if result.startswith("refused"):
                refused += 1
            else:
                read += 1
            print(f"ok   {name}: {result}")
    print(f"xdd: {len(files)} files, {read} read, {refused} refused, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
