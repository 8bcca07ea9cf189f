#!/usr/bin/env python3
"""mbtool sunspec against pysunspec2's scan (the SunSpec Alliance's own library), in one
run, on the same device: examples/sunspec-inverter.txt (models 1, 103, 120, 121, 160 and
a vendor's) served by mbtool serve at 40000, 50000 and 0. For each base: the requests
each makes (pysunspec2's counted by wrapping its read), and the time of a whole scan,
best of five, process start included for both (a Python interpreter for pysunspec2).

    python3 bench/sunspec.py        (needs pysunspec2)
"""
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from support import free_port  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
DEVICE = os.path.join(ROOT, "tests", "peers", "sunspec_device.py")


def best(args, runs=5):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        done = subprocess.run(args, capture_output=True, text=True, check=True)
        times.append(time.perf_counter() - start)
    return min(times), done


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    with tempfile.TemporaryDirectory() as folder:
        for base in (40000, 50000, 0):
            data = os.path.join(folder, f"device-{base}.txt")
            subprocess.run([sys.executable, DEVICE, "image", str(base), data,
                            os.path.join(folder, f"device-{base}.json")], check=True)
            port = free_port()
            server = subprocess.Popen([MBTOOL, "serve", "--port", f"tcp://127.0.0.1:{port}",
                                       "--slave", "1", "--data", data, "--quiet"],
                                      stderr=subprocess.DEVNULL)
            try:
                time.sleep(0.5)
                ours, done = best([MBTOOL, "--port", f"tcp://127.0.0.1:{port}", "sunspec", "1",
                                   "-o", "json"])
                our_requests = json.loads(done.stdout)["requests"]
                theirs, done = best([sys.executable, DEVICE, "tcp", str(port), "1"])
                their_requests = json.loads(done.stdout)["requests"]
                print(f"SunS at {base}: mbtool {our_requests} requests {ours * 1000:.1f} ms, "
                      f"pysunspec2 {their_requests} requests {theirs * 1000:.1f} ms; "
                      f"pysunspec2's time / mbtool's: {theirs / ours:.1f}")
            finally:
                server.kill()
                server.wait()


if __name__ == "__main__":
    main()
