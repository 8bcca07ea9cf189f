#!/usr/bin/env python3
"""A pymodbus master for mbtool's tests: runs a fixed script of reads and writes against
slave 17 and prints one JSON object with what it read.

    pymodbus_master.py --framer ascii --serial /dev/pts/5
    pymodbus_master.py --tcp 5020 --every-function
    pymodbus_master.py --udp 5020 --records
"""
import argparse
import json

from pymodbus import FramerType
from pymodbus.client import ModbusSerialClient, ModbusTcpClient, ModbusUdpClient
from pymodbus.pdu.file_message import FileRecord


def answer(response):
    """What a response says, as JSON: its fields, or the exception code."""
    if response.isError():
        return {"exception": getattr(response, "exception_code", None)}
    fields = {}
    for name in ("registers", "status", "message", "identifier", "information", "values"):
        value = getattr(response, name, None)
        if isinstance(value, bytes):
            value = value.hex()
        elif isinstance(value, dict):
            value = {str(k): v.hex() if isinstance(v, bytes) else v for k, v in value.items()}
        if value not in (None, [], b""):
            fields[name] = value
    bits = getattr(response, "bits", None)
    if bits:
        fields["bits"] = [int(b) for b in bits]
    return fields


def every_function(client, out, skip):
    """The functions past reads and writes, each answer recorded as it comes."""
    out["exception_status"] = answer(client.read_exception_status(device_id=17))
    out["diagnostics_echo"] = answer(client.diag_query_data(b"\x12\x34", device_id=17))
    out["server_id"] = answer(client.report_device_id(device_id=17))
    out["mask_write"] = answer(client.mask_write_register(address=5, and_mask=0xF0F0, or_mask=0x0505, device_id=17))
    out["after_mask"] = client.read_holding_registers(5, count=1, device_id=17).registers
    out["read_write"] = answer(client.readwrite_registers(read_address=10, read_count=3, write_address=20, values=[4, 5], device_id=17))
    out["device_identification"] = answer(client.read_device_information(read_code=1, object_id=0, device_id=17))
    if "fifo" not in skip:
        # The FIFO queue of the specification's example, where mbtool's built-in slave keeps it.
        out["fifo"] = answer(client.read_fifo_queue(address=0x04DE, device_id=17))


def records(client, out):
    """Functions 20-24 on the specification's examples, as mbtool's built-in slave holds them."""
    asked = [
        FileRecord(file_number=4, record_number=1, record_length=4),
        FileRecord(file_number=3, record_number=9, record_length=4),
    ]
    read = client.read_file_record(asked, device_id=17)
    out["file_records"] = [record.record_data.hex() for record in read.records]
    written = FileRecord(file_number=4, record_number=7, record_data=bytes.fromhex("06af04be100d"))
    out["file_write"] = answer(client.write_file_record([written], device_id=17))
    again = client.read_file_record([FileRecord(file_number=4, record_number=7, record_length=6)], device_id=17)
    out["file_written"] = [record.record_data.hex() for record in again.records]
    out["file_zero"] = answer(client.read_file_record([FileRecord(file_number=0, record_number=1, record_length=2)], device_id=17))
    out["fifo"] = answer(client.read_fifo_queue(address=0x04DE, device_id=17))
    out["fifo_missing"] = answer(client.read_fifo_queue(address=1, device_id=17))
    client.write_register(4, 0x12, device_id=17)
    out["mask_write"] = answer(client.mask_write_register(address=4, and_mask=0xF2, or_mask=0x25, device_id=17))
    out["after_mask"] = client.read_holding_registers(4, count=1, device_id=17).registers
    out["read_write"] = answer(client.readwrite_registers(read_address=3, read_count=6, write_address=14, values=[255, 255, 255], device_id=17))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--framer", choices=["rtu", "ascii"])
    parser.add_argument("--serial")
    parser.add_argument("--tcp", type=int, help="a Modbus TCP server on 127.0.0.1")
    parser.add_argument("--udp", type=int, help="a Modbus/UDP server on 127.0.0.1")
    parser.add_argument("--every-function", action="store_true")
    parser.add_argument("--records", action="store_true", help="functions 20-24 alone")
    parser.add_argument(
        "--skip", action="append", default=[], help="fifo: a slave that never answers it"
    )
    args = parser.parse_args()
    if args.udp:
        client = ModbusUdpClient("127.0.0.1", port=args.udp, timeout=3)
    elif args.tcp:
        client = ModbusTcpClient("127.0.0.1", port=args.tcp, timeout=3)
    else:
        # A pseudo-terminal carries bytes: the line settings do not matter there.
        client = ModbusSerialClient(
            args.serial, framer=FramerType(args.framer), baudrate=19200, parity="N", timeout=2
        )
    if not client.connect():
        raise SystemExit("cannot connect")
    out = {}
    if args.records:
        records(client, out)
        print(json.dumps(out))
        return
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
    if args.every_function:
        every_function(client, out, args.skip)
    client.close()
    print(json.dumps(out, sort_keys=True))


if __name__ == "__main__":
    main()
