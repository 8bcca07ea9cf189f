#!/usr/bin/env python3
"""A pymodbus slave for mbtool's tests: RTU or ASCII on a serial device, or TCP on 127.0.0.1.

    pymodbus_slave.py --framer rtu --serial /dev/pts/5
    pymodbus_slave.py --framer socket --tcp 5020 --identity VendorName=ACME ...
    pymodbus_slave.py --framer tls --tcp 8802 --tls server.pem,server.key,ca.pem
    pymodbus_slave.py --framer socket --udp 5020
"""
import argparse
import ssl

from pymodbus import FramerType
from pymodbus.datastore import (
    ModbusDeviceContext,
    ModbusSequentialDataBlock,
    ModbusSparseDataBlock,
    ModbusServerContext,
)
from pymodbus.pdu.device import ModbusDeviceIdentification
from pymodbus.server import StartSerialServer, StartTcpServer, StartTlsServer, StartUdpServer

SIZE = 5000


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--framer", choices=["rtu", "ascii", "socket", "tls"], required=True)
    parser.add_argument("--serial")
    parser.add_argument("--tcp", type=int)
    parser.add_argument("--udp", type=int, help="Modbus/UDP on 127.0.0.1")
    parser.add_argument("--address", default="127.0.0.1", help="where --tcp listens")
    parser.add_argument(
        "--every-unit", action="store_true", help="answer every unit id, as one device"
    )
    parser.add_argument(
        "--tls",
        metavar="CERT,KEY,CA",
        help="Modbus/TCP Security: this certificate and key, clients' certificates signed by CA",
    )
    parser.add_argument("--identity", action="append", default=[], metavar="NAME=VALUE")
    parser.add_argument(
        "--holding",
        metavar="ADDRESS=VALUE,...",
        help="only these holding registers exist (protocol addresses); the others are holes",
    )
    args = parser.parse_args()
    identity = ModbusDeviceIdentification(
        info_name=dict(item.split("=", 1) for item in args.identity)
    )

    def block():
        # pymodbus counts block addresses from 1; protocol address 0 is its first cell.
        return ModbusSequentialDataBlock(1, [0] * SIZE)

    holding = block()
    if args.holding:
        # A sparse block's keys are protocol addresses, unlike a sequential block's start.
        cells = dict(item.split("=") for item in args.holding.split(","))
        holding = ModbusSparseDataBlock({int(a): int(v) for a, v in cells.items()})
    device = ModbusDeviceContext(di=block(), co=block(), ir=block(), hr=holding)
    context = ModbusServerContext(devices=device if args.every_unit else {17: device},
                                  single=args.every_unit)
    framer = FramerType(args.framer)
    if args.tcp and args.tls:
        cert, key, ca = args.tls.split(",")
        sslctx = ssl.SSLContext(ssl.PROTOCOL_TLS_SERVER)
        sslctx.load_cert_chain(cert, key)
        sslctx.load_verify_locations(ca)
        sslctx.verify_mode = ssl.CERT_REQUIRED
        StartTlsServer(
            context,
            framer=framer,
            identity=identity,
            address=("127.0.0.1", args.tcp),
            sslctx=sslctx,
        )
    elif args.udp:
        StartUdpServer(
            context, framer=framer, identity=identity, address=("127.0.0.1", args.udp)
        )
    elif args.tcp:
        StartTcpServer(
            context, framer=framer, identity=identity, address=(args.address, args.tcp)
        )
    else:
        # A pseudo-terminal carries bytes, not bits: line settings mean nothing there, and
        # pyserial's even parity is refused by the pty driver.
        StartSerialServer(
            context,
            framer=framer,
            identity=identity,
            port=args.serial,
            baudrate=19200,
            bytesize=8,
            parity="N",
            stopbits=1,
        )


if __name__ == "__main__":
    main()
