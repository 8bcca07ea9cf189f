"""A bare Modbus TCP server for the scripted peers: each connection in a thread of its own,
MBAP frames cut from the stream, and each request's answer PDU asked of `answer(unit,
pdu)`; `None` leaves the request unanswered."""
import socket
import struct
import threading


def serve_forever(address, port, answer):
    accept_forever(address, port, lambda connection: _serve(connection, answer))


def accept_forever(address, port, handle):
    """Listens on ADDRESS:PORT and hands each connection to `handle` on a thread of its
    own."""
    listener = socket.socket()
    listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    listener.bind((address, port))
    listener.listen(16)
    while True:
        connection, _ = listener.accept()
        threading.Thread(target=handle, args=(connection,), daemon=True).start()


def _serve(connection, answer):
    buffer = b""
    with connection:
        while True:
            data = connection.recv(1024)
            if not data:
                return
            buffer += data
            while len(buffer) >= 7:
                transaction, _, length, unit = struct.unpack(">HHHB", buffer[:7])
                if len(buffer) < 6 + length:
                    break
                pdu, buffer = buffer[7:6 + length], buffer[6 + length:]
                reply = answer(unit, pdu) if pdu else None
                if reply is not None:
                    header = struct.pack(">HHHB", transaction, 0, len(reply) + 1, unit)
                    connection.sendall(header + reply)
