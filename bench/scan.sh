#!/usr/bin/env bash
# Time of `mbtool scan --ids 1-247` over a pseudo-terminal pair against `mbtool serve` with
# three ids, against its floor: the silent ids times the timeout (the answered ones are
# asked twice and cost a round trip each). Then the same arithmetic for a real line.
#
#   bash bench/scan.sh [TIMEOUT_MS ...]      (default: 20 100)
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
work=$(mktemp -d)
socat "pty,raw,echo=0,link=$work/a" "pty,raw,echo=0,link=$work/b" &
socat=$!
trap 'kill $socat ${serve:-} 2>/dev/null; rm -rf "$work"' EXIT
while [ ! -e "$work/b" ]; do sleep 0.05; done
./target/release/mbtool serve --port "$work/a" --slave 3 --slave 17 --slave 200 --quiet &
serve=$!
until ./target/release/mbtool --port "$work/b" read-holding 17 1 --timeout 200ms >/dev/null 2>&1; do
    sleep 0.1
done
for timeout in "${@:-20 100}"; do
    for t in $timeout; do
        start=$(date +%s.%N)
        ./target/release/mbtool --port "$work/b" scan --timeout "${t}ms" -o values > "$work/found"
        end=$(date +%s.%N)
        python3 - "$start" "$end" "$t" "$(paste -sd, "$work/found")" <<'PY'
import sys
start, end, timeout_ms, found = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
took = end - start
floor = (247 - 3) * timeout_ms / 1000
print(f"scan --timeout {timeout_ms}ms on a pty: {took:.2f} s, found {found}; "
      f"floor {floor:.2f} s (244 silent ids x {timeout_ms} ms); ratio {took / floor:.3f}")
PY
    done
done
# A real line adds the request's time on the wire and the silence before the next one;
# scan's default timeout is 100 ms plus the time of a 7-byte answer at the baud rate.
python3 - <<'PY'
for baud in (19200, 9600):
    char = 11 / baud
    request = 8 * char
    t35 = 3.5 * char if baud <= 19200 else 0.00175
    timeout = 0.100 + 7 * char
    per_id = request + t35 + timeout
    print(f"at {baud} baud, default timeout: {request * 1e3:.2f} ms request + {t35 * 1e3:.2f} ms "
          f"t3.5 + {timeout * 1e3:.1f} ms = {per_id * 1e3:.1f} ms a silent id; "
          f"247 ids {247 * per_id:.1f} s")
PY
