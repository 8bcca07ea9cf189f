#!/usr/bin/env python3
"""`mbtool gateway` in front of a slave that stalls: `mbtool serve` on a pty pair
(RTU, 19200 baud) is stopped (SIGSTOP) for STALL of every PERIOD and then answers
everything it missed, late. Clients of different roles read different registers of the
same shape through TLS and a plain listener, and every answer is checked: its value must
be its own register's, and a viewer limited to 400001-400010 must never see another's.

    python3 bench/stall.py [SECONDS] [STALL] [PERIOD]
"""
import os
import signal
import socket
import ssl
import struct
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from soak import MBTOOL, certificates, free_port  # noqa: E402

SECONDS = float(sys.argv[1]) if len(sys.argv) > 1 else 60
STALL = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
PERIOD = float(sys.argv[3]) if len(sys.argv) > 3 else 2.0
VALUES = {0: 1111, 1: 2222, 499: 4242, 500: 4343}


def main():
    folder = tempfile.mkdtemp()
    path = lambda name: os.path.join(folder, name)
    certificates(folder)
    with open(path("data.txt"), "w") as f:
        f.write("400001 = 1111 2222\n400500 = 4242 4343\n")
    a, b = path("a"), path("b")
    socat = subprocess.Popen(["socat", f"pty,raw,echo=0,link={a}", f"pty,raw,echo=0,link={b}"])
    time.sleep(0.5)
    slave = subprocess.Popen([MBTOOL, "--port", a, "serve", "--data", path("data.txt"), "--quiet"],
                             stderr=subprocess.DEVNULL)
    secure, plain = free_port(), free_port()
    gateway = subprocess.Popen(
        [MBTOOL, "--port", b, "--timeout", "300ms", "--cert", path("server.pem"),
         "--key", path("server.key"), "--ca", path("ca.pem"), "gateway",
         "--listen", f"tls://127.0.0.1:{secure}", "--listen", f"tcp://127.0.0.1:{plain}",
         "--role", "operator=read,write", "--role", "viewer=read:400001-400010",
         "--plain-role", "viewer", "--quiet"],
        stderr=subprocess.DEVNULL)
    time.sleep(0.5)
    operator = ssl.create_default_context(cafile=path("ca.pem"))
    operator.load_cert_chain(path("client.pem"), path("client.key"))
    end = time.time() + SECONDS
    tally = {"own": 0, "others": 0, "exception": 0, "outside the role": 0}
    lock = threading.Lock()

    def client(connect, address, role):
        transaction = 0
        with connect() as s:
            while time.time() < end:
                transaction = (transaction + 1) & 0xFFFF
                s.sendall(struct.pack(">HHHBBHH", transaction, 0, 6, 17, 3, address, 1))
                answer = b""
                while len(answer) < 9:
                    answer += s.recv(64)
                length = struct.unpack(">H", answer[4:6])[0]
                while len(answer) < 6 + length:
                    answer += s.recv(64)
                assert struct.unpack(">H", answer[:2])[0] == transaction
                with lock:
                    if answer[7] & 0x80:
                        tally["exception"] += 1
                        continue
                    value = struct.unpack(">H", answer[9:11])[0]
                    tally["own" if value == VALUES[address] else "others"] += 1
                    if role == "viewer" and value in (4242, 4343):
                        tally["outside the role"] += 1

    tls = lambda: operator.wrap_socket(socket.create_connection(("127.0.0.1", secure)),
                                       server_hostname="localhost")
    tcp = lambda: socket.create_connection(("127.0.0.1", plain))
    clients = [threading.Thread(target=client, args=(tls, 499, "operator")),
               threading.Thread(target=client, args=(tls, 500, "operator")),
               threading.Thread(target=client, args=(tcp, 0, "viewer")),
               threading.Thread(target=client, args=(tcp, 1, "viewer"))]
    for c in clients:
        c.start()
    while time.time() < end:
        time.sleep(PERIOD - STALL)
        slave.send_signal(signal.SIGSTOP)
        time.sleep(STALL)
        slave.send_signal(signal.SIGCONT)
    for c in clients:
        c.join()
    for process in (gateway, slave, socat):
        process.terminate()
        process.wait()
    answers = tally["own"] + tally["others"]
    print(f"{SECONDS:.0f} s, the slave stopped {STALL} s of every {PERIOD} s: {answers} answers, "
          f"{tally['own']} their own, {tally['others']} another's, "
          f"{tally['outside the role']} outside the viewer's range; {tally['exception']} exceptions (0B)")


if __name__ == "__main__":
    main()
