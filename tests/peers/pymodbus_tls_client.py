#!/usr/bin/env python3
"""pymodbus as a master over Modbus/TCP Security (or plain Modbus TCP): reads and writes
slave 17 and prints what it read, one JSON object, for a test to compare.

    pymodbus_tls_client.py PORT --tls CERT,KEY,CA
    pymodbus_tls_client.py PORT               (plain Modbus TCP)
"""
import argparse
import json
import ssl

from pymodbus.client import ModbusTcpClient, ModbusTlsClient


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("port", type=int)
    parser.add_argument("--tls", metavar="CERT,KEY,CA")
    args = parser.parse_args()
    if args.tls:
        cert, key, ca = args.tls.split(",")
        sslctx = ssl.SSLContext(ssl.PROTOCOL_TLS_CLIENT)
        sslctx.load_cert_chain(cert, key)
        sslctx.load_verify_locations(ca)
        # pymodbus gives no server name to check; the CA is checked all the same.
        sslctx.check_hostname = False
        client = ModbusTlsClient("localhost", port=args.port, sslctx=sslctx, timeout=5, retries=0)
    else:
        client = ModbusTcpClient("127.0.0.1", port=args.port, timeout=5, retries=0)
    if not client.connect():
        raise SystemExit("cannot connect")
    seen = {}
    seen["holding"] = client.read_holding_registers(107, count=3, device_id=17).registers
    client.write_register(1, 4711, device_id=17)
    client.write_registers(2, [1, 2, 3], device_id=17)
    seen["written"] = client.read_holding_registers(1, count=4, device_id=17).registers
    client.write_coil(172, True, device_id=17)
    seen["coil"] = client.read_coils(172, count=1, device_id=17).bits[:1]
    seen["inputs"] = client.read_input_registers(8, count=1, device_id=17).registers
    client.close()
    print(json.dumps(seen))


if __name__ == "__main__":
    main()
