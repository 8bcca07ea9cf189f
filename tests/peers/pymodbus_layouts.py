#!/usr/bin/env python3
"""Writes one value in every type and byte order into slave 17 of a Modbus TCP server on
127.0.0.1, each at an address of its own, and prints what it wrote, a JSON line each:
{"address": protocol address, "registers": n, "type": "f32", "order": "CDAB", "value": "229.01"}.

The values are laid out by pymodbus's own converter (big-endian words and bytes, its
word_order for the word swap) and Python's struct, then reordered as the layout says.

    pymodbus_layouts.py PORT
"""
import json
import struct
import sys

from pymodbus.client import ModbusTcpClient

VALUES = [
    ("u16", "H", 51234),
    ("i16", "h", -1234),
    ("u32", "I", 3000000000),
    ("i32", "i", -123456789),
    ("f32", "f", 229.01),
    ("u64", "Q", 12345678901234567890),
    ("i64", "q", -1234567890123),
    ("f64", "d", -1234.5678),
]


def reorder(data, order):
    """Big-endian bytes in the order named: A the most significant byte."""
    words = [data[i:i + 2] for i in range(0, len(data), 2)]
    if order == "CDAB":
        words.reverse()
    elif order == "BADC":
        words = [w[::-1] for w in words]
    elif order == "DCBA":
        words = [w[::-1] for w in reversed(words)]
    return b"".join(words)


def main():
    client = ModbusTcpClient("127.0.0.1", port=int(sys.argv[1]), timeout=3)
    if not client.connect():
        raise SystemExit("cannot connect")
    address = 100
    for name, code, value in VALUES:
        big = struct.pack(">" + code, value)
        orders = ["ABCD", "BADC"] if len(big) == 2 else ["ABCD", "CDAB", "BADC", "DCBA"]
        for order in orders:
            data = reorder(big, order)
            registers = [int.from_bytes(data[i:i + 2], "big") for i in range(0, len(data), 2)]
            if order == "ABCD" and name in ("u32", "i32", "f32", "u64", "i64", "f64"):
                # The layout pymodbus itself writes these types in.
                data_type = getattr(client.DATATYPE, {"u32": "UINT32", "i32": "INT32",
                    "f32": "FLOAT32", "u64": "UINT64", "i64": "INT64", "f64": "FLOAT64"}[name])
                assert client.convert_to_registers(value, data_type) == registers, name
            client.write_registers(address, registers, device_id=17)
            print(json.dumps({"address": address, "registers": len(registers), "type": name,
                              "order": order, "value": repr(value)}))
            address += 10
    client.close()


if __name__ == "__main__":
    main()
