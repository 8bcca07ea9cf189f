#!/usr/bin/env python3
"""A TCP listener that takes connections and never answers, counting how many are open at
once and how many were closed by the client (a FIN: recv gives b"").

    counting_listener.py ADDRESS PORT REPORT_FILE [SERVER_PORT]

With SERVER_PORT it stands in front of the server on ADDRESS:SERVER_PORT, each
connection carried to a connection of its own there, both ways, so that the server's
connections are counted.

Each time a connection ends it rewrites REPORT_FILE with
{"most_at_once": n, "accepted": n, "closed_by_client": n}.
"""
import json
import socket
import sys
import threading

address, port, report = sys.argv[1], int(sys.argv[2]), sys.argv[3]
server_port = int(sys.argv[4]) if len(sys.argv) > 4 else None
lock = threading.Lock()
state = {"open": 0, "most_at_once": 0, "accepted": 0, "closed_by_client": 0}


def write():
    with open(report, "w") as f:
        json.dump({k: state[k] for k in ("most_at_once", "accepted", "closed_by_client")}, f)


def carry(source, target):
    """The server's bytes to the client, until the server closes."""
    try:
        while True:
            data = source.recv(4096)
            if not data:
                break
            target.sendall(data)
    except OSError:
        pass


def serve(connection):
    server = None
    if server_port is not None:
        server = socket.create_connection((address, server_port))
        threading.Thread(target=carry, args=(server, connection), daemon=True).start()
    try:
        while True:
            data = connection.recv(512)
            if data and server is not None:
                server.sendall(data)
            if not data:
                with lock:
                    state["closed_by_client"] += 1
                break
    except OSError:
        pass
    finally:
        # Counted closed before the client can see it closed: a client that connects again
        # as soon as it does is otherwise counted open beside this one.
        with lock:
            state["open"] -= 1
            write()
        if server is not None:
            server.close()
        connection.close()


listener = socket.socket()
listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
listener.bind((address, port))
listener.listen(64)
print("listening", flush=True)
while True:
    connection, _ = listener.accept()
    with lock:
        state["open"] += 1
        state["accepted"] += 1
        state["most_at_once"] = max(state["most_at_once"], state["open"])
    threading.Thread(target=serve, args=(connection,), daemon=True).start()
