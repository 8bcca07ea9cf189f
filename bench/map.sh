#!/usr/bin/env bash
# read --map of a 500-point map against `mbtool serve` on TCP: the requests it sends and its
# time, against the same points read one by one (--max-per-request 1), and the ratio.
#
#   bash bench/map.sh [RUNS]      (default: 20 reads of each)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-20}
cargo build --release --quiet
work=$(mktemp -d)
trap 'kill ${serve:-} 2>/dev/null; rm -rf "$work"' EXIT
# 500 one-register points over 400001-400550: u16, and i16 with a scale, with a hole
# after every tenth point (so that --max-per-request 1 reads them one by one).
python3 - "$work" <<'PY'
import sys
work = sys.argv[1]
points, data, address = ["name,ref,type,scale,unit"], [], 0
for i in range(500):
    kind = ["u16", "i16"][i % 2]
    width = 1
    points.append(f"p{i},{400001 + address},{kind},{'0.1' if kind == 'i16' else ''},")
    data.append(f"{400001 + address}-{400001 + address + width - 1} = {i}")
    address += width + (1 if i % 10 == 9 else 0)
open(f"{work}/map.csv", "w").write("\n".join(points) + "\n")
open(f"{work}/data.txt", "w").write("\n".join(data) + "\n")
PY
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
./target/release/mbtool serve --port "tcp://127.0.0.1:$port" --data "$work/data.txt" --quiet 2>/dev/null &
serve=$!
until ./target/release/mbtool --port "127.0.0.1:$port" read-holding 17 400001 >/dev/null 2>&1; do sleep 0.1; done
measure() {
    local label=$1; shift
    local requests
    requests=$(./target/release/mbtool --port "127.0.0.1:$port" read 17 --map "$work/map.csv" "$@" -v -o values 2>&1 >/dev/null | grep -c '] > ')
    local start end
    start=$(date +%s.%N)
    for _ in $(seq "$runs"); do
        ./target/release/mbtool --port "127.0.0.1:$port" read 17 --map "$work/map.csv" "$@" -o values >/dev/null
    done
    end=$(date +%s.%N)
    python3 -c "print(f'$label: $requests requests, {($end - $start) / $runs * 1e3:.1f} ms a read')"
    echo "$requests $(python3 -c "print(($end - $start) / $runs)")" > "$work/$label"
}
measure grouped
measure one-by-one --max-per-request 1
python3 - "$work" <<'PY'
import sys
work = sys.argv[1]
g = open(f"{work}/grouped").read().split()
o = open(f"{work}/one-by-one").read().split()
print(f"ratio: {int(o[0]) / int(g[0]):.1f}x fewer requests, {float(o[1]) / float(g[1]):.1f}x faster")
PY
