#!/usr/bin/env python3
"""Transactions per second that `mbtool serve` answers, beside a libmodbus slave
(bench/libmodbus_slave.c) and pymodbus's server, all with the same client in the same run:
mbpoll reading 3 holding registers 2,000 times in one process (`mbpoll -1 -a 17,17,...`),
over TCP on 127.0.0.1 and over a socat pty pair. mbtool serve runs with --quiet; its cost
of logging every request is measured too.

    python3 bench/serve.py        (needs gcc, libmodbus-dev, mbpoll, socat, pymodbus)
"""
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
PEER = os.path.join(ROOT, "tests", "peers", "pymodbus_slave.py")
N = 2000


def timed(args):
    start = time.perf_counter()
    subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - start


def rates(clients, rounds=5):
    """Transactions per second of 2,000 reads in one mbpoll process, start-up taken out.
    The slaves are measured in turn, round after round, and each keeps its best: this
    machine's speed drifts, and turns share the drift fairly."""
    best = {name: (float("inf"), float("inf")) for name in clients}
    for _ in range(rounds):
        for name, client in clients.items():
            one = timed(client("17"))
            many = timed(client(",".join(["17"] * N)))
            best[name] = (min(best[name][0], one), min(best[name][1], many))
    return {name: (N - 1) / (many - one) for name, (one, many) in best.items()}


def wait_answering(client_args):
    deadline = time.time() + 20
    while time.time() < deadline:
        if subprocess.run(client_args("17"), stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL).returncode == 0:
            return
        time.sleep(0.2)
    raise SystemExit("a slave never answered")


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    work = tempfile.mkdtemp()
    libmodbus = os.path.join(work, "libmodbus_slave")
    subprocess.run(
        f"gcc -O2 -o {libmodbus} {ROOT}/bench/libmodbus_slave.c $(pkg-config --cflags --libs libmodbus)",
        shell=True, check=True)
    slaves = {
        "mbtool serve": lambda where: [MBTOOL, "serve", "--quiet", "--port", where],
        "mbtool serve, logging": lambda where: [MBTOOL, "serve", "--port", where],
        "libmodbus": lambda where: [libmodbus, "tcp", where.rsplit(":", 1)[1]]
        if where.startswith("tcp") else [libmodbus, "rtu", where],
        "pymodbus": lambda where: ["python3", PEER, "--framer", "socket", "--tcp", where.rsplit(":", 1)[1]]
        if where.startswith("tcp") else ["python3", PEER, "--framer", "rtu", "--serial", where],
    }
    results = {}
    children = []
    try:
        tcp_clients, pty_clients = {}, {}
        port = 15600
        for name, command in slaves.items():
            port += 1
            children.append(subprocess.Popen(command(f"tcp://127.0.0.1:{port}"),
                                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
            tcp_clients[name] = lambda a, p=port: ["mbpoll", "-m", "tcp", "-a", a, "-t", "4", "-r", "108",
                                                   "-c", "3", "-1", "-p", str(p), "127.0.0.1"]
            a, b = os.path.join(work, f"a{port}"), os.path.join(work, f"b{port}")
            children.append(subprocess.Popen(
                ["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"],
                stderr=subprocess.DEVNULL))
            while not (os.path.exists(a) and os.path.exists(b)):
                time.sleep(0.02)
            children.append(subprocess.Popen(command(a), stdout=subprocess.DEVNULL,
                                             stderr=subprocess.DEVNULL))
            pty_clients[name] = lambda addresses, b=b: ["mbpoll", "-m", "rtu", "-b", "19200", "-P", "even",
                                                        "-a", addresses, "-t", "4", "-r", "108", "-c", "3",
                                                        "-1", b]
        for client in list(tcp_clients.values()) + list(pty_clients.values()):
            wait_answering(client)
        for name, per_second in rates(tcp_clients).items():
            results[("tcp", name)] = per_second
        for name, per_second in rates(pty_clients).items():
            results[("pty", name)] = per_second
    finally:
        for child in children:
            child.kill()
            child.wait()

    for (where, name), per_second in results.items():
        print(f"{where} {name:24} {per_second:10,.0f} transactions/s")
    for where in ("tcp", "pty"):
        ours = results[(where, "mbtool serve")]
        print(f"{where}: mbtool serve / libmodbus {ours / results[(where, 'libmodbus')]:.2f}, "
              f"mbtool serve / pymodbus {ours / results[(where, 'pymodbus')]:.2f}")


if __name__ == "__main__":
    sys.exit(main())
