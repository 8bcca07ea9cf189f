#!/usr/bin/env python3
"""A TCP server on a Modbus port that is no Modbus device:

    not_modbus.py garbage|close|reset ADDRESS PORT

garbage answers the first bytes it gets with an HTTP error, as a web server would; close
closes each connection as soon as it is taken; reset resets it (RST).
"""
import socket
import struct
import sys

from mbap_server import accept_forever

mode, address, port = sys.argv[1], sys.argv[2], int(sys.argv[3])


def serve(connection):
    with connection:
        if mode == "close":
            return
        if mode == "reset":
            connection.setsockopt(socket.SOL_SOCKET, socket.SO_LINGER, struct.pack("ii", 1, 0))
            return
        while connection.recv(1024):
            connection.sendall(b"HTTP/1.0 400 Bad Request\r\nContent-Length: 0\r\n\r\n")


accept_forever(address, port, serve)
