"""python canopen's RemoteNode against `fieldcodec serve` (serve_node.eds) or, with the mode
`example`, against examples/example_serve_node (the XENAX CANopen dictionary), on an slcan line
(python-can's slcan interface): the peer of tests/cli/serve_test.cpp.

usage: serve_peer.py PORT EDS NODE [MODE]
Prints "ready" once it listens, then one line per check, "done" at the end."""
import sys
import time

import can
import canopen


def say(*words):
    print(*words, flush=True)


def serve_checks(node):
    node.nmt.wait_for_bootup(15)
    say("boot-up")
    say("heartbeat", node.nmt.wait_for_heartbeat(5))
    say("vendor", hex(node.sdo["Identity Object"]["Vendor Id"].raw))
    say("name", node.sdo["Manufacturer Device Name"].raw)
    say("limit", node.sdo["Current Limit"].raw)  # set from serve's standard input
    say("label", node.sdo["Label"].raw)
    node.sdo["Current Limit"].raw = 1999
    say("limit", node.sdo["Current Limit"].raw)
    node.sdo["Label"].raw = "axis two"
    say("label", node.sdo["Label"].raw)
    for name, value in (("Current Limit", 2001), ("Label", "seventeen chars!!")):
        try:
            node.sdo[name].raw = value
            say("accepted", name)
        except canopen.SdoAbortedError as e:
            say("abort", name, "0x%08X" % e.code)
    try:
        node.sdo.upload(0x2002, 0)
    except canopen.SdoAbortedError as e:
        say("abort 2002", "0x%08X" % e.code)
    node.nmt.state = "OPERATIONAL"
    time.sleep(0.3)
    say("heartbeat", node.nmt.wait_for_heartbeat(5))
    node.nmt.state = "STOPPED"
    time.sleep(0.3)
    say("heartbeat", node.nmt.wait_for_heartbeat(5))
    try:
        node.sdo["Current Limit"].raw
        say("stopped: answered")
    except canopen.SdoCommunicationError:
        say("stopped: no SDO answer")
    node.nmt.state = "PRE-OPERATIONAL"
    time.sleep(0.3)
    say("heartbeat", node.nmt.wait_for_heartbeat(5))
    say("limit", node.sdo["Current Limit"].raw)


def storage_checks(node):
    """`serve --storage FILE`: 1010h "save", a reset puts the saved values back, 1011h "load"."""
    node.nmt.wait_for_bootup(15)
    say("boot-up")
    node.sdo["Current Limit"].raw = 1999
    node.sdo["Label"].raw = "stored"
    say("capability", node.sdo.upload(0x1010, 1).hex())
    node.store(1)  # 1010h sub 1 = "save"
    say("stored")
    node.sdo["Current Limit"].raw = 1200  # not saved
    for step in ("reset", "load", "reset"):
        if step == "load":
            node.restore(1)  # 1011h sub 1 = "load": the current values stay
        else:
            node.nmt.state = "RESET"
            time.sleep(0.6)  # the boot-up and the saved values put back
        say(step, node.sdo["Current Limit"].raw, node.sdo["Label"].raw)
    try:
        node.sdo.download(0x1010, 1, b"evas")
        say("accepted evas")
    except canopen.SdoAbortedError as e:
        say("abort evas", "0x%08X" % e.code)


def example_checks(node):
    node.nmt.wait_for_bootup(15)
    say("boot-up")
    say("device type", hex(node.sdo[0x1000].raw))
    node.sdo[0x6073].raw = 123
    say("6073", node.sdo[0x6073].raw)
    try:
        node.sdo.download(0x6073, 0, (0x7D1).to_bytes(2, "little"))  # HighLimit 0x7D0
        say("accepted 0x7D1")
    except canopen.SdoAbortedError as e:
        say("abort 6073", "0x%08X" % e.code)
    node.nmt.state = "OPERATIONAL"
    node.nmt.state = "PRE-OPERATIONAL"
    say("6073", node.sdo[0x6073].raw)


def main():
    port, eds, node_id = sys.argv[1], sys.argv[2], int(sys.argv[3])
    mode = sys.argv[4] if len(sys.argv) > 4 else "serve"
    bus = can.Bus(interface="slcan", channel=port, bitrate=500000, sleep_after_open=0)
    network = canopen.Network(bus)
    node = canopen.RemoteNode(node_id, eds)
    network.add_node(node)
    node.sdo.RESPONSE_TIMEOUT = 1.0
    network.connect()
    say("ready")
    try:
        {"example": example_checks, "storage": storage_checks}.get(mode, serve_checks)(node)
    except Exception as e:  # the test shows what failed
        say("error", type(e).__name__, e)
    say("done")
    network.disconnect()


if __name__ == "__main__":
    main()
