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
the drive saw the whole handshake. Exit 0 / 1, or 77 (skipped) without the peer or python-can.

usage: interop_master.py --bridge EXE --root REPO
"""
import argparse
import os
import queue
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
    finally:
        network.disconnect()
        bridge.close()


if __name__ == "__main__":
    try:
        main()
    except Failed as e:
        print(f"FAILED {e}", flush=True)
        sys.exit(1)
