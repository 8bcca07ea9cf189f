#!/usr/bin/env python3
"""mbtool scan --hosts against nmap's modbus-discover, in one run, over the same sweep of
40 addresses of 127.0.0.0/8: 6 run mbtool serve (a few unit ids each), 2 a pymodbus server
that answers every unit id, the other 32 refuse. Both ask unit ids 1-246 with function 17
(nmap: modbus-discover.aggressive; mbtool: --ids 1-246 --probe id): mbtool with its
default politeness (16 hosts at once, one connection each, 20 ms between two requests to a
host), and with no pause, as nmap asks.

Hosts that take a connection and never answer are left out: nmap waits 2 s for each of
246 ids there.

    python3 bench/hosts.py        (needs nmap, pymodbus)
"""
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from support import free_port  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
SLAVE = os.path.join(ROOT, "tests", "peers", "pymodbus_slave.py")


def timed(args):
    start = time.perf_counter()
    subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - start


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    port = free_port()
    children = []
    try:
        for i in range(2, 8):
            children.append(subprocess.Popen(
                [MBTOOL, "serve", "--port", f"tcp://127.0.0.{i}:{port}", "--slave", "1",
                 "--slave", str(i * 10), "--quiet"], stderr=subprocess.DEVNULL))
        for i in (20, 30):
            children.append(subprocess.Popen(
                [sys.executable, SLAVE, "--framer", "socket", "--tcp", str(port),
                 "--address", f"127.0.0.{i}", "--every-unit"],
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        time.sleep(3)
        hosts = "127.0.0.1-40"
        sweep = [MBTOOL, "scan", "--hosts", hosts, "--tcp-port", str(port), "--ids", "1-246",
                 "--probe", "id", "--timeout", "1s", "-o", "json"]
        theirs = min(timed(["nmap", "-n", "-Pn", "-p", str(port), "--script",
                            "+modbus-discover", "--script-args",
                            "modbus-discover.aggressive=true", "127.0.0.1-40"])
                     for _ in range(3))
        for name, extra in (("its 20 ms pause", []), ("--pause 0s, as nmap", ["--pause", "0s"])):
            ours = min(timed(sweep + extra) for _ in range(3))
            print(f"40 addresses, ids 1-246: mbtool ({name}) {ours:.2f} s, nmap {theirs:.2f} s; "
                  f"nmap's time / mbtool's: {theirs / ours:.2f}")
    finally:
        for child in children:
            child.kill()
            child.wait()


if __name__ == "__main__":
    main()
