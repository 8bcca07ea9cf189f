#!/usr/bin/env python3
"""What Home Assistant's own modbus integration makes of configuration files.

usage: ha_reference.py FILE...

For each file, one JSON line: whether Home Assistant loads it (its YAML loader, with
!secret and !include, then the modbus CONFIG_SCHEMA), what it warns of, and every
entity it sets up with the state it would show when each register at address A of a
table holds register(table, A) and each bit bit(table, A), computed by the
integration's own entity classes. A file is taken as a user includes it: a mapping
with `modbus:` as a configuration, a list or mapping of hubs for `modbus: !include`,
a list of entities for `sensors: !include` (another platform where its keys say so),
in a hub named modbus_hub.
"""
import json
import logging
import sys
from pathlib import Path

import voluptuous as vol
from homeassistant.components import modbus
from homeassistant.components.modbus import binary_sensor as ha_binary
from homeassistant.components.modbus import sensor as ha_sensor
from homeassistant.util.yaml import loader

PLATFORMS = ["sensors", "binary_sensors", "switches", "lights", "fans", "covers", "climates"]
HUB_KEYS = {"type", "host", "port", "method", "baudrate"} | set(PLATFORMS)
TABLES = {"holding": 4, "input": 3, "coil": 0, "discrete_input": 1}


def register(table, address):
    """Printable ASCII in both bytes, so that strings decode; numbers of every size."""
    high = 0x41 + (address * 7 + TABLES[table]) % 26
    low = 0x41 + (address * 11 + 3) % 26
    return (high << 8) | low


def bit(table, address):
    return (address * 5 + TABLES[table]) % 3 == 0


class Warnings(logging.Handler):
    def __init__(self):
        super().__init__(logging.WARNING)
        self.messages = []

    def emit(self, record):
        self.messages.append(record.getMessage())


def platform_of(items):
    keys = set()
    for item in items:
        if isinstance(item, dict):
            keys |= set(map(str, item))
    if "target_temp_register" in keys:
        return "climates"
    if keys & {"status_register", "state_open"}:
        return "covers"
    if keys & {"write_type", "command_on", "verify"}:
        return "switches"
    kinds = {str(i.get("input_type")) for i in items if isinstance(i, dict)}
    if kinds and kinds <= {"coil", "discrete_input"}:
        return "binary_sensors"
    return "sensors"


def as_configuration(data):
    if isinstance(data, dict) and "modbus" in data:
        return data
    items = data if isinstance(data, list) else [data]
    if any(isinstance(i, dict) and HUB_KEYS & set(map(str, i)) for i in items):
        return {"modbus": data}
    hub = {"name": "modbus_hub", "type": "tcp", "host": "127.0.0.1", "port": 502}
    hub[platform_of(items)] = data
    return {"modbus": [hub]}


def states(platform, entity):
    """(name, table, address, state) of the entity and those its count adds."""
    slaves = entity.get("slave_count") or entity.get("virtual_count") or 0
    names = [entity["name"]] + [f"{entity['name']} {i + 1}" for i in range(slaves)]
    address = entity["address"]
    if platform in ("sensors", "climates"):
        table = entity.get("input_type", "holding")
        count = entity["count"] * (slaves + 1)
        registers = [register(table, address + i) for i in range(count)]
        sensor = ha_sensor.ModbusRegisterSensor(None, None, dict(entity), slaves)
        value = sensor.unpack_structure_result(registers)
        values = value.split(",") if slaves and value is not None else [value]
        return [(n, table, address + i * entity["count"], v) for i, (n, v) in enumerate(zip(names, values))]
    if platform == "binary_sensors":
        table = entity.get("input_type", "coil")
        out = []
        for i, name in enumerate(names):
            if table in ("coil", "discrete_input"):
                on = bit(table, address + i)
            else:
                on = register(table, address + i) & 1 == 1
            out.append((name, table, address + i, "on" if on else "off"))
        return out
    return [(entity["name"], None, address, None)]


def reference(path):
    warnings = Warnings()
    logging.getLogger().addHandler(warnings)
    try:
        data = loader.load_yaml(str(path), loader.Secrets(path.parent))
        configuration = modbus.CONFIG_SCHEMA(as_configuration(data))
    except Exception as error:  # the loader's and the schema's errors alike
        return {"file": path.name, "loads": False, "error": str(error).splitlines()[0]}
    finally:
        logging.getLogger().removeHandler(warnings)
    entities = []
    for hub in configuration["modbus"]:
        for platform in PLATFORMS:
            for entity in hub.get(platform, []):
                for name, table, address, state in states(platform, entity):
                    slave = entity.get("slave")
                    if slave is None:
                        slave = entity.get("device_address")
                    entities.append({
                        "platform": platform, "name": name, "table": table,
                        "address": address, "slave": slave, "state": state,
                    })
    return {"file": path.name, "loads": True, "warnings": warnings.messages, "entities": entities}


def main():
    logging.getLogger().setLevel(logging.WARNING)
    for name in sys.argv[1:]:
        print(json.dumps(reference(Path(name).resolve()), ensure_ascii=False), flush=True)


if __name__ == "__main__":
    main()
