#!/usr/bin/env python3
"""Show that two builds of mbtool behave the same on the command line.

    python3 tests/tools/compare_cli.py OLD_BINARY NEW_BINARY [--lines N] [--seed S]

for instance, from the repository's root:

    python3 tests/tools/compare_cli.py /tmp/mbtool-before target/release/mbtool

Generates N (default 3000) random command lines from a grammar written out below by
hand (from the commands' --help and README.md): every command and alias, `encode`
with every request command, every option with valid and invalid values, options
before and after the command name (and between `encode` and its request command),
options a command does not take, mbpoll's options typed out of habit, missing and
extra arguments, unknown commands and typos, MBTOOL_* variables set or not (and set
to bad values). About 40% of the lines are "clean": they make no mistake on purpose.
Each line is run with both binaries in the same way; stdout, stderr, the exit status
and the files left in the working directory (dump -o FILE, --log FILE, --save,
--pcap, ...) are compared once what legitimately changes from run to run is
normalised (see TIMING below): timestamps, measured durations, temporary paths, pids,
the fresh value of the diagnostic echo, and when a poll that cannot connect tries
again.

Every process runs:
  - as `mbtool` (argv[0]), so that usage messages name the same program;
  - in a fresh working directory, also its HOME, holding a few fixture files
    (register maps, data files, captures from tests/captures);
  - with stdin from /dev/null, or from a generated log (decode without frames) or
    capture (sniff --input -);
  - with only PATH, HOME, LANG=C, NO_COLOR=1, TERM=dumb and the line's MBTOOL_*
    variables in its environment;
  - in its own process group, under a timeout (--timeout, 3 s; 1 s, --forever-timeout,
    for lines meant to run until stopped: serve, gateway, a poll without --count,
    sniff --interface lo): the group gets SIGINT (Ctrl-C), SIGKILL a second later.
    A line that runs until stopped with both builds is counted as such and compared
    on what is deterministic: the distinct lines it wrote, digits masked.

Bus commands mostly use `--port sim`, the built-in slave, so that they really run;
otherwise a refused 127.0.0.1 port, a missing /dev/ttyNOPE or a bad value. Nothing
touches real hardware or the network beyond 127.0.0.1: no real serial device, no host
name, no listener beyond 127.0.0.1. serve and gateway listen on ports of their line's
own, where no master line connects; sniff --interface lo runs alone.

Lines asking for help or the version (-h, --help, help, -V, --version, mbtool with no
command) are not run: help text changes on purpose. Line K is the same for a given
--seed whatever --lines is: `--line K` runs it alone, `--list` prints the lines.

Each difference is printed with its command line, its environment and a short unified
diff; the last line is `N lines, D differ, H help lines skipped`, and the exit status
is 1 when any line differs. At most two processes run at once (--jobs 2: two lines
at a time, each running its two processes one after the other); 3000 lines take one
to three minutes, most of it lines that wait a second (serve, gateway, a poll, a dump
asking a slave that does not answer).

Plain Python 3 standard library only.
"""

import argparse
import difflib
import os
import random
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field

from cli_grammar import *  # noqa: F401,F403 (the lines to run)

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# --------------------------------------------------------------------------------------
# Running a line.
# --------------------------------------------------------------------------------------


@dataclass
class Outcome:
    status: int
    stdout: bytes
    stderr: bytes
    files: dict
    timed_out: bool
    seconds: float


def run(binary, case, place, fixtures, timeout):
    """Run `case` with `binary` in the directory `place` (made afresh)."""
    wd = os.path.join(place, "wd")
    shutil.rmtree(place, ignore_errors=True)
    os.makedirs(wd)
    for name, data in {**fixtures, **case.files}.items():
        path = os.path.join(wd, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    stdin_path = os.devnull
    if case.stdin is not None:
        stdin_path = os.path.join(place, "stdin")
        with open(stdin_path, "wb") as f:
            f.write(case.stdin)
    env = {"PATH": "/usr/local/bin:/usr/bin:/bin", "HOME": wd, "LANG": "C", "NO_COLOR": "1",
           "TERM": "dumb", **case.env}
    out_path, err_path = os.path.join(place, "stdout"), os.path.join(place, "stderr")
    if STOPPING.is_set():
        raise RuntimeError("interrupted")
    start = time.monotonic()
    timed_out = False
    with open(stdin_path, "rb") as stdin, open(out_path, "wb") as out, open(err_path, "wb") as err:
        proc = subprocess.Popen(["mbtool", *case.argv], executable=binary, cwd=wd, env=env, stdin=stdin,
                                stdout=out, stderr=err, start_new_session=True)
        RUNNING.add(proc.pid)
        try:
            status = proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            signal_group(proc.pid, signal.SIGINT)
            try:
                status = proc.wait(timeout=1.0)
            except subprocess.TimeoutExpired:
                signal_group(proc.pid, signal.SIGKILL)
                status = proc.wait()
        signal_group(proc.pid, signal.SIGKILL)  # anything it left behind
        RUNNING.discard(proc.pid)
    seconds = time.monotonic() - start
    with open(out_path, "rb") as f:
        stdout = f.read()
    with open(err_path, "rb") as f:
        stderr = f.read()
    files = {}
    for folder, _, names in os.walk(wd):
        for name in names:
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, wd)
            try:
                with open(path, "rb") as f:
                    files[rel] = f.read()
            except OSError as e:
                files[rel] = f"<unreadable: {e.strerror}>".encode()
    return Outcome(status, stdout, stderr, files, timed_out, seconds)


RUNNING = set()  # process groups under way, to end if this script is interrupted
STOPPING = threading.Event()  # set when interrupted: no more processes are started


def signal_group(pid, sig):
    try:
        os.killpg(pid, sig)
    except (ProcessLookupError, PermissionError):
        pass


class Gate:
    """Lines share the machine, except those marked exclusive, which run alone."""

    def __init__(self):
        self.cond = threading.Condition()
        self.sharing = 0
        self.alone = False
        self.waiting_alone = 0

    def enter(self, exclusive):
        with self.cond:
            if exclusive:
                self.waiting_alone += 1
                self.cond.wait_for(lambda: not self.alone and self.sharing == 0)
                self.waiting_alone -= 1
                self.alone = True
            else:
                self.cond.wait_for(lambda: not self.alone and self.waiting_alone == 0)
                self.sharing += 1

    def leave(self, exclusive):
        with self.cond:
            if exclusive:
                self.alone = False
            else:
                self.sharing -= 1
            self.cond.notify_all()


# --------------------------------------------------------------------------------------
# Normalising and comparing.
# --------------------------------------------------------------------------------------

UNIT = r"(?:ns|us|µs|ms|s)"
NUMBER = r"\d+(?:\.\d+)?"
# What changes from run to run, and what it becomes.
TIMING = [
    # -v and serve's log: seconds since the start
    (re.compile(r"\[\s*\d+\.\d+\]"), "[<T>]"),
    # RFC 3339 times of --poll rows, --log files, gateway rows
    (re.compile(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d(?:\.\d+)?(?:Z|[+-]\d\d:\d\d)?"), "<TIME>"),
    # dump's header
    (re.compile(r"\d{4}-\d\d-\d\d \d\d:\d\d:\d\d(?:\.\d+)?(?: ?(?:UTC|[+-]\d\d:?\d\d))?"), "<DATE>"),
    # a clock time of day (gateway rows)
    (re.compile(r"\b\d\d:\d\d:\d\d\.\d{3,6}\b"), "<CLOCK>"),
    # measured times: response times (min / mean / max) of a poll and of diag's round
    # trips, how long a dump or a scan took, when a poll tries to connect again
    (re.compile(rf"\b(min|mean|max|p95) {NUMBER} ?{UNIT}\b"), r"\1 <DUR>"),
    (re.compile(rf"\b(over|in) {NUMBER} ?{UNIT}\b"), r"\1 <DUR>"),
    (re.compile(r'"((?:min|mean|max|p95|queued|response_time)_(?:us|ms))":\s*\d+(?:\.\d+)?'), r'"\1":<N>'),
    # A poll that cannot connect tries again on a timer of its own, so whether a given
    # poll makes an attempt (and fails with its reason) or finds the line still down
    # depends on timing: both say the same reason.
    (re.compile(r"not connected \((.*)\); trying again in <DUR>"), r"\1"),
    # The diagnostic echo (08/00) that brings a line back in step after a timeout carries
    # a fresh random value (and so its own CRC/LRC): masked in the -v trace.
    (re.compile(r"^(\[<T>\] [<>] (?:[0-9A-F]{2} )*?[0-9A-F]{2} 08 00 00)(?: [0-9A-F]{2})+$"), r"\1 <ECHO>"),
    (re.compile(r"^(\[<T>\] [<>] :[0-9A-F]{2}080000)[0-9A-F]+$"), r"\1<ECHO>"),
    # process ids
    (re.compile(r"\b(pid) \d+"), r"\1 <PID>"),
    (re.compile(r'"pid":\s*\d+'), '"pid":<PID>'),
]
BOX = re.compile(r"[│┆╭╰╞├┼┤]")


def normalise(data, place, root):
    """Text with what varies from run to run replaced by placeholders."""
    text = data.decode("utf-8", errors="replace")
    text = text.replace(os.path.join(place, "wd"), "<WD>").replace(place, "<PLACE>").replace(root, "<TMP>")
    lines = text.split("\n")
    table_changed = False
    for i, line in enumerate(lines):
        new = line
        for pattern, replacement in TIMING:
            new = pattern.sub(replacement, new)
        if new != line:
            if BOX.search(new):
                table_changed = True
            else:
                new = re.sub(r" {2,}", " ", new)  # columns aligned on a value that changed
        lines[i] = new
    if table_changed:  # a table's widths follow its values: compare it without its padding
        lines = [squeeze(line) if BOX.search(line) else line for line in lines]
    return "\n".join(lines)


def squeeze(line):
    line = re.sub(r"─+", "─", line)
    line = re.sub(r"═+", "═", line)
    return re.sub(r" {2,}", " ", line)


def excerpt(data, head=256 * 1024, tail=64 * 1024):
    """Of what a line run until stopped wrote (a poll with --poll 0 writes tens of MB a
    second), its first and last whole lines: enough to hold every kind it writes."""
    if len(data) <= head + tail:
        return data
    first = data[:head]
    last = data[-tail:]
    return first[:first.rfind(b"\n") + 1] + last[last.find(b"\n") + 1:]


def masked_lines(text):
    """For a line run until stopped: the distinct lines printed, digits masked. A last
    line without its end (cut by the kill) is left out."""
    lines = text.split("\n")
    if lines and not text.endswith("\n"):
        lines.pop()
    return "\n".join(sorted({re.sub(r"\d+", "#", line) for line in lines if line.strip()}))


def is_binary(data):
    if b"\x00" in data:
        return True
    try:
        data.decode("utf-8")
    except UnicodeDecodeError:
        return True
    return False


def compare(case, old, new, place, root):
    """The differences between two outcomes: a list of (what, old text, new text)."""
    diffs = []
    both_stopped = old.timed_out and new.timed_out
    if old.timed_out != new.timed_out:
        diffs.append(("ran until stopped", str(old.timed_out), str(new.timed_out)))
    elif not both_stopped and old.status != new.status:
        diffs.append(("exit status", str(old.status), str(new.status)))
    streams = [("stdout", old.stdout, new.stdout), ("stderr", old.stderr, new.stderr)]
    for name in sorted(set(old.files) | set(new.files)):
        streams.append((f"file {name}", old.files.get(name), new.files.get(name)))
    for what, a, b in streams:
        if a is None or b is None:
            diffs.append((what, "<absent>" if a is None else "<present>", "<absent>" if b is None else "<present>"))
            continue
        if a == b:
            continue
        if both_stopped:
            a, b = excerpt(a), excerpt(b)
        if is_binary(a) or is_binary(b):
            if not both_stopped:  # (a live capture's files hold the times it ran)
                diffs.append((what, f"<{len(a)} bytes>", f"<{len(b)} bytes, different>"))
            continue
        ta, tb = normalise(a, place, root), normalise(b, place, root)
        if both_stopped:
            ta, tb = masked_lines(ta), masked_lines(tb)
        if ta != tb:
            diffs.append((what, ta, tb))
    return diffs, both_stopped


def report(case, diffs, old, new, out):
    print(f"=== line {case.index}: differs", file=out)
    print(f"  $ {case.shell()}", file=out)
    if case.stdin is not None:
        preview = case.stdin[:200].decode("utf-8", errors="replace").replace("\n", "\\n")
        print(f"  stdin: {preview!r}", file=out)
    print(f"  old: status {old.status}{' (stopped)' if old.timed_out else ''}, {old.seconds:.2f} s; "
          f"new: status {new.status}{' (stopped)' if new.timed_out else ''}, {new.seconds:.2f} s", file=out)
    for what, a, b in diffs:
        if "\n" not in a and "\n" not in b and len(a) < 80 and len(b) < 80:
            print(f"  {what}: old {a!r}, new {b!r}", file=out)
            continue
        lines = list(difflib.unified_diff(a.splitlines(), b.splitlines(), f"old {what}", f"new {what}",
                                          n=1, lineterm=""))
        for line in lines[:30]:
            print("    " + line, file=out)
        if len(lines) > 30:
            print(f"    ... {len(lines) - 30} more diff lines", file=out)


# --------------------------------------------------------------------------------------
# Main.
# --------------------------------------------------------------------------------------


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("old", help="the binary of the build before")
    parser.add_argument("new", help="the binary of the build after")
    parser.add_argument("--lines", type=int, default=3000, help="how many lines to generate (3000)")
    parser.add_argument("--seed", default="1", help="the seed of the lines (1)")
    parser.add_argument("--jobs", type=int, default=2, help="lines run at once (2)")
    parser.add_argument("--timeout", type=float, default=3.0, help="seconds a process may run (3)")
    parser.add_argument("--forever-timeout", type=float, default=1.0,
                        help="seconds for a line meant to run until stopped (1)")
    parser.add_argument("--line", type=int, help="run this line alone")
    parser.add_argument("--list", action="store_true", help="print the lines, run nothing")
    parser.add_argument("--keep", action="store_true", help="keep the temporary directory")
    args = parser.parse_args()

    binaries = [os.path.abspath(args.old), os.path.abspath(args.new)]
    for binary in binaries:
        if not os.access(binary, os.X_OK):
            sys.exit(f"compare_cli: {binary} is not an executable")
    generator = Generator(args.seed)
    indices = [args.line] if args.line is not None else list(range(args.lines))
    cases = [generator.case(i) for i in indices]
    for case in cases:
        case.help = case.help or is_help(case.argv)
    if args.list:
        for case in cases:
            flags = "".join(["h" if case.help else "", "x" if case.exclusive else "", "f" if case.forever else ""])
            print(f"{case.index:5} {flags:3} {case.shell()}")
        return 0

    fixtures = load_fixtures()
    root = tempfile.mkdtemp(prefix="compare_cli.")
    gate = Gate()
    results = {}
    done = threading.Condition()
    queue = list(enumerate(cases))
    queue_lock = threading.Lock()
    started = time.monotonic()

    def worker(number):
        while True:
            with queue_lock:
                if not queue:
                    return
                position, case = queue.pop(0)
            if case.help:
                result = ("help",)
            else:
                place = os.path.join(root, f"w{number}")
                timeout = args.forever_timeout if case.forever else args.timeout
                try:
                    gate.enter(case.exclusive)
                    try:
                        old = run(binaries[0], case, place, fixtures, timeout)
                        new = run(binaries[1], case, place, fixtures, timeout)
                    finally:
                        gate.leave(case.exclusive)
                    diffs, stopped = compare(case, old, new, place, root)
                    result = ("run", diffs, stopped, old if diffs else None, new if diffs else None)
                except Exception as error:  # a fault of this script, told as the line's
                    result = ("error", f"{type(error).__name__}: {error}")
            with done:
                results[position] = result
                done.notify_all()

    threads = [threading.Thread(target=worker, args=(n,), daemon=True) for n in range(max(1, args.jobs))]
    for thread in threads:
        thread.start()
    differ = helped = stopped_both = 0
    try:
        for position, case in enumerate(cases):
            with done:
                done.wait_for(lambda: position in results)
                result = results.pop(position)
            if result[0] == "help":
                helped += 1
                continue
            if result[0] == "error":
                differ += 1
                print(f"=== line {case.index}: could not be compared: {result[1]}\n  $ {case.shell()}")
                continue
            _, diffs, stopped, old, new = result
            stopped_both += stopped
            if diffs:
                differ += 1
                report(case, diffs, old, new, sys.stdout)
                sys.stdout.flush()
        for thread in threads:
            thread.join()
    except KeyboardInterrupt:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        STOPPING.set()
        with queue_lock:
            queue.clear()
        deadline = time.monotonic() + 5
        while any(thread.is_alive() for thread in threads) and time.monotonic() < deadline:
            for pid in list(RUNNING):
                signal_group(pid, signal.SIGKILL)
            time.sleep(0.05)
        shutil.rmtree(root, ignore_errors=True)
        print("interrupted", file=sys.stderr)
        return 130
    if not args.keep:
        shutil.rmtree(root, ignore_errors=True)
    else:
        print(f"kept {root}")
    elapsed = time.monotonic() - started
    print(f"({stopped_both} lines both ran until stopped; {elapsed:.1f} s)")
    print(f"{len(cases)} lines, {differ} differ, {helped} help lines skipped")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
