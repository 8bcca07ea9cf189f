#!/usr/bin/env python3
"""`mbtool gateway` under churn: clients that connect, read once and leave, as fast as
they can, for SECONDS, over plain Modbus TCP and over TLS (certificates made with
openssl, each client with a role), while a flood of connections that send one byte of a
ClientHello and connect again when closed runs beside them. Every 5 s the gateway's
resident memory, open descriptors and threads are sampled from /proc; at the end their
growth from the first sample after warm-up to the last is printed, and as a rate per hour.

    python3 bench/soak.py [SECONDS]
"""
import os
import socket
import ssl
import struct
import subprocess
import sys
import tempfile
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
SECONDS = float(sys.argv[1]) if len(sys.argv) > 1 else 60
ROLE_OID = "1.3.6.1.4.1.50316.802.1"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def openssl(*args, cwd):
    subprocess.run(["openssl", *args], cwd=cwd, check=True, capture_output=True)


def certificates(folder):
    """A CA, the gateway's certificate and a client's with the role 'operator'."""
    openssl("req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:P-256", "-nodes",
            "-keyout", "ca.key", "-out", "ca.pem", "-days", "30", "-subj", "/CN=Soak CA", cwd=folder)
    for name, ext in [
        ("server", "subjectAltName=DNS:localhost,IP:127.0.0.1\nextendedKeyUsage=serverAuth\n"),
        ("client", f"extendedKeyUsage=clientAuth\n{ROLE_OID}=ASN1:UTF8String:operator\n"),
    ]:
        with open(os.path.join(folder, f"{name}.ext"), "w") as f:
            f.write(ext)
        openssl("req", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:P-256", "-nodes",
                "-keyout", f"{name}.key", "-out", f"{name}.csr", "-subj", f"/CN={name}", cwd=folder)
        openssl("x509", "-req", "-in", f"{name}.csr", "-CA", "ca.pem", "-CAkey", "ca.key",
                "-CAcreateserial", "-out", f"{name}.pem", "-days", "30", "-extfile", f"{name}.ext",
                cwd=folder)


def read_once(sock, transaction):
    sock.sendall(struct.pack(">HHHBBHH", transaction, 0, 6, 17, 3, 107, 1))
    answer = b""
    while len(answer) < 11:
        chunk = sock.recv(11 - len(answer))
        if not chunk:
            raise ConnectionError("closed")
        answer += chunk
    if answer[7:11] != b"\x03\x02\x02\x2b":
        raise ValueError(f"wrong answer {answer.hex()}")


def holds(pid):
    status = open(f"/proc/{pid}/status").read()
    field = lambda name: int(next(l for l in status.splitlines() if l.startswith(name)).split()[1])
    return field("VmRSS:"), len(os.listdir(f"/proc/{pid}/fd")), field("Threads:")


def main():
    folder = tempfile.mkdtemp()
    certificates(folder)
    path = lambda name: os.path.join(folder, name)
    plain, secure = free_port(), free_port()
    gateway = subprocess.Popen(
        [MBTOOL, "--port", "sim", "--cert", path("server.pem"), "--key", path("server.key"),
         "--ca", path("ca.pem"), "gateway", "--listen", f"tcp://127.0.0.1:{plain}",
         "--listen", f"tls://127.0.0.1:{secure}", "--role", "operator=read,write",
         "--role", "viewer=read", "--plain-role", "viewer", "--quiet"],
        stdout=subprocess.DEVNULL, stderr=open(path("gateway.log"), "w"))
    time.sleep(0.5)
    context = ssl.create_default_context(cafile=path("ca.pem"))
    context.load_cert_chain(path("client.pem"), path("client.key"))
    end = time.time() + SECONDS
    counts = {"plain": 0, "tls": 0, "flood": 0, "failed": 0}
    failures = {}

    def clients(kind, connect):
        n = 0
        while time.time() < end:
            try:
                with connect() as s:
                    read_once(s, n & 0xFFFF)
                counts[kind] += 1
            except (OSError, ValueError) as e:
                counts["failed"] += 1
                failures[f"{kind}: {e}"] = failures.get(f"{kind}: {e}", 0) + 1
            n += 1

    plain_connect = lambda: socket.create_connection(("127.0.0.1", plain), timeout=5)
    tls_connect = lambda: context.wrap_socket(
        socket.create_connection(("127.0.0.1", secure), timeout=5), server_hostname="localhost")

    def flood():
        while time.time() < end:
            try:
                with socket.create_connection(("127.0.0.1", secure), timeout=5) as s:
                    s.sendall(b"\x16")
                    s.settimeout(max(0.1, end - time.time()))
                    s.recv(1)
                counts["flood"] += 1
            except OSError:
                pass

    workers = [threading.Thread(target=clients, args=("plain", plain_connect)) for _ in range(2)]
    workers += [threading.Thread(target=clients, args=("tls", tls_connect))]
    workers += [threading.Thread(target=flood) for _ in range(20)]
    for worker in workers:
        worker.start()
    samples = []
    started = time.time()
    while time.time() < end:
        time.sleep(min(5, max(0, end - time.time())))
        samples.append((time.time() - started, *holds(gateway.pid)))
    for worker in workers:
        worker.join()
    time.sleep(1)
    samples.append((time.time() - started, *holds(gateway.pid)))
    gateway.terminate()
    gateway.wait()
    log = open(path("gateway.log")).read().splitlines()
    print(f"{SECONDS:.0f} s: {counts['plain']} plain clients, {counts['tls']} TLS clients, "
          f"{counts['flood']} slow-ClientHello connections closed, {counts['failed']} failed")
    for failure, n in sorted(failures.items(), key=lambda f: -f[1])[:5]:
        print(f"  {n} x {failure}")
    print("  time      RSS KiB  descriptors  threads")
    for t, rss, fds, threads in samples:
        print(f"  {t:6.1f} s  {rss:8d}  {fds:11d}  {threads:7d}")
    # Growth from the first sample after warm-up to the last, idle, one.
    (t0, rss0, fds0, thr0), (t1, rss1, fds1, thr1) = samples[min(1, len(samples) - 1)], samples[-1]
    hours = max(t1 - t0, 1e-9) / 3600
    print(f"growth: RSS {rss1 - rss0:+d} KiB ({(rss1 - rss0) / hours:+.0f} KiB/hour), "
          f"descriptors {fds1 - fds0:+d}, threads {thr1 - thr0:+d}")
    print(f"log lines: {len(log)} in {SECONDS:.0f} s (the summary included); the first and last:")
    for line in log[:12] + ["..."] + log[-6:]:
        print(f"  {line}")


if __name__ == "__main__":
    main()
