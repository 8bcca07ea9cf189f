#!/usr/bin/env python3
"""A Modbus/TCP Security device that closes each connection after one answer, as devices
close idle connections: answers any request with one holding register counting up.

    tls_closing_slave.py CERT KEY CA PORT [1.2]

Built on Python's ssl (OpenSSL), as many devices' TLS is; with 1.2, it speaks TLS 1.2 only.
"""
import socket
import ssl
import sys


def main():
    cert, key, ca, port = sys.argv[1:5]
    context = ssl.SSLContext(ssl.PROTOCOL_TLS_SERVER)
    if sys.argv[5:] == ["1.2"]:
        context.maximum_version = ssl.TLSVersion.TLSv1_2
    context.load_cert_chain(cert, key)
    context.load_verify_locations(ca)
    context.verify_mode = ssl.CERT_REQUIRED
    server = socket.socket()
    server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    server.bind(("127.0.0.1", int(port)))
    server.listen(8)
    answered = 0
    while True:
        client, _ = server.accept()
        tls = context.wrap_socket(client, server_side=True, do_handshake_on_connect=False)
        try:
            tls.do_handshake()
        except (ssl.SSLError, OSError):
            refuse(tls)
            continue
        try:
            with tls:
                request = tls.recv(260)
                if len(request) < 8:
                    continue
                # The transaction and unit of the request; function 03, one register.
                tls.sendall(request[:2] + b"\x00\x00\x00\x05" + request[6:7] + b"\x03\x02"
                            + answered.to_bytes(2, "big"))
                answered += 1
        except (ssl.SSLError, OSError):
            pass


def refuse(tls):
    """Closes a connection whose handshake failed, once the alert is sent and the client's
    flight read: a close with unread bytes would be a reset, which can overtake the alert."""
    try:
        tls.shutdown(socket.SHUT_WR)
        tls.settimeout(1)
        while tls.recv(4096):
            pass
    except OSError:
        pass
    tls.close()


if __name__ == "__main__":
    main()
