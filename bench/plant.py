#!/usr/bin/env python3
"""`mbtool poll` of a plant at scale, and of a serial line at its pace.

1. DEVICES Modbus TCP devices (10 `mbtool serve` processes, each answering for DEVICES/10
   unit ids), each read every second, 10 registers a read, for SECONDS: the poller's CPU
   (share of one core), its peak memory, how late each poll started against its schedule
   (p50, p99, max), and whether any value was lost (a device-second without its 10 values).
2. Ten slaves on a 19200 8E1 line (a pseudo-terminal pair, `serve` at one end): the poll
   cycle of the ten against the time the line itself takes. A pseudo-terminal moves bytes
   at once, so the time on a real line is the time measured here plus the bytes' time on
   the wire; the line's own time is the bytes' time plus the 3.5-character silence the
   specification asks between an answer and the next request.

    python3 bench/plant.py [SECONDS] [DEVICES]      (default: 300 1000)
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time
from datetime import datetime

from support import free_port, wait_listening

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
TICKS = os.sysconf("SC_CLK_TCK")
SERVERS = 10
REGISTERS = 10


def cpu_seconds(pid):
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / TICKS


def memory_kib(pid, key):
    for line in open(f"/proc/{pid}/status"):
        if line.startswith(key + ":"):
            return int(line.split()[1])
    return 0


def points_yaml(indent):
    return "".join(
        f"{indent}- {{name: r{i}, ref: {400001 + i}}}\n" for i in range(REGISTERS)
    )


def percentile(values, share):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(share * len(ordered)))]


def plant_at_scale(seconds, devices, folder):
    per_server = devices // SERVERS
    servers, ports = [], []
    for _ in range(SERVERS):
        port = free_port()
        ids = [arg for i in range(1, per_server + 1) for arg in ("--slave", str(i))]
        servers.append(subprocess.Popen(
            [MBTOOL, "serve", "--port", f"tcp://127.0.0.1:{port}", "--quiet", *ids],
            stderr=subprocess.DEVNULL))
        ports.append(port)
    for port in ports:
        wait_listening(port)
    plant = os.path.join(folder, "plant.yaml")
    with open(plant, "w") as f:
        f.write("devices:\n")
        for s, port in enumerate(ports):
            for unit in range(1, per_server + 1):
                f.write(f"  - name: d{s}-{unit}\n    port: tcp://127.0.0.1:{port}\n"
                        f"    slave: {unit}\n    every: 1s\n    points:\n")
                f.write(points_yaml("      "))
    rows_path = os.path.join(folder, "rows.jsonl")
    with open(rows_path, "w") as rows_file:
        started = time.time()
        poll = subprocess.Popen([MBTOOL, "poll", plant, "-o", "json", "--for", f"{seconds}s"],
                                stdout=rows_file, stderr=subprocess.DEVNULL)
        peak = [0]

        def watch():
            while poll.poll() is None:
                try:
                    peak[0] = max(peak[0], memory_kib(poll.pid, "VmRSS"))
                    cpu[0] = cpu_seconds(poll.pid)
                except OSError:
                    return
                time.sleep(0.5)

        cpu = [0.0]
        watcher = threading.Thread(target=watch)
        watcher.start()
        poll.wait()
        watcher.join()
        elapsed = time.time() - started
    for server in servers:
        server.kill()
        server.wait()

    by_device = {}
    whole = True
    for line in open(rows_path):
        row = json.loads(line)
        t = datetime.fromisoformat(row["time"]).timestamp()
        by_device.setdefault(row["device"], []).append(t)
        if len(row["values"]) != REGISTERS or "error" in row or "errors" in row:
            whole = False
    # Every device is due at the start and then each second after: the start is taken as
    # the earliest row of all, and a row's lateness is its time past its second.
    base = min(times[0] for times in by_device.values())
    late = []
    for times in by_device.values():
        for t in times:
            k = round(t - base)
            late.append((t - (base + k)) * 1000)
    expected = int(seconds)
    short = sum(1 for times in by_device.values() if len(times) < expected)
    rows = sum(len(times) for times in by_device.values())
    print(f"{devices} TCP devices ({SERVERS} serve processes), {REGISTERS} registers each, every 1 s, "
          f"for {seconds} s: {rows} rows")
    print(f"  CPU: {cpu[0]:.1f} s in {elapsed:.0f} s = {100 * cpu[0] / elapsed:.1f}% of a core (limit 10%)")
    print(f"  memory: {peak[0] / 1024:.1f} MB peak resident (limit 100 MB)")
    print(f"  start of each poll past its schedule: p50 {percentile(late, 0.5):.1f} ms, "
          f"p99 {percentile(late, 0.99):.1f} ms, max {max(late):.1f} ms (limit: p99 50 ms)")
    missing = len(by_device) != devices
    print(f"  values lost: {'none' if whole and not short and not missing else 'SOME'}"
          f" ({len(by_device)} devices with rows, {short} with fewer than {expected}, "
          f"every row {'whole' if whole else 'NOT whole'})")


def serial_line(folder, seconds=10):
    if not shutil.which("socat"):
        print("serial line: skipped, socat is not installed")
        return
    a, b = os.path.join(folder, "a"), os.path.join(folder, "b")
    socat = subprocess.Popen(["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"],
                             stderr=subprocess.DEVNULL)
    while not (os.path.exists(a) and os.path.exists(b)):
        time.sleep(0.05)
    ids = [arg for i in range(1, 11) for arg in ("--slave", str(i))]
    line = ["-b", "19200", "--parity", "even"]
    serve = subprocess.Popen([MBTOOL, "serve", "--port", a, "--quiet", *line, *ids],
                             stderr=subprocess.DEVNULL)
    time.sleep(0.5)
    plant = os.path.join(folder, "line.yaml")
    with open(plant, "w") as f:
        f.write("devices:\n")
        for unit in range(1, 11):
            f.write(f"  - name: s{unit}\n    port: {b}\n    baud: 19200\n    parity: even\n"
                    f"    slave: {unit}\n    every: 10ms\n    points:\n")
            f.write(points_yaml("      "))
    out = subprocess.run([MBTOOL, "poll", plant, "-o", "json", "--for", f"{seconds}s"],
                         capture_output=True, text=True)
    serve.kill()
    socat.kill()
    rows = [json.loads(l) for l in out.stdout.splitlines()]
    whole = sum(1 for r in rows if len(r["values"]) == REGISTERS)
    times = [datetime.fromisoformat(r["time"]).timestamp() for r in rows]
    per_read = (times[-1] - times[0]) / (len(times) - 1)
    char = 11 / 19200  # start, 8 data, parity, stop
    request, answer = 8, 5 + 2 * REGISTERS
    wire = (request + answer) * char
    silence = 3.5 * char
    real = per_read + wire
    ideal = wire + silence
    print(f"10 slaves on a 19200 8E1 line, {REGISTERS} registers each, polled back to back for {seconds} s: "
          f"{len(rows)} reads, {whole} whole")
    print(f"  one read: {per_read * 1e3:.2f} ms of mbtool and serve on a pseudo-terminal "
          f"+ {wire * 1e3:.2f} ms of bytes on the wire = {real * 1e3:.2f} ms on a real line")
    print(f"  the line's own time: {wire * 1e3:.2f} ms of bytes + {silence * 1e3:.2f} ms of silence "
          f"= {ideal * 1e3:.2f} ms; the cycle of ten: {10 * real * 1e3:.1f} ms, "
          f"{real / ideal:.3f} of it (limit 1.1)")


def main():
    seconds = int(sys.argv[1]) if len(sys.argv) > 1 else 300
    devices = int(sys.argv[2]) if len(sys.argv) > 2 else 1000
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    with tempfile.TemporaryDirectory() as folder:
        serial_line(folder)
        plant_at_scale(seconds, devices, folder)


if __name__ == "__main__":
    main()
