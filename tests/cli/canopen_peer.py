"""A python-canopen LocalNode on an slcan line (python-can's slcan interface), the peer of the
CLI's `sdo read/write` test (tests/cli/python_peer_test.cpp).

usage: canopen_peer.py PORT EDS NODE
Prints "ready" once it listens, then one line per SDO write it serves: "write 6040:00 0f00".
Runs until its standard input closes (or 60 s pass)."""
import select
import sys
import time

import can
import canopen


def main():
    port, eds, node_id = sys.argv[1], sys.argv[2], int(sys.argv[3])
    bus = can.Bus(interface="slcan", channel=port, bitrate=500000, sleep_after_open=0)
    network = canopen.Network(bus)
    node = canopen.LocalNode(node_id, eds)
    network.add_node(node)
    node.set_data(0x1018, 1, (0x12E).to_bytes(4, "little"))

    def on_write(index, subindex, od, data):
        print("write %04x:%02x %s" % (index, subindex, bytes(data).hex()), flush=True)

    node.add_write_callback(on_write)
    network.connect()
    print("ready", flush=True)
    end = time.time() + 60
    while time.time() < end:
        readable, _, _ = select.select([sys.stdin], [], [], 0.2)
        if readable and not sys.stdin.readline():
            break
    network.disconnect()


if __name__ == "__main__":
    main()
