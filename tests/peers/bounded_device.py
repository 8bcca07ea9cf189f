#!/usr/bin/env python3
"""A Modbus TCP device whose holding registers are those of a data file's `4xxxxx = ...`
lines, that refuses (exception 02) any read crossing one of BOUNDARIES (protocol
addresses where a read may start but not run across), as some SunSpec inverters refuse a
read that spans two models.

    bounded_device.py DATA_FILE PORT BOUNDARY,BOUNDARY,...

Only function 03 is answered; every other function gets exception 01.
"""
import struct
import sys

from mbap_server import serve_forever

path, port = sys.argv[1], int(sys.argv[2])
boundaries = [int(b) for b in sys.argv[3].split(",") if b]
registers = {}
for line in open(path):
    line = line.split("#")[0].strip()
    if not line:
        continue
    reference, words = line.split("=")
    start = int(reference) - 400001
    for offset, word in enumerate(words.split()):
        registers[start + offset] = int(word)


def answer(_unit, pdu):
    if pdu[0] != 0x03 or len(pdu) < 5:
        return bytes([pdu[0] | 0x80, 0x01])
    address, count = struct.unpack(">HH", pdu[1:5])
    span = range(address, address + count)
    crosses = any(address < b < address + count for b in boundaries)
    if crosses or not 1 <= count <= 125 or any(a not in registers for a in span):
        return bytes([0x83, 0x02])
    return bytes([0x03, 2 * count]) + b"".join(struct.pack(">H", registers[a]) for a in span)


serve_forever("127.0.0.1", port, answer)
