#!/usr/bin/env python3
"""mbusd against `mbtool gateway`, in one run, on the same pty pair and the same slave
(`mbtool serve`, RTU at 19200 baud):

  1. mbpoll reading 3 registers 2,000 times through each (one connection, one client);
  2. 20 concurrent clients, 200 requests each;
  3. the latency a gateway adds over a direct serial master on the same line
     (`mbtool read-holding --poll 0` on the pty, against the one client of 1).

For each: transactions per second, CPU per transaction of the gateway process (from
/proc/PID/stat), and the ratio mbtool / mbusd. mbusd is built from its source
(github.com/3cky/mbusd) when MBUSD does not name a binary; it runs with -R 1 so that it
does not pause 100 ms between requests.

    python3 bench/gateway.py [REQUESTS]
"""
import os
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time

from support import free_port, wait_listening

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
REQUESTS = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
CLIENTS = 20
PER_CLIENT = 200
TICKS = os.sysconf("SC_CLK_TCK")


def mbusd_binary():
    if os.environ.get("MBUSD"):
        return os.environ["MBUSD"]
    if shutil.which("mbusd"):
        return shutil.which("mbusd")
    build = os.path.join(ROOT, "target", "bench", "mbusd")
    binary = os.path.join(build, "mbusd")
    if not os.path.exists(binary):
        if not os.path.exists(build):
            subprocess.run(["git", "clone", "-q", "https://github.com/3cky/mbusd", build], check=True)
        sources = [os.path.join(build, "src", f) for f in sorted(os.listdir(os.path.join(build, "src"))) if f.endswith(".c")]
        # The definitions its CMakeLists.txt gives on Linux.
        subprocess.run(
            ["gcc", "-O2", "-o", binary, '-DPACKAGE="mbusd"', '-DVERSION="bench"', "-DTRXCTL", "-DLOG",
             "-DHAVE_CFMAKERAW", "-DHAVE_CFSETSPEED", "-DHAVE_TIOCRS485", "-DHRDATE", *sources],
            check=True,
        )
    return binary


def cpu_seconds(pid):
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / TICKS


def mbap_read(transaction):
    return struct.pack(">HHHBBHH", transaction, 0, 6, 17, 3, 107, 3)


def client(port, count, times):
    """`count` reads of 3 registers, one at a time; each one's time appended to `times`."""
    with socket.create_connection(("127.0.0.1", port)) as s:
        s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        for n in range(count):
            start = time.perf_counter()
            s.sendall(mbap_read(n & 0xFFFF))
            answer = b""
            while len(answer) < 15:
                chunk = s.recv(64)
                if not chunk:
                    raise SystemExit("the gateway closed the connection")
                answer += chunk
            if answer[7:9] != b"\x03\x06":
                raise SystemExit(f"bad answer {answer.hex()}")
            times.append(time.perf_counter() - start)


def mbpoll_reads(port, count):
    """mbpoll reading 400108-400110 `count` times, one process each (mbpoll's own loop
    waits at least 10 ms between polls)."""
    for _ in range(count):
        subprocess.run(
            ["mbpoll", "-m", "tcp", "-p", str(port), "-a", "17", "-r", "108", "-c", "3", "-1", "-q", "127.0.0.1"],
            check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        )


def measure(name, pid, work, transactions):
    before, start = cpu_seconds(pid), time.perf_counter()
    work()
    wall, cpu = time.perf_counter() - start, cpu_seconds(pid) - before
    return {"name": name, "tps": transactions / wall, "cpu_us": cpu / transactions * 1e6, "wall": wall}


def run_gateway(kind, line, port, mbusd):
    if kind == "mbusd":
        command = [mbusd, "-d", "-L", "/dev/null", "-v", "0", "-p", line, "-s", "19200", "-m", "8N1",
                   "-A", "127.0.0.1", "-P", str(port), "-R", "1", "-W", "1000", "-N", "0", "-C", "64"]
    else:
        command = [MBTOOL, "gateway", "--listen", f"tcp://127.0.0.1:{port}", "--port", line,
                   "-b", "19200", "--parity", "none", "-q"]
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wait_listening(port)
    return process


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    mbusd = mbusd_binary()
    work = tempfile.mkdtemp()
    a, b = os.path.join(work, "a"), os.path.join(work, "b")
    socat = subprocess.Popen(["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"])
    while not (os.path.exists(a) and os.path.exists(b)):
        time.sleep(0.01)
    slave = subprocess.Popen([MBTOOL, "serve", "--port", a, "-q", "-b", "19200", "--parity", "none"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(0.3)
    results = {}
    try:
        # A direct serial master on the same line: what a transaction costs without a gateway.
        start = time.perf_counter()
        subprocess.run([MBTOOL, "--port", b, "-b", "19200", "--parity", "none", "read-holding", "17",
                        "400108", "3", "--poll", "0", "--count", str(REQUESTS), "-o", "csv"],
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        direct = (time.perf_counter() - start) / REQUESTS
        for kind in ("mbusd", "mbtool"):
            port = free_port()
            gateway = run_gateway(kind, b, port, mbusd)
            try:
                times = []
                rows = [
                    measure("mbpoll, one process a read", gateway.pid,
                            lambda: mbpoll_reads(port, REQUESTS // 10), REQUESTS // 10),
                    measure("one client, back to back", gateway.pid,
                            lambda: client(port, REQUESTS, times), REQUESTS),
                ]

                def concurrent():
                    threads = [threading.Thread(target=client, args=(port, PER_CLIENT, []))
                               for _ in range(CLIENTS)]
                    for t in threads:
                        t.start()
                    for t in threads:
                        t.join()
                rows.append(measure(f"{CLIENTS} clients at once", gateway.pid, concurrent, CLIENTS * PER_CLIENT))
                rows.append({"name": "added latency", "added_ms": (sum(times) / len(times) - direct) * 1000})
                results[kind] = rows
            finally:
                gateway.terminate()
                gateway.wait()
    finally:
        slave.terminate()
        socat.terminate()
        shutil.rmtree(work, ignore_errors=True)
    print(f"direct serial master on the pty: {direct * 1000:.3f} ms a transaction ({REQUESTS} reads)")
    for mine, theirs in zip(results["mbtool"], results["mbusd"]):
        if "added_ms" in mine:
            print(f"{mine['name']:>28}: mbtool {mine['added_ms']:+.3f} ms, mbusd {theirs['added_ms']:+.3f} ms")
            continue
        print(f"{mine['name']:>28}: mbtool {mine['tps']:7.1f} tx/s {mine['cpu_us']:6.1f} us CPU/tx | "
              f"mbusd {theirs['tps']:7.1f} tx/s {theirs['cpu_us']:6.1f} us CPU/tx | "
              f"throughput x{mine['tps'] / theirs['tps']:.2f}, CPU x{mine['cpu_us'] / max(theirs['cpu_us'], 1e-9):.2f}")


if __name__ == "__main__":
    main()
