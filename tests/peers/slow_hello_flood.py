#!/usr/bin/env python3
"""Clients that never finish a TLS handshake: each connects, sends one byte of a
ClientHello (16) and waits; when the server closes it, it connects again at once.

    slow_hello_flood.py PORT CONNECTIONS SECONDS [spread] [whole]

With spread, the connections come from 127.0.0.2 to 127.0.0.201 (loopback addresses
all), as from many machines; without, all from 127.0.0.1. With whole, each sends a whole
ClientHello (Python's ssl) and stalls after the server's answer instead. Prints how many
connections were made in all.
"""
import selectors
import socket
import ssl
import sys
import time


def client_hello():
    """A whole ClientHello, as Python's ssl would send it."""
    context = ssl.SSLContext(ssl.PROTOCOL_TLS_CLIENT)
    context.check_hostname = False
    context.verify_mode = ssl.CERT_NONE
    incoming, outgoing = ssl.MemoryBIO(), ssl.MemoryBIO()
    tls = context.wrap_bio(incoming, outgoing, server_hostname="localhost")
    try:
        tls.do_handshake()
    except ssl.SSLWantReadError:
        pass
    return outgoing.read()


def main():
    port, count, seconds = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3])
    spread, whole = "spread" in sys.argv[4:], "whole" in sys.argv[4:]
    first = client_hello() if whole else b"\x16"
    selector = selectors.DefaultSelector()
    made = 0

    def connect(n):
        nonlocal made
        s = socket.socket()
        if spread:
            s.bind((f"127.0.0.{2 + n % 200}", 0))
        s.setblocking(False)
        try:
            s.connect(("127.0.0.1", port))
        except BlockingIOError:
            pass
        except OSError:
            s.close()
            return
        selector.register(s, selectors.EVENT_WRITE, n)
        made += 1

    for n in range(count):
        connect(n)
    end = time.time() + seconds
    while time.time() < end:
        for key, events in selector.select(timeout=0.05):
            s, n = key.fileobj, key.data
            if events & selectors.EVENT_WRITE:
                try:
                    s.send(first)
                    selector.modify(s, selectors.EVENT_READ, n)
                    continue
                except OSError:
                    pass
            else:
                try:
                    if s.recv(64):
                        continue
                except BlockingIOError:
                    continue
                except OSError:
                    pass
            selector.unregister(s)
            s.close()
            connect(n)
        if len(selector.get_map()) < count:
            connect(made)
    print(made)


if __name__ == "__main__":
    main()
