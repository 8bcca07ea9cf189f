#!/usr/bin/env python3
"""A pymodbus master for mbtool's tests: runs a fixed script of reads and writes against
slave 17 and prints one JSON object with what it read.

    pymodbus_master.py --framer ascii --serial /dev/pts/5
"""
import argparse
import json

from pymodbus import FramerType
from pymodbus.client import ModbusSerialClient


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--framer", choices=["rtu", "ascii"], required=True)
    parser.add_argument("--serial", required=True)
    args = parser.parse_args()
    # A pseudo-terminal carries bytes: the line settings do not matter there.
    client = ModbusSerialClient(
        args.serial, framer=FramerType(args.framer), baudrate=19200, parity="N", timeout=2
    )
    if not client.connect():
        raise SystemExit("cannot open " + args.serial)
    out = {}
    out["holding"] = client.read_holding_registers(107, count=3, device_id=17).registers
    out["input_register"] = client.read_input_registers(8, count=1, device_id=17).registers
    out["coils"] = [int(b) for b in client.read_coils(19, count=8, device_id=17).bits[:8]]
    out["inputs"] = [int(b) for b in client.read_discrete_inputs(196, count=8, device_id=17).bits[:8]]
    client.write_register(1, 1234, device_id=17)
    client.write_registers(10, [7, 8, 9], device_id=17)
    client.write_coil(172, True, device_id=17)
    client.write_coils(99, [True, False, True], device_id=17)
    out["written_registers"] = client.read_holding_registers(1, count=1, device_id=17).registers + \
        client.read_holding_registers(10, count=3, device_id=17).registers
    out["written_coils"] = [int(b) for b in client.read_coils(99, count=3, device_id=17).bits[:3]] + \
        [int(client.read_coils(172, count=1, device_id=17).bits[0])]
    client.close()
    print(json.dumps(out))


if __name__ == "__main__":
    main()
