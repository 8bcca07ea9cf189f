#!/usr/bin/env bash
# Throughput of `mbtool sniff --input capture.bin` over a 100 MB capture: the real wizmodbus
# recording (tests/captures, 9600 8N1, frames with turnaround noise bytes) repeated.
# Three runs: JSON Lines, the table, and a filter that shows nothing (`--slave 250`: the
# framing and pairing alone). Prints MB/s and frames/s.
#
#   bash bench/sniff.sh [MEGABYTES]
set -euo pipefail
cd "$(dirname "$0")/.."
megabytes=${1:-100}
cargo build --release --quiet
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$megabytes" "$work/capture.bin" <<'PY'
import sys
source = open("tests/captures/wizmodbus.bin", "rb").read()
size = int(sys.argv[1]) * 1000 * 1000
with open(sys.argv[2], "wb") as out:
    out.write(source * (size // len(source)))
PY
bytes=$(stat -c %s "$work/capture.bin")
# The recording holds 88 frames in 804 bytes.
frames=$(( bytes / 804 * 88 ))
for options in "-o json" "-o table" "-o json --slave 250"; do
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    ./target/release/mbtool sniff -b 9600 --parity none --input "$work/capture.bin" $options > /dev/null
    end=$(date +%s.%N)
    python3 -c "
s = $end - $start
print(f'mbtool sniff $options > /dev/null: {$bytes/1e6:.0f} MB, {$frames:,} frames in {s:.2f} s = {$bytes/1e6/s:.1f} MB/s, {$frames/s:,.0f} frames/s')"
done
