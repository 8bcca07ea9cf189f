#!/usr/bin/env python3
"""A plant read by pymodbus as a Telegraf-style configuration describes it: for each
device (a TCP port and a slave) its fields, each an address (0-based), a data type
(UINT16, INT16, UINT32, FLOAT32), a byte order (ABCD, CDAB) and a scale. Reads the
configuration as JSON on stdin and prints {device: {field: value}} as JSON.
"""
import json
import sys

from pymodbus.client import ModbusTcpClient

TYPES = {
    "UINT16": ModbusTcpClient.DATATYPE.UINT16,
    "INT16": ModbusTcpClient.DATATYPE.INT16,
    "UINT32": ModbusTcpClient.DATATYPE.UINT32,
    "FLOAT32": ModbusTcpClient.DATATYPE.FLOAT32,
}


def main():
    devices = json.load(sys.stdin)
    read = {}
    for device in devices:
        client = ModbusTcpClient("127.0.0.1", port=device["port"], timeout=3)
        client.connect()
        fields = {}
        for field in device["fields"]:
            data_type = TYPES[field["data_type"]]
            count = 2 if field["data_type"] in ("UINT32", "FLOAT32") else 1
            response = client.read_holding_registers(field["address"], count=count, device_id=device["slave"])
            if response.isError():
                sys.exit(f"{device['name']} {field['name']}: {response}")
            word_order = "little" if field["byte_order"] == "CDAB" else "big"
            value = client.convert_from_registers(response.registers, data_type, word_order=word_order)
            fields[field["name"]] = value * field["scale"]
        client.close()
        read[device["name"]] = fields
    json.dump(read, sys.stdout)


if __name__ == "__main__":
    main()
