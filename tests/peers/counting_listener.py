#!/usr/bin/env python3
"""A TCP listener that takes connections and never answers, counting how many are open at
once and how many were closed by the client (a FIN: recv gives b"").

    counting_listener.py ADDRESS PORT REPORT_FILE

Each time a connection ends it rewrites REPORT_FILE with
{"most_at_once": n, "accepted": n, "closed_by_client": n}.
"""
import json
import socket
import sys
import threading

address, port, report = sys.argv[1], int(sys.argv[2]), sys.argv[3]
lock = threading.Lock()
state = {"open": 0, "most_at_once": 0, "accepted": 0, "closed_by_client": 0}


def write():
    with open(report, "w") as f:
        json.dump({k: state[k] for k in ("most_at_once", "accepted", "closed_by_client")}, f)


def serve(connection):
    try:
        while True:
            data = connection.recv(512)
            if not data:
                with lock:
                    state["closed_by_client"] += 1
                break
    except OSError:
        pass
    finally:
        connection.close()
        with lock:
            state["open"] -= 1
            write()


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
