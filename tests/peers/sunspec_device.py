#!/usr/bin/env python3
"""A SunSpec device image laid out by pysunspec2 (the SunSpec Alliance's own library), and
pysunspec2's reading of a device, for holding `mbtool sunspec` to it.

    sunspec_device.py image BASE DATA_FILE JSON_FILE
        Lays out common (1), three-phase inverter (103), nameplate (120), settings (121),
        multiple MPPT (160, two modules), a vendor's model pysunspec2 has no definition
        of, and the end marker, from register BASE (0-based); writes them as an
        `mbtool serve --data` file, and as pysunspec2's JSON device image.
    sunspec_device.py tcp PORT UNIT
        Scans the device on 127.0.0.1:PORT with pysunspec2's Modbus TCP client.
    sunspec_device.py file JSON_FILE
        Reads the JSON device image with pysunspec2's file client (its device simulation).

The two readings print one JSON object: {"requests": n, "points": {name: value}}, every
point pysunspec2 gives a value, pads left out, scale factors applied, named as mbtool names
them in a map (model name, group and its instance, point: `mppt.module_2.DCA`).
"""
import json
import sys

import sunspec2.device as device
import sunspec2.file.client as file_client
import sunspec2.modbus.client as modbus_client

# A vendor's model: no published definition, so its registers are only skipped.
VENDOR_MODEL = [64999, 4, 1, 2, 3, 4]

MODELS = [
    {"ID": 1, "Mn": "SunSpecTest", "Md": "Inverter 5000", "Vr": "1.2.3", "SN": "SN-0042",
     "DA": 1},
    {"ID": 103, "A": 1234, "AphA": 411, "AphB": 412, "A_SF": -2,
     "PPVphAB": 4001, "PPVphBC": 4002, "PPVphCA": 4003,
     "PhVphA": 2301, "PhVphB": 2302, "PhVphC": 2303, "V_SF": -1,
     "W": 5012, "W_SF": 0, "Hz": 5001, "Hz_SF": -2, "VA": 5100, "VA_SF": 0,
     "PF": -95, "PF_SF": -2, "WH": 123456789, "WH_SF": 0,
     "DCA": 1100, "DCA_SF": -2, "DCV": 4500, "DCV_SF": -1, "DCW": 5200, "DCW_SF": 0,
     "TmpCab": 451, "Tmp_SF": -1, "St": 4, "StVnd": 7, "Evt1": 0b101},
    {"ID": 120, "DERTyp": 4, "WRtg": 5000, "WRtg_SF": 0, "VARtg": 5500, "VARtg_SF": 0,
     "ARtg": 2200, "ARtg_SF": -2, "PFRtgQ1": -800, "PFRtgQ4": 800, "PFRtg_SF": -3},
    {"ID": 121, "WMax": 5000, "WMax_SF": 0, "VRef": 230, "VRef_SF": 0, "VRefOfs": 0,
     "VRefOfs_SF": 0, "VMax": 2530, "VMin": 1960, "VMinMax_SF": -1, "ECPNomHz": 50,
     "ECPNomHz_SF": 0},
    {"ID": 160, "DCA_SF": -2, "DCV_SF": -1, "DCW_SF": 0, "DCWH_SF": 0, "Evt": 0, "N": 2,
     "module": [
         {"ID": 1, "IDStr": "PV1", "DCA": 512, "DCV": 3801, "DCW": 1946, "DCWH": 98765,
          "Tms": 1000, "Tmp": 35, "DCSt": 4},
         {"ID": 2, "IDStr": "PV2", "DCA": 498, "DCV": 3799, "DCW": 1892, "DCWH": 97531,
          "Tms": 1000, "Tmp": 36, "DCSt": 4},
     ]},
]


def registers(data):
    return [int.from_bytes(data[i:i + 2], "big") for i in range(0, len(data), 2)]


def image(base, data_path, json_path):
    words = registers(b"SunS")
    models = []
    for values in MODELS:
        model = device.Model(values["ID"], data=values)
        data = model.get_mb()
        model_words = registers(data)
        model_words[1] = len(model_words) - 2
        words += model_words
        values = dict(values, L=model_words[1])
        models.append(values)
    words += VENDOR_MODEL
    words += [0xFFFF, 0]
    with open(data_path, "w") as out:
        out.write("# A SunSpec device laid out by pysunspec2\n")
        out.write("4%05d = %s\n" % (base + 1, " ".join(str(w) for w in words)))
    with open(json_path, "w") as out:
        json.dump({"name": "mbtool test device", "models": models}, out, indent=1)


def points_of(group, prefix, out):
    for name, point in group.points.items():
        if point.pdef.get("type") == "pad":
            continue
        value = point.cvalue
        if value is not None:
            out[prefix + "." + name] = value
    for name, inner in group.groups.items():
        if isinstance(inner, list):
            for index, instance in enumerate(inner, start=1):
                points_of(instance, "%s.%s_%d" % (prefix, name, index), out)
        else:
            points_of(inner, prefix + "." + name, out)


def reading(dev, requests):
    points = {}
    seen = {}
    for model in dev.model_list:
        if model.gdef is None:
            continue
        name = model.gdef["name"]
        seen[name] = seen.get(name, 0) + 1
        if seen[name] > 1:
            name = "%s_%d" % (name, seen[name])
        points_of(model, name, points)
    print(json.dumps({"requests": requests, "points": points}))


def tcp(port, unit):
    dev = modbus_client.SunSpecModbusClientDeviceTCP(slave_id=unit, ipaddr="127.0.0.1",
                                                     ipport=port, timeout=5)
    asked = [0]
    read = dev.read

    def counted(addr, count, *args, **kwargs):
        asked[0] += 1
        return read(addr, count, *args, **kwargs)

    dev.read = counted
    dev.scan()
    reading(dev, asked[0])
    dev.close()


def from_file(json_path):
    dev = file_client.FileClientDevice(json_path)
    dev.scan()
    reading(dev, 0)


if __name__ == "__main__":
    if sys.argv[1] == "image":
        image(int(sys.argv[2]), sys.argv[3], sys.argv[4])
    elif sys.argv[1] == "tcp":
        tcp(int(sys.argv[2]), int(sys.argv[3]))
    else:
        from_file(sys.argv[2])
