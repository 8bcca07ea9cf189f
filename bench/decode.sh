#!/usr/bin/env bash
# Frames per second of `mbtool decode` over a file of 1,000,000 RTU frames (the worked
# frames of the manuals, repeated), with output to /dev/null: as bare hex, and as log
# lines (mbtool's own -v trace, a time stamp and a direction mark before each frame).
#
#   bash bench/decode.sh [FRAMES]
set -euo pipefail
cd "$(dirname "$0")/.."
frames=${1:-1000000}
cargo build --release --quiet
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$frames" > "$work/frames.txt" <<'PY'
import sys
worked = [
    "11 01 00 13 00 25 0E 84", "11 01 05 CD 6B B2 0E 1B 45 E6",
    "11 02 00 C4 00 16 BA A9", "11 02 03 AC DB 35 20 18",
    "11 03 00 6B 00 03 76 87", "11 03 06 02 2B 00 00 00 64 C8 BA",
    "11 04 00 08 00 01 B2 98", "11 04 02 00 0A F8 F4",
    "11 05 00 AC FF 00 4E 8B", "11 06 00 01 00 03 9A 9B",
    "11 10 00 01 00 02 04 00 0A 01 02 C6 F0", "11 10 00 01 00 02 12 98",
]
n = int(sys.argv[1])
out = sys.stdout
for i in range(n):
    out.write(worked[i % len(worked)] + "\n")
PY
awk '{ printf "[%12.6f] %s %s\n", NR / 1000, (NR % 2 ? ">" : "<"), $0 }' \
    "$work/frames.txt" > "$work/trace.txt"
for input in frames trace; do
    size=$(du -h "$work/$input.txt" | cut -f1)
    for format in json values; do
        start=$(date +%s.%N)
        ./target/release/mbtool decode -o "$format" < "$work/$input.txt" > /dev/null
        end=$(date +%s.%N)
        python3 -c "
s = $end - $start
print(f'mbtool decode -o $format, $input: $frames frames ($size) in {s:.2f} s = {$frames / s:,.0f} frames/s')"
    done
done
