#!/usr/bin/env python3
"""mbtool's master over Modbus/UDP against the same master over Modbus TCP, in one run,
both reading 3 holding registers from one pymodbus server that serves both (one process,
one data store, TCP and UDP on 127.0.0.1).

  - the loop: 2,000 reads in one process (--poll 0 --count 2000), per transaction, the
    cost of starting the process taken out by also timing a run of one read; TCP and UDP
    runs taken in turn, five of each, so that both meet the same machine; the best of each;
  - printed: each time, and UDP's speed as a ratio of TCP's (above 1: UDP is faster).

The same loops against mbtool serve are printed beside, for scale.

    python3 bench/udp.py        (needs pymodbus)
"""
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from support import free_port, wait_listening  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
LOOP = 2000

# One pymodbus process serving one data store over TCP and UDP.
SERVER = """
import asyncio, sys
from pymodbus.datastore import ModbusDeviceContext, ModbusSequentialDataBlock, ModbusServerContext
from pymodbus.server import ModbusTcpServer, ModbusUdpServer
def block():
    return ModbusSequentialDataBlock(1, [0] * 1000)
device = ModbusDeviceContext(di=block(), co=block(), ir=block(), hr=block())
context = ModbusServerContext(devices={17: device}, single=False)
async def main():
    tcp = ModbusTcpServer(context, address=("127.0.0.1", int(sys.argv[1])))
    udp = ModbusUdpServer(context, address=("127.0.0.1", int(sys.argv[2])))
    await asyncio.gather(tcp.serve_forever(), udp.serve_forever())
asyncio.run(main())
"""


def timed(args):
    start = time.perf_counter()
    subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - start


def loop(port, count):
    read = [MBTOOL, "--port", port, "read-holding", "17", "400108", "3", "-o", "values",
            "--poll", "0", "--count", str(count)]
    return timed(read)


def per_transaction(ports):
    """Seconds per read in mbtool's loop on each of `ports`, process start-up taken out:
    the ports taken in turn, the best of five runs of each."""
    one = {port: min(loop(port, 1) for _ in range(5)) for port in ports}
    many = {port: [] for port in ports}
    for _ in range(5):
        for port in ports:
            many[port].append(loop(port, LOOP))
    return [(min(many[port]) - one[port]) / (LOOP - 1) for port in ports]


def answering(port, within=15):
    deadline = time.time() + within
    while time.time() < deadline:
        probe = [MBTOOL, "--port", port, "--timeout", "300ms", "read-holding", "17", "400108"]
        if subprocess.run(probe, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0:
            return
        time.sleep(0.1)
    raise SystemExit(f"nothing answers on {port}")


def compare(name, tcp, udp):
    tcp_time, udp_time = per_transaction([tcp, udp])
    print(f"{name}: TCP {tcp_time * 1e6:.0f} us a read, UDP {udp_time * 1e6:.0f} us a read; "
          f"UDP's speed / TCP's: {tcp_time / udp_time:.2f}")
    return tcp_time / udp_time


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    children = []
    try:
        tcp, udp = free_port(), free_port()
        children.append(subprocess.Popen([sys.executable, "-c", SERVER, str(tcp), str(udp)],
                                         stderr=subprocess.DEVNULL))
        wait_listening(tcp)
        answering(f"udp://127.0.0.1:{udp}")
        ratio = compare("pymodbus", f"tcp://127.0.0.1:{tcp}", f"udp://127.0.0.1:{udp}")
        serve_tcp, serve_udp = free_port(), free_port()
        for address in (f"tcp://127.0.0.1:{serve_tcp}", f"udp://127.0.0.1:{serve_udp}"):
            children.append(subprocess.Popen([MBTOOL, "serve", "--port", address],
                                             stderr=subprocess.DEVNULL))
        wait_listening(serve_tcp)
        answering(f"udp://127.0.0.1:{serve_udp}")
        compare("mbtool serve", f"tcp://127.0.0.1:{serve_tcp}", f"udp://127.0.0.1:{serve_udp}")
        if ratio < 1:
            print("UDP is slower than TCP against pymodbus", file=sys.stderr)
            return 1
        return 0
    finally:
        for child in children:
            child.kill()
            child.wait()


if __name__ == "__main__":
    sys.exit(main())
