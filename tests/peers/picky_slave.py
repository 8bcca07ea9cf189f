#!/usr/bin/env python3
"""A slave that answers only at its own serial settings, for testing scan's sweep.

It holds both ends of a pseudo-terminal, prints the path a master opens, and before each
answer reads the master's line settings on its own end with the TCGETS2 ioctl (a master
that sets any baud rate through termios2 leaves BOTHER in the old termios): a Linux pty
keeps the baud rate and the odd-parity bit set on it (it clears PARENB and forces 8 data
bits). It answers a read of holding registers as slave ID when the baud rate is BAUD
and the odd-parity bit is as PARITY says, and stays silent otherwise.

    picky_slave.py --id 17 --baud 38400 --parity odd
"""
import argparse
import fcntl
import os
import pty
import struct
import sys
import termios
import time

# struct termios2 on Linux: four flags, the line discipline, 19 control characters, and
# the input and output speeds.
TERMIOS2 = struct.Struct("4IB19s2I")
TCGETS2 = 0x802C542A


def line_settings(fd):
    """(baud, odd parity) as the master set them."""
    raw = fcntl.ioctl(fd, TCGETS2, bytes(TERMIOS2.size))
    _, _, cflag, _, _, _, _, ospeed = TERMIOS2.unpack(raw)
    return ospeed, bool(cflag & termios.PARODD)


def crc16(data):
    crc = 0xFFFF
    for byte in data:
        crc ^= byte
        for _ in range(8):
            crc = (crc >> 1) ^ 0xA001 if crc & 1 else crc >> 1
    return bytes([crc & 0xFF, crc >> 8])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--id", type=int, required=True)
    parser.add_argument("--baud", type=int, required=True)
    parser.add_argument("--parity", choices=["odd", "even-or-none"], required=True)
    args = parser.parse_args()
    master, slave = pty.openpty()
    print(os.ttyname(slave), flush=True)
    pending = b""
    while True:
        pending += os.read(master, 256)
        time.sleep(0.003)
        while len(pending) >= 8:
            frame, pending = pending[:8], pending[8:]
            if crc16(frame[:6]) != frame[6:] or frame[1] != 3:
                pending = b""
                break
            baud, odd = line_settings(slave)
            if baud != args.baud or odd != (args.parity == "odd") or frame[0] != args.id:
                continue
            body = bytes([args.id, 3, 2, 0, 42])
            os.write(master, body + crc16(body))
            sys.stderr.write(f"answered at {baud} {'odd' if odd else 'even-or-none'}\n")


if __name__ == "__main__":
    main()
