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

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# --------------------------------------------------------------------------------------
# Fixture files, written into every working directory before each run.
# --------------------------------------------------------------------------------------

PUMP3_CSV = """\
# Pump station 3: the points of pump3.txt by name.
name,ref,type,scale,unit,access,description
voltage,400001,f32,,V,r,mains voltage
speed,400003,u16,,rpm,rw,pump speed
pressure_max,400020,u16,0.1,bar,rw,trip pressure
running,000001,bool,,,rw,pump contactor
flow,300001,i16,0.5,m3/h,r,outlet flow
"""

PUMP3_TXT = """\
# Pump station 3, as serve --data reads it: the addresses that exist and their values.
400001 = 230.5 f32           # setpoint, two registers
400003 = 1450                # speed, rpm
400004-400010 = 0            # one value for the whole range
400020-400025 = 10 20 30 40 50 60
000001-000008 = on off on on off off off off
300001-300004 = 9
"""

DUMP_TXT = """\
# mbtool dump of slave 17 from the built-in slave (sim), 2026-01-01 00:00:00 UTC
400100 = 0 0 0 0 0 0 0 0 555 0 100
000020 = 1 0 1 1 0 0 1 1
400001 = 3.14 f32
400020 = "PUMP 1" ascii
"""

BAD_TXT = """\
400001 = 1 2 3
400002 = 5                   # named twice
400010-400005 = 1
000001 = maybe
399999 = 1
"""

BAD_CSV = """\
name,ref,type,scale
speed,400003,u16,0
speed,400004,u16,1
temp,300001,f32,
wide,000001,u32,1
"""

PLANT_YAML = """\
modbus:
  - name: hub1
    type: tcp
    host: 127.0.0.1
    port: 1
    sensors:
      - name: temp
        address: 107
        slave: 17
        data_type: int16
        scale: 0.1
        precision: 1
        unit_of_measurement: "C"
      - name: level
        address: 8
        input_type: input
        slave: 17
      - name: total
        address: 0
        slave: 17
        data_type: uint32
    switches:
      - name: pump
        address: 19
        slave: 17
        write_type: coil
    binary_sensors:
      - name: alarm
        address: 196
        slave: 17
        input_type: discrete_input
"""

SERIAL_YAML = """\
modbus:
  name: line
  type: serial
  port: /dev/ttyNOPE
  baudrate: 9600
  bytesize: 8
  method: rtu
  parity: N
  stopbits: 1
  sensors:
    - name: speed
      address: 2
      slave: 17
      scale: !secret speed_scale
"""

BAD_PEM = "-----BEGIN CERTIFICATE-----\nnot a certificate\n-----END CERTIFICATE-----\n"

TEXT_FIXTURES = {
    "pump3.csv": PUMP3_CSV,
    "pump3.txt": PUMP3_TXT,
    "dump.txt": DUMP_TXT,
    "bad.txt": BAD_TXT,
    "bad.csv": BAD_CSV,
    "empty.txt": "",
    "plant.yaml": PLANT_YAML,
    "serial.yaml": SERIAL_YAML,
    "bad.pem": BAD_PEM,
    "root/sys/class/tty/.keep": "",
    "root/dev/.keep": "",
    "root/proc/.keep": "",
}

# Real captures from the repository, when they are there (the same bytes for both).
REPO_FIXTURES = {
    "wizmodbus.bin": "tests/captures/wizmodbus.bin",
    "brainchild.bin": "tests/captures/brainchild-io-16do.bin",
    "modbus-tcp.pcap": "tests/captures/modbus-tcp.pcap",
}


def load_fixtures():
    files = {name: text.encode() for name, text in TEXT_FIXTURES.items()}
    for name, path in REPO_FIXTURES.items():
        full = os.path.join(REPO, path)
        if os.path.exists(full):
            with open(full, "rb") as f:
                files[name] = f.read()
    return files


# --------------------------------------------------------------------------------------
# Modbus frames, to give decode, sniff and raw something real to chew on.
# --------------------------------------------------------------------------------------


def crc16(data):
    crc = 0xFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return bytes([crc & 0xFF, crc >> 8])


def lrc(data):
    return (-sum(data)) & 0xFF


def random_pdu(rng):
    """A request or response PDU, mostly well formed."""
    fn = rng.choice([1, 2, 3, 4, 5, 6, 15, 16, 3, 3, 1, 7, 8, 11, 17, 22, 23, 43, 0x83, 0x81, 0x41, 0])
    addr = rng.choice([0, 19, 107, 196, 8, 65535, rng.randrange(65536)])
    count = rng.choice([1, 2, 3, 8, 125, 126, 2000, 0])
    b = lambda *xs: bytes(xs)  # noqa: E731
    w = lambda v: bytes([(v >> 8) & 0xFF, v & 0xFF])  # noqa: E731
    kind = rng.random()
    if fn in (1, 2, 3, 4):
        if kind < 0.5:
            return b(fn) + w(addr) + w(count)
        n = rng.choice([1, 2, 3, 6])
        return b(fn, n) + bytes(rng.randrange(256) for _ in range(n))
    if fn in (5, 6):
        value = rng.choice([0xFF00, 0x0000, 0x0004, 555, rng.randrange(65536)])
        return b(fn) + w(addr) + w(value)
    if fn in (15, 16):
        if kind < 0.3:
            return b(fn) + w(addr) + w(count)
        n = rng.choice([1, 2, 3])
        size = n * 2 if fn == 16 else (n + 7) // 8
        return b(fn) + w(addr) + w(n) + b(size) + bytes(rng.randrange(256) for _ in range(size))
    if fn == 8:
        return b(8) + w(rng.choice([0, 0x0A, 0x0B, 0x0E, 0x12, 0x55])) + w(0x1234)
    if fn == 22:
        return b(22) + w(addr) + w(0xFFFB) + w(0x0004)
    if fn == 23:
        return b(23) + w(addr) + w(2) + w(addr) + w(1) + b(2) + w(42)
    if fn == 43:
        return b(43, 14, rng.choice([1, 2, 3, 4]), 0)
    if fn & 0x80:
        return b(fn, rng.choice([1, 2, 3, 4, 0x0B]))
    if fn in (7, 11, 17):
        return b(fn) if kind < 0.6 else b(fn, 0xFF, 0xFF, 1, 8)
    return b(fn) + bytes(rng.randrange(256) for _ in range(rng.randrange(6)))


def random_frame_bytes(rng, mode="rtu"):
    slave = rng.choice([17, 17, 1, 5, 0, 247, 255])
    adu = bytes([slave]) + random_pdu(rng)
    if mode == "tcp":
        pdu_len = len(adu)
        return bytes([0, rng.randrange(1, 5), 0, 0, 0, pdu_len]) + adu
    frame = adu + crc16(adu)
    if rng.random() < 0.12:  # a bad checksum
        frame = frame[:-1] + bytes([frame[-1] ^ 0x01])
    return frame


def random_frame_text(rng):
    """A frame in one of the spellings decode accepts, or something that is not one."""
    r = rng.random()
    if r < 0.08:
        return rng.choice(["zz", "11 03 0", "# a comment", "0x", "hello world", "11 03 GG", "::", "[11][03]"])
    if r < 0.2:
        adu = bytes([rng.choice([17, 1])]) + random_pdu(rng)
        return ":" + (adu + bytes([lrc(adu)])).hex().upper()
    mode = "tcp" if r < 0.3 else "rtu"
    frame = random_frame_bytes(rng, mode)
    style = rng.randrange(6)
    if style == 0:
        return " ".join(f"{x:02X}" for x in frame)
    if style == 1:
        return frame.hex().upper()
    if style == 2:
        return ",".join(f"0x{x:02x}" for x in frame)
    if style == 3:
        return ":".join(f"{x:02x}" for x in frame)
    if style == 4:
        return "".join(f"[{x:02X}]" for x in frame)
    return "{" + ", ".join(f"0x{x:02X}" for x in frame) + "}"


def random_log_text(rng):
    """Lines for decode's standard input: frames as logs write them."""
    lines = []
    for _ in range(rng.randint(0, 8)):
        frame = random_frame_text(rng)
        style = rng.randrange(10)
        if style == 0:
            lines.append(f"[    0.{rng.randrange(10**6):06d}] {rng.choice('><')} {frame}")
        elif style == 1:
            lines.append(f"{rng.randrange(10**6):06d}-{rng.choice(['Tx', 'Rx'])}:{frame}")
        elif style == 2:
            lines.append(f"{rng.choice(['TX', 'RX', 'SEND:', 'recv:'])} {frame}")
        elif style == 3:
            lines.append(rng.choice(["", "# comment", "Waiting for a confirmation...", "   "]))
        elif style == 4:
            lines.append(f"0000   {frame.lower()}   ....")
        else:
            lines.append(frame)
    text = "\n".join(lines) + ("\n" if lines and rng.random() < 0.8 else "")
    data = text.encode()
    if rng.random() < 0.03:
        data += b"11 03 \x00 6B\n"  # a NUL byte: a binary file
    elif rng.random() < 0.02:
        data = b"\xff\xfe" + text.encode("utf-16-le")  # a log saved as UTF-16
    return data


def random_capture(rng):
    """Raw RTU bytes of a bus: frames, now and then noise."""
    out = b""
    for _ in range(rng.randint(0, 12)):
        if rng.random() < 0.15:
            out += bytes(rng.choice([0x00, 0xFE, rng.randrange(256)]) for _ in range(rng.randint(1, 3)))
        out += random_frame_bytes(rng)
    return out


def random_timing(rng, size):
    """A .timing file for a capture of `size` bytes, as sniff --save writes it."""
    lines = []
    if rng.random() < 0.7:
        lines.append(f"# line: {rng.choice(['rtu', 'ascii', 'tcp'])} {rng.choice([9600, 19200, 49])} "
                     f"{rng.choice(['8N2', '8E1', '7E1', '8X1'])}")
    t, left = 0, size
    while left > 0:
        n = min(left, rng.randint(1, 9))
        t += rng.randint(100, 5000)
        lines.append(f"{t} {n}")
        left -= n
        if rng.random() < 0.2:
            t += 20000
            lines.append(f"{t} idle")
    if rng.random() < 0.8:
        lines.append(f"{t + 1000} end")
    if rng.random() < 0.1:
        lines.append("12x bad")
    return ("\n".join(lines) + "\n").encode()


# --------------------------------------------------------------------------------------
# The grammar: values, options, commands.
# --------------------------------------------------------------------------------------


class LineRandom(random.Random):
    """The random source of one line; a clean line makes no mistakes on purpose, and
    `ports` are the TCP ports the line may listen on."""
    clean = False
    ports = ()


def pick(rng, good, bad=(), p_bad=0.05):
    """A value from `good`, or now and then (never on a clean line) from `bad`."""
    if bad and not rng.clean and rng.random() < p_bad:
        return rng.choice(list(bad))
    return rng.choice(list(good))


# Ports a master may be pointed at: nothing beyond 127.0.0.1, no real serial device.
# 127.0.0.1:1 and :502 have nothing listening: serve and gateway never listen there.
MASTER_PORTS_GOOD = ["sim"] * 14 + ["tcp://127.0.0.1:1", "127.0.0.1:1", "rtu+tcp://127.0.0.1:1",
                                    "tls://127.0.0.1:1", "/dev/ttyNOPE", "tcp://127.0.0.1"]
MASTER_PORTS_BAD = ["", "COM3", "tcp://127.0.0.1:99999", "tcp://127.0.0.1:x", "udp://127.0.0.1:1",
                    "tcp://", "sim:1", "tls://127.0.0.1:1:2", "rtu+tcp://127.0.0.1"]
# serve and gateway listen on 127.0.0.1 only, on two ports of their line's own
# (LineRandom.ports): two lines that run at once never want the same port, so they need
# not run alone. Below the ephemeral range, and not 5020, which other tests may be using.

DURATIONS_BAD = ["500", "fast", "0", "-1s", "61", "1h", "ms", "1.5.2s", ""]
TYPES = ["u16", "i16", "u32", "i32", "f32", "u64", "i64", "f64", "hex", "bin", "ascii"]
TYPES_BAD = ["float", "4:float", "4", "U16", "u8", "0"]
ORDERS = ["ABCD", "CDAB", "BADC", "DCBA"]
ORDERS_BAD = ["abcd", "XYZW", "AB", "DCAB"]


def v_port(rng, cmd):
    if cmd == "serve":  # where serve listens
        return v_listen_port(rng, cmd)
    return pick(rng, MASTER_PORTS_GOOD, MASTER_PORTS_BAD)


def v_listen_port(rng, cmd):
    if rng.random() < 0.85:
        return "tcp://:" + rng.choice(rng.ports)
    return rng.choice(["tcp://127.0.0.1:" + rng.choice(rng.ports), "sim", "/dev/ttyNOPE",
                       "tls://127.0.0.1:" + rng.choice(rng.ports), "rtu+tcp://127.0.0.1:" + rng.choice(rng.ports),
                       "tcp://:99999", "udp://:" + rng.choice(rng.ports), ""])


def v_mode(rng, cmd):
    return pick(rng, ["rtu", "ascii", "tcp", "rtu"], ["RTU", "modbus", "", "ascii,rtu"])


def v_baud(rng, cmd):
    good = ["9600", "19200", "115200", "38400", "1200"]
    if cmd == "scan":
        good += ["9600,19200", "9600,19200,38400", "19200,115200"]
    return pick(rng, good, ["fast", "0", "-1", "12.5", "9600,", "9600,19200"])


def v_parity(rng, cmd):
    good = ["none", "even", "odd"]
    if cmd == "scan":
        good += ["none,even", "none,even,odd"]
    return pick(rng, good, ["e", "mark", "N", "none,even", ""])


def v_timeout(rng, cmd):
    # Short: a line's real waits (a secondary path, dump and restore asking again) are
    # multiples of it, and must stay well inside the process timeout.
    return pick(rng, ["50ms", "100ms", "200ms", "20ms", "0.1"], DURATIONS_BAD)


def v_switch_on(rng, cmd):
    return pick(rng, ["timeout:3,disconnect", "timeout:1", "bad-frame:2", "exception:0B", "disconnect",
                      "timeout:1,bad-frame:1,exception:0A"],
                ["timeout:x", "foo", "exception:ZZ", "timeout:0", ""], 0.3)


def v_dump_output(rng, cmd):
    if cmd == "dump":
        return pick(rng, ["out.txt", "dump2.txt", "pump3.txt", "sub/out.txt"], ["", "root", "json"], 0.15)
    return pick(rng, ["table", "json", "values", "csv"], ["xml", "JSON", "", "tabel"])


def v_count(rng, cmd):
    if cmd == "diag":
        return pick(rng, ["1", "3", "5", "20"], ["0", "-1", "x", "100001"])
    return pick(rng, ["1", "2", "3", "5"], ["0", "-1", "x"])


def v_poll(rng, cmd):
    return pick(rng, ["0", "0", "10ms", "20ms", "50ms", "100ms", "300ms"], ["fast", "500", "-1", "0s0", ""])


def v_log(rng, cmd):
    return pick(rng, ["log.csv", "log.jsonl", "log.txt"], ["sub/log.csv", "root", ""], 0.15)


def v_map(rng, cmd):
    return pick(rng, ["pump3.csv", "pump3.csv", "plant.yaml", "serial.yaml"],
                ["bad.csv", "nope.csv", "pump3.txt", "empty.txt", "root"], 0.25)


def v_function(rng, cmd):
    if cmd == "sniff":
        return pick(rng, ["3", "0x10", "1", "6", "43"], ["x", "256", "-1"])
    return pick(rng, ["5", "6", "15", "16"], ["3", "x", "0x10"])


def v_slave_id(rng, cmd):
    return pick(rng, ["17", "1", "5", "18", "247"], ["0", "256", "x", "-1"])


def v_rate(rng, cmd):
    return pick(rng, ["5%", "0.5", "0", "1", "100%"], ["2", "x", "-1%", "150%"])


def v_exception(rng, cmd):
    return pick(rng, ["2@400100-400120", "4", "1", "2@400108", "11@300009", "2@000020-000030"],
                ["x", "2@", "@400001", "0", "256"], 0.25)


def v_role(rng, cmd):
    return pick(rng, ["operator=read,write:400001-400100", "viewer=read", "admin=read,write",
                      "tech=write:000001-000010"], ["viewer", "=read", "x=fly", "viewer=read:zz"], 0.25)


def v_identity(rng, cmd):
    return pick(rng, ["VendorUrl=https://example.com", "ProductName=Pump", "0x80=serial 4711",
                      "ModelName=M1"], ["Nope=1", "0x07", "=x", "0x100=x"], 0.25)


def v_listen(rng, cmd):
    if cmd == "scan":
        return pick(rng, ["100ms", "1s", "50ms"], ["x", "-1"])
    if rng.random() < 0.8:
        return "tcp://:" + rng.choice(rng.ports)
    return rng.choice(["tls://:" + rng.choice(rng.ports), "tcp://127.0.0.1:" + rng.choice(rng.ports), "udp://:1502",
                       "tcp://:99999", "sim", "", ":" + rng.choice(rng.ports)])


def v_input(rng, cmd):
    return pick(rng, ["wizmodbus.bin", "brainchild.bin", "modbus-tcp.pcap", "cap.bin", "cap.bin", "-"],
                ["nope.bin", "empty.txt", "pump3.txt", "root"], 0.2)


def v_interface(rng, cmd):
    return pick(rng, ["nope0", "nope0", "lo"], ["", "nope0:1"], 0.2)


@dataclass
class Opt:
    long: str
    short: str = ""
    values: object = None  # None: a flag; else a function (rng, cmd) -> str


def values(*good, bad=(), p_bad=0.05):
    return lambda rng, cmd: pick(rng, good, bad, p_bad)


OPTIONS = {o.long: o for o in [
    # Connection
    Opt("--port", "-p", v_port),
    Opt("--mode", "-m", v_mode),
    Opt("--baud", "-b", v_baud),
    Opt("--parity", "", v_parity),
    Opt("--data-bits", "", values("7", "8", bad=["5", "9", "x", ""])),
    Opt("--stop-bits", "", values("1", "2", bad=["0", "3", "1.5"])),
    Opt("--timeout", "", v_timeout),
    Opt("--retries", "", values("0", "1", "2", bad=["-1", "x", "many"])),
    Opt("--retry-non-idempotent"),
    Opt("--frame-gap", "", values("0", "2ms", "1.75ms", "5ms", bad=["x", "-1ms", "500"])),
    Opt("--rs485"),
    Opt("--rs485-delay-before", "", values("0", "5", "100", bad=["101", "-1", "x", "1ms"])),
    Opt("--rs485-delay-after", "", values("0", "5", "100", bad=["101", "-1", "x"])),
    Opt("--rts-level", "", values("high", "low", bad=["up", "HIGH", ""])),
    Opt("--rts-toggle"),
    # Output
    Opt("--output", "-o", v_dump_output),
    Opt("--json"),
    Opt("--verbose", "-v"),
    # Addresses and values
    Opt("--pdu-addresses"),
    Opt("--address-base", "", values("0", "1", bad=["2", "-1", "one"])),
    Opt("--type", "-t", values(*TYPES, bad=TYPES_BAD)),
    Opt("--order", "", values(*ORDERS, bad=ORDERS_BAD)),
    Opt("--max-per-request", "", values("1", "2", "3", "10", "125", bad=["0", "-1", "x", "2001", "70000"])),
    # Watching
    Opt("--poll", "", v_poll),
    Opt("--count", "", v_count),
    Opt("--log", "", v_log),
    # Redundancy
    Opt("--secondary-port", "", values("tcp://127.0.0.1:1", "/dev/ttyNOPE", "rtu+tcp://127.0.0.1:1",
                                       bad=["sim", "sim", "", "udp://127.0.0.1:1"], p_bad=0.15)),
    Opt("--secondary-baud", "", values("9600", "19200", bad=["x", "0"])),
    Opt("--secondary-parity", "", values("none", "even", "odd", bad=["x"])),
    Opt("--secondary-data-bits", "", values("7", "8", bad=["9"])),
    Opt("--secondary-stop-bits", "", values("1", "2", bad=["3"])),
    Opt("--secondary-mode", "", values("rtu", "ascii", "tcp", bad=["x"])),
    Opt("--switch-on", "", v_switch_on),
    Opt("--switch-when", "", values("any", "all", bad=["some", ""])),
    # TLS
    Opt("--cert", "", values("nope.pem", "bad.pem", "empty.txt", bad=[""])),
    Opt("--key", "", values("nope.pem", "bad.pem", "empty.txt")),
    Opt("--ca", "", values("nope.pem", "bad.pem", "empty.txt")),
    Opt("--tls-server-name", "", values("plc1", "plc1.plant.local", "127.0.0.1", bad=["", "bad name"])),
    # read, write, watch
    Opt("--map", "", v_map),
    Opt("--function", "", v_function),
    # scan
    Opt("--ids", "", values("1-20", "17", "1-10,17,200", "15-18", "1-247", "16,17,18",
                            bad=["0-300", "x", "20-1", "", "248"])),
    Opt("--probe", "", values("read", "id", bad=["ping", ""])),
    Opt("--listen", "", v_listen),
    Opt("--all"),
    # diag, restore
    Opt("--clear"),
    Opt("--dry-run"),
    # decode
    Opt("--direction", "", values("request", "response", bad=["req", "both", ""])),
    # sniff
    Opt("--input", "", v_input),
    Opt("--interface", "", v_interface),
    Opt("--tcp-port", "", values("502", "5020", "1502", bad=["x", "70000", "0"])),
    Opt("--save", "", values("save.bin", "sub/save.bin", "cap.bin")),
    Opt("--pcap", "", values("out.pcap", "sub/out.pcap")),
    Opt("--stats"),
    Opt("--slave", "", v_slave_id),
    Opt("--low-latency"),
    # serve
    Opt("--data", "", values("pump3.txt", "dump.txt", "bad.txt", "nope.txt", "empty.txt", "pump3.csv")),
    Opt("--read-only", "", values("400001-400010", "000020", "400108", bad=["x", "400010-400001"])),
    Opt("--delay", "", values("10ms", "200ms", "0", bad=["x", "500"])),
    Opt("--drop", "", v_rate),
    Opt("--corrupt", "", v_rate),
    Opt("--exception", "", v_exception),
    Opt("--garbage"),
    Opt("--seed", "", values("1", "42", "0", bad=["x", "-1"])),
    Opt("--quiet", "-q"),
    Opt("--role", "", v_role),
    Opt("--default-role", "", values("viewer", "operator", bad=[""])),
    Opt("--plain-role", "", values("viewer", "operator", bad=[""])),
    Opt("--vendor", "", values("ACME", "mbtool", "Pump Works", bad=[""])),
    Opt("--product-code", "", values("P-1", "mbtool-sim", bad=[""])),
    Opt("--identity", "", v_identity),
    # gateway
    Opt("--unit-map", "", values("1=17,2=18", "1=17", "5=17", bad=["x", "1=", "1=300", "1:17"])),
    Opt("--broadcast-reply"),
    # ports
    Opt("--root", "", values("root", "/nonexist", ".", bad=["", "pump3.txt"])),
]}

# mbpoll's and modpoll's options, typed out of habit (refused with advice).
HABITS = [["-a", "17"], ["-r", "1"], ["-c", "2"], ["-t", "4:float"], ["-t", "0"], ["-1"], ["-l", "1000"],
          ["-P", "none"], ["-0"], ["-R"], ["-F"], ["-a", "17", "-r", "1", "-c", "2"], ["-t", "3"]]

CONN = ["--port", "--mode", "--baud", "--parity", "--data-bits", "--stop-bits", "--rs485",
        "--rs485-delay-before", "--rs485-delay-after", "--rts-level", "--rts-toggle"]
MASTER = ["--timeout", "--retries", "--frame-gap"]
RNI = ["--retry-non-idempotent"]
OUT = ["--output", "--json", "--verbose"]
ADDR = ["--pdu-addresses", "--address-base"]
VALUE_TYPES = ["--type", "--order"]
MPR = ["--max-per-request"]
POLL = ["--poll", "--count", "--log"]
SECONDARY = ["--secondary-port", "--secondary-baud", "--secondary-parity", "--secondary-data-bits",
             "--secondary-stop-bits", "--secondary-mode", "--switch-on", "--switch-when"]
TLS = ["--cert", "--key", "--ca", "--tls-server-name"]

# The options each command takes, as its --help lists them: first its own (under
# "Options:", which must come after the command name), then the global ones (which
# may stand before or after it).
OWN = {
    "read": ["--map"],
    "write": ["--map", "--function"],
    "scan": ["--ids", "--probe", "--listen", "--all"],
    "watch": ["--map", "--poll"],
    "diag": ["--clear", "--count"],
    "dump": ["--output"],
    "restore": ["--dry-run"],
    "decode": ["--direction"],
    "sniff": ["--input", "--interface", "--tcp-port", "--save", "--pcap", "--stats", "--slave", "--function",
              "--low-latency"],
    "serve": ["--slave", "--data", "--read-only", "--delay", "--drop", "--corrupt", "--exception", "--garbage",
              "--seed", "--quiet", "--role", "--default-role", "--plain-role", "--vendor", "--product-code",
              "--identity"],
    "gateway": ["--listen", "--unit-map", "--broadcast-reply", "--quiet", "--role", "--default-role",
                "--plain-role", "--log"],
    "ports": ["--root"],
}
GLOBAL_TAKEN = {
    "read-coils": CONN + MASTER + OUT + ADDR + MPR + POLL + SECONDARY + TLS,
    "read-inputs": CONN + MASTER + OUT + ADDR + MPR + POLL + SECONDARY + TLS,
    "read-holding": CONN + MASTER + OUT + ADDR + VALUE_TYPES + MPR + POLL + SECONDARY + TLS,
    "read-input-registers": CONN + MASTER + OUT + ADDR + VALUE_TYPES + MPR + POLL + SECONDARY + TLS,
    "read": CONN + MASTER + OUT + ADDR + VALUE_TYPES + MPR + POLL + SECONDARY + TLS,
    "write-coil": CONN + MASTER + OUT + ADDR + TLS,
    "write-coils": CONN + MASTER + OUT + ADDR + MPR + TLS,
    "write-register": CONN + MASTER + RNI + OUT + ADDR + VALUE_TYPES + TLS,
    "write-registers": CONN + MASTER + OUT + ADDR + VALUE_TYPES + MPR + TLS,
    "write": CONN + MASTER + RNI + OUT + ADDR + VALUE_TYPES + MPR + TLS,
    "raw": CONN + MASTER + RNI + OUT + VALUE_TYPES + TLS,
    "scan": CONN + ["--timeout", "--frame-gap"] + OUT + TLS,
    "watch": CONN + MASTER + ADDR + VALUE_TYPES + MPR + SECONDARY + TLS,
    "info": CONN + MASTER + OUT + TLS,
    "diag": CONN + MASTER + OUT + TLS,
    "dump": CONN + MASTER + ["--verbose"] + MPR + SECONDARY + TLS,
    "restore": CONN + MASTER + ["--verbose"] + MPR + SECONDARY + TLS,
    "decode": ["--mode", "--output", "--json", "--type", "--order"],
    "sniff": CONN + ["--output", "--json"],
    "serve": CONN + ["--output", "--json"] + TLS,
    "gateway": CONN + MASTER + RNI + OUT + TLS,
    "ports": ["--output", "--json"],
}
TAKES = {cmd: OWN.get(cmd, []) + GLOBAL_TAKEN[cmd] for cmd in GLOBAL_TAKEN}

# How likely an option is drawn among those a command takes (1 unless said here):
# options that only make sense with another are rarer, and bring it along.
RARITY = {**{o: 0.1 for o in TLS}, "--rs485": 0.08, "--rts-toggle": 0.08, "--rs485-delay-before": 0.08,
          "--rs485-delay-after": 0.08, "--rts-level": 0.08,
          **{o: 0.3 for o in SECONDARY if o != "--secondary-port"}}
COMPANIONS = {"--rs485-delay-before": ["--rs485", "--rts-toggle"], "--rs485-delay-after": ["--rs485", "--rts-toggle"],
              "--rts-level": ["--rs485", "--rts-toggle"],
              **{o: ["--secondary-port"] for o in SECONDARY if o != "--secondary-port"},
              "--log": ["--poll"], "--count": ["--poll"]}

# encode REQUEST-COMMAND: the options of each request command under encode.
ENCODE_BASE = ["--port", "--mode", "--output", "--json"]
ENCODE_TAKES = {
    "read-coils": ENCODE_BASE + ADDR + MPR,
    "read-inputs": ENCODE_BASE + ADDR + MPR,
    "read-holding": ENCODE_BASE + ADDR + VALUE_TYPES + MPR,
    "read-input-registers": ENCODE_BASE + ADDR + VALUE_TYPES + MPR,
    "read": ["--map"] + ENCODE_BASE + ADDR + VALUE_TYPES + MPR,
    "write-coil": ENCODE_BASE + ADDR,
    "write-coils": ENCODE_BASE + ADDR + MPR,
    "write-register": ENCODE_BASE + RNI + ADDR + VALUE_TYPES,
    "write-registers": ENCODE_BASE + ADDR + VALUE_TYPES + MPR,
    "write": ["--map", "--function"] + ENCODE_BASE + RNI + ADDR + VALUE_TYPES + MPR,
    "raw": ENCODE_BASE + RNI + VALUE_TYPES,
}

ENCODE_OWN = {"read": ["--map"], "write": ["--map", "--function"]}

ALIASES = {
    "read-inputs": ["read-discrete-inputs"],
    "read-holding": ["read-holding-registers"],
    "read-input-registers": ["read-input-regs"],
}

# How often each command is drawn.
WEIGHTS = {
    "read-holding": 10, "read-coils": 5, "read-inputs": 4, "read-input-registers": 4, "read": 8,
    "write-coil": 4, "write-coils": 4, "write-register": 4, "write-registers": 4, "write": 7, "raw": 5,
    "scan": 4, "watch": 3, "info": 3, "diag": 3, "dump": 4, "restore": 4, "decode": 9, "encode": 9,
    "sniff": 6, "serve": 3, "gateway": 3, "ports": 2,
}

# Commands that talk to a device through --port.
BUS_COMMANDS = {"read-coils", "read-inputs", "read-holding", "read-input-registers", "read", "write-coil",
                "write-coils", "write-register", "write-registers", "write", "raw", "scan", "watch", "info",
                "diag", "dump", "restore"}

# MBTOOL_* variables: (name, good values, bad values).
ENVIRONMENT = [
    ("MBTOOL_PORT", ["sim", "sim", "sim", "tcp://127.0.0.1:1", "/dev/ttyNOPE"], ["", "udp://127.0.0.1:1", "COM3"]),
    ("MBTOOL_BAUD", ["9600", "19200"], ["fast", "0"]),
    ("MBTOOL_PARITY", ["none", "even", "odd"], ["mark", ""]),
    ("MBTOOL_DATA_BITS", ["7", "8"], ["9"]),
    ("MBTOOL_STOP_BITS", ["1", "2"], ["3"]),
    ("MBTOOL_MODE", ["rtu", "ascii", "tcp"], ["x"]),
    ("MBTOOL_TIMEOUT", ["100ms", "50ms", "200ms"], ["500", "x"]),
    ("MBTOOL_RETRIES", ["0", "1"], ["-1"]),
    ("MBTOOL_ADDRESS_BASE", ["0", "1"], ["2"]),
    ("MBTOOL_RS485", ["1", "0", "true"], ["yes please"]),
    ("MBTOOL_RTS_TOGGLE", ["1", "0"], ["x"]),
    ("MBTOOL_RS485_DELAY_BEFORE", ["0", "10"], ["101"]),
    ("MBTOOL_RS485_DELAY_AFTER", ["0", "10"], ["x"]),
    ("MBTOOL_RTS_LEVEL", ["high", "low"], ["mid"]),
    ("MBTOOL_SECONDARY_PORT", ["tcp://127.0.0.1:1", "sim", "/dev/ttyNOPE"], [""]),
    ("MBTOOL_SECONDARY_BAUD", ["9600"], ["x"]),
    ("MBTOOL_SECONDARY_PARITY", ["none"], ["x"]),
    ("MBTOOL_SECONDARY_DATA_BITS", ["7"], ["x"]),
    ("MBTOOL_SECONDARY_STOP_BITS", ["2"], ["x"]),
    ("MBTOOL_SECONDARY_MODE", ["ascii"], ["x"]),
    ("MBTOOL_SWITCH_ON", ["timeout:1,disconnect"], ["timeout:x"]),
    ("MBTOOL_SWITCH_WHEN", ["any", "all"], ["some"]),
    ("MBTOOL_CERT", ["nope.pem", "bad.pem"], [""]),
    ("MBTOOL_KEY", ["nope.pem"], [""]),
    ("MBTOOL_CA", ["bad.pem"], [""]),
    ("MBTOOL_TLS_SERVER_NAME", ["plc1"], [""]),
    ("MBTOOL_NOT_AN_OPTION", ["1"], []),
]

# ----- positional arguments -----

SLAVES_GOOD = ["17"] * 14 + ["1", "5", "247", "0x11", "18"]
SLAVES_BAD = ["0", "0", "255", "255", "256", "-1", "x", "17.5", "", "0b"]

ADDRESSES = {
    "coil": (["000020", "20", "19", "0x13", "00020", "000020-000056", "000001", "1", "0", "65535",
              "000001-000010", "0b10011"],
             ["100197", "400108", "x", "-3", "000056-000020", "065537", "000020.1", "400108.05"]),
    "input": (["100197", "196", "100197-100218", "10197", "0", "100001", "100197-100199"],
              ["000020", "400108", "300009", "x", "100197.01"]),
    "inreg": (["300009", "8", "300009-300011", "300009.00", "30009", "300001", "300009.15"],
              ["400108", "000020", "x", "300009.16", "300011-300009"]),
    "holding": (["400108", "40108", "107", "0x6B", "0b1101011", "400108-400110", "400108.05", "400001",
                 "400002", "465536", "1", "400020", "400108.00"],
                ["465537", "400108.16", "000020", "x", "400110-400108", "300009", "1.5", "0x"]),
}
COMMAND_TABLE = {"read-coils": "coil", "read-inputs": "input", "read-input-registers": "inreg",
                 "read-holding": "holding", "write-coil": "coil", "write-coils": "coil",
                 "write-register": "holding", "write-registers": "holding"}
COUNTS_GOOD = ["1", "2", "3", "3", "10", "16", "125", "126", "2000", "250"]
COUNTS_BAD = ["0", "x", "-1", "65536", "2001", "1.5"]
COIL_VALUES = (["on", "off", "1", "0", "true", "false", "ON"], ["2", "yes", "x", "-1", ""])
REGISTER_VALUES = (["42", "-1", "65535", "555", "3.14", "0x2A", "0b101", "0", "-32768", "1e3", "PUMP"],
                   ["65536", "abc", "-32769", "", "1,5", "0xZZ"])
PDUS = ["03 00 6B 00 03", "03006B0003", "01 00 13 00 25", "02 00 C4 00 16", "04 00 08 00 01",
        "05 00 AC FF 00", "06 00 01 00 03", "0F 00 13 00 0A 02 CD 01", "10 00 01 00 02 04 00 0A 01 02",
        "16 00 6B FF FB 00 04", "17 00 6B 00 02 00 6B 00 01 02 00 2A", "2B 0E 01 00", "2B 0E 04 81",
        "08 00 00 12 34", "08 00 0B 00 00", "07", "0B", "11", "41 01 02", "00", "03 00 6B", "80 01"]
PDUS_BAD = ["zz", "", "03 0", "0x03 0x00 0x6B 0x00 0x03", "GG", "03 00 6B 00 03 extra"]
DUMP_RANGES = (["400001-400010", "000001-000010", "400100-400110", "300009", "100197-100218", "400108",
                "000020-000056", "400001-400300", "300001-300004", "465530-465536"],
               ["x", "400010-400001", "107", "500001", "400001-", "000001-400001"])
MAP_NAMES = ["voltage", "speed", "pressure_max", "running", "flow", "temp", "level", "pump", "alarm", "total",
             "nope"]
MAP_WRITES = ["pressure_max=2.5", "speed=1500", "running=on", "flow=3", "voltage=230", "pump=on", "pump=off",
              "temp=21.5", "nope=1", "speed", "speed=x", "speed=70000", "=1", "pressure_max=-1"]


@dataclass
class Case:
    """One generated line: what to run and how."""
    index: int
    argv: list
    env: dict
    stdin: bytes = None  # None: /dev/null
    files: dict = field(default_factory=dict)  # extra files for the working directory
    help: bool = False  # asks for help or the version: not run
    exclusive: bool = False  # runs alone (sniff --interface lo would hear the others)
    forever: bool = False  # meant to run until stopped
    clean: bool = False  # no mistakes made on purpose

    def shell(self):
        env = " ".join(f"{k}={shlex.quote(v)}" for k, v in sorted(self.env.items()))
        line = shlex.join(["mbtool", *self.argv])
        stdin = ""
        if self.stdin is not None:
            stdin = f"  < stdin ({len(self.stdin)} bytes)"
        return (env + " " if env else "") + line + stdin


SHORT = {o.short: o.long for o in OPTIONS.values() if o.short}


def option_name(words):
    """The long name of the option these words give (--port for -psim)."""
    word = words[0]
    if word.startswith("--"):
        return word.split("=")[0]
    return SHORT.get(word[:2], word)


def typo(rng, word):
    """A word with one slip of the fingers."""
    if len(word) < 3:
        return word + rng.choice("xs")
    i = rng.randrange(1, len(word) - 1)
    kind = rng.randrange(4)
    if kind == 0:
        return word[:i] + word[i + 1:]
    if kind == 1:
        return word[:i] + word[i + 1] + word[i] + word[i + 2:]
    if kind == 2:
        return word[:i] + word[i] + word[i:]
    return word[:i] + rng.choice("aeiorstln") + word[i + 1:]


class Generator:
    def __init__(self, seed):
        self.seed = seed

    def case(self, index):
        rng = LineRandom(f"{self.seed}:{index}")
        base = 20000 + index % 5000 * 2
        rng.ports = [str(base), str(base + 1)]
        case = Case(index=index, argv=[], env={})
        r = rng.random()
        rng.clean = case.clean = rng.random() < 0.4
        if r < 0.025:
            return self.help_line(rng, case)
        if r < 0.045:
            return self.unknown_command(rng, case)
        command = rng.choices(list(WEIGHTS), weights=list(WEIGHTS.values()))[0]
        self.build(rng, case, command)
        self.environment(rng, case)
        return case

    # ----- special lines -----

    def help_line(self, rng, case):
        cmd = rng.choice(list(WEIGHTS))
        forms = [[], ["-h"], ["--help"], ["help"], ["help", cmd], [cmd, "--help"], [cmd, "-h"],
                 ["-V"], ["--version"], [cmd, "-V"], ["--port", "sim"], ["encode"],
                 ["encode", rng.choice(list(ENCODE_TAKES)), "--help"], ["encode", "help"], ["-v"],
                 ["--json", "help", "read"]]
        case.argv = rng.choice(forms)
        case.help = True
        return case

    def unknown_command(self, rng, case):
        known = list(WEIGHTS) + [a for names in ALIASES.values() for a in names]
        word = rng.choice([typo(rng, rng.choice(known)), "foo", "reed", "get", "READ", "read_holding",
                           "serve2", "17", "--", "-", "sim"])
        rest = rng.choice([[], ["17", "400108"], ["--port", "sim", "17"]])
        if rng.random() < 0.5:
            case.argv = [word] + rest
        else:  # a typo under encode
            case.argv = ["encode", typo(rng, rng.choice(list(ENCODE_TAKES))), "17", "400108"]
        self.environment(rng, case)
        return case

    # ----- a command line -----

    def build(self, rng, case, command):
        name = command
        if command in ALIASES and rng.random() < 0.2:
            name = rng.choice(ALIASES[command])
        sub, sub_name = None, None
        if command == "encode":
            sub = rng.choice(list(ENCODE_TAKES))
            sub_name = sub
            if sub in ALIASES and rng.random() < 0.2:
                sub_name = rng.choice(ALIASES[sub])
        request = sub or command
        positionals = self.positionals(rng, case, request, command)

        # Mistakes in the arguments.
        m = 1.0 if rng.clean else rng.random()
        if m < 0.04 and positionals:
            positionals = positionals[:rng.randrange(len(positionals))]  # missing arguments
        elif m < 0.06:
            positionals = positionals + [rng.choice(["17", "extra", "400001", "--", "on"])]

        # The options: mostly those the command takes, now and then one it does not.
        takes = ENCODE_TAKES[sub] if sub else TAKES[command]
        options = []  # lists of words
        chosen = set()
        if command in BUS_COMMANDS and rng.random() < 0.85:
            port = "sim" if rng.random() < 0.82 else v_port(rng, command)
            options.append(self.spell(rng, OPTIONS["--port"], port))
            chosen.add("--port")
        elif command in ("serve", "gateway"):
            self.server_options(rng, case, command, options, chosen)
        elif command == "sniff":
            self.sniff_options(rng, case, options, chosen)
        elif command == "encode" and rng.random() < 0.3:
            port = rng.choice(["sim", "tcp://127.0.0.1:1", "/dev/ttyNOPE", "tls://127.0.0.1:1", "x"])
            options.append(self.spell(rng, OPTIONS["--port"], port))
            chosen.add("--port")
        own = ENCODE_OWN.get(sub, []) if sub else OWN.get(command, [])
        for _ in range(rng.choice([0, 1, 1, 2, 2, 3, 4, 6])):
            if rng.clean or rng.random() < 0.97:
                opt = OPTIONS[rng.choices(takes, [RARITY.get(o, 1) * (3 if o in own else 1) for o in takes])[0]]
            else:
                opt = rng.choice(list(OPTIONS.values()))
            if opt.long in chosen and (rng.clean or rng.random() < 0.95):
                continue
            picked = [opt]
            companions = [c for c in COMPANIONS.get(opt.long, []) if c not in chosen and opt.long not in own]
            if companions and len(companions) == len(COMPANIONS[opt.long]) and rng.random() < 0.7:
                picked.append(OPTIONS[rng.choice(companions)])
            for opt in picked:
                chosen.add(opt.long)
                value = opt.values(rng, request if command != "encode" else "encode") if opt.values else None
                options.append(self.spell(rng, opt, value))
        if not rng.clean and rng.random() < 0.02:
            options.append(rng.choice(HABITS))
        if not rng.clean and rng.random() < 0.025:  # a typo in an option's name
            opt = rng.choice(list(OPTIONS.values()))
            bad = "--" + typo(rng, opt.long[2:])
            options.append([bad] + ([opt.values(rng, request)] if opt.values else []))
        if not rng.clean and rng.random() < 0.01:
            options.append([rng.choice(["--bogus", "-x", "--", "---port", "-"])])

        # Bound how long a poll may last, as long as it is not meant to run forever.
        if "--poll" in chosen and command != "watch":
            if "--count" not in chosen and rng.random() < 0.8:
                options.append(["--count", rng.choice(["1", "2", "3"])])
            elif "--count" not in chosen:
                case.forever = True
        if command in ("serve", "gateway"):
            case.forever = True

        # Where each option goes: before the command name, after it, or among the arguments.
        before, after = [], []
        middle = []  # for encode: between encode and its request command
        for words in options:
            where = rng.random()
            if option_name(words) in own and where < 0.3:  # a command's own option: after it
                misplaced = not rng.clean and rng.random() < 0.15
                where = rng.choice([0.1, 0.4]) if misplaced else 1.0
            if where < 0.3:
                before.append(words)
            elif sub and where < 0.45:
                middle.append(words)
            else:
                after.append(words)
        argv = [w for words in before for w in words] + [name]
        if sub:
            argv += [w for words in middle for w in words] + [sub_name]
        groups = [[word] for word in positionals]  # options go between whole groups
        for words in after:
            if rng.random() < 0.7 or not groups:
                groups.append(words)
            else:
                groups.insert(rng.randrange(len(groups) + 1), words)
        argv += [w for words in groups for w in words]
        if not rng.clean and rng.random() < 0.015:  # the command name itself mistyped
            argv[argv.index(name)] = typo(rng, name)
        case.argv = argv
        if command == "sniff" and any(w in ("lo", "--interface=lo") for w in argv):
            case.exclusive = True  # a live capture on lo would hear the other lines
            case.forever = True

    def spell(self, rng, opt, value):
        """--name value, --name=value, -x value or -xvalue."""
        if value is None:
            if opt.short and rng.random() < 0.5:
                return [opt.short]
            return [opt.long]
        r = rng.random()
        if opt.short and r < 0.3:
            return [opt.short + value] if r < 0.08 and value else [opt.short, value]
        if r < 0.45:
            return [f"{opt.long}={value}"]
        return [opt.long, value]

    def server_options(self, rng, case, command, options, chosen):
        if command == "serve":
            port = v_listen_port(rng, command) if rng.random() < 0.9 else None
            if port is not None:
                options.append(self.spell(rng, OPTIONS["--port"], port))
                chosen.add("--port")
            # Mostly a fault, so that it ends at once.
            if rng.random() < 0.8:
                fault = rng.choice([
                    ["--data", rng.choice(["bad.txt", "nope.txt", "pump3.csv"])], ["--drop", "2"],
                    ["--slave", rng.choice(["0", "256", "x"])], ["--exception", "x"],
                    ["--role", "viewer=read"], ["--cert", "nope.pem"], ["--port", "sim"],
                    ["--port", "/dev/ttyNOPE"], ["--corrupt", "150%"], ["--identity", "Nope=1"],
                    ["--read-only", "x"], ["--delay", "500"], ["--timeout", "1s"], ["--baud", "x"],
                    ["--verbose"], ["--plain-role", "viewer", "--role", "x"],
                ])
                options.append(fault)
        else:
            if rng.random() < 0.9:
                options.append(self.spell(rng, OPTIONS["--listen"], v_listen(rng, command)))
                chosen.add("--listen")
            if rng.random() < 0.9:
                port = rng.choice(["sim", "sim", "/dev/ttyNOPE", "tcp://127.0.0.1:1", "rtu+tcp://127.0.0.1:1",
                                   "tls://127.0.0.1:1", ""])
                options.append(self.spell(rng, OPTIONS["--port"], port))
                chosen.add("--port")
            if rng.random() < 0.8:
                fault = rng.choice([
                    ["--unit-map", rng.choice(["x", "1=300", "1:17"])], ["--role", "viewer=read"],
                    ["--listen", "udp://:1502"], ["--listen", "tls://:" + rng.ports[1]], ["--timeout", "500"],
                    ["--log", "sub/gw.csv"], ["--interface", "lo"], ["--retries", "-1"],
                    ["--default-role", ""], ["--baud", "fast"], ["--map", "pump3.csv"],
                ])
                options.append(fault)

    def sniff_options(self, rng, case, options, chosen):
        r = rng.random()
        if r < 0.75:
            source = v_input(rng, "sniff")
            options.append(self.spell(rng, OPTIONS["--input"], source))
            chosen.add("--input")
            if source == "-":
                case.stdin = random_capture(rng) if rng.random() < 0.7 else load_stdin_capture(rng)
        elif r < 0.85:
            options.append(["--interface", v_interface(rng, "sniff")])
            chosen.add("--interface")
        elif r < 0.95:
            options.append(self.spell(rng, OPTIONS["--port"], rng.choice(["/dev/ttyNOPE", "sim",
                                                                         "tcp://127.0.0.1:1", ""])))
            chosen.add("--port")

    def positionals(self, rng, case, request, command):
        """The arguments of a command (or of encode's request command)."""
        slave = pick(rng, SLAVES_GOOD, SLAVES_BAD, 0.08)
        if request in ("read-coils", "read-inputs", "read-holding", "read-input-registers"):
            good, bad = ADDRESSES[COMMAND_TABLE[request]]
            args = [slave, pick(rng, good, bad, 0.1)]
            if rng.random() < (0.1 if "-" in args[1] else 0.7):
                args.append(pick(rng, COUNTS_GOOD, COUNTS_BAD, 0.1))
            return args
        if request in ("read", "watch"):
            if rng.random() < 0.25:  # by map
                args = [slave] if rng.random() < 0.7 else []
                args += rng.sample(MAP_NAMES, rng.randint(0, 3))
                return ["--map", v_map(rng, request)] + args
            table = rng.choice(list(ADDRESSES))
            good, bad = ADDRESSES[table]
            ref = rng.choice([g for g in good if len(g.split("-")[0].split(".")[0]) >= 5] or good)
            if rng.random() < 0.15:
                ref = pick(rng, good, bad, 0.5)
            args = [slave, ref]
            if rng.random() < 0.6:
                args.append(pick(rng, COUNTS_GOOD, COUNTS_BAD, 0.1))
            return args
        if request == "write-coil":
            return [slave, pick(rng, *ADDRESSES["coil"], 0.1), pick(rng, *COIL_VALUES)]
        if request == "write-coils":
            vals = (["".join(rng.choice("01") for _ in range(rng.randint(1, 12)))] if rng.random() < 0.3
                    else [pick(rng, *COIL_VALUES) for _ in range(rng.randint(1, 5))])
            return [slave, pick(rng, *ADDRESSES["coil"], 0.1)] + vals
        if request == "write-register":
            return [slave, pick(rng, *ADDRESSES["holding"], 0.1), pick(rng, *REGISTER_VALUES)]
        if request == "write-registers":
            return [slave, pick(rng, *ADDRESSES["holding"], 0.1)] + [
                pick(rng, *REGISTER_VALUES) for _ in range(rng.randint(1, 4))]
        if request == "write":
            if rng.random() < 0.2:
                return ["--map", v_map(rng, request), slave] + rng.sample(MAP_WRITES, rng.randint(0, 3))
            if rng.random() < 0.5:
                ref = pick(rng, ["000020", "000001", "000020-000022", "00020"], ["100197", "300009"], 0.15)
                vals = [pick(rng, *COIL_VALUES) for _ in range(rng.randint(1, 3))]
            else:
                ref = pick(rng, ["400108", "400001", "400108.02", "400001-400002", "40001", "400108.15"],
                           ["465537", "300009", "107"], 0.15)
                vals = [pick(rng, *REGISTER_VALUES) for _ in range(rng.randint(1, 3))]
            return [slave, ref] + vals
        if request == "raw":
            pdu = pick(rng, PDUS, PDUS_BAD, 0.1)
            words = pdu.split() if rng.random() < 0.6 else [pdu]
            return [slave] + words
        if command in ("info", "diag"):
            return [slave]
        if command == "dump":
            return [slave] + [pick(rng, *DUMP_RANGES, 0.1) for _ in range(rng.randint(1, 3))]
        if command == "restore":
            return [slave, pick(rng, ["pump3.txt", "dump.txt", "pump3.txt"],
                                ["bad.txt", "nope.txt", "empty.txt", "pump3.csv", "root"], 0.3)]
        if command == "decode":
            if rng.random() < 0.35:
                case.stdin = random_log_text(rng)
                return []
            args = []
            for _ in range(rng.randint(1, 3)):
                text = random_frame_text(rng)
                args += text.split() if rng.random() < 0.6 else [text]
            if rng.random() < 0.05:
                args.append("")
            return args
        if command == "sniff":
            case.files["cap.bin"] = random_capture(rng)
            if rng.random() < 0.25:
                case.files["cap.bin.timing"] = random_timing(rng, len(case.files["cap.bin"]))
            return []
        return []  # scan, serve, gateway, ports

    def environment(self, rng, case):
        p = 0.1 if rng.random() < 0.3 else 0.0
        listens = any(w in ("serve", "gateway") for w in case.argv)
        for name, good, bad in ENVIRONMENT:
            chance = p * (3 if name == "MBTOOL_PORT" else 1)
            if rng.random() < chance:
                if name == "MBTOOL_PORT" and listens:  # never where masters connect
                    good = [g for g in good if "127.0.0.1" not in g]
                case.env[name] = pick(rng, good, bad, 0.15)
        # A bus command without --port that would find none: now and then give it sim.
        if "--port" not in " ".join(case.argv) and rng.random() < 0.5 and "MBTOOL_PORT" not in case.env:
            if any(c in case.argv for c in BUS_COMMANDS):
                case.env["MBTOOL_PORT"] = "sim"
        if listens:
            case.forever = True
        # dump and restore wait for a slave that does not answer in real time, each retry
        # and each try on a path with a secondary again: with retries or a secondary, keep
        # their timeout short (unless one is given), well inside the process timeout.
        secondary = "MBTOOL_SECONDARY_PORT" in case.env or any(w.startswith("--secondary-port") for w in case.argv)
        retries = case.env.get("MBTOOL_RETRIES", "0") not in ("0", "-1") or any(
            w.startswith("--retries") for w in case.argv)
        if (secondary or retries) and ("dump" in case.argv or "restore" in case.argv) \
                and "MBTOOL_TIMEOUT" not in case.env and not any(w.startswith("--timeout") for w in case.argv):
            case.argv += ["--timeout", "100ms"]


def load_stdin_capture(rng):
    path = os.path.join(REPO, REPO_FIXTURES["wizmodbus.bin"])
    if os.path.exists(path):
        with open(path, "rb") as f:
            return f.read()
    return random_capture(rng)


def is_help(argv):
    """Whether a line asks for help or the version. (Lines that name no command, which
    print the short help, come only from Generator.help_line, which marks them.)"""
    return not argv or any(w in ("-h", "--help", "-V", "--version", "help") for w in argv)


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
