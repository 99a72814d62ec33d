#!/usr/bin/env python3
"""Every EDS/DCF in dictionaries/ loads in python canopen, an independent CANopen stack.

For each file: canopen.import_od() reads it, and a RemoteNode is built on it (the node's PDO
maps need, for every PDO communication parameter 1400h../1800h.., the mapping parameter
1600h../1A00h..; a missing one raised KeyError for dictionaries/xenax_canopen.eds, issue 12
#6). Each object the file declares must be found under the same index in python's dictionary,
and python reads every default PDO mapping of the file (PdoBase.read(from_od=True)): each
mapped object must exist.

Runs with Debian's /usr/bin/python3 (python-can: apt-get install python3-can) and the peer in
../shared/peers/python-canopen (or $FIELDCODEC_PYTHON_CANOPEN). When either is missing the
script says so and exits 77, which CTest reports as skipped.

With --gen FIELDCODEC_GEN, each EDS/DCF of dictionaries/ also goes through fieldcodec's own EDS
export (fieldcodec-gen --eds) and the exported file must load the same way and hold, as python
reads it, the same objects with the same data types, access and defaults as the original.

usage: load_eds_with_python_canopen.py [REPO_ROOT] [--gen FIELDCODEC_GEN]
"""
import glob
import os
import re
import subprocess
import sys
import tempfile

SKIP = 77


def main() -> int:
    here = os.path.dirname(os.path.abspath(__file__))
    args = sys.argv[1:]
    gen = None
    if "--gen" in args:
        i = args.index("--gen")
        gen = args[i + 1]
        del args[i:i + 2]
    root = os.path.abspath(args[0] if args else os.path.join(here, "..", ".."))
    shared = os.environ.get("FIELDCODEC_SHARED_DIR", os.path.join(root, "..", "shared"))
    peer = os.environ.get("FIELDCODEC_PYTHON_CANOPEN",
                          os.path.join(shared, "peers", "python-canopen"))
    if not os.path.isdir(os.path.join(peer, "canopen")):
        print(f"SKIPPED: python canopen peer not found at {peer}")
        return SKIP
    try:
        import can  # noqa: F401  (python-can: the peer imports it)
    except ImportError:
        print(f"SKIPPED: python-can is not installed for {sys.executable} "
              "(apt-get install python3-can)")
        return SKIP
    sys.path.insert(0, peer)
    import canopen  # pylint: disable=import-outside-toplevel

    files = sorted(glob.glob(os.path.join(root, "dictionaries", "*.eds")) +
                   glob.glob(os.path.join(root, "dictionaries", "*.dcf")) +
                   glob.glob(os.path.join(root, "dictionaries", "export", "*.eds")))
    if not files:
        print(f"FAILED: no EDS/DCF files in {root}/dictionaries")
        return 1
    failures = 0
    for path in files:
        name = os.path.relpath(path, root)
        try:
            od = canopen.import_od(path, node_id=1)
            node = canopen.RemoteNode(1, od)
            canopen.Network().add_node(node)  # not connected: no bus is opened
            with open(path, encoding="ascii", errors="replace") as f:
                declared = sorted({int(m.group(1), 16) for m in
                                   re.finditer(r"^\[([0-9A-Fa-f]{4})\]\s*$", f.read(), re.M)})
            missing = [f"{i:04X}h" for i in declared if i not in od]
            if missing:
                raise KeyError(f"objects not in python's dictionary: {', '.join(missing)}")
            node.rpdo.read(from_od=True)
            node.tpdo.read(from_od=True)
            maps = list(node.rpdo.map.values()) + list(node.tpdo.map.values())
            mapped = sum(len(m.map) for m in maps)
            print(f"ok      {name}: {len(declared)} objects, RemoteNode with {len(node.rpdo.map)} "
                  f"RPDO / {len(node.tpdo.map)} TPDO maps, {mapped} objects mapped by default")
        except Exception as e:  # pylint: disable=broad-except
            failures += 1
            print(f"FAILED  {name}: {type(e).__name__}: {e}")
    print(f"{len(files) - failures} of {len(files)} files load in python canopen")
    if gen:
        failures += round_trips(canopen, root, gen)
    return 1 if failures else 0


def described(od):
    """What python read: (index, sub) -> (data type, access, default)."""
    import canopen  # pylint: disable=import-outside-toplevel
    out = {}
    for obj in od.values():
        subs = [obj] if isinstance(obj, canopen.objectdictionary.Variable) else obj.values()
        for v in subs:
            out[(v.index, v.subindex)] = (v.data_type, v.access_type, v.default)
    return out


def round_trips(canopen, root, gen):
    """Each EDS/DCF of dictionaries/ exported by fieldcodec-gen loads alike in python."""
    failures = 0
    sources = sorted(glob.glob(os.path.join(root, "dictionaries", "*.eds")) +
                     glob.glob(os.path.join(root, "dictionaries", "*.dcf")))
    with tempfile.TemporaryDirectory() as tmp:
        for path in sources:
            name = os.path.relpath(path, root)
            out = os.path.join(tmp, os.path.basename(path))
            try:
                r = subprocess.run([gen, "--quiet", "--eds", out, path], capture_output=True,
                                   text=True, check=False)
                if r.returncode != 0:
                    raise RuntimeError(f"fieldcodec-gen --eds failed: {r.stderr.strip()}")
                original = described(canopen.import_od(path, node_id=1))
                exported_od = canopen.import_od(out, node_id=1)
                node = canopen.RemoteNode(1, exported_od)
                canopen.Network().add_node(node)
                node.rpdo.read(from_od=True)
                node.tpdo.read(from_od=True)
                exported = described(exported_od)
                missing = sorted(set(original) - set(exported))
                extra = sorted(set(exported) - set(original))
                differ = sorted(k for k in set(original) & set(exported)
                                if original[k] != exported[k])
                if missing or extra or differ:
                    def show(keys):
                        return ", ".join(f"{i:04X}h:{s:02X}" for i, s in keys[:5])
                    detail = [f"missing {show(missing)}" if missing else "",
                              f"extra {show(extra)}" if extra else "",
                              "differ " + "; ".join(f"{i:04X}h:{s:02X} {original[(i, s)]} -> "
                                                    f"{exported[(i, s)]}"
                                                    for i, s in differ[:3]) if differ else ""]
                    raise ValueError(", ".join(d for d in detail if d))
                print(f"ok      {name} exported by fieldcodec-gen: {len(exported)} entries "
                      "alike in python")
            except Exception as e:  # pylint: disable=broad-except
                failures += 1
                print(f"FAILED  {name} exported by fieldcodec-gen: {type(e).__name__}: {e}")
    return failures


if __name__ == "__main__":
    sys.exit(main())
