#!/usr/bin/env python3
"""fieldcodec's host API (host::remote_node, host::remote_drive; docs/host.md) against python
canopen's LocalNode as a XENAX.

The host program is tests/interop/bridge/interop_remote.cpp, a child process whose CAN bus is its
standard input and output (candump-style lines), carried to a python-can virtual bus by
interop_peer.Bridge. Python canopen's LocalNode, built from dictionaries/xenax_canopen.eds, answers
its SDO transfers from its data store (the PDO mappings included); the drive's application around
it is interop_master.Drive (CiA 402 state machine and the profile position handshake on RPDO 1 /
TPDO 1), here also taking RPDO 2 (6040h, 607Ah: the XENAX default mapping) as a drive does.

1. "!move 12345": examples/move_axis.hpp, the guide's example, unchanged: setup() reads the
   mappings from the LocalNode by SDO and finds the words in RPDO 1 / RPDO 2 / TPDO 1, NMT start,
   enable, profile position (6060h by SDO, 6061h read back), the move with 607Ah in RPDO 2.
   Checked from python: the LocalNode's store holds 6060h = 1, 607Ah = 12345, 6064h = 12345, the
   drive saw the whole handshake, and the node was started.
2. "!events 200": the remote node's events from frames python sends: a boot-up, heartbeats
   (pre-operational, operational), an EMCY from python's own EmcyProducer, a malformed EMCY of
   3 bytes (reported, not taken), then no more heartbeats: heartbeat lost.
3. "!domain 3000": streamed SDO (host::sdo_session::write_parts / read_parts, one buffer of 64
   bytes) of a DOMAIN python adds to the LocalNode (2FF0h): python's store holds the 3000 bytes
   written, and the bytes read back are the same (checked by the host program).
Exit 0 / 1, or 77 (skipped) without the peer or python-can.

usage: interop_remote.py --bridge EXE --root REPO
"""
import argparse
import os
import queue
import sys
import threading
import time

from interop_peer import Bridge, Failed, check, load_peer, ok
from interop_master import NODE, Drive

RUN_TIMEOUT = 20.0


class Drive402(Drive):
    """interop_master.Drive, also on RPDO 2 (6040h, 607Ah) and counting NMT commands."""

    def __init__(self, node, network):
        super().__init__(node, network)
        self.nmt = []
        network.subscribe(0x300 + NODE, self.on_rpdo2)
        network.subscribe(0x000, self.on_nmt)

    def on_rpdo2(self, cob_id, data, timestamp):
        with self.lock:
            if len(data) < 6:
                return
            self.node.set_data(0x607A, 0, bytes(data[2:6]))
            self.node.set_data(0x6040, 0, bytes(data[:2]))
            self.network.send_message(0x180 + NODE, self.statusword().to_bytes(2, "little"))

    def on_nmt(self, cob_id, data, timestamp):
        if len(data) == 2 and data[1] in (0, NODE):
            self.nmt.append(data[0])


def answer(bridge, step):
    try:
        return bridge.answers.get(timeout=RUN_TIMEOUT)
    except queue.Empty:
        raise Failed(f"{step}: no answer from the fieldcodec host program within {RUN_TIMEOUT} s")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--bridge", required=True)
    p.add_argument("--root", required=True)
    args = p.parse_args()
    load_peer(args.root)
    import canopen

    eds = os.path.join(args.root, "dictionaries", "xenax_canopen.eds")
    channel = f"fieldcodec-interop-remote-{os.getpid()}"
    bridge = Bridge(args.bridge, "xenax", NODE, channel)
    network = canopen.Network()
    network.connect(interface="virtual", channel=channel)
    try:
        local = canopen.LocalNode(NODE, eds)
        network.add_node(local)
        drive = Drive402(local, network)

        # 1. the guide's example against the LocalNode
        bridge.write("!move 12345")
        a = answer(bridge, "move")
        check(a == "ok", "move", a)

        def stored(index, sub=0):
            v = local.data_store.get(index, {}).get(sub)
            check(v is not None, "move", f"{index:04X}h sub {sub} was never written")
            return int.from_bytes(v, "little", signed=True)

        check(stored(0x6060) == 1, "move", "6060h is not 1 (profile position)")
        check(stored(0x607A) == 12345, "move", f"607Ah = {stored(0x607A)}, expected 12345")
        check(stored(0x6064) == 12345, "move", "6064h did not take the target")
        check(0x01 in drive.nmt, "move", f"no NMT start (NMT commands seen: {drive.nmt})")
        with drive.lock:
            seen = list(drive.seen)
        # from switch on disabled (the drive's state at the start): shutdown first, then enable
        # operation, possibly through switched on
        walked = [s for s in seen if s not in ("switched on", "switch on disabled")]
        expected = ["ready to switch on", "operation enabled",
                    "set-point acknowledged", "set-point released", "target reached"]
        check(walked == expected, "handshake", f"the drive saw {seen}")
        ok("move", "examples/move_axis.hpp: PDOs read by SDO, NMT start, " + " -> ".join(seen))

        # 2. events
        bridge.write("!events 200")
        check(answer(bridge, "events") == "listening", "events", "no 'listening'")
        network.send_message(0x700 + NODE, bytes([0x00]))  # boot-up
        time.sleep(0.02)
        network.send_message(0x700 + NODE, bytes([0x7F]))  # pre-operational
        for _ in range(3):
            time.sleep(0.03)
            network.send_message(0x700 + NODE, bytes([0x05]))  # operational
        local.emcy.send(0x2310, 0x03, b"\x01\x02")
        network.send_message(0x080 + NODE, bytes([0x10, 0x23, 0x03]))  # 3 bytes: malformed
        lines = []
        while True:
            a = answer(bridge, "events")
            if not a.startswith("event "):
                check(a == "ok", "events", f"{a} (events: {lines})")
                break
            lines.append(a.removeprefix("event "))
        want = ["boot-up boot-up", "NMT state pre-operational", "NMT state operational",
                "EMCY 2310 0003", "bad frame bad length", "heartbeat lost operational"]
        check(lines == want, "events", f"got {lines}, expected {want}")
        ok("events", "; ".join(lines))

        # 3. streamed SDO of a DOMAIN
        var = canopen.objectdictionary.ODVariable("Large domain", 0x2FF0, 0)
        var.data_type = canopen.objectdictionary.DOMAIN
        var.access_type = "rw"
        local.object_dictionary.add_object(var)
        bridge.write("!domain 3000")
        a = answer(bridge, "domain")
        check(a.startswith("ok 3000 "), "domain", a)
        stored = local.data_store.get(0x2FF0, {}).get(0)
        want = bytes((i * 7 + 3) & 0xFF for i in range(3000))
        check(stored == want, "domain", "the LocalNode does not hold the 3000 bytes written "
              f"({len(stored or b'')} bytes)")
        ok("domain", f"3000 bytes written and read back in parts of 64 bytes ({a.split()[2]} parts)")
        bridge.write("!quit")
    finally:
        network.disconnect()
        bridge.close()


if __name__ == "__main__":
    try:
        main()
    except Failed as e:
        print(f"FAILED {e}", flush=True)
        sys.exit(1)
