//! The examples of each command's `--help` (and of its man page), each a command line a
//! test runs.

/// One example: what it does and the command line.
pub struct Example {
    pub what: &'static str,
    pub command: &'static str,
}

const fn ex(what: &'static str, command: &'static str) -> Example {
    Example { what, command }
}

/// Examples by subcommand; `""` is the top-level page.
const EXAMPLES: &[(&str, &[Example])] = &[
    (
        "",
        &[
            ex(
                "Decode a frame copied from a log",
                "mbtool decode 11 03 00 6B 00 03 76 87",
            ),
            ex(
                "Build the request that reads holding registers 400108-400110 of slave 17",
                "mbtool encode read-holding 17 400108 3",
            ),
            ex(
                "The same request as a Modbus ASCII frame",
                "mbtool encode --mode ascii read-holding 17 400108 3",
            ),
        ],
    ),
    (
        "read-coils",
        &[ex(
            "Read coils 000020-000056 of slave 17",
            "mbtool --port /dev/ttyUSB0 read-coils 17 000020 37",
        )],
    ),
    (
        "read-inputs",
        &[ex(
            "Read discrete inputs 100197-100218 of slave 17",
            "mbtool --port /dev/ttyUSB0 read-inputs 17 100197-100218",
        )],
    ),
    (
        "read-holding",
        &[
            ex(
                "Read holding registers 400108-400110 of slave 17",
                "mbtool --port /dev/ttyUSB0 read-holding 17 400108 3",
            ),
            ex(
                "Read two 32-bit floats stored low word first",
                "mbtool --port tcp://10.0.0.5 read-holding 1 400001 2 --type f32 --order CDAB",
            ),
        ],
    ),
    (
        "read-input-registers",
        &[ex(
            "Read input register 300009 of slave 17",
            "mbtool --port /dev/ttyUSB0 read-input-registers 17 300009",
        )],
    ),
    (
        "read",
        &[
            ex(
                "Read by reference: the 4 picks the holding registers",
                "mbtool --port /dev/ttyUSB0 read 17 400108 3",
            ),
            ex(
                "The meter shows 229 V: which type and byte order give it, and the map line",
                "mbtool --port tcp://10.0.0.5 read 1 400001 10 --expect 228..230",
            ),
        ],
    ),
    (
        "write-coil",
        &[ex(
            "Switch coil 000173 of slave 17 on",
            "mbtool --port /dev/ttyUSB0 write-coil 17 000173 on",
        )],
    ),
    (
        "write-coils",
        &[ex(
            "Write five coils from 000020 as a bit string",
            "mbtool --port /dev/ttyUSB0 write-coils 17 000020 10110",
        )],
    ),
    (
        "write-register",
        &[ex(
            "Write 3 to holding register 400002 of slave 17",
            "mbtool --port /dev/ttyUSB0 write-register 17 400002 3",
        )],
    ),
    (
        "write-registers",
        &[ex(
            "Write 0x000A and 0x0102 to 400002-400003",
            "mbtool --port /dev/ttyUSB0 write-registers 17 400002 0x000A 0x0102",
        )],
    ),
    (
        "write",
        &[
            ex(
                "Write a 32-bit float to 400001-400002",
                "mbtool --port /dev/ttyUSB0 write 17 400001 3.14 --type f32",
            ),
            ex(
                "Write two registers one at a time (function 06)",
                "mbtool --port /dev/ttyUSB0 write 17 400001 1 2 --function 6",
            ),
        ],
    ),
    (
        "read-file",
        &[
            ex(
                "Read records 1-2 of file 4 and 9-10 of file 3 in one request",
                "mbtool --port /dev/ttyUSB0 read-file 17 4:1 2 3:9 2",
            ),
            ex(
                "Read a meter's history of 50 floats from file 2",
                "mbtool --port udp://10.0.0.5 read-file 1 2:0 50 --type f32 -o csv",
            ),
        ],
    ),
    (
        "write-file",
        &[ex(
            "Write records 7-9 of file 4",
            "mbtool --port /dev/ttyUSB0 write-file 17 4:7 0x06AF 0x04BE 0x100D",
        )],
    ),
    (
        "mask-write",
        &[
            ex(
                "Set bit 5 of 400108 alone, in the device, with one request",
                "mbtool --port /dev/ttyUSB0 mask-write 17 400108.05=1",
            ),
            ex(
                "Keep the bits of AND 00F2, set those of OR 0025 among the others",
                "mbtool --port /dev/ttyUSB0 mask-write 17 400005 0x00F2 0x0025",
            ),
        ],
    ),
    (
        "read-write",
        &[ex(
            "Write 400015-400017, then read 400004-400009, in one transaction",
            "mbtool --port /dev/ttyUSB0 read-write 17 400004 6 400015 255 255 255",
        )],
    ),
    (
        "read-fifo",
        &[ex(
            "Read the FIFO queue whose pointer is 401247",
            "mbtool --port /dev/ttyUSB0 read-fifo 17 401247",
        )],
    ),
    (
        "raw",
        &[ex(
            "Send function 17 (report slave id) to slave 17",
            "mbtool --port /dev/ttyUSB0 raw 17 11",
        )],
    ),
    (
        "scan",
        &[
            ex(
                "Find the slaves on a line at 19200 baud, even parity",
                "mbtool --port /dev/ttyUSB0 scan",
            ),
            ex(
                "Find a device whose settings are forgotten: sweep baud rates and parities",
                "mbtool --port /dev/ttyUSB0 scan --baud 9600,19200,38400 --parity none,even,odd --ids 1-20",
            ),
            ex(
                "On a bus with a master on it: listen first, send only if nothing is heard",
                "mbtool --port /dev/ttyUSB0 scan --listen 2s",
            ),
            ex(
                "Find the Modbus TCP devices of a subnet, and their unit ids 1-10 too",
                "mbtool scan --hosts 192.168.1.0/24 --ids 1-10",
            ),
            ex(
                "The unit ids behind a TCP gateway, as JSON Lines",
                "mbtool --port tcp://10.0.0.5 scan --ids 1-32 --json",
            ),
        ],
    ),
    (
        "dump",
        &[
            ex(
                "Save the settings of slave 17: holding registers and coils",
                "mbtool --port /dev/ttyUSB0 dump 17 400001-400200 000001-000064 -o pump3.txt",
            ),
            ex(
                "Stand in for the dumped device, holes included",
                "mbtool serve --port tcp://:5020 --data pump3.txt",
            ),
        ],
    ),
    (
        "restore",
        &[
            ex(
                "Clone the settings onto a replacement device, and check them",
                "mbtool --port /dev/ttyUSB0 restore 17 pump3.txt",
            ),
            ex(
                "Only show the frames it would send",
                "mbtool restore 17 pump3.txt --dry-run",
            ),
        ],
    ),
    (
        "watch",
        &[
            ex(
                "Watch the points of a map, twice a second",
                "mbtool --port /dev/ttyUSB0 watch 17 --map pump3.csv --poll 500ms",
            ),
            ex(
                "Watch two floats stored low word first",
                "mbtool --port tcp://10.0.0.5 watch 1 400001 2 --type f32 --order CDAB",
            ),
            ex(
                "Through a gateway, the device's own serial line standing by for when the gateway fails",
                "mbtool --port tcp://10.0.0.5 watch 17 400108 3 --secondary-port /dev/ttyUSB0 --switch-on timeout:3,exception:0B,disconnect",
            ),
        ],
    ),
    (
        "info",
        &[
            ex("Ask slave 17 who it is", "mbtool --port /dev/ttyUSB0 info 17"),
            ex(
                "The same over Modbus TCP, as JSON",
                "mbtool --port tcp://10.0.0.5 info 17 --json",
            ),
        ],
    ),
    (
        "sunspec",
        &[
            ex(
                "Read an inverter's SunSpec models, named and scaled",
                "mbtool --port tcp://10.0.0.7 sunspec 1",
            ),
            ex(
                "Write them as a map too, to read by name with read --map",
                "mbtool --port tcp://10.0.0.7 sunspec 1 --map-out inverter.csv",
            ),
            ex(
                "A device that puts its map one register later, at 40001",
                "mbtool --port /dev/ttyUSB0 sunspec 3 --base 40001",
            ),
        ],
    ),
    (
        "diag",
        &[
            ex(
                "Round trips, counters and exception status of slave 17",
                "mbtool --port /dev/ttyUSB0 diag 17",
            ),
            ex(
                "Time 50 round trips, then clear the counters",
                "mbtool --port /dev/ttyUSB0 diag 17 --count 50 --clear",
            ),
        ],
    ),
    (
        "sniff",
        &[
            ex(
                "Watch an RS-485 line at 9600 baud, no parity, and keep every byte",
                "mbtool sniff --port /dev/ttyUSB0 -b 9600 --parity none --save bus.bin",
            ),
            ex(
                "Replay a capture as JSON Lines, slave 17 only",
                "mbtool sniff --input bus.bin --json --slave 17",
            ),
            ex(
                "Write the frames for Wireshark too",
                "mbtool sniff --port /dev/ttyUSB0 --pcap bus.pcap",
            ),
        ],
    ),
    (
        "serve",
        &[
            ex(
                "Stand in for slave 17 on a serial line",
                "mbtool serve --port /dev/ttyUSB0 --slave 17",
            ),
            ex(
                "Serve Modbus TCP on 127.0.0.1:5020 with the values of a data file",
                "mbtool serve --port tcp://:5020 --data plant.txt",
            ),
            ex(
                "Test a master's error handling: late answers, 5% dropped, exception 02 on 400100-400120",
                "mbtool serve --port tcp://:5020 --delay 200ms --drop 5% --exception 2@400100-400120",
            ),
        ],
    ),
    (
        "gateway",
        &[
            ex(
                "Let Modbus TCP clients reach the RTU devices on a USB adapter, every transaction shown",
                "mbtool gateway --listen tcp://0.0.0.0:502 --port /dev/ttyUSB0 -b 19200",
            ),
            ex(
                "Run as a service: no rows, the transactions logged to a file, retries on a noisy line",
                "mbtool gateway --listen tcp://0.0.0.0:502 --port /dev/ttyUSB0 --retries 2 --quiet --log gateway.jsonl",
            ),
            ex(
                "Watch what a SCADA asks of a Modbus TCP device: point the SCADA at port 1502",
                "mbtool gateway --listen tcp://0.0.0.0:1502 --port tcp://192.168.1.10 -o json",
            ),
            ex(
                "On an industrial PC whose RS-485 transceiver the host switches: the kernel's RS-485 mode",
                "mbtool gateway --listen tcp://0.0.0.0:502 --port /dev/ttyS1 --rs485 --rs485-delay-after 1",
            ),
        ],
    ),
    (
        "poll",
        &[
            ex(
                "Keep the devices of a plant file read, a line a device a poll",
                "mbtool poll examples/plant.yaml --for 2s",
            ),
            ex(
                "The same as InfluxDB line protocol, for Telegraf's execd input",
                "mbtool poll examples/plant.yaml --for 2s -o influx",
            ),
        ],
    ),
    (
        "ports",
        &[
            ex("Which port is which adapter", "mbtool ports"),
            ex(
                "Each port as a JSON line, for a script to pick an adapter by serial number",
                "mbtool ports --json",
            ),
        ],
    ),
    (
        "decode",
        &[
            ex(
                "Decode an RTU response",
                "mbtool decode 11 03 06 02 2B 00 00 00 64 C8 BA",
            ),
            ex("Decode an ASCII frame", "mbtool decode :1103006B00037E"),
            ex(
                "Decode a log, one frame per line, as JSON Lines",
                "mbtool decode --json < frames.txt",
            ),
        ],
    ),
    (
        "encode",
        &[
            ex(
                "The RTU request for 400108-400110 of slave 17",
                "mbtool encode read-holding 17 400108 3",
            ),
            ex(
                "The same as Modbus TCP",
                "mbtool encode --mode tcp read-holding 17 400108 3",
            ),
            ex(
                "Write coil 000173 on, as ASCII",
                "mbtool encode --mode ascii write-coil 17 000173 on",
            ),
        ],
    ),
];

/// Every example of every help page.
pub fn examples() -> impl Iterator<Item = &'static Example> {
    EXAMPLES.iter().flat_map(|(_, examples)| examples.iter())
}

pub fn examples_of(name: &str) -> &'static [Example] {
    EXAMPLES
        .iter()
        .find(|(command, _)| *command == name)
        .map_or(&[], |(_, examples)| *examples)
}

fn examples_help(examples: &[Example]) -> String {
    let mut text = String::from("Examples:\n");
    for example in examples {
        text.push_str(&format!("  {}:\n    $ {}\n", example.what, example.command));
    }
    text
}

/// `command` with the examples of each `--help`.
pub fn with_examples(command: clap::Command) -> clap::Command {
    // Each command changed where it stands: the commands keep their order.
    command
        .after_long_help(examples_help(examples_of("")))
        .mut_subcommands(|sub| match examples_of(sub.get_name()) {
            [] => sub,
            examples => sub.after_long_help(examples_help(examples)),
        })
}
