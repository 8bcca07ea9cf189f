#!/usr/bin/env bash
# Throughput of `mbtool sniff --input capture.bin` over a 100 MB capture: the real wizmodbus
# recording (tests/captures, 9600 8N1, frames with turnaround noise bytes) repeated.
# Four runs: JSON Lines, the table, and a filter that shows nothing (`--slave 250`: the
# framing and pairing alone), from the file and from standard input; then as many random
# bytes (pure noise: every position looked at, no frame to step by), filtered. Prints MB/s
# and frames/s, tshark's frames/s on the same frames, and the ratios. Each run is timed
# ROUNDS times (3 by default) and the best is shown, with the median beside it: on a shared
# machine the other tenants' load only ever adds.
#
#   bash bench/sniff.sh [MEGABYTES [ROUNDS]]
set -euo pipefail
cd "$(dirname "$0")/.."
megabytes=${1:-100}
rounds=${2:-3}
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
head -c "$bytes" /dev/urandom > "$work/noise.bin"
# The recording holds 88 frames in 804 bytes.
frames=$(( bytes / 804 * 88 ))
# The file is framed on every core while few frames are shown (the filter); standard input
# is framed in order, as a pipe from a live line must be: the last run shows the difference.
rates="$work/rates"
for options in "-o json" "-o table" "-o json --slave 250" "-o json --slave 250 --input -" \
    "-o json --slave 250 noise"; do
    capture="$work/capture.bin"
    if [[ $options == *noise ]]; then
        capture="$work/noise.bin"
        options=${options% noise}
    fi
    input=("--input" "$capture")
    [[ $options == *"--input -"* ]] && input=()
    times=()
    for _ in $(seq "$rounds"); do
        start=$(date +%s.%N)
        # shellcheck disable=SC2086
        ./target/release/mbtool sniff -b 9600 --parity none "${input[@]}" $options < "$capture" > /dev/null
        end=$(date +%s.%N)
        times+=("$(python3 -c "print($end - $start)")")
    done
    list=$(IFS=,; echo "${times[*]}")
    what=$([[ $capture == *noise.bin ]] && echo "random bytes" || echo "the recording")
    python3 -c "
times = sorted([$list])
s, median = times[0], times[len(times) // 2]
noise = '$what' == 'random bytes'
frames = '' if noise else f', {$frames/s:,.0f} frames/s'
held = '' if noise else f' ({$frames:,} frames)'
print(f'mbtool sniff $options > /dev/null: {$bytes/1e6:.0f} MB of $what{held} in {s:.2f} s '
      f'(best of {len(times)}; median {median:.2f} s) = {$bytes/1e6/s:.1f} MB/s{frames}')
print('$options' + ('' if noise else ' recording'), $frames / s, file=open('$rates', 'a'))"
done

# Wireshark on the same frames, already framed: sniff writes them as a pcap (DLT_USER0,
# Modbus RTU), and tshark dissects every one. Over the first hundredth and the first tenth
# of the capture, since tshark is far slower. Its time per frame is not the same for every
# file: on traffic with many unanswered requests its Modbus dissector slows as the file
# grows (ten times the frames took a hundred times as long on one such capture). Both sizes
# are shown, so that the rate is seen to hold on these frames before it is compared.
if command -v tshark > /dev/null; then
    for part in 100 10; do
        head -c $(( bytes / part / 804 * 804 )) "$work/capture.bin" > "$work/part.bin"
        ./target/release/mbtool sniff -b 9600 --parity none --input "$work/part.bin" \
            --pcap "$work/frames.pcap" -o json > /dev/null
        part_frames=$(( $(stat -c %s "$work/part.bin") / 804 * 88 ))
        start=$(date +%s.%N)
        tshark -r "$work/frames.pcap" -n \
            -o 'uat:user_dlts:"User 0 (DLT=147)","mbrtu","0","","0",""' \
            -T fields -e modbus.func_code > /dev/null 2>&1
        end=$(date +%s.%N)
        python3 -c "
s = $end - $start
print(f'tshark -T fields on the first 1/$part of the frames, pcap: {$part_frames:,} frames in {s:.2f} s = {$part_frames/s:,.0f} frames/s')
print('tshark', $part_frames / s, file=open('$rates', 'a'))"
    done
    # Against tshark's better rate of the two; random bytes hold no frame for tshark.
    python3 - "$rates" <<'PY'
import sys
rates = [line.rsplit(' ', 1) for line in open(sys.argv[1]).read().splitlines()]
tshark = max(float(rate) for what, rate in rates if what == 'tshark')
for what, rate in rates:
    if what.endswith(' recording'):
        print(f'mbtool sniff {what[:-len(" recording")]} frames {float(rate) / tshark:.1f} times as fast as tshark')
PY
else
    echo "tshark: not installed, no figure beside mbtool's"
fi
