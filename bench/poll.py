#!/usr/bin/env python3
"""CPU time of `--poll 100ms --log` and of `watch` over a while, against `mbtool serve` on
TCP, and the drift of the poll schedule: how far the last of N polls is from start +
N x interval.

    python3 bench/poll.py [SECONDS] [DRIFT_SECONDS]     (default: 60 600)
"""
import os
import socket
import subprocess
import sys
import tempfile
import time
from datetime import datetime

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
TICKS = os.sysconf("SC_CLK_TCK")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def cpu_seconds(pid):
    fields = open(f"/proc/{pid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / TICKS


def main():
    seconds = int(sys.argv[1]) if len(sys.argv) > 1 else 60
    drift_seconds = int(sys.argv[2]) if len(sys.argv) > 2 else 600
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    port = free_port()
    serve = subprocess.Popen(
        [MBTOOL, "serve", "--port", f"tcp://127.0.0.1:{port}", "--quiet"],
        stderr=subprocess.DEVNULL,
    )
    work = tempfile.mkdtemp()
    try:
        time.sleep(0.5)
        target = ["--port", f"127.0.0.1:{port}"]
        # --poll 100ms --log: CPU time over the run, from the kernel's own count.
        count = seconds * 10
        log = os.path.join(work, "poll.csv")
        poller = subprocess.Popen(
            [MBTOOL, *target, "read-holding", "17", "400108", "10", "--poll", "100ms",
             "--count", str(count), "--log", log],
            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
        )
        _, _, usage = os.wait4(poller.pid, 0)
        cpu = usage.ru_utime + usage.ru_stime
        print(f"--poll 100ms --log, {seconds} s: {cpu:.2f} s CPU = {100 * cpu / seconds:.2f}% of one core")
        # watch in a terminal of its own (tmux), measured before it is told to stop.
        socket_path = os.path.join(work, "tmux")
        pid_file = os.path.join(work, "pid")
        subprocess.run(
            ["tmux", "-S", socket_path, "new-session", "-d", "-x", "100", "-y", "30",
             f"{MBTOOL} {' '.join(target)} watch 17 400108 10 --poll 100ms & echo $! > {pid_file}; wait"],
            check=True,
        )
        time.sleep(1)
        pid = int(open(pid_file).read())
        start = cpu_seconds(pid)
        time.sleep(seconds)
        cpu = cpu_seconds(pid) - start
        subprocess.run(["tmux", "-S", socket_path, "send-keys", "q"])
        time.sleep(0.5)
        subprocess.run(["tmux", "-S", socket_path, "kill-server"], stderr=subprocess.DEVNULL)
        print(f"watch --poll 100ms, {seconds} s: {cpu:.2f} s CPU = {100 * cpu / seconds:.2f}% of one core")
        # Drift: N polls at 100 ms; the last one's time against start + (N - 1) x 100 ms.
        polls = drift_seconds * 10
        out = subprocess.run(
            [MBTOOL, *target, "read-holding", "17", "400108", "--poll", "100ms",
             "--count", str(polls), "-o", "csv"],
            capture_output=True, text=True, check=True,
        ).stdout.splitlines()[1:]
        first = datetime.fromisoformat(out[0].split(",")[0])
        last = datetime.fromisoformat(out[-1].split(",")[0])
        drift = (last - first).total_seconds() - (polls - 1) * 0.1
        print(f"drift over {drift_seconds} s ({polls} polls at 100 ms): {drift * 1e3:+.1f} ms")
    finally:
        serve.kill()
        serve.wait()


if __name__ == "__main__":
    main()
