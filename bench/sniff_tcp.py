#!/usr/bin/env python3
"""Throughput of `mbtool sniff --input` on pcaps of Modbus TCP against tshark's Modbus/TCP
dissector on the same files, in one run.

    python3 bench/sniff_tcp.py [TRANSACTIONS [COPIES]]   # defaults 1,000,000 and 70

Two captures:
- generated: eight clients polling one server on port 502, each transaction a read of 10
  holding registers and its answer, in segments of their own, over Ethernet;
- field: the public 4SICS capture in tests/corpus/modbus-tcp (14 connections from one
  client to PLCs, several PDUs in a segment now and then, 15,984 frames) repeated COPIES
  times one after the other, each copy's client at an address of its own, so that every
  copy's connections are new ones (about 100 MB, 1.1 M frames by default).

Three runs a capture, each the best of three: mbtool with JSON Lines, mbtool with a filter
that shows nothing (`--slave 250`: reassembly, framing and pairing alone), and `tshark -T
fields` with the fields that pair requests and answers. Prints MB/s, frames/s, peak memory
(also for a tenth of the field capture), and the ratios. The field capture holds no FIN, so
every copy leaves its 14 connections open: its peak grows with the connections held open,
about 10 kB each, not with the bytes read; the generated one, whose eight connections go on,
shows the same peak at any size.
"""
import os
import struct
import subprocess
import sys
import tempfile
import time

TRANSACTIONS = int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000
COPIES = int(sys.argv[2]) if len(sys.argv) > 2 else 70
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
FIELD = os.path.join(ROOT, "tests", "corpus", "modbus-tcp", "12-iti-4sics-ModbusTCP-pipelined.pcap")
ROUNDS = 3


def checksum(data):
    if len(data) % 2:
        data += b"\0"
    total = sum(struct.unpack(f"!{len(data) // 2}H", data))
    while total >> 16:
        total = (total & 0xFFFF) + (total >> 16)
    return ~total & 0xFFFF


def packet(client, to_server, seq, ack, payload):
    """Ethernet, IPv4 and TCP headers around `payload`."""
    port = 40000 + client
    source, destination = (port, 502) if to_server else (502, port)
    ips = (bytes([10, 0, 0, client]), bytes([10, 0, 1, 1]))
    src_ip, dst_ip = ips if to_server else ips[::-1]
    tcp = struct.pack("!HHIIBBHHH", source, destination, seq, ack, 5 << 4, 0x18, 1024, 0, 0)
    length = 20 + len(tcp) + len(payload)
    ip = struct.pack("!BBHHHBBH4s4s", 0x45, 0, length, 0, 0, 64, 6, 0, src_ip, dst_ip)
    ip = ip[:10] + struct.pack("!H", checksum(ip)) + ip[12:]
    return b"\x02" * 6 + b"\x04" * 6 + b"\x08\x00" + ip + tcp + payload


def make_capture(path):
    request_pdu = struct.pack("!BHH", 3, 0, 10)
    answer_pdu = bytes([3, 20]) + bytes(range(20))
    seqs = {c: [1000, 5000] for c in range(1, 9)}
    with open(path, "wb") as out:
        out.write(struct.pack("<IHHiIII", 0xA1B2C3D4, 2, 4, 0, 0, 65535, 1))
        t = 1_700_000_000_000_000
        records = []
        for n in range(TRANSACTIONS):
            client = n % 8 + 1
            transaction = n & 0xFFFF
            request = struct.pack("!HHHB", transaction, 0, len(request_pdu) + 1, 17) + request_pdu
            answer = struct.pack("!HHHB", transaction, 0, len(answer_pdu) + 1, 17) + answer_pdu
            c, s = seqs[client]
            for to_server, data, seq, ack, dt in (
                (True, request, c, s, 100),
                (False, answer, s, c + len(request), 250),
            ):
                frame = packet(client, to_server, seq, ack, data)
                t += dt
                records.append(struct.pack("<IIII", t // 1_000_000, t % 1_000_000, len(frame), len(frame)) + frame)
            seqs[client] = [c + len(request), s + len(answer)]
            if len(records) > 10000:
                out.write(b"".join(records))
                records.clear()
        out.write(b"".join(records))


def make_field_capture(path, copies):
    """The field capture repeated `copies` times, each copy later than the one before and
    its client (141.81.0.10) moved to an address of its own: the first and third bytes of
    the address change by the same amount in opposite directions, so that the IP and TCP
    checksums still hold."""
    data = open(FIELD, "rb").read()
    header, records, at = data[:24], [], 24
    assert struct.unpack("<I", header[:4])[0] == 0xA1B2C3D4 and struct.unpack("<I", header[20:24])[0] == 1
    while at < len(data):
        seconds, micros, length, _ = struct.unpack("<IIII", data[at:at + 16])
        records.append((seconds, micros, data[at + 16:at + 16 + length]))
        at += 16 + length
    span = records[-1][0] - records[0][0] + 1
    client = bytes([141, 81, 0, 10])
    with open(path, "wb") as out:
        out.write(header)
        for copy in range(copies):
            moved = bytes([141 - copy, 81, copy, 10])
            batch = []
            for seconds, micros, frame in records:
                frame = bytearray(frame)
                if frame[12:14] == b"\x08\x00":
                    for place in (26, 30):
                        if frame[place:place + 4] == client:
                            frame[place:place + 4] = moved
                frame = bytes(frame)
                batch.append(struct.pack("<IIII", seconds + copy * span, micros, len(frame), len(frame)) + frame)
            out.write(b"".join(batch))


def frames_in(path):
    """The frames mbtool finds in a capture."""
    out = subprocess.run([MBTOOL, "sniff", "--input", path, "-o", "json"], capture_output=True, check=True)
    return sum(1 for line in out.stdout.splitlines() if line.startswith(b'{"type":"frame"'))


def timed(command, stdout=subprocess.DEVNULL):
    """Seconds and peak memory (MB) of a command, by GNU time: the best of ROUNDS."""
    best = None
    for _ in range(ROUNDS):
        start = time.perf_counter()
        result = subprocess.run(
            ["/usr/bin/time", "-f", "%M"] + command, stdout=stdout, stderr=subprocess.PIPE, check=True
        )
        seconds = time.perf_counter() - start
        peak = int(result.stderr.decode().strip().splitlines()[-1]) / 1024
        if best is None or seconds < best[0]:
            best = (seconds, peak)
    return best


def runs(path, frames, name):
    size = os.path.getsize(path) / 1e6
    print(f"{name} capture: {frames:,} frames, {size:.0f} MB")
    commands = {
        "mbtool sniff --json": [MBTOOL, "sniff", "--input", path, "--json"],
        "mbtool sniff --slave 250": [MBTOOL, "sniff", "--input", path, "--slave", "250"],
        "tshark -T fields": [
            "tshark", "-r", path, "-T", "fields", "-e", "frame.number",
            "-e", "mbtcp.trans_id", "-e", "mbtcp.unit_id", "-e", "modbus.func_code",
            "-e", "modbus.request_frame", "-e", "modbus.response_time",
        ],
    }
    results = {}
    for what, command in commands.items():
        seconds, peak = timed(command)
        results[what] = seconds
        print(
            f"  {what:26} {seconds:7.2f} s  {size / seconds:7.1f} MB/s  "
            f"{frames / seconds:11,.0f} frames/s  peak {peak:.0f} MB  (best of {ROUNDS})"
        )
    for what in ("mbtool sniff --json", "mbtool sniff --slave 250"):
        print(f"  {what} is {results['tshark -T fields'] / results[what]:.1f} times as fast as tshark")


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "modbus.pcap")
        make_capture(path)
        runs(path, 2 * TRANSACTIONS, "generated")
        os.remove(path)
        field = os.path.join(work, "field.pcap")
        make_field_capture(field, 1)
        per_copy = frames_in(field)
        tenth = os.path.join(work, "tenth.pcap")
        make_field_capture(tenth, max(1, COPIES // 10))
        make_field_capture(field, COPIES)
        runs(field, per_copy * COPIES, "field (4SICS, repeated)")
        for what, path in (("a tenth of it", tenth), ("all of it", field)):
            _, peak = timed([MBTOOL, "sniff", "--input", path, "--json"])
            print(f"  mbtool sniff --json on {what}: peak {peak:.0f} MB")


main()
