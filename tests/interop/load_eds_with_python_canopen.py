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

usage: load_eds_with_python_canopen.py [REPO_ROOT]
"""
import glob
import os
import re
import sys

SKIP = 77


def main() -> int:
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", ".."))
    peer = os.environ.get("FIELDCODEC_PYTHON_CANOPEN",
                          os.path.join(root, "..", "shared", "peers", "python-canopen"))
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
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
