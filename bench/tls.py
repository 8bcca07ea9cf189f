#!/usr/bin/env python3
"""What Modbus/TCP Security costs: 10,000 reads in one process (`read-holding --poll 0
--count 10000`) against the same `mbtool serve`, once over tls:// and once over plain
tcp://, taken in turn three times; then one-shot processes (a connection and a read each),
whose difference is the handshake. Certificates are made with openssl's command line.

    python3 bench/tls.py [READS] [PROCESSES]
"""
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MBTOOL = os.path.join(ROOT, "target", "release", "mbtool")
READS = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000
PROCESSES = int(sys.argv[2]) if len(sys.argv) > 2 else 200
ROLE_OID = "1.3.6.1.4.1.50316.802.1"


def openssl(*args):
    subprocess.run(["openssl", *args], check=True, capture_output=True)


def certificates(folder):
    """A CA, a server certificate for localhost and an operator's client certificate."""
    ca, ca_key = f"{folder}/ca.pem", f"{folder}/ca.key"
    openssl("req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:P-256", "-nodes",
            "-keyout", ca_key, "-out", ca, "-days", "2", "-subj", "/CN=Bench CA")
    for name, extensions in [
        ("server", "subjectAltName=DNS:localhost,IP:127.0.0.1"),
        ("client", f"subjectAltName=DNS:client\n{ROLE_OID}=ASN1:UTF8String:operator"),
    ]:
        key, csr, pem = (f"{folder}/{name}.{ext}" for ext in ("key", "csr", "pem"))
        openssl("req", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:P-256", "-nodes",
                "-keyout", key, "-out", csr, "-subj", f"/CN={name}")
        with open(f"{folder}/{name}.ext", "w") as out:
            out.write(extensions + "\n")
        openssl("x509", "-req", "-in", csr, "-CA", ca, "-CAkey", ca_key, "-CAcreateserial",
                "-out", pem, "-days", "2", "-extfile", f"{folder}/{name}.ext")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(port):
    for _ in range(200):
        try:
            socket.create_connection(("127.0.0.1", port), timeout=0.1).close()
            return
        except OSError:
            time.sleep(0.05)
    raise SystemExit(f"nothing listens on {port}")


def timed(args):
    start = time.perf_counter()
    subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - start


def main():
    subprocess.run(["cargo", "build", "--release", "--quiet"], cwd=ROOT, check=True)
    folder = tempfile.mkdtemp()
    certificates(folder)
    server = ["--cert", f"{folder}/server.pem", "--key", f"{folder}/server.key",
              "--ca", f"{folder}/ca.pem"]
    client = ["--cert", f"{folder}/client.pem", "--key", f"{folder}/client.key",
              "--ca", f"{folder}/ca.pem"]
    tls_port, tcp_port = free_port(), free_port()
    servers = [
        subprocess.Popen([MBTOOL, "--port", f"tls://127.0.0.1:{tls_port}", *server, "serve", "-q"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL),
        subprocess.Popen([MBTOOL, "--port", f"tcp://127.0.0.1:{tcp_port}", "serve", "-q"],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL),
    ]
    try:
        wait_for(tls_port)
        wait_for(tcp_port)
        tls = [MBTOOL, "--port", f"tls://localhost:{tls_port}", *client]
        tcp = [MBTOOL, "--port", f"tcp://127.0.0.1:{tcp_port}"]
        many = ["read-holding", "17", "400108", "3", "--poll", "0", "--count", str(READS),
                "-o", "csv"]
        runs = {"tls": [], "tcp": []}
        for _ in range(3):
            runs["tls"].append(timed(tls + many))
            runs["tcp"].append(timed(tcp + many))
        per = {k: statistics.median(v) / READS * 1e6 for k, v in runs.items()}
        print(f"{READS:,} reads in one process: tls {per['tls']:.1f} us, tcp {per['tcp']:.1f} us "
              f"a transaction (median of 3); TLS costs {per['tls'] - per['tcp']:+.1f} us, "
              f"x{per['tls'] / per['tcp']:.3f}")
        once = ["read-holding", "17", "400108", "3"]
        shots = {"tls": [], "tcp": []}
        for _ in range(PROCESSES):
            shots["tls"].append(timed(tls + once))
            shots["tcp"].append(timed(tcp + once))
        one = {k: statistics.median(v) * 1e3 for k, v in shots.items()}
        print(f"one read a process ({PROCESSES} each): tls {one['tls']:.2f} ms, "
              f"tcp {one['tcp']:.2f} ms (median); handshake and certificates "
              f"{one['tls'] - one['tcp']:+.2f} ms")
    finally:
        for process in servers:
            process.kill()
            process.wait()


if __name__ == "__main__":
    main()
