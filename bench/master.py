#!/usr/bin/env python3
"""mbtool against mbpoll, in one run, both reading 3 holding registers from the same fast
slave (libmodbus, bench/libmodbus_slave.c) over TCP on 127.0.0.1 and over a socat pty pair.

  - the loop: 2,000 reads in one process (mbtool --poll 0 --count 2000; mbpoll -1 with the
    slave address repeated 2,000 times), per transaction, the cost of starting the process
    taken out by also timing a run of one read;
  - whole processes: 30 runs of one read each, the median.

On the pty mbtool runs with --frame-gap 0 (mbpoll keeps no gap between transactions); the
cost of the RTU gap is measured on its own.

    python3 bench/master.py        (needs gcc, libmodbus-dev, mbpoll, socat)
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
LOOP = 2000
PROCESSES = 30


def timed(args):
    start = time.perf_counter()
    subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - start


def per_transaction(make_args):
    """Seconds per transaction in a loop, process start-up taken out."""
    one = min(timed(make_args(1)) for _ in range(5))
    many = min(timed(make_args(LOOP)) for _ in range(3))
    return (many - one) / (LOOP - 1)


def whole_process(args):
    return statistics.median(timed(args) for _ in range(PROCESSES))


def mbpoll_addresses(n):
    return ",".join(["17"] * n)


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    work = tempfile.mkdtemp()
    slave_bin = os.path.join(work, "libmodbus_slave")
    subprocess.run(
        f"gcc -O2 -o {slave_bin} {ROOT}/bench/libmodbus_slave.c $(pkg-config --cflags --libs libmodbus)",
        shell=True, check=True)
    children = []
    try:
        port = 15502
        children.append(subprocess.Popen([slave_bin, "tcp", str(port)]))
        time.sleep(0.3)
        tcp = f"tcp://127.0.0.1:{port}"
        mbtool_read = [MBTOOL, "--port", tcp, "read-holding", "17", "400108", "3", "-o", "values"]
        results = {}
        results["tcp loop mbtool"] = per_transaction(
            lambda n: mbtool_read + ["--poll", "0", "--count", str(n)])
        results["tcp loop mbpoll"] = per_transaction(
            lambda n: ["mbpoll", "-m", "tcp", "-a", mbpoll_addresses(n), "-t", "4", "-r", "108",
                       "-c", "3", "-1", "-p", str(port), "127.0.0.1"])
        results["tcp process mbtool"] = whole_process(mbtool_read)
        results["tcp process mbpoll"] = whole_process(
            ["mbpoll", "-m", "tcp", "-a", "17", "-t", "4", "-r", "108", "-c", "3", "-1",
             "-p", str(port), "127.0.0.1"])

        a, b = os.path.join(work, "a"), os.path.join(work, "b")
        children.append(subprocess.Popen(
            ["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"],
            stderr=subprocess.DEVNULL))
        while not (os.path.exists(a) and os.path.exists(b)):
            time.sleep(0.02)
        children.append(subprocess.Popen([slave_bin, "rtu", a]))
        time.sleep(0.3)
        pty_read = [MBTOOL, "--port", b, "read-holding", "17", "400108", "3", "-o", "values"]
        mbpoll_pty = lambda n: ["mbpoll", "-m", "rtu", "-b", "19200", "-P", "even", "-a",
                                mbpoll_addresses(n), "-t", "4", "-r", "108", "-c", "3", "-1", b]
        results["pty loop mbtool"] = per_transaction(
            lambda n: pty_read + ["--frame-gap", "0", "--poll", "0", "--count", str(n)])
        results["pty loop mbtool, RTU gap kept"] = per_transaction(
            lambda n: pty_read + ["--poll", "0", "--count", str(n)])
        results["pty loop mbpoll"] = per_transaction(mbpoll_pty)
        results["pty process mbtool"] = whole_process(pty_read + ["--frame-gap", "0"])
        results["pty process mbpoll"] = whole_process(mbpoll_pty(1))
    finally:
        for child in children:
            child.kill()
            child.wait()

    for name, seconds in results.items():
        print(f"{name:34} {seconds * 1e6:10.1f} us")
    for where in ("tcp", "pty"):
        loop = results[f"{where} loop mbtool"] / results[f"{where} loop mbpoll"]
        process = results[f"{where} process mbtool"] / results[f"{where} process mbpoll"]
        print(f"{where}: mbtool/mbpoll time per transaction in a loop {loop:.2f}, "
              f"per whole process {process:.3f}")
    gap = results["pty loop mbtool, RTU gap kept"] - results["pty loop mbtool"]
    print(f"pty: the RTU frame gap (3.5 characters at 19200 8E1 = 2.005 ms) costs {gap * 1e3:.2f} ms a transaction")


if __name__ == "__main__":
    sys.exit(main())
