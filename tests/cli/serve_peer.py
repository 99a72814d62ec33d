"""python canopen's RemoteNode against `fieldcodec serve` on an slcan line (python-can's slcan
interface): the peer of tests/cli/serve_test.cpp.

usage: serve_peer.py PORT EDS NODE
Prints "ready" once it listens, then one line per check, "done" at the end."""
import sys
import time

import can
import canopen


def say(*words):
    print(*words, flush=True)


def main():
    port, eds, node_id = sys.argv[1], sys.argv[2], int(sys.argv[3])
    bus = can.Bus(interface="slcan", channel=port, bitrate=500000, sleep_after_open=0)
    network = canopen.Network(bus)
    node = canopen.RemoteNode(node_id, eds)
    network.add_node(node)
    node.sdo.RESPONSE_TIMEOUT = 1.0
    network.connect()
    say("ready")
    try:
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
    except Exception as e:  # the test shows what failed
        say("error", type(e).__name__, e)
    say("done")
    network.disconnect()


if __name__ == "__main__":
    main()
