#!/usr/bin/env python3
"""fieldcodec-gen against python canopen's EDS/DCF reader, side by side on the same files.

    bench/gen_vs_python.py --gen build-bench/codegen/fieldcodec-gen [--runs 7] FILE...

For every file:
  * fieldcodec-gen, whole process (start-up included): `fieldcodec-gen --quiet FILE` (read and
    check) and `fieldcodec-gen --quiet -o OUT.hpp FILE` (read + emit the header), CPU time
    (user + system) of the child from wait4(), the minimum of --runs runs;
  * python canopen, in process (interpreter start-up and imports excluded):
    `canopen.objectdictionary.import_od(FILE)`, time.process_time() around the call, the minimum
    of --runs runs ("fails" when it raises on the file). The columns are skipped when python canopen is not found
    (../shared/peers/python-canopen beside the repository, or --python-canopen DIR).
The minimum is the run least disturbed by other work on the machine. Prints a markdown table:
MB/s (10^6 bytes of input per second) of read and read+emit, and python's time / fieldcodec's.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time


def child_cpu(cmd):
    """CPU seconds (user + system) of one run of cmd; fails on a non-zero exit."""
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, ru = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    err = p.stderr.read().decode(errors="replace")
    p.stderr.close()
    if p.returncode not in (0,):
        sys.exit(f"{' '.join(cmd)}: exit {p.returncode}\n{err}")
    return ru.ru_utime + ru.ru_stime


def best(f, runs):
    return min(f() for _ in range(runs))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--gen", required=True, help="the fieldcodec-gen executable")
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--python-canopen",
                    default=os.path.join(here, "..", "..", "shared", "peers", "python-canopen"))
    ap.add_argument("files", nargs="+")
    a = ap.parse_args()

    import_od = None
    if os.path.isdir(os.path.join(a.python_canopen, "canopen")):
        sys.path.insert(0, a.python_canopen)
        import logging
        logging.disable(logging.CRITICAL)  # its warnings about the files are not timed output
        from canopen.objectdictionary import import_od
    else:
        print(f"python canopen not found in {a.python_canopen}: its columns are skipped",
              file=sys.stderr)

    out = tempfile.mkdtemp()
    hdr = os.path.join(out, "bench_out.hpp")
    cols = ["file", "bytes", "fieldcodec read ms", "read MB/s", "read+emit ms", "read+emit MB/s"]
    if import_od:
        cols += ["python import_od ms", "python MB/s", "× (read+emit)"]
    print("| " + " | ".join(cols) + " |")
    print("|---|" + "---:|" * (len(cols) - 1))
    for f in a.files:
        size = os.path.getsize(f)
        read = best(lambda: child_cpu([a.gen, "--quiet", f]), a.runs)
        emit = best(lambda: child_cpu([a.gen, "--quiet", "--name", "bench_out", "-o", hdr, f]),
                    a.runs)
        row = [os.path.basename(f), f"{size}", f"{read * 1e3:.1f}", f"{size / read / 1e6:.1f}",
               f"{emit * 1e3:.1f}", f"{size / emit / 1e6:.1f}"]
        if import_od:
            def py():
                t = time.process_time()
                import_od(f)
                return time.process_time() - t
            try:
                p = best(py, a.runs)
                row += [f"{p * 1e3:.1f}", f"{size / p / 1e6:.2f}", f"**{p / emit:.1f}**"]
            except Exception as e:  # python canopen refuses some real files
                row += [f"fails: {type(e).__name__}", "", ""]
        print("| " + " | ".join(row) + " |", flush=True)
        try:
            os.remove(hdr)
        except FileNotFoundError:
            pass
    os.rmdir(out)


if __name__ == "__main__":
    main()
