#!/usr/bin/env python3
"""Several RTU slaves on one pseudo-terminal, each with a habit of a real shared bus.

It holds both ends of a pty, prints the path a master opens, and answers reads of holding
registers (03) as the slaves given say, with the value 42 + id:

    busy_line.py 3=now 9=late:300 12=badcrc:2 20=exception:2

    now          answers at once
    late:MS      answers MS milliseconds after the request, whatever came in between
    badcrc:N     the first N answers have a broken CRC, then good ones
    exception:C  answers exception C

Every frame it writes is logged on stderr as 'id HEX', so a test can tell what was said.
"""
import os
import pty
import sys
import threading
import time

lock = threading.Lock()


def crc16(data):
    crc = 0xFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return bytes([crc & 0xFF, crc >> 8])


def say(fd, slave, frame, delay=0.0):
    def write():
        if delay:
            time.sleep(delay)
        with lock:
            os.write(fd, frame)
        sys.stderr.write(f"{slave} {frame.hex(' ')}\n")
        sys.stderr.flush()

    if delay:
        threading.Thread(target=write, daemon=True).start()
    else:
        write()


def main():
    slaves = {}
    for spec in sys.argv[1:]:
        slave, habit = spec.split("=")
        name, _, arg = habit.partition(":")
        slaves[int(slave)] = [name, int(arg or 0)]
    master, slave_end = pty.openpty()
    os.set_blocking(master, True)
    print(os.ttyname(slave_end), flush=True)
    pending = b""
    while True:
        pending += os.read(master, 256)
        # Requests of function 03 are 8 bytes; anything that is not one is dropped.
        while len(pending) >= 8:
            frame, pending = pending[:8], pending[8:]
            if crc16(frame[:6]) != frame[6:] or frame[1] != 3:
                pending = b""
                break
            habit = slaves.get(frame[0])
            if habit is None:
                continue
            name, arg = habit
            if name == "exception":
                body = bytes([frame[0], 0x83, arg])
            else:
                body = bytes([frame[0], 3, 2, 0, 42 + frame[0]])
            answer = body + crc16(body)
            if name == "badcrc" and arg > 0:
                habit[1] -= 1
                answer = answer[:-1] + bytes([answer[-1] ^ 0xFF])
            say(master, frame[0], answer, arg / 1000 if name == "late" else 0.0)


if __name__ == "__main__":
    main()
