#!/usr/bin/env python3
"""Drive the simulated XENAX (example_sim_drive --stdio) with python canopen.

python canopen (an independent CANopen master, ../shared/peers/python-canopen) talks over
python-can's in-process virtual bus; a bridge moves frames between that bus and the drive's
standard input/output (one `ID#DATA` line per frame). The script does what a host program
does with a real drive:

1. NMT reset node, wait for the boot-up message;
2. SDO: read the device type (1000h) and identity, write mode (6060h), speed, acceleration;
   read them back; a value out of the dictionary's limits is refused with the right abort code;
3. PDO configuration with python's own PdoMap.save(): the CiA 301 sequence (COB-ID invalid,
   mapping sub 0 = 0, entries, sub 0 = n, COB-ID valid) on the drive's RPDO 2 and TPDO 2;
4. NMT start; walk the CiA 402 state machine to "operation enabled" through RPDO 2, watching
   the statusword in TPDO 2; one profile position move; wait for "target reached";
5. block download and block upload (python's BlockDownloadStream / BlockUploadStream) of the
   speed 6081h, and of a string object when the dictionary gives one a capacity.

usage: sim_drive_python.py EXAMPLE_SIM_DRIVE [REPO_ROOT]
Exit 0 on success, 1 on a failure, 77 (CTest: skipped) without python-can or the peer.
"""
import os
import subprocess
import sys
import threading
import time

SKIP = 77
NODE = 1


def log(msg):
    print(msg, flush=True)


def main() -> int:
    exe = sys.argv[1]
    root = os.path.abspath(sys.argv[2] if len(sys.argv) > 2 else
                           os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
    shared = os.environ.get("FIELDCODEC_SHARED_DIR", os.path.join(root, "..", "shared"))
    peer = os.environ.get("FIELDCODEC_PYTHON_CANOPEN",
                          os.path.join(shared, "peers", "python-canopen"))
    if not os.path.isdir(os.path.join(peer, "canopen")):
        print(f"SKIPPED: python canopen peer not found at {peer}")
        return SKIP
    try:
        import can
    except ImportError:
        print(f"SKIPPED: python-can is not installed for {sys.executable} "
              "(apt-get install python3-can)")
        return SKIP
    sys.path.insert(0, peer)
    import canopen  # pylint: disable=import-outside-toplevel

    channel = f"fieldcodec-sim-drive-{os.getpid()}"
    proc = subprocess.Popen([exe, "--stdio", str(NODE)], stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, text=True, bufsize=1)
    bridge = can.Bus(interface="virtual", channel=channel)
    running = True

    def drive_to_bus():
        for line in proc.stdout:
            ident, _, data = line.strip().partition("#")
            if data.startswith("R"):
                msg = can.Message(arbitration_id=int(ident, 16), is_extended_id=False,
                                  is_remote_frame=True, dlc=int(data[1:] or "0"))
            else:
                msg = can.Message(arbitration_id=int(ident, 16), is_extended_id=False,
                                  data=bytes.fromhex(data))
            bridge.send(msg)

    def bus_to_drive():
        while running:
            msg = bridge.recv(0.05)
            if msg is None:
                continue
            if msg.is_remote_frame:
                line = f"{msg.arbitration_id:03X}#R{msg.dlc}"
            else:
                line = f"{msg.arbitration_id:03X}#{bytes(msg.data).hex().upper()}"
            try:
                proc.stdin.write(line + "\n")
                proc.stdin.flush()
            except BrokenPipeError:
                return

    threads = [threading.Thread(target=drive_to_bus, daemon=True),
               threading.Thread(target=bus_to_drive, daemon=True)]
    for t in threads:
        t.start()

    network = canopen.Network()
    network.connect(interface="virtual", channel=channel)
    failures = []

    def check(cond, what):
        log(("ok    " if cond else "FAIL  ") + what)
        if not cond:
            failures.append(what)

    try:
        eds = os.path.join(root, "dictionaries", "xenax_canopen.eds")
        od = canopen.import_od(eds, NODE)
        # python canopen builds one PDO map per communication record and needs its mapping
        # record; an EDS without one (issue 12 #6) is read with those PDOs left out
        for comm, mapping in ((0x1400, 0x1600), (0x1800, 0x1A00)):
            for n in range(512):
                if comm + n in od and mapping + n not in od:
                    del od[comm + n]
        node = canopen.RemoteNode(NODE, od)
        network.add_node(node)
        node.sdo.RESPONSE_TIMEOUT = 1.0

        # 1. NMT
        node.nmt.state = "RESET"
        node.nmt.wait_for_bootup(5)
        check(True, "boot-up after NMT reset node")

        # 2. SDO
        check(node.sdo[0x1000].raw == 0x00020192, "SDO upload 1000h device type = 0x00020192")
        check(node.sdo[0x1018][3].raw == 0x00010000, "SDO upload 1018h sub 3 revision")
        node.sdo[0x6060].raw = 1
        node.sdo[0x6081].raw = 50000
        node.sdo[0x6083].raw = 400000
        check(node.sdo[0x6060].raw == 1, "SDO 6060h mode = profile position")
        check(node.sdo[0x6081].raw == 50000, "SDO 6081h speed read back")
        try:
            node.sdo[0x6081].raw = 5  # below the dictionary's low limit 0xA
            check(False, "6081h = 5 refused")
        except canopen.SdoAbortedError as e:
            check(e.code == 0x06090032, f"6081h = 5 refused with 0x{e.code:08X} (value too low)")
        try:
            node.sdo[0x1000].raw = 1
            check(False, "1000h write refused")
        except canopen.SdoAbortedError as e:
            check(e.code == 0x06010002, f"1000h write refused with 0x{e.code:08X} (read-only)")

        # 3. PDOs, configured with python's CiA 301 sequence
        rpdo2 = node.rpdo[2]
        rpdo2.read()
        rpdo2.clear()
        rpdo2.add_variable(0x6040)
        rpdo2.add_variable(0x607A)
        rpdo2.trans_type = 255
        rpdo2.enabled = True
        rpdo2.save()
        tpdo2 = node.tpdo[2]
        tpdo2.read()
        tpdo2.clear()
        tpdo2.add_variable(0x6041)
        tpdo2.add_variable(0x6064)
        tpdo2.trans_type = 255
        tpdo2.event_timer = 100
        tpdo2.enabled = True
        tpdo2.save()
        check(node.sdo[0x1A01][0].raw == 2 and node.sdo[0x1801][1].raw == 0x281,
              "TPDO 2 mapping and COB-ID saved by python's PdoMap.save()")
        try:
            node.sdo[0x1A01][0].raw = 1  # the PDO is valid: refused
            check(False, "mapping change of a valid PDO refused")
        except canopen.SdoAbortedError as e:
            check(e.code == 0x06040043,
                  f"mapping change of a valid PDO refused with 0x{e.code:08X}")

        # 4. operational, CiA 402 state machine through the PDOs, one move
        statuswords = []
        tpdo2.add_callback(lambda m: statuswords.append(m["Statusword"].raw))
        node.nmt.state = "OPERATIONAL"
        time.sleep(0.2)

        def statusword():
            tpdo2.wait_for_reception(1.0)
            return tpdo2["Statusword"].raw

        for cw in (0x06, 0x0F):  # shutdown, then switch on + enable operation (3 + 4)
            rpdo2["Controlword"].raw = cw
            rpdo2["Target Position"].raw = 0
            rpdo2.transmit()
            time.sleep(0.1)
        sw = statusword()
        check(sw & 0x6F == 0x27, f"operation enabled (statusword 0x{sw:04X})")
        rpdo2["Target Position"].raw = 20000
        rpdo2["Controlword"].raw = 0x1F  # new set-point
        rpdo2.transmit()
        time.sleep(0.05)
        rpdo2["Controlword"].raw = 0x0F
        rpdo2.transmit()
        deadline = time.time() + 5
        reached = False
        while time.time() < deadline:
            tpdo2.wait_for_reception(1.0)
            if tpdo2["Statusword"].raw & 0x0400 and tpdo2["Position Actual Value"].raw == 20000:
                reached = True
                break
        check(reached, "profile position move to 20000: target reached (TPDO 2)")
        check(any(s & 0x1000 for s in statuswords), "set-point acknowledge seen (bit 12)")
        check(node.sdo[0x6064].raw == 20000, "6064h position actual = 20000 (SDO)")

        # 5. block transfer, both directions: a number (6081h), then a string object when the
        # dictionary gives one a capacity
        with node.sdo.open(0x6081, 0, "wb", block_transfer=True, size=4) as f:
            f.write((60000).to_bytes(4, "little"))
        with node.sdo.open(0x6081, 0, "rb", block_transfer=True) as f:
            back = f.read()
        check(back == (60000).to_bytes(4, "little") and node.sdo[0x6081].raw == 60000,
              "block download + block upload of 6081h (4 bytes)")
        try:
            with node.sdo.open(0x1008, 0, "rb", block_transfer=True) as f:
                name = f.read()
            check(name == b"Servocontroller XENAX Xvi xxVx",
                  f"block upload of 1008h ({len(name)} bytes: {name!r})")
        except canopen.SdoAbortedError as e:
            # an older generated dictionary gives 1008h no capacity (0x06010000)
            log(f"      1008h: no block upload (0x{e.code:08X}): the dictionary gives it no size")
        text = b"fieldcodec block " + bytes(range(0x41, 0x5B))
        for index in (0x5021, 0x5011):
            try:
                with node.sdo.open(index, 0, "wb", block_transfer=True, size=len(text)) as f:
                    f.write(text)
            except canopen.SdoAbortedError as e:
                log(f"      {index:04X}h: block download refused (0x{e.code:08X}): "
                    "the dictionary gives it no size")
                continue
            with node.sdo.open(index, 0, "rb", block_transfer=True) as f:
                back = f.read()
            check(back == text, f"block download + block upload of {index:04X}h "
                  f"({len(text)} bytes)")
            break

        node.nmt.state = "PRE-OPERATIONAL"
    except Exception as e:  # pylint: disable=broad-except
        failures.append(f"exception: {e!r}")
        log(f"FAIL  exception: {e!r}")
    finally:
        running = False
        network.disconnect()
        proc.stdin.close()
        proc.wait(5)
        bridge.shutdown()
    if failures:
        log(f"{len(failures)} failure(s)")
        return 1
    log("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
