#!/usr/bin/env python3
"""What one process costs: `mbtool read-holding` against mbpoll, each reading 3 registers
once from the same `mbtool serve` over TCP on 127.0.0.1, 50 processes of each, taken in
turn. CPU per process from getrusage of the children (user + system), wall time per
process, and the ratios mbtool / mbpoll. Then the start alone (`--version`, `-V`) beside a
process that does nothing, to tell what a start costs from what the read does.

mbtool is timed as installed: `cargo install` copies the binary, as a package manager
writes mbpoll's. The file the linker wrote in target/release costs each process about half
a millisecond more to load than a copy of the same bytes (on Linux 6, measured), so it is
timed too, beside the copy, but the ratios are the installed copy's.

    python3 bench/oneshot.py [RUNS]        (needs mbpoll)
"""
import os
import resource
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
RUNS = int(sys.argv[1]) if len(sys.argv) > 1 else 50


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def run(args):
    """(CPU seconds, wall seconds) of one process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    work = tempfile.mkdtemp()
    port = free_port()
    server = subprocess.Popen(
        [MBTOOL, "--port", f"tcp://127.0.0.1:{port}", "serve", "--slave", "17", "-q"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        for _ in range(100):
            try:
                socket.create_connection(("127.0.0.1", port), timeout=0.1).close()
                break
            except OSError:
                time.sleep(0.05)
        installed = os.path.join(work, "mbtool")
        shutil.copy2(MBTOOL, installed)
        read = ["--port", f"127.0.0.1:{port}", "read-holding", "17", "400108", "3"]
        commands = {
            "mbtool": [installed] + read,
            "mbtool as linked in target/release": [MBTOOL] + read,
            "mbpoll": ["mbpoll", "-m", "tcp", "-p", str(port), "-a", "17", "-r", "108", "-c", "3",
                       "-1", "127.0.0.1"],
            # What a start alone costs, beside a process that does nothing.
            "mbtool --version": [installed, "--version"],
            "mbpoll -V": ["mbpoll", "-V"],
            "true": [shutil.which("true")],
        }
        samples = {name: [] for name in commands}
        for _ in range(RUNS):
            for name, args in commands.items():
                samples[name].append(run(args))
        figures = {}
        for name, runs in samples.items():
            cpu = statistics.mean(c for c, _ in runs) * 1e3
            wall = statistics.median(w for _, w in runs) * 1e3
            figures[name] = (cpu, wall)
            print(f"{name}: {cpu:.2f} ms CPU per process (mean of {RUNS}), "
                  f"{wall:.2f} ms wall (median)")
        (tool_cpu, tool_wall), (peer_cpu, peer_wall) = figures["mbtool"], figures["mbpoll"]
        print(f"mbtool / mbpoll: CPU x{tool_cpu / peer_cpu:.2f}, wall x{tool_wall / peer_wall:.2f}")
        nothing = figures["true"][0]
        print(f"CPU of a start beyond a process that does nothing: mbtool "
              f"{figures['mbtool --version'][0] - nothing:.2f} ms, mbpoll "
              f"{figures['mbpoll -V'][0] - nothing:.2f} ms; of the read beyond the start: mbtool "
              f"{tool_cpu - figures['mbtool --version'][0]:.2f} ms, mbpoll "
              f"{peer_cpu - figures['mbpoll -V'][0]:.2f} ms")
    finally:
        server.terminate()
        server.wait()
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
