#!/usr/bin/env python3
"""Every XDD/XDC/XPD and ESI of the XML corpus is read by fieldcodec-gen, or refused with a
diagnostic naming the construct; what it reads is checked against an independent reading with
xml.etree.

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

For each device of each file of CORPUS/esi/ (chosen with --device PRODUCTCODE:REVISION where a
file has several) the same: the dictionary's objects plus what its PDOs describe and the
dictionary lacks (mapping objects, mapped objects, sync manager assignments 1C10h+n); every
sub-object of a record or array flattened from its DataType (SubItems, arrays of ArrayInfo,
Info/SubItem defaults by name, the rest in order); every default (DefaultValue, DefaultString,
DefaultData little-endian); every PDO entry: in the PDO layouts header (--pdo-header), and as
the default of the mapping object the generator adds where the dictionary lacks it. And the
device's SII EEPROM image (--sii), decoded here on its own (ETG.2010): the configuration area
(Eeprom/ConfigData) and its CRC-8 (x^8+x^2+x+1 from 0xFF, bit by bit), the identity, the
mailboxes (Sm MBoxOut/MBoxIn, Eeprom/BootStrap), the size word, the categories' chain, and every
PDO of the RxPDO/TxPDO categories against RxPdo/TxPdo (index, sync manager, entries, names):
all of them, or where the EEPROM is too small (a warning) those assigned by default, or none.

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


# ---- ESI --------------------------------------------------------------------------------------

ESI_TYPES = {"BOOL": 0x01, "BIT": 0x01, "BIT1": 0x01, "SINT": 0x02, "INT": 0x03, "DINT": 0x04,
             "USINT": 0x05, "UINT": 0x06, "UDINT": 0x07, "REAL": 0x08, "TIME_OF_DAY": 0x0C,
             "TIME_DIFFERENCE": 0x0D, "INT24": 0x10, "LREAL": 0x11, "INT40": 0x12, "INT48": 0x13,
             "INT56": 0x14, "LINT": 0x15, "UINT24": 0x16, "UINT40": 0x18, "UINT48": 0x19,
             "UINT56": 0x1A, "ULINT": 0x1B, "BYTE": 0x05, "WORD": 0x06, "DWORD": 0x07,
             "LWORD": 0x1B, "BITARR8": 0x05, "BITARR16": 0x06, "BITARR32": 0x07, "INT8": 0x02,
             "INT16": 0x03, "INT32": 0x04, "INT64": 0x15, "UINT8": 0x05, "UINT16": 0x06,
             "UINT32": 0x07, "UINT64": 0x1B, "FLOAT": 0x08, "DOUBLE": 0x11}
WIDTH = {0x01: 1, 0x02: 1, 0x03: 2, 0x04: 4, 0x05: 1, 0x06: 2, 0x07: 4, 0x08: 4, 0x10: 3,
         0x11: 8, 0x12: 5, 0x13: 6, 0x14: 7, 0x15: 8, 0x16: 3, 0x18: 5, 0x19: 6, 0x1A: 7,
         0x1B: 8}
SIGNED = {0x02, 0x03, 0x04, 0x10, 0x12, 0x13, 0x14, 0x15}


def text_of(el, name):
    for c in el:
        if local(c.tag) == name:
            return (c.text or "").strip()
    return None


def esi_int(t):
    t = t.strip()
    return int(t[2:], 16) if t.lower().startswith("#x") else int(t, 0 if t.lower().startswith("0x") else 10)


def english_name(el):
    names = children(el, "Name")
    for n in names:
        if n.get("LcId") == "1033":
            return (n.text or "").strip()
    return (names[0].text or "").strip() if names else ""


class esi_device:
    """The independent reading of one device of an ESI."""

    def __init__(self, dev):
        self.dev = dev
        self.types = {}
        prof = children(dev, "Profile")
        self.dictionary = None
        if prof and children(prof[0], "Dictionary"):
            self.dictionary = children(prof[0], "Dictionary")[0]
            for dts in children(self.dictionary, "DataTypes"):
                for dt in children(dts, "DataType"):
                    self.types.setdefault(text_of(dt, "Name"), dt)

    def type_code(self, name):
        if name.startswith("STRING("):
            return 0x09
        if name in ESI_TYPES:
            return ESI_TYPES[name]
        if re.fullmatch(r"BIT[2-8]", name):
            return 0x30 + int(name[3]) - 1
        dt = self.types.get(name)
        if dt is not None:
            if children(dt, "ArrayInfo") and not children(dt, "SubItem"):
                return 0x0A
            base = text_of(dt, "BaseType")
            if base and not children(dt, "SubItem"):
                return self.type_code(base)
            if name.startswith("STRING"):
                return 0x09
        if re.fullmatch(r"ARRAY \[0\.\.\d+\] OF BYTE", name):
            return 0x0A
        return None

    def objects(self):
        if self.dictionary is None:
            return []
        out = []
        for objs in children(self.dictionary, "Objects"):
            out += children(objs, "Object")
        return out

    def flatten(self, dt):
        """[(sub, name or None, type name, from an array)] of a DataType with SubItems."""
        out, nxt = [], 0
        for si in children(dt, "SubItem"):
            sub, name, t = text_of(si, "SubIdx"), text_of(si, "Name"), text_of(si, "Type")
            adt = self.types.get(t)
            if sub is None and adt is not None and children(adt, "ArrayInfo") and \
                    not children(adt, "SubItem"):
                ai = children(adt, "ArrayInfo")[0]
                lb, n = esi_int(text_of(ai, "LBound") or "0"), esi_int(text_of(ai, "Elements"))
                out += [(lb + k, None, text_of(adt, "BaseType"), True) for k in range(n)]
                nxt = lb + n
                continue
            s = esi_int(sub) if sub is not None else nxt
            nxt = s + 1
            out.append((s, name, t, False))
        return out

    def entries(self, obj):
        """[(sub, type name, Info element or None)] of an object."""
        t = text_of(obj, "Type")
        dt = self.types.get(t)
        info = children(obj, "Info")
        info = info[0] if info else None
        if dt is None or not children(dt, "SubItem"):
            return [(0, t, info)]
        flat = self.flatten(dt)
        infos = children(info, "SubItem") if info is not None else []
        used = [False] * len(infos)
        got = []
        for sub, name, tn, arr in flat:
            hit = None
            if not arr:
                for i, x in enumerate(infos):
                    if not used[i] and text_of(x, "Name") == name:
                        used[i], hit = True, x
                        break
            got.append([sub, tn, hit, arr])
        i = 0
        for g in got:
            if g[3]:
                while i < len(infos) and used[i]:
                    i += 1
                if i < len(infos):
                    used[i], g[2] = True, infos[i]
        return [(sub, tn, (children(x, "Info") or [None])[0] if x is not None else None)
                for sub, tn, x, _ in got]


def esi_default(info, code):
    """The default an Info gives, as the text the EDS export must hold (or None)."""
    if info is None:
        return None
    for c in info:
        tag = local(c.tag)
        t = (c.text or "")
        if tag == "DefaultString":
            return ("text", t)
        if tag == "DefaultValue":
            return ("value", t.strip())
        if tag == "DefaultData":
            data = bytes.fromhex(t.strip())
            return ("data", data)
    return None


def same_esi_default(d, eds_text, code):
    kind, v = d
    if code in (0x09,):
        want = v if kind != "data" else v.decode("latin-1")
        return eds_text in (want, '"' + want + '"') or (kind == "data" and
                                                         v.hex().upper() == eds_text)
    if code in (0x0A, 0x0B, 0x0F) or code >= 0x30:
        if kind == "data":
            return v.hex().upper() == eds_text
        t = v[2:] if v.lower().startswith("#x") else v
        return t.upper() == eds_text.upper()
    if kind == "data":
        width = WIDTH.get(code, len(v))
        raw = int.from_bytes(v.ljust(width, b"\0"), "little")
        if code in REALS:
            return real_value(hex(raw), code) == real_value(eds_text, code)
        if code in SIGNED and raw >= 1 << (8 * width - 1):
            raw -= 1 << (8 * width)
        return raw == number(eds_text)
    if code in REALS:
        return float(v) == real_value(eds_text, code)
    return same_value(v.replace("#x", "0x").replace("#X", "0x"), eds_text, code)


def check_esi_device(gen, path, work, dev, selector, vendor_id):
    name = os.path.basename(path)
    out = os.path.join(work, name + (f".{selector.replace(':', '_')}" if selector else "") + ".eds")
    cmd = [gen, "-q", path, "--eds", out, "--pdo-header", out + ".pdos.hpp", "--sii",
           out + ".sii.bin"] + (["--device", selector] if selector else [])
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        return [f"device {selector or '(only)'} refused:\n{run.stderr}"]
    eds = read_eds(out)
    x = esi_device(dev)
    problems = []
    objects = {s for s in eds.sections() if re.fullmatch(r"[0-9A-F]{4}", s)}
    dict_objects = {esi_int(text_of(o, "Index")) for o in x.objects()}
    # what the PDOs describe and the dictionary lacks is added from the PDOs
    pdos = children(dev, "RxPdo") + children(dev, "TxPdo")
    added = set()
    for p in pdos:
        idx = esi_int(text_of(p, "Index"))
        if idx not in dict_objects:
            added.add(idx)
        for e in children(p, "Entry"):
            ei = esi_int(text_of(e, "Index"))
            if ei != 0 and ei not in dict_objects:
                added.add(ei)
        if p.get("Sm") is not None and 0x1C10 + int(p.get("Sm")) not in dict_objects:
            added.add(0x1C10 + int(p.get("Sm")))
    want = {f"{i:04X}" for i in dict_objects | added}
    if objects != want:
        problems.append(f"objects differ: only EDS {sorted(objects - want)[:5]}, "
                        f"only ESI {sorted(want - objects)[:5]}")
    entries = defaults = 0
    for o in x.objects():
        index = esi_int(text_of(o, "Index"))
        ents = x.entries(o)
        single = len(ents) == 1 and ents[0][0] == 0 and \
            (x.types.get(text_of(o, "Type")) is None or
             not children(x.types[text_of(o, "Type")], "SubItem"))
        for sub, tn, info in ents:
            entries += 1
            sec = eds_section(eds, index, sub, single)
            where = f"0x{index:04X} sub {sub}"
            if sec is None:
                problems.append(f"{where}: no EDS section")
                continue
            code = x.type_code(tn)
            if code is None or int(sec.get("DataType"), 16) != code:
                problems.append(f"{where}: data type {sec.get('DataType')}, ESI {tn}")
                continue
            d = esi_default(info, code)
            if d is None:
                continue
            e = sec.get("DefaultValue")
            if e is None or not same_esi_default(d, e, code):
                problems.append(f"{where}: DefaultValue {e!r}, ESI {d!r}")
                continue
            defaults += 1
    pdo_entries = 0
    # every PDO entry in the PDO layouts header
    with open(out + ".pdos.hpp", encoding="utf-8") as f:
        header = f.read()
    layouts = {}
    for m in re.finditer(r"(rx|tx)pdo_([0-9a-f]{4})_entries\[\]\{(.*)\};", header):
        layouts[(m.group(1), int(m.group(2), 16))] = [
            tuple(int(v, 0) for v in t.split(","))
            for t in re.findall(r"\{([^{}]*)\}", m.group(3))]
    for p in pdos:
        idx = esi_int(text_of(p, "Index"))
        want_l = [(esi_int(text_of(e, "Index")), esi_int(text_of(e, "SubIndex") or "0"),
                   esi_int(text_of(e, "BitLen"))) for e in children(p, "Entry")]
        key = ("tx" if local(p.tag) == "TxPdo" else "rx", idx)
        if not want_l or len(want_l) > 64:
            if key in layouts:
                problems.append(f"PDO 0x{idx:04X}: a layout of {len(want_l)} entries")
            continue
        if layouts.get(key) != want_l:
            problems.append(f"PDO 0x{idx:04X}: layout {layouts.get(key)}, ESI {want_l}")
            continue
        pdo_entries += len(want_l)
    for p in pdos:
        idx = esi_int(text_of(p, "Index"))
        es = children(p, "Entry")
        if idx in dict_objects:
            continue  # the dictionary's mapping object: its defaults are checked above
        sec0 = eds_section(eds, idx, 0, False)
        if sec0 is None or number(sec0.get("DefaultValue")) != len(es):
            problems.append(f"PDO 0x{idx:04X}: sub 0 {sec0 and sec0.get('DefaultValue')}, "
                            f"ESI {len(es)} entries")
            continue
        for k, e in enumerate(es, 1):
            want_v = (esi_int(text_of(e, "Index")) << 16) | \
                (esi_int(text_of(e, "SubIndex") or "0") << 8) | esi_int(text_of(e, "BitLen"))
            sec = eds_section(eds, idx, k, False)
            if sec is None or number(sec.get("DefaultValue")) != want_v:
                problems.append(f"PDO 0x{idx:04X} entry {k}: "
                                f"{sec and sec.get('DefaultValue')}, ESI 0x{want_v:08X}")
    sii_problems, sii_pdos, all_pdos = check_sii(out + ".sii.bin", dev, vendor_id)
    problems += sii_problems
    if problems:
        return problems
    return (len(want), entries, defaults, pdo_entries, 1, sii_pdos, all_pdos)


def crc8(data):
    crc = 0xFF
    for byte in data:
        for bit in range(7, -1, -1):
            top = (crc >> 7) & 1
            crc = (crc << 1) & 0xFF
            if top ^ ((byte >> bit) & 1):
                crc ^= 0x07
    return crc


def check_sii(image_path, dev, vendor_id):
    """The SII image of one device against its ESI; (problems, how many PDOs it holds)."""
    with open(image_path, "rb") as f:
        img = f.read()
    problems = []

    def u16(at):
        return struct.unpack_from("<H", img, at)[0]

    def u32(at):
        return struct.unpack_from("<I", img, at)[0]

    eeprom = children(dev, "Eeprom")
    size = esi_int(text_of(eeprom[0], "ByteSize")) if eeprom and text_of(eeprom[0], "ByteSize") \
        else None
    if size is not None and len(img) != size:
        problems.append(f"SII of {len(img)} bytes, Eeprom/ByteSize {size}")
    if len(img) % 128 or u16(0x7C) != len(img) // 128 - 1 or u16(0x7E) != 1:
        problems.append(f"SII size word {u16(0x7C)} / version {u16(0x7E)} for {len(img)} bytes")
    config = bytes.fromhex(text_of(eeprom[0], "ConfigData") or "") if eeprom else b""
    if img[:14] != (config + bytes(14))[:14]:
        problems.append(f"SII configuration area {img[:14].hex()}, ConfigData {config.hex()}")
    if img[14] != crc8(img[:14]) or img[15] != 0:
        problems.append(f"SII checksum {u16(14):#06x}, CRC-8 {crc8(img[:14]):#04x}")
    t = children(dev, "Type")[0]
    if (u32(0x10), u32(0x14), u32(0x18)) != \
            (vendor_id, esi_int(t.get("ProductCode")), esi_int(t.get("RevisionNo") or "0")):
        problems.append(f"SII identity {u32(0x10):#x} {u32(0x14):#x} {u32(0x18):#x}")
    sms = children(dev, "Sm")
    mbx = {(s.text or "").strip(): (esi_int(s.get("StartAddress") or "0"),
                                    esi_int(s.get("DefaultSize") or "0")) for s in sms}
    std = [mbx.get("MBoxOut", (0, 0)), mbx.get("MBoxIn", (0, 0))]
    if "MBoxOut" not in mbx or "MBoxIn" not in mbx:
        std = [(0, 0), (0, 0)]
    boot = std
    if eeprom and text_of(eeprom[0], "BootStrap"):
        b = bytes.fromhex(text_of(eeprom[0], "BootStrap"))
        boot = [struct.unpack_from("<HH", b, 0), struct.unpack_from("<HH", b, 4)]
    got = [(u16(0x28), u16(0x2A)), (u16(0x2C), u16(0x2E)), (u16(0x30), u16(0x32)),
           (u16(0x34), u16(0x36))]
    if got != [tuple(boot[0]), tuple(boot[1]), tuple(std[0]), tuple(std[1])]:
        problems.append(f"SII mailboxes {got}, ESI bootstrap {boot} standard {std}")
    # the categories
    at, cats = 128, []
    while True:
        if at + 2 > len(img):
            problems.append("SII without an end category")
            break
        typ = u16(at)
        if typ == 0xFFFF:
            break
        n = u16(at + 2)
        cats.append((typ, img[at + 4:at + 4 + 2 * n]))
        at += 4 + 2 * n
    if any(b != 0xFF for b in img[at:]):
        problems.append("SII: bytes after the end category that are not 0xFF")
    strings = [None]
    for typ, data in cats:
        if typ == 10:
            k = 1
            for _ in range(data[0]):
                strings.append(data[k + 1:k + 1 + data[k]].decode("utf-8", "replace"))
                k += 1 + data[k]

    def decoded_pdos(typ):
        out = []
        for t_, data in cats:
            if t_ != typ:
                continue
            k = 0
            while k < len(data):
                index, n, sm, _, name, flags = struct.unpack_from("<HBBBBH", data, k)
                ents = [struct.unpack_from("<HBBBBH", data, k + 8 + 8 * j) for j in range(n)]
                out.append((index, sm, name, ents))
                k += 8 + 8 * n
        return out

    written = 0
    wanted_all = 0
    for kind, typ in (("RxPdo", 51), ("TxPdo", 50)):
        esi_pdos = children(dev, kind)
        got = decoded_pdos(typ)
        by_default = [p for p in esi_pdos if p.get("Sm") is not None]
        if len(got) == len(esi_pdos):
            want = esi_pdos
        elif len(got) == len(by_default):
            want = by_default
        elif not got:
            want = []
        else:
            problems.append(f"SII {kind}: {len(got)} PDOs of {len(esi_pdos)}")
            continue
        wanted_all += len(esi_pdos)
        for p, (index, sm, name, ents) in zip(want, got):
            es = children(p, "Entry")
            where = f"SII {kind} {index:#06x}"
            if index != esi_int(text_of(p, "Index")) or len(ents) != len(es):
                problems.append(f"{where}: {len(ents)} entries, ESI {text_of(p, 'Index')} "
                                f"{len(es)}")
                continue
            if sm != (int(p.get("Sm")) if p.get("Sm") is not None else 0xFF):
                problems.append(f"{where}: SM {sm}, ESI {p.get('Sm')}")
            if name and strings[name] != english_name(p):
                problems.append(f"{where}: name {strings[name]!r}, ESI {english_name(p)!r}")
            for e, (ei, es_, en, _, bits, _) in zip(es, ents):
                w = (esi_int(text_of(e, "Index")), esi_int(text_of(e, "SubIndex") or "0"),
                     esi_int(text_of(e, "BitLen")))
                if (ei, es_, bits) != w or (en and strings[en] != english_name(e)):
                    problems.append(f"{where}: entry {(ei, es_, bits)}, ESI {w}")
            written += 1
    return problems, written, wanted_all


def check_esi(gen, path, work):
    root = ET.parse(path).getroot()
    devices = [d for d in root.iter() if local(d.tag) == "Device" and
               any(local(c.tag) == "Type" for c in d)]
    # Modules/Module have no Type with ProductCode in a Devices list: only Devices/Device
    devices = [d for d in devices if d in list(root.iter())]
    devices = []
    for ds in root.iter():
        if local(ds.tag) == "Devices":
            devices += children(ds, "Device")
    vendor_id = esi_int(text_of(children(root, "Vendor")[0], "Id"))
    totals = [0, 0, 0, 0, 0, 0, 0]
    problems = []
    for d in devices:
        t = children(d, "Type")[0]
        selector = (f"{t.get('ProductCode')}:{t.get('RevisionNo')}"
                    if len(devices) > 1 else None)
        r = check_esi_device(gen, path, work, d, selector, vendor_id)
        if isinstance(r, list):
            problems += [f"[{selector or 'device'}] {p}" for p in r]
        else:
            totals = [a + b for a, b in zip(totals, r)]
    if problems:
        return problems
    return (f"{len(devices)} device{'s' if len(devices) != 1 else ''}, {totals[0]} objects, "
            f"{totals[1]} dictionary entries, {totals[2]} defaults, {totals[3]} PDO entries; "
            f"{totals[4]} SII images with {totals[5]} of {totals[6]} PDOs")


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    gen, corpus, work = sys.argv[1:]
    os.makedirs(work, exist_ok=True)
    files = sorted(os.path.join(corpus, "xdd", f) for f in os.listdir(os.path.join(corpus, "xdd")))
    esi = sorted(os.path.join(corpus, "esi", f) for f in os.listdir(os.path.join(corpus, "esi")))
    failed = 0
    read = refused = 0
    for path in files + esi:
        result = (check_esi if path in esi else check_xdd)(gen, path, work)
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
    print(f"xdd and esi: {len(files) + len(esi)} files, {read} read, {refused} refused, "
          f"{failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
