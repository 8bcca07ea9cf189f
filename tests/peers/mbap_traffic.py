#!/usr/bin/env python3
"""Modbus TCP traffic for mbtool's capture tests, to slave 17 at 127.0.0.1:PORT.

    mbap_traffic.py PORT

pymodbus as the client for every common function, one exception; then raw sockets for
what a client library does not do: requests pipelined in one segment, a request written
one byte at a time across segments, and several connections at once.
"""
import socket
import struct
import sys
import threading
import time

from pymodbus.client import ModbusTcpClient

PORT = int(sys.argv[1])


def library_client():
    client = ModbusTcpClient("127.0.0.1", port=PORT)
    client.connect()
    kw = {"device_id": 17}
    client.read_coils(0, count=10, **kw)
    client.read_discrete_inputs(0, count=9, **kw)
    client.read_holding_registers(0, count=4, **kw)
    client.read_input_registers(0, count=3, **kw)
    client.write_coil(3, True, **kw)
    client.write_register(4, 1234, **kw)
    client.write_coils(10, [True, False, True], **kw)
    client.write_registers(20, [1, 2, 3], **kw)
    client.mask_write_register(address=20, and_mask=0x00F0, or_mask=0x0005, **kw)
    client.readwrite_registers(
        read_address=20, read_count=3, write_address=30, values=[7, 8], **kw
    )
    # An address past the end of the table: exception 02.
    client.read_holding_registers(65530, count=10, **kw)
    client.close()


def mbap(transaction, pdu, unit=17):
    return struct.pack(">HHHB", transaction, 0, len(pdu) + 1, unit) + pdu


def answers(sock, count):
    """Reads up to `count` answers, framed by their MBAP length; a server that answers
    fewer (pymodbus answers the first of requests pipelined in one segment) is waited for
    a second."""
    data = b""
    try:
        for _ in range(count):
            while len(data) < 6 or len(data) < 6 + struct.unpack(">H", data[4:6])[0]:
                chunk = sock.recv(4096)
                if not chunk:
                    return
                data += chunk
            data = data[6 + struct.unpack(">H", data[4:6])[0]:]
    except socket.timeout:
        pass


def raw_connection():
    sock = socket.create_connection(("127.0.0.1", PORT), timeout=1)
    sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
    return sock


def pipelined():
    with raw_connection() as sock:
        requests = [mbap(100 + i, struct.pack(">BHH", 3, i * 2, 2)) for i in range(3)]
        sock.sendall(b"".join(requests))
        answers(sock, 3)


def byte_by_byte():
    with raw_connection() as sock:
        for byte in mbap(200, struct.pack(">BHH", 4, 0, 5)):
            sock.send(bytes([byte]))
            time.sleep(0.002)
        answers(sock, 1)


def polling(worker):
    with raw_connection() as sock:
        for i in range(5):
            sock.sendall(mbap(1000 * worker + i, struct.pack(">BHH", 3, worker, 1 + i)))
            answers(sock, 1)


library_client()
pipelined()
byte_by_byte()
threads = [threading.Thread(target=polling, args=(w,)) for w in range(1, 5)]
for thread in threads:
    thread.start()
for thread in threads:
    thread.join()
