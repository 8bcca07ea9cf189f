#!/usr/bin/env python3
"""A Modbus TCP gateway with one device behind it, at unit id UNIT, that stays silent for
every other unit id (as some gateways are, where others answer 0B).

    one_unit_gateway.py ADDRESS PORT UNIT

The device answers report server id (17) with UNIT, running, "GW-UNIT", read holding
registers (03) with zeros, and anything else with exception 01.
"""
import struct
import sys

from mbap_server import serve_forever

address, port, unit = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])


def answer(asked, pdu):
    if asked != unit:
        return None
    function = pdu[0]
    if function == 0x11:
        # The server id, "running", then the device's own text.
        data = bytes([unit, 0xFF]) + b"GW-%d" % unit
        return bytes([0x11, len(data)]) + data
    if function == 0x03 and len(pdu) >= 5:
        count = struct.unpack(">H", pdu[3:5])[0]
        return bytes([0x03, 2 * count]) + b"\x00" * (2 * count)
    return bytes([function | 0x80, 0x01])


serve_forever(address, port, answer)
