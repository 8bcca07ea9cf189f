"""The fixtures, frames and option values that compare_cli.py draws its command lines
from: files written into every working directory, real Modbus frames, logs and captures,
and the good and bad values of each option."""

import os
import random

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
