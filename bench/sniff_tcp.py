#!/usr/bin/env python3
"""Throughput of `mbtool sniff --input` on a pcap of Modbus TCP against tshark's Modbus/TCP
dissector on the same file, in one run.

    python3 bench/sniff_tcp.py [TRANSACTIONS]   # default 1,000,000

The capture is made once: eight clients polling one server on port 502, each transaction a
read of 10 holding registers and its answer, in segments of their own, over Ethernet.
Three runs are timed: mbtool with JSON Lines, mbtool with a filter that shows nothing
(`--slave 250`: reassembly, framing and pairing alone), and `tshark -T fields` with the
fields that pair requests and answers. Prints MB/s, frames/s, peak memory, and the ratios.
"""
import os
import struct
import subprocess
import sys
import tempfile
import time

TRANSACTIONS = int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")


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


def timed(command, stdout=subprocess.DEVNULL):
    """Seconds and peak memory (MB) of a command, by GNU time."""
    start = time.perf_counter()
    result = subprocess.run(
        ["/usr/bin/time", "-f", "%M"] + command, stdout=stdout, stderr=subprocess.PIPE, check=True
    )
    seconds = time.perf_counter() - start
    peak = int(result.stderr.decode().strip().splitlines()[-1]) / 1024
    return seconds, peak


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "modbus.pcap")
        make_capture(path)
        size = os.path.getsize(path) / 1e6
        frames = 2 * TRANSACTIONS
        print(f"capture: {TRANSACTIONS:,} transactions, {frames:,} frames, {size:.0f} MB")
        runs = {
            "mbtool sniff --json": [MBTOOL, "sniff", "--input", path, "--json"],
            "mbtool sniff --slave 250": [MBTOOL, "sniff", "--input", path, "--slave", "250"],
            "tshark -T fields": [
                "tshark", "-r", path, "-T", "fields", "-e", "frame.number",
                "-e", "mbtcp.trans_id", "-e", "mbtcp.unit_id", "-e", "modbus.func_code",
                "-e", "modbus.request_frame", "-e", "modbus.response_time",
            ],
        }
        results = {}
        for name, command in runs.items():
            seconds, peak = timed(command)
            results[name] = seconds
            print(
                f"{name:26} {seconds:7.2f} s  {size / seconds:7.1f} MB/s  "
                f"{frames / seconds:11,.0f} frames/s  peak {peak:.0f} MB"
            )
        for name in ("mbtool sniff --json", "mbtool sniff --slave 250"):
            print(f"{name} is {results['tshark -T fields'] / results[name]:.1f} times as fast as tshark")


main()
