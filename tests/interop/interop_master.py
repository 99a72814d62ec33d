#!/usr/bin/env python3
"""fieldcodec's master machines against python canopen's LocalNode as a XENAX (docs/canopen.md,
"Interoperability"; docs/master.md).

The master is tests/interop/bridge/interop_master.cpp (a configurator and a CiA 402 drive
helper), a child process speaking candump-style frames on standard input and output, carried to
a python-can virtual bus by interop_peer.Bridge. Here python canopen's LocalNode, built from
dictionaries/xenax_canopen.eds, answers the master's SDO transfers from its data store, and this
script plays the drive's application around it:

* RPDO 1 (200h + node, 6040h): the controlword goes into the LocalNode (set_data, so the write
  callbacks run); the statusword 6041h follows the CiA 402 state machine (shutdown -> ready to
  switch on, switch on -> switched on, enable operation -> operation enabled, disable voltage /
  quick stop -> switch on disabled) and is sent back at once in TPDO 1 (180h + node).
* Profile position: a rising new set-point (bit 4) in operation enabled clears target reached
  (bit 10) and sets set-point acknowledge (bit 12); bit 4 released clears bit 12; target reached
  comes at the first RPDO at least 50 ms later, and 6064h takes 607Ah.
* 6060h written -> 6061h shows the same mode.

Checks: the master's own steps (its "= ok" / "= FAILED <step>: <why>"), then from python that
the configured values are in the LocalNode's data store, that 607Ah holds the target, and that
the drive saw the whole handshake.

Then the CiA 302 boot slave process (master::boot from slave_objects, "!boot302"): python plays
an NMT slave around the LocalNode (a boot-up after NMT reset node / communication, heartbeats of
its state every 100 ms, 1011h "load" and 1020h added to its dictionary) and writes the master's
CiA 302 objects, among them a concise DCF it packs itself: a whole boot (identity, concise DCF,
heartbeat, NMT start), a vendor-ID mismatch (D: nothing written), keep-alive with the node
operational (L: no reset, nothing written), restore defaults with 1020h showing the expected
configuration (reset node, no download), and a refused entry (J).
Exit 0 / 1, or 77 (skipped) without the peer or python-can.

usage: interop_master.py --bridge EXE --root REPO
"""
import argparse
import os
import queue
import struct
import sys
import threading

from interop_peer import Bridge, Failed, check, load_peer, ok

NODE = 5
RUN_TIMEOUT = 20.0  # the master's steps have their own deadlines (at most ~15 s in all)
SETTLE_S = 0.05     # from set-point released to target reached

# CiA 402 statusword state bits (with voltage enabled 0x10 and remote 0x200)
SWITCH_ON_DISABLED = 0x0040
READY_TO_SWITCH_ON = 0x0021
SWITCHED_ON = 0x0023
OPERATION_ENABLED = 0x0027
BASE = 0x0210


class Drive:
    """The application of the simulated XENAX around a LocalNode."""

    def __init__(self, node, network):
        import time
        self.time = time
        self.node = node
        self.network = network
        self.state = SWITCH_ON_DISABLED
        self.previous_cw = 0
        self.ack = False
        self.reached = True
        self.released_at = None
        self.seen = []  # the states the drive went through, and the handshake events
        self.lock = threading.Lock()
        self._store(0x6041, self.statusword().to_bytes(2, "little"))
        self._store(0x6061, bytes([0]))
        node.add_write_callback(self.on_write)
        network.subscribe(0x200 + NODE, self.on_rpdo)

    def _store(self, index, data, sub=0):
        self.node.data_store.setdefault(index, {})[sub] = bytes(data)

    def statusword(self):
        w = BASE | self.state
        if self.reached:
            w |= 0x0400
        if self.ack:
            w |= 0x1000
        return w

    def _note(self, what):
        self.seen.append(what)

    def on_write(self, index, subindex, od, data):
        if index == 0x6060:
            self._store(0x6061, data)  # the mode follows at once
        elif index == 0x6040:
            self.apply(int.from_bytes(data, "little"))

    def apply(self, cw):
        s = self.state
        if (cw & 0x02) == 0 or (cw & 0x06) == 0x02:  # disable voltage / quick stop
            s = SWITCH_ON_DISABLED
        elif (cw & 0x87) == 0x06:  # shutdown
            s = READY_TO_SWITCH_ON
        elif (cw & 0x8F) == 0x07 and s in (READY_TO_SWITCH_ON, OPERATION_ENABLED):  # switch on
            s = SWITCHED_ON
        elif (cw & 0x8F) == 0x0F and s in (READY_TO_SWITCH_ON, SWITCHED_ON, OPERATION_ENABLED):
            s = OPERATION_ENABLED  # enable operation (3 + 4 at once from ready to switch on)
        if s != self.state or not self.seen:
            self._note({SWITCH_ON_DISABLED: "switch on disabled", READY_TO_SWITCH_ON:
                    "ready to switch on", SWITCHED_ON: "switched on", OPERATION_ENABLED:
                        "operation enabled"}[s])
        self.state = s
        now = self.time.monotonic()
        rising = (cw & 0x10) and not (self.previous_cw & 0x10)
        if s == OPERATION_ENABLED and rising and self.node.data_store.get(0x6061, {}).get(0) \
                == bytes([1]):
            self.ack = True
            self.reached = False
            self.released_at = None
            self._note("set-point acknowledged")
        if not (cw & 0x10) and self.ack:
            self.ack = False
            self.released_at = now
            self._note("set-point released")
        if self.released_at is not None and not self.reached and now - self.released_at >= SETTLE_S:
            self.reached = True
            self._store(0x6064, self.node.get_data(0x607A, 0))
            self._note("target reached")
        self.previous_cw = cw
        self._store(0x6041, self.statusword().to_bytes(2, "little"))

    def on_rpdo(self, cob_id, data, timestamp):
        with self.lock:
            if len(data) < 2:
                return
            self.node.set_data(0x6040, 0, bytes(data[:2]))  # the write callback applies it
            self.network.send_message(0x180 + NODE, self.statusword().to_bytes(2, "little"))


class NmtSlave302:
    """The NMT side of the LocalNode for the boot tests: boot-up after a reset, heartbeats."""

    HEARTBEAT_MS = 100

    def __init__(self, node, network):
        self.node = node
        self.network = network
        self.commands = []  # (command specifier) for this node, in order
        self.lock = threading.Lock()
        network.subscribe(0x000, self.on_nmt)
        node.nmt.start_heartbeat(self.HEARTBEAT_MS)

    def on_nmt(self, cob_id, data, timestamp):
        if len(data) != 2 or data[1] not in (0, NODE):
            return
        with self.lock:
            self.commands.append(data[0])
        if data[0] in (0x81, 0x82):
            # python canopen's NmtSlave stays in INITIALISING: finish the reset as a device does
            self.node.nmt._state = 127
            self.network.send_message(0x700 + NODE, [0])
            self.node.nmt.update_heartbeat()

    def take(self, expected=None, timeout=2.0):
        """The NMT commands received since the last take. The bridge answers once it has sent
        its last frame, which the bus may deliver a little later: wait until `expected` has
        arrived (or, without it, a moment for stray commands)."""
        import time
        end = time.monotonic() + (timeout if expected is not None else 0.2)
        while time.monotonic() < end:
            with self.lock:
                if expected is not None and self.commands == expected:
                    break
            time.sleep(0.01)
        with self.lock:
            c, self.commands = self.commands, []
        return c

    def state(self):
        return self.node.nmt._state


def concise_dcf(entries):
    """The 1F22h format: UNSIGNED32 count, then per entry index, sub-index, size, data."""
    out = struct.pack("<I", len(entries))
    for index, sub, data in entries:
        out += struct.pack("<HBI", index, sub, len(data)) + data
    return out


def boot302(bridge, step, assignment, consumer, expected, dcf, software=0, date=0, time_=0,
            restore=0):
    numbers = [assignment, consumer, *expected, software, date, time_, restore]
    line = "!boot302 " + " ".join(f"{v:X}" for v in numbers) + " " + (dcf.hex().upper() or "-")
    return bridge.command(line, step)


def boot_tests(bridge, local, network, canopen):
    """The CiA 302 boot slave process against the LocalNode (see the top of this file)."""
    slave = NmtSlave302(local, network)
    vendor = 0x21B
    local.data_store.setdefault(0x1018, {})[1] = struct.pack("<I", vendor)
    identity = (0x00020192, vendor, 0, 0x00010000, 0)

    def u32(index, sub=0):
        return struct.unpack("<I", local.data_store[index][sub])[0]

    # a whole boot: reset, identity, the concise DCF, the first heartbeat, NMT start
    dcf = concise_dcf([(0x6081, 0, struct.pack("<I", 1111)), (0x6083, 0, struct.pack("<I", 2222)),
                       (0x6065, 0, struct.pack("<I", 333))])
    answer = boot302(bridge, "boot", 0x05, 500, identity, dcf)
    check(answer == "ok booted", "boot", answer)
    seen = slave.take([0x82, 0x01])
    check(seen == [0x82, 0x01], "boot", f"the node saw NMT commands {seen}, expected reset "
          "communication, start")
    check((u32(0x6081), u32(0x6083), u32(0x6065)) == (1111, 2222, 333), "boot",
          "the concise DCF's values are not in the LocalNode's store")
    check(slave.state() == 5, "boot", f"NMT state {slave.state()}, expected operational")
    ok("boot302", "1F81h = 05h: reset, 1000h and 1018h checked, 3 entries of a concise DCF "
       "packed by python, heartbeat, NMT start: booted")

    # D: another vendor-ID, nothing is written
    answer = boot302(bridge, "vendor", 0x05, 500, (0, 0x12345678, 0, 0, 0),
                     concise_dcf([(0x6081, 0, struct.pack("<I", 4444))]))
    check(answer.startswith("FAILED D: "), "vendor", answer)
    check("expected 12345678 actual 0000021B" in answer, "vendor", answer)
    check(u32(0x6081) == 1111, "vendor", "6081h was written after a failed identity check")
    ok("boot302", "vendor-ID mismatch reported as D; nothing written")

    # L: keep-alive, the node runs: no reset, no download
    slave.node.nmt._state = 5
    slave.node.nmt.update_heartbeat()
    slave.take()
    answer = boot302(bridge, "keep-alive", 0x15, 500, identity,
                     concise_dcf([(0x6081, 0, struct.pack("<I", 5555))]))
    check(answer == "ok L: initially operational", "keep-alive", answer)
    check(slave.take() == [], "keep-alive", "the master sent an NMT command to a running node")
    check(u32(0x6081) == 1111, "keep-alive", "6081h was written to a node kept alive")
    ok("boot302", "keep-alive with the node operational: L, no NMT command, nothing written")

    # restore defaults (1011h sub 1 "load", reset node), 1020h shows the expected configuration
    od = local.object_dictionary
    for index, name in ((0x1011, "Restore default parameters"), (0x1020, "Verify configuration")):
        record = canopen.objectdictionary.ODRecord(name, index)
        for sub in range(0, 3 if index == 0x1020 else 2):
            v = canopen.objectdictionary.ODVariable(f"{name} {sub}", index, sub)
            v.data_type = 0x05 if sub == 0 else 0x07
            v.access_type = "ro" if sub == 0 else "rw"
            v.default = 2 if sub == 0 else 0
            record.add_member(v)
        od.add_object(record)
    local.data_store[0x1020] = {1: struct.pack("<I", 0x1234), 2: struct.pack("<I", 0x5678)}
    slave.take()
    answer = boot302(bridge, "restore", 0x85, 500, identity,
                     concise_dcf([(0x6081, 0, struct.pack("<I", 6666))]),
                     date=0x1234, time_=0x5678, restore=1)
    check(answer == "ok booted", "restore", answer)
    check(local.data_store.get(0x1011, {}).get(1) == b"load", "restore",
          "1011h sub 1 did not receive \"load\"")
    seen = slave.take([0x82, 0x81, 0x01])
    check(seen == [0x82, 0x81, 0x01], "restore",
          f"NMT commands {seen}, expected reset communication, reset node (after the restore), "
          "start")
    check(u32(0x6081) == 1111, "restore", "downloaded although 1020h showed the configuration")
    ok("boot302", "restore (1011h sub 1 = \"load\", reset node), 1020h sub 1/2 = 1F26h/1F27h: "
       "no download, booted")

    # J: the node refuses an entry (1000h is read-only)
    answer = boot302(bridge, "refused", 0x05, 500, identity,
                     concise_dcf([(0x6081, 0, struct.pack("<I", 7777)),
                                  (0x1000, 0, struct.pack("<I", 1))]))
    check(answer.startswith("FAILED J: "), "refused", answer)
    check(answer.endswith("entry 1)"), "refused", answer)
    check(u32(0x6081) == 7777, "refused", "the entry before the refused one is missing")
    ok("boot302", "a refused entry of the concise DCF reported as J with its position")


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--bridge", required=True)
    p.add_argument("--root", required=True)
    args = p.parse_args()
    load_peer(args.root)
    import canopen

    eds = os.path.join(args.root, "dictionaries", "xenax_canopen.eds")
    channel = f"fieldcodec-interop-master-{os.getpid()}"
    bridge = Bridge(args.bridge, "xenax", NODE, channel)
    network = canopen.Network()
    network.connect(interface="virtual", channel=channel)
    try:
        local = canopen.LocalNode(NODE, eds)
        network.add_node(local)
        drive = Drive(local, network)
        step = "run"
        bridge.write("!run")
        try:
            answer = bridge.answers.get(timeout=RUN_TIMEOUT)
        except queue.Empty:
            raise Failed(f"{step}: no answer from the fieldcodec master within {RUN_TIMEOUT} s")
        check(answer == "ok", answer.removeprefix("FAILED ").split(":")[0],
              answer.removeprefix("FAILED ").partition(": ")[2] or answer)
        ok("master", "configured, enabled, moved (its steps are above)")

        def stored(index, sub, size):
            v = local.data_store.get(index, {}).get(sub)
            check(v is not None, "configured", f"{index:04X}h sub {sub} was never written")
            check(len(v) == size, "configured", f"{index:04X}h sub {sub} has {len(v)} bytes")
            return int.from_bytes(v, "little", signed=True)

        for index, sub, size, value in ((0x6081, 0, 4, 50000), (0x6083, 0, 4, 200000),
                                        (0x1800, 5, 2, 100)):
            got = stored(index, sub, size)
            check(got == value, "configured", f"{index:04X}h sub {sub} = {got}, expected {value}")
        ok("configured", "LocalNode's store: 6081h = 50000, 6083h = 200000, 1800h sub 5 = 100")
        check(stored(0x6060, 0, 1) == 1, "mode", "6060h is not 1 (profile position)")
        check(stored(0x607A, 0, 4) == 12345, "move", "607Ah is not 12345")
        check(stored(0x6064, 0, 4) == 12345, "move", "6064h did not take the target")
        with drive.lock:
            seen = list(drive.seen)
        expected = ["switch on disabled", "ready to switch on", "operation enabled",
                    "set-point acknowledged", "set-point released", "target reached"]
        # enable may go through switched on (0x07) or straight on (3 + 4 at once)
        walked = [s for s in seen if s != "switched on"]
        check(walked == expected, "handshake",
              f"the drive saw {seen}")
        ok("handshake", " -> ".join(seen))
        boot_tests(bridge, local, network, canopen)
    finally:
        network.disconnect()
        bridge.close()


if __name__ == "__main__":
    try:
        main()
    except Failed as e:
        print(f"FAILED {e}", flush=True)
        sys.exit(1)
