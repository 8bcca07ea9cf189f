#!/usr/bin/env python3
"""What one process costs: `mbtool read-holding` against mbpoll, each reading 3 registers
once from the same `mbtool serve` over TCP on 127.0.0.1, 50 processes of each, taken in
turn. CPU per process from getrusage of the children (user + system), wall time per
process, and the ratios mbtool / mbpoll. Then the start alone (`--version`, `-V`) beside a
process that does nothing, to tell what a start costs from what the read does.

Each command runs as a script's loop runs it: over and over, in blocks of ten, the blocks
of the commands taken in turn so that the host's drift falls on all of them alike. Each
block starts with a run that is not counted. What one process leaves behind is paid by
the next: mbpoll sleeps 20 ms after it connects, and a process that starts after a CPU
has been idle costs about 0.15 ms more (measured: `true` after a program that only sleeps
20 ms, against `true` after `true`). In a loop of mbpoll that next process is mbpoll; taken
one by one in turn, it would be whichever command came after it.

mbtool is timed as installed: `cargo install` copies the binary, as a package manager
writes mbpoll's. The file the linker wrote in target/release costs each process about half
a millisecond more to load than a copy of the same bytes (on Linux 6, measured), so it is
timed too, beside the copy. Two builds are timed: `cargo build --release`, linked against
the shared C library, and `cargo build-static` (.cargo/config.toml), linked static-pie,
which `cargo install-static` installs; the ratios are given for each.

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
HOST = next(line.split(": ", 1)[1] for line in subprocess.run(
    ["rustc", "-vV"], capture_output=True, text=True, check=True).stdout.splitlines()
    if line.startswith("host: "))
STATIC = os.path.join(ROOT, "target", HOST, "release", "mbtool")
RUNS = int(sys.argv[1]) if len(sys.argv) > 1 else 50
BLOCK = 10


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
    subprocess.run(["cargo", "build-static", "--quiet"], cwd=ROOT, check=True)
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
        installed_static = os.path.join(work, "mbtool-static")
        shutil.copy2(STATIC, installed_static)
        read = ["--port", f"127.0.0.1:{port}", "read-holding", "17", "400108", "3"]
        commands = {
            "mbtool": [installed] + read,
            "mbtool static-pie": [installed_static] + read,
            "mbtool as linked in target/release": [MBTOOL] + read,
            "mbpoll": ["mbpoll", "-m", "tcp", "-p", str(port), "-a", "17", "-r", "108", "-c", "3",
                       "-1", "127.0.0.1"],
            # What a start alone costs, beside a process that does nothing.
            "mbtool --version": [installed, "--version"],
            "mbtool static-pie --version": [installed_static, "--version"],
            "mbpoll -V": ["mbpoll", "-V"],
            "true": [shutil.which("true")],
        }
        samples = {name: [] for name in commands}
        while any(len(runs) < RUNS for runs in samples.values()):
            for name, args in commands.items():
                run(args)
                for _ in range(min(BLOCK, RUNS - len(samples[name]))):
                    samples[name].append(run(args))
        figures = {}
        for name, runs in samples.items():
            cpu = statistics.mean(c for c, _ in runs) * 1e3
            wall = statistics.median(w for _, w in runs) * 1e3
            figures[name] = (cpu, wall)
            print(f"{name}: {cpu:.2f} ms CPU per process (mean of {RUNS}), "
                  f"{wall:.2f} ms wall (median)")
        peer_cpu, peer_wall = figures["mbpoll"]
        nothing = figures["true"][0]
        peer_start = figures["mbpoll -V"][0]
        print(f"mbpoll: start beyond a process that does nothing {peer_start - nothing:.2f} ms "
              f"CPU, the read beyond the start {peer_cpu - peer_start:.2f} ms")
        for build in ["mbtool", "mbtool static-pie"]:
            tool_cpu, tool_wall = figures[build]
            tool_start = figures[f"{build} --version"][0]
            print(f"{build} / mbpoll: CPU x{tool_cpu / peer_cpu:.2f}, "
                  f"wall x{tool_wall / peer_wall:.2f}; start beyond a process that does "
                  f"nothing {tool_start - nothing:.2f} ms CPU, the read beyond the start "
                  f"{tool_cpu - tool_start:.2f} ms")
    finally:
        server.terminate()
        server.wait()
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
