#!/usr/bin/env bash
# The whole test suite, as CI runs it: the outside peers the tests talk to are installed
# when missing, then formatting, lints and every test.
set -euo pipefail
cd "$(dirname "$0")/.."

# Debian packages: socat (pty pairs), tmux (a real terminal), mbpoll (a master we did not write), libmodbus-dev
# (the C slave of the benchmarks), libudev-dev and pkg-config (tokio-serial, under the
# tokio-modbus slave of the tests).
missing=()
command -v socat >/dev/null || missing+=(socat)
command -v mbpoll >/dev/null || missing+=(mbpoll)
command -v tmux >/dev/null || missing+=(tmux)
# tcpdump records the loopback, tshark (with editcap) is the reference dissector of the
# Modbus TCP capture tests.
command -v tcpdump >/dev/null || missing+=(tcpdump)
command -v tshark >/dev/null || missing+=(tshark)
command -v pkg-config >/dev/null || missing+=(pkg-config)
pkg-config --exists libudev 2>/dev/null || missing+=(libudev-dev)
pkg-config --exists libmodbus 2>/dev/null || missing+=(libmodbus-dev)
# InfluxDB 1.x, the server poll --influx writes to, and Prometheus with promtool, which
# read poll --metrics (each test starts its own).
command -v influxd >/dev/null || missing+=(influxdb)
command -v promtool >/dev/null || missing+=(prometheus)
# The mosquitto broker and its clients, which poll --mqtt publishes to (each test starts
# its own).
command -v mosquitto >/dev/null || missing+=(mosquitto)
command -v mosquitto_sub >/dev/null || missing+=(mosquitto-clients)
# nmap, whose modbus-discover script is the reference for scan --hosts.
command -v nmap >/dev/null || missing+=(nmap)
# libpcap at run time: sniff --interface loads it (tcpdump brings it too).
ldconfig -p 2>/dev/null | grep -q 'libpcap\.so' || missing+=(libpcap0.8)
if [ ${#missing[@]} -gt 0 ]; then
    echo "installing ${missing[*]}"
    sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
# pysunspec2 (PyPI): the SunSpec Alliance's own reading of a SunSpec device, and the
# device images of the sunspec tests laid out by it.
if ! python3 -c 'import sunspec2' 2>/dev/null; then
    echo "installing pysunspec2"
    python3 -m pip install --quiet pysunspec2
fi
# pymodbus (PyPI): a slave in RTU, ASCII and TCP, and a master.
if ! python3 -c 'import pymodbus, serial' 2>/dev/null; then
    echo "installing pymodbus"
    python3 -m pip install --quiet pymodbus pyserial
fi

# Home Assistant (PyPI), the reference reader of its own modbus configurations, in a
# virtual environment of its own: it pins its own pymodbus.
home_assistant=target/home-assistant
if ! "$home_assistant/bin/python" -c 'import homeassistant.components.modbus' 2>/dev/null; then
    echo "installing Home Assistant"
    rm -rf "$home_assistant"
    python3 -m venv "$home_assistant"
    "$home_assistant/bin/pip" install --quiet homeassistant==2024.3.3 pymodbus==3.6.6
fi

cargo fmt --all -- --check
cargo clippy --workspace --all-targets --quiet -- -D warnings
cargo test --workspace --all-targets
# The core's API documentation builds without a broken link.
RUSTDOCFLAGS="-D warnings" cargo doc --package mbtool-core --no-deps --quiet
