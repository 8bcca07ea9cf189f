#!/usr/bin/env python3
"""A Modbus TCP gateway with one device behind it, at unit id UNIT, that stays silent for
every other unit id (as some gateways are, where others answer 0B).

    one_unit_gateway.py ADDRESS PORT UNIT

The device answers report server id (17) with UNIT, running, "GW-UNIT", read holding registers (03) with
zeros, and anything else with exception 01.
"""
import socket
import struct
import sys
import threading

address, port, unit = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])


def answer(pdu):
    function = pdu[0]
    if function == 0x11:
        # The server id, "running", then the device's own text.
        data = bytes([unit, 0xFF]) + b"GW-%d" % unit
        return bytes([0x11, len(data)]) + data
    if function == 0x03 and len(pdu) >= 5:
        count = struct.unpack(">H", pdu[3:5])[0]
        return bytes([0x03, 2 * count]) + b"\x00" * (2 * count)
    return bytes([function | 0x80, 0x01])


def serve(connection):
    buffer = b""
    with connection:
        while True:
            data = connection.recv(1024)
            if not data:
                return
            buffer += data
            while len(buffer) >= 7:
                transaction, _, length, asked = struct.unpack(">HHHB", buffer[:7])
                if len(buffer) < 6 + length:
                    break
                pdu, buffer = buffer[7:6 + length], buffer[6 + length:]
                if asked != unit or not pdu:
                    continue
                reply = answer(pdu)
                connection.sendall(struct.pack(">HHHB", transaction, 0, len(reply) + 1, unit) + reply)


listener = socket.socket()
listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
listener.bind((address, port))
listener.listen(16)
while True:
    connection, _ = listener.accept()
    threading.Thread(target=serve, args=(connection,), daemon=True).start()
