"""The grammar compare_cli.py generates command lines from: the options, which command
takes which, how often each is drawn, the MBTOOL_* variables, and the generator."""

import os
import random
import shlex
from dataclasses import dataclass, field

from cli_values import *  # noqa: F401,F403 (the values the grammar draws)

@dataclass
class Opt:
    long: str
    short: str = ""
    values: object = None  # None: a flag; else a function (rng, cmd) -> str


def values(*good, bad=(), p_bad=0.05):
    return lambda rng, cmd: pick(rng, good, bad, p_bad)


OPTIONS = {o.long: o for o in [
    # Connection
    Opt("--port", "-p", v_port),
    Opt("--mode", "-m", v_mode),
    Opt("--baud", "-b", v_baud),
    Opt("--parity", "", v_parity),
    Opt("--data-bits", "", values("7", "8", bad=["5", "9", "x", ""])),
    Opt("--stop-bits", "", values("1", "2", bad=["0", "3", "1.5"])),
    Opt("--timeout", "", v_timeout),
    Opt("--retries", "", values("0", "1", "2", bad=["-1", "x", "many"])),
    Opt("--retry-non-idempotent"),
    Opt("--frame-gap", "", values("0", "2ms", "1.75ms", "5ms", bad=["x", "-1ms", "500"])),
    Opt("--rs485"),
    Opt("--rs485-delay-before", "", values("0", "5", "100", bad=["101", "-1", "x", "1ms"])),
    Opt("--rs485-delay-after", "", values("0", "5", "100", bad=["101", "-1", "x"])),
    Opt("--rts-level", "", values("high", "low", bad=["up", "HIGH", ""])),
    Opt("--rts-toggle"),
    # Output
    Opt("--output", "-o", v_dump_output),
    Opt("--json"),
    Opt("--verbose", "-v"),
    # Addresses and values
    Opt("--pdu-addresses"),
    Opt("--address-base", "", values("0", "1", bad=["2", "-1", "one"])),
    Opt("--type", "-t", values(*TYPES, bad=TYPES_BAD)),
    Opt("--order", "", values(*ORDERS, bad=ORDERS_BAD)),
    Opt("--max-per-request", "", values("1", "2", "3", "10", "125", bad=["0", "-1", "x", "2001", "70000"])),
    # Watching
    Opt("--poll", "", v_poll),
    Opt("--count", "", v_count),
    Opt("--log", "", v_log),
    # Redundancy
    Opt("--secondary-port", "", values("tcp://127.0.0.1:1", "/dev/ttyNOPE", "rtu+tcp://127.0.0.1:1",
                                       bad=["sim", "sim", "", "udp://127.0.0.1:1"], p_bad=0.15)),
    Opt("--secondary-baud", "", values("9600", "19200", bad=["x", "0"])),
    Opt("--secondary-parity", "", values("none", "even", "odd", bad=["x"])),
    Opt("--secondary-data-bits", "", values("7", "8", bad=["9"])),
    Opt("--secondary-stop-bits", "", values("1", "2", bad=["3"])),
    Opt("--secondary-mode", "", values("rtu", "ascii", "tcp", bad=["x"])),
    Opt("--switch-on", "", v_switch_on),
    Opt("--switch-when", "", values("any", "all", bad=["some", ""])),
    # TLS
    Opt("--cert", "", values("nope.pem", "bad.pem", "empty.txt", bad=[""])),
    Opt("--key", "", values("nope.pem", "bad.pem", "empty.txt")),
    Opt("--ca", "", values("nope.pem", "bad.pem", "empty.txt")),
    Opt("--tls-server-name", "", values("plc1", "plc1.plant.local", "127.0.0.1", bad=["", "bad name"])),
    # read, write, watch
    Opt("--map", "", v_map),
    Opt("--function", "", v_function),
    # scan
    Opt("--ids", "", values("1-20", "17", "1-10,17,200", "15-18", "1-247", "16,17,18",
                            bad=["0-300", "x", "20-1", "", "248"])),
    Opt("--probe", "", values("read", "id", bad=["ping", ""])),
    Opt("--listen", "", v_listen),
    Opt("--all"),
    # diag, restore
    Opt("--clear"),
    Opt("--dry-run"),
    # decode
    Opt("--direction", "", values("request", "response", bad=["req", "both", ""])),
    # sniff
    Opt("--input", "", v_input),
    Opt("--interface", "", v_interface),
    Opt("--tcp-port", "", values("502", "5020", "1502", bad=["x", "70000", "0"])),
    Opt("--save", "", values("save.bin", "sub/save.bin", "cap.bin")),
    Opt("--pcap", "", values("out.pcap", "sub/out.pcap")),
    Opt("--stats"),
    Opt("--slave", "", v_slave_id),
    Opt("--low-latency"),
    # serve
    Opt("--data", "", values("pump3.txt", "dump.txt", "bad.txt", "nope.txt", "empty.txt", "pump3.csv")),
    Opt("--read-only", "", values("400001-400010", "000020", "400108", bad=["x", "400010-400001"])),
    Opt("--delay", "", values("10ms", "200ms", "0", bad=["x", "500"])),
    Opt("--drop", "", v_rate),
    Opt("--corrupt", "", v_rate),
    Opt("--exception", "", v_exception),
    Opt("--garbage"),
    Opt("--seed", "", values("1", "42", "0", bad=["x", "-1"])),
    Opt("--quiet", "-q"),
    Opt("--role", "", v_role),
    Opt("--default-role", "", values("viewer", "operator", bad=[""])),
    Opt("--plain-role", "", values("viewer", "operator", bad=[""])),
    Opt("--vendor", "", values("ACME", "mbtool", "Pump Works", bad=[""])),
    Opt("--product-code", "", values("P-1", "mbtool-sim", bad=[""])),
    Opt("--identity", "", v_identity),
    # gateway
    Opt("--unit-map", "", values("1=17,2=18", "1=17", "5=17", bad=["x", "1=", "1=300", "1:17"])),
    Opt("--broadcast-reply"),
    # ports
    Opt("--root", "", values("root", "/nonexist", ".", bad=["", "pump3.txt"])),
]}

# mbpoll's and modpoll's options, typed out of habit (refused with advice).
HABITS = [["-a", "17"], ["-r", "1"], ["-c", "2"], ["-t", "4:float"], ["-t", "0"], ["-1"], ["-l", "1000"],
          ["-P", "none"], ["-0"], ["-R"], ["-F"], ["-a", "17", "-r", "1", "-c", "2"], ["-t", "3"]]

CONN = ["--port", "--mode", "--baud", "--parity", "--data-bits", "--stop-bits", "--rs485",
        "--rs485-delay-before", "--rs485-delay-after", "--rts-level", "--rts-toggle"]
MASTER = ["--timeout", "--retries", "--frame-gap"]
RNI = ["--retry-non-idempotent"]
OUT = ["--output", "--json", "--verbose"]
ADDR = ["--pdu-addresses", "--address-base"]
VALUE_TYPES = ["--type", "--order"]
MPR = ["--max-per-request"]
POLL = ["--poll", "--count", "--log"]
SECONDARY = ["--secondary-port", "--secondary-baud", "--secondary-parity", "--secondary-data-bits",
             "--secondary-stop-bits", "--secondary-mode", "--switch-on", "--switch-when"]
TLS = ["--cert", "--key", "--ca", "--tls-server-name"]

# The options each command takes, as its --help lists them: first its own (under
# "Options:", which must come after the command name), then the global ones (which
# may stand before or after it).
OWN = {
    "read": ["--map"],
    "write": ["--map", "--function"],
    "scan": ["--ids", "--probe", "--listen", "--all"],
    "watch": ["--map", "--poll"],
    "diag": ["--clear", "--count"],
    "dump": ["--output"],
    "restore": ["--dry-run"],
    "decode": ["--direction"],
    "sniff": ["--input", "--interface", "--tcp-port", "--save", "--pcap", "--stats", "--slave", "--function",
              "--low-latency"],
    "serve": ["--slave", "--data", "--read-only", "--delay", "--drop", "--corrupt", "--exception", "--garbage",
              "--seed", "--quiet", "--role", "--default-role", "--plain-role", "--vendor", "--product-code",
              "--identity"],
    "gateway": ["--listen", "--unit-map", "--broadcast-reply", "--quiet", "--role", "--default-role",
                "--plain-role", "--log"],
    "ports": ["--root"],
}
GLOBAL_TAKEN = {
    "read-coils": CONN + MASTER + OUT + ADDR + MPR + POLL + SECONDARY + TLS,
    "read-inputs": CONN + MASTER + OUT + ADDR + MPR + POLL + SECONDARY + TLS,
    "read-holding": CONN + MASTER + OUT + ADDR + VALUE_TYPES + MPR + POLL + SECONDARY + TLS,
    "read-input-registers": CONN + MASTER + OUT + ADDR + VALUE_TYPES + MPR + POLL + SECONDARY + TLS,
    "read": CONN + MASTER + OUT + ADDR + VALUE_TYPES + MPR + POLL + SECONDARY + TLS,
    "write-coil": CONN + MASTER + OUT + ADDR + TLS,
    "write-coils": CONN + MASTER + OUT + ADDR + MPR + TLS,
    "write-register": CONN + MASTER + RNI + OUT + ADDR + VALUE_TYPES + TLS,
    "write-registers": CONN + MASTER + OUT + ADDR + VALUE_TYPES + MPR + TLS,
    "write": CONN + MASTER + RNI + OUT + ADDR + VALUE_TYPES + MPR + TLS,
    "raw": CONN + MASTER + RNI + OUT + VALUE_TYPES + TLS,
    "scan": CONN + ["--timeout", "--frame-gap"] + OUT + TLS,
    "watch": CONN + MASTER + ADDR + VALUE_TYPES + MPR + SECONDARY + TLS,
    "info": CONN + MASTER + OUT + TLS,
    "diag": CONN + MASTER + OUT + TLS,
    "dump": CONN + MASTER + ["--verbose"] + MPR + SECONDARY + TLS,
    "restore": CONN + MASTER + ["--verbose"] + MPR + SECONDARY + TLS,
    "decode": ["--mode", "--output", "--json", "--type", "--order"],
    "sniff": CONN + ["--output", "--json"],
    "serve": CONN + ["--output", "--json"] + TLS,
    "gateway": CONN + MASTER + RNI + OUT + TLS,
    "ports": ["--output", "--json"],
}
TAKES = {cmd: OWN.get(cmd, []) + GLOBAL_TAKEN[cmd] for cmd in GLOBAL_TAKEN}

# How likely an option is drawn among those a command takes (1 unless said here):
# options that only make sense with another are rarer, and bring it along.
RARITY = {**{o: 0.1 for o in TLS}, "--rs485": 0.08, "--rts-toggle": 0.08, "--rs485-delay-before": 0.08,
          "--rs485-delay-after": 0.08, "--rts-level": 0.08,
          **{o: 0.3 for o in SECONDARY if o != "--secondary-port"}}
COMPANIONS = {"--rs485-delay-before": ["--rs485", "--rts-toggle"], "--rs485-delay-after": ["--rs485", "--rts-toggle"],
              "--rts-level": ["--rs485", "--rts-toggle"],
              **{o: ["--secondary-port"] for o in SECONDARY if o != "--secondary-port"},
              "--log": ["--poll"], "--count": ["--poll"]}

# encode REQUEST-COMMAND: the options of each request command under encode.
ENCODE_BASE = ["--port", "--mode", "--output", "--json"]
ENCODE_TAKES = {
    "read-coils": ENCODE_BASE + ADDR + MPR,
    "read-inputs": ENCODE_BASE + ADDR + MPR,
    "read-holding": ENCODE_BASE + ADDR + VALUE_TYPES + MPR,
    "read-input-registers": ENCODE_BASE + ADDR + VALUE_TYPES + MPR,
    "read": ["--map"] + ENCODE_BASE + ADDR + VALUE_TYPES + MPR,
    "write-coil": ENCODE_BASE + ADDR,
    "write-coils": ENCODE_BASE + ADDR + MPR,
    "write-register": ENCODE_BASE + RNI + ADDR + VALUE_TYPES,
    "write-registers": ENCODE_BASE + ADDR + VALUE_TYPES + MPR,
    "write": ["--map", "--function"] + ENCODE_BASE + RNI + ADDR + VALUE_TYPES + MPR,
    "raw": ENCODE_BASE + RNI + VALUE_TYPES,
}

ENCODE_OWN = {"read": ["--map"], "write": ["--map", "--function"]}

ALIASES = {
    "read-inputs": ["read-discrete-inputs"],
    "read-holding": ["read-holding-registers"],
    "read-input-registers": ["read-input-regs"],
}

# How often each command is drawn.
WEIGHTS = {
    "read-holding": 10, "read-coils": 5, "read-inputs": 4, "read-input-registers": 4, "read": 8,
    "write-coil": 4, "write-coils": 4, "write-register": 4, "write-registers": 4, "write": 7, "raw": 5,
    "scan": 4, "watch": 3, "info": 3, "diag": 3, "dump": 4, "restore": 4, "decode": 9, "encode": 9,
    "sniff": 6, "serve": 3, "gateway": 3, "ports": 2,
}

# Commands that talk to a device through --port.
BUS_COMMANDS = {"read-coils", "read-inputs", "read-holding", "read-input-registers", "read", "write-coil",
                "write-coils", "write-register", "write-registers", "write", "raw", "scan", "watch", "info",
                "diag", "dump", "restore"}

# MBTOOL_* variables: (name, good values, bad values).
ENVIRONMENT = [
    ("MBTOOL_PORT", ["sim", "sim", "sim", "tcp://127.0.0.1:1", "/dev/ttyNOPE"], ["", "udp://127.0.0.1:1", "COM3"]),
    ("MBTOOL_BAUD", ["9600", "19200"], ["fast", "0"]),
    ("MBTOOL_PARITY", ["none", "even", "odd"], ["mark", ""]),
    ("MBTOOL_DATA_BITS", ["7", "8"], ["9"]),
    ("MBTOOL_STOP_BITS", ["1", "2"], ["3"]),
    ("MBTOOL_MODE", ["rtu", "ascii", "tcp"], ["x"]),
    ("MBTOOL_TIMEOUT", ["100ms", "50ms", "200ms"], ["500", "x"]),
    ("MBTOOL_RETRIES", ["0", "1"], ["-1"]),
    ("MBTOOL_ADDRESS_BASE", ["0", "1"], ["2"]),
    ("MBTOOL_RS485", ["1", "0", "true"], ["yes please"]),
    ("MBTOOL_RTS_TOGGLE", ["1", "0"], ["x"]),
    ("MBTOOL_RS485_DELAY_BEFORE", ["0", "10"], ["101"]),
    ("MBTOOL_RS485_DELAY_AFTER", ["0", "10"], ["x"]),
    ("MBTOOL_RTS_LEVEL", ["high", "low"], ["mid"]),
    ("MBTOOL_SECONDARY_PORT", ["tcp://127.0.0.1:1", "sim", "/dev/ttyNOPE"], [""]),
    ("MBTOOL_SECONDARY_BAUD", ["9600"], ["x"]),
    ("MBTOOL_SECONDARY_PARITY", ["none"], ["x"]),
    ("MBTOOL_SECONDARY_DATA_BITS", ["7"], ["x"]),
    ("MBTOOL_SECONDARY_STOP_BITS", ["2"], ["x"]),
    ("MBTOOL_SECONDARY_MODE", ["ascii"], ["x"]),
    ("MBTOOL_SWITCH_ON", ["timeout:1,disconnect"], ["timeout:x"]),
    ("MBTOOL_SWITCH_WHEN", ["any", "all"], ["some"]),
    ("MBTOOL_CERT", ["nope.pem", "bad.pem"], [""]),
    ("MBTOOL_KEY", ["nope.pem"], [""]),
    ("MBTOOL_CA", ["bad.pem"], [""]),
    ("MBTOOL_TLS_SERVER_NAME", ["plc1"], [""]),
    ("MBTOOL_NOT_AN_OPTION", ["1"], []),
]

# ----- positional arguments -----

SLAVES_GOOD = ["17"] * 14 + ["1", "5", "247", "0x11", "18"]
SLAVES_BAD = ["0", "0", "255", "255", "256", "-1", "x", "17.5", "", "0b"]

ADDRESSES = {
    "coil": (["000020", "20", "19", "0x13", "00020", "000020-000056", "000001", "1", "0", "65535",
              "000001-000010", "0b10011"],
             ["100197", "400108", "x", "-3", "000056-000020", "065537", "000020.1", "400108.05"]),
    "input": (["100197", "196", "100197-100218", "10197", "0", "100001", "100197-100199"],
              ["000020", "400108", "300009", "x", "100197.01"]),
    "inreg": (["300009", "8", "300009-300011", "300009.00", "30009", "300001", "300009.15"],
              ["400108", "000020", "x", "300009.16", "300011-300009"]),
    "holding": (["400108", "40108", "107", "0x6B", "0b1101011", "400108-400110", "400108.05", "400001",
                 "400002", "465536", "1", "400020", "400108.00"],
                ["465537", "400108.16", "000020", "x", "400110-400108", "300009", "1.5", "0x"]),
}
COMMAND_TABLE = {"read-coils": "coil", "read-inputs": "input", "read-input-registers": "inreg",
                 "read-holding": "holding", "write-coil": "coil", "write-coils": "coil",
                 "write-register": "holding", "write-registers": "holding"}
COUNTS_GOOD = ["1", "2", "3", "3", "10", "16", "125", "126", "2000", "250"]
COUNTS_BAD = ["0", "x", "-1", "65536", "2001", "1.5"]
COIL_VALUES = (["on", "off", "1", "0", "true", "false", "ON"], ["2", "yes", "x", "-1", ""])
REGISTER_VALUES = (["42", "-1", "65535", "555", "3.14", "0x2A", "0b101", "0", "-32768", "1e3", "PUMP"],
                   ["65536", "abc", "-32769", "", "1,5", "0xZZ"])
PDUS = ["03 00 6B 00 03", "03006B0003", "01 00 13 00 25", "02 00 C4 00 16", "04 00 08 00 01",
        "05 00 AC FF 00", "06 00 01 00 03", "0F 00 13 00 0A 02 CD 01", "10 00 01 00 02 04 00 0A 01 02",
        "16 00 6B FF FB 00 04", "17 00 6B 00 02 00 6B 00 01 02 00 2A", "2B 0E 01 00", "2B 0E 04 81",
        "08 00 00 12 34", "08 00 0B 00 00", "07", "0B", "11", "41 01 02", "00", "03 00 6B", "80 01"]
PDUS_BAD = ["zz", "", "03 0", "0x03 0x00 0x6B 0x00 0x03", "GG", "03 00 6B 00 03 extra"]
DUMP_RANGES = (["400001-400010", "000001-000010", "400100-400110", "300009", "100197-100218", "400108",
                "000020-000056", "400001-400300", "300001-300004", "465530-465536"],
               ["x", "400010-400001", "107", "500001", "400001-", "000001-400001"])
MAP_NAMES = ["voltage", "speed", "pressure_max", "running", "flow", "temp", "level", "pump", "alarm", "total",
             "nope"]
MAP_WRITES = ["pressure_max=2.5", "speed=1500", "running=on", "flow=3", "voltage=230", "pump=on", "pump=off",
              "temp=21.5", "nope=1", "speed", "speed=x", "speed=70000", "=1", "pressure_max=-1"]


@dataclass
class Case:
    """One generated line: what to run and how."""
    index: int
    argv: list
    env: dict
    stdin: bytes = None  # None: /dev/null
    files: dict = field(default_factory=dict)  # extra files for the working directory
    help: bool = False  # asks for help or the version: not run
    exclusive: bool = False  # runs alone (sniff --interface lo would hear the others)
    forever: bool = False  # meant to run until stopped
    clean: bool = False  # no mistakes made on purpose

    def shell(self):
        env = " ".join(f"{k}={shlex.quote(v)}" for k, v in sorted(self.env.items()))
        line = shlex.join(["mbtool", *self.argv])
        stdin = ""
        if self.stdin is not None:
            stdin = f"  < stdin ({len(self.stdin)} bytes)"
        return (env + " " if env else "") + line + stdin


SHORT = {o.short: o.long for o in OPTIONS.values() if o.short}


def option_name(words):
    """The long name of the option these words give (--port for -psim)."""
    word = words[0]
    if word.startswith("--"):
        return word.split("=")[0]
    return SHORT.get(word[:2], word)


def typo(rng, word):
    """A word with one slip of the fingers."""
    if len(word) < 3:
        return word + rng.choice("xs")
    i = rng.randrange(1, len(word) - 1)
    kind = rng.randrange(4)
    if kind == 0:
        return word[:i] + word[i + 1:]
    if kind == 1:
        return word[:i] + word[i + 1] + word[i] + word[i + 2:]
    if kind == 2:
        return word[:i] + word[i] + word[i:]
    return word[:i] + rng.choice("aeiorstln") + word[i + 1:]


class Generator:
    def __init__(self, seed):
        self.seed = seed

    def case(self, index):
        rng = LineRandom(f"{self.seed}:{index}")
        base = 20000 + index % 5000 * 2
        rng.ports = [str(base), str(base + 1)]
        case = Case(index=index, argv=[], env={})
        r = rng.random()
        rng.clean = case.clean = rng.random() < 0.4
        if r < 0.025:
            return self.help_line(rng, case)
        if r < 0.045:
            return self.unknown_command(rng, case)
        command = rng.choices(list(WEIGHTS), weights=list(WEIGHTS.values()))[0]
        self.build(rng, case, command)
        self.environment(rng, case)
        return case

    # ----- special lines -----

    def help_line(self, rng, case):
        cmd = rng.choice(list(WEIGHTS))
        forms = [[], ["-h"], ["--help"], ["help"], ["help", cmd], [cmd, "--help"], [cmd, "-h"],
                 ["-V"], ["--version"], [cmd, "-V"], ["--port", "sim"], ["encode"],
                 ["encode", rng.choice(list(ENCODE_TAKES)), "--help"], ["encode", "help"], ["-v"],
                 ["--json", "help", "read"]]
        case.argv = rng.choice(forms)
        case.help = True
        return case

    def unknown_command(self, rng, case):
        known = list(WEIGHTS) + [a for names in ALIASES.values() for a in names]
        word = rng.choice([typo(rng, rng.choice(known)), "foo", "reed", "get", "READ", "read_holding",
                           "serve2", "17", "--", "-", "sim"])
        rest = rng.choice([[], ["17", "400108"], ["--port", "sim", "17"]])
        if rng.random() < 0.5:
            case.argv = [word] + rest
        else:  # a typo under encode
            case.argv = ["encode", typo(rng, rng.choice(list(ENCODE_TAKES))), "17", "400108"]
        self.environment(rng, case)
        return case

    # ----- a command line -----

    def build(self, rng, case, command):
        name = command
        if command in ALIASES and rng.random() < 0.2:
            name = rng.choice(ALIASES[command])
        sub, sub_name = None, None
        if command == "encode":
            sub = rng.choice(list(ENCODE_TAKES))
            sub_name = sub
            if sub in ALIASES and rng.random() < 0.2:
                sub_name = rng.choice(ALIASES[sub])
        request = sub or command
        positionals = self.positionals(rng, case, request, command)

        # Mistakes in the arguments.
        m = 1.0 if rng.clean else rng.random()
        if m < 0.04 and positionals:
            positionals = positionals[:rng.randrange(len(positionals))]  # missing arguments
        elif m < 0.06:
            positionals = positionals + [rng.choice(["17", "extra", "400001", "--", "on"])]

        # The options: mostly those the command takes, now and then one it does not.
        takes = ENCODE_TAKES[sub] if sub else TAKES[command]
        options = []  # lists of words
        chosen = set()
        if command in BUS_COMMANDS and rng.random() < 0.85:
            port = "sim" if rng.random() < 0.82 else v_port(rng, command)
            options.append(self.spell(rng, OPTIONS["--port"], port))
            chosen.add("--port")
        elif command in ("serve", "gateway"):
            self.server_options(rng, case, command, options, chosen)
        elif command == "sniff":
            self.sniff_options(rng, case, options, chosen)
        elif command == "encode" and rng.random() < 0.3:
            port = rng.choice(["sim", "tcp://127.0.0.1:1", "/dev/ttyNOPE", "tls://127.0.0.1:1", "x"])
            options.append(self.spell(rng, OPTIONS["--port"], port))
            chosen.add("--port")
        own = ENCODE_OWN.get(sub, []) if sub else OWN.get(command, [])
        for _ in range(rng.choice([0, 1, 1, 2, 2, 3, 4, 6])):
            if rng.clean or rng.random() < 0.97:
                opt = OPTIONS[rng.choices(takes, [RARITY.get(o, 1) * (3 if o in own else 1) for o in takes])[0]]
            else:
                opt = rng.choice(list(OPTIONS.values()))
            if opt.long in chosen and (rng.clean or rng.random() < 0.95):
                continue
            picked = [opt]
            companions = [c for c in COMPANIONS.get(opt.long, []) if c not in chosen and opt.long not in own]
            if companions and len(companions) == len(COMPANIONS[opt.long]) and rng.random() < 0.7:
                picked.append(OPTIONS[rng.choice(companions)])
            for opt in picked:
                chosen.add(opt.long)
                value = opt.values(rng, request if command != "encode" else "encode") if opt.values else None
                options.append(self.spell(rng, opt, value))
        if not rng.clean and rng.random() < 0.02:
            options.append(rng.choice(HABITS))
        if not rng.clean and rng.random() < 0.025:  # a typo in an option's name
            opt = rng.choice(list(OPTIONS.values()))
            bad = "--" + typo(rng, opt.long[2:])
            options.append([bad] + ([opt.values(rng, request)] if opt.values else []))
        if not rng.clean and rng.random() < 0.01:
            options.append([rng.choice(["--bogus", "-x", "--", "---port", "-"])])

        # Bound how long a poll may last, as long as it is not meant to run forever.
        if "--poll" in chosen and command != "watch":
            if "--count" not in chosen and rng.random() < 0.8:
                options.append(["--count", rng.choice(["1", "2", "3"])])
            elif "--count" not in chosen:
                case.forever = True
        if command in ("serve", "gateway"):
            case.forever = True

        # Where each option goes: before the command name, after it, or among the arguments.
        before, after = [], []
        middle = []  # for encode: between encode and its request command
        for words in options:
            where = rng.random()
            if option_name(words) in own and where < 0.3:  # a command's own option: after it
                misplaced = not rng.clean and rng.random() < 0.15
                where = rng.choice([0.1, 0.4]) if misplaced else 1.0
            if where < 0.3:
                before.append(words)
            elif sub and where < 0.45:
                middle.append(words)
            else:
                after.append(words)
        argv = [w for words in before for w in words] + [name]
        if sub:
            argv += [w for words in middle for w in words] + [sub_name]
        groups = [[word] for word in positionals]  # options go between whole groups
        for words in after:
            if rng.random() < 0.7 or not groups:
                groups.append(words)
            else:
                groups.insert(rng.randrange(len(groups) + 1), words)
        argv += [w for words in groups for w in words]
        if not rng.clean and rng.random() < 0.015:  # the command name itself mistyped
            argv[argv.index(name)] = typo(rng, name)
        case.argv = argv
        if command == "sniff" and any(w in ("lo", "--interface=lo") for w in argv):
            case.exclusive = True  # a live capture on lo would hear the other lines
            case.forever = True

    def spell(self, rng, opt, value):
        """--name value, --name=value, -x value or -xvalue."""
        if value is None:
            if opt.short and rng.random() < 0.5:
                return [opt.short]
            return [opt.long]
        r = rng.random()
        if opt.short and r < 0.3:
            return [opt.short + value] if r < 0.08 and value else [opt.short, value]
        if r < 0.45:
            return [f"{opt.long}={value}"]
        return [opt.long, value]

    def server_options(self, rng, case, command, options, chosen):
        if command == "serve":
            port = v_listen_port(rng, command) if rng.random() < 0.9 else None
            if port is not None:
                options.append(self.spell(rng, OPTIONS["--port"], port))
                chosen.add("--port")
            # Mostly a fault, so that it ends at once.
            if rng.random() < 0.8:
                fault = rng.choice([
                    ["--data", rng.choice(["bad.txt", "nope.txt", "pump3.csv"])], ["--drop", "2"],
                    ["--slave", rng.choice(["0", "256", "x"])], ["--exception", "x"],
                    ["--role", "viewer=read"], ["--cert", "nope.pem"], ["--port", "sim"],
                    ["--port", "/dev/ttyNOPE"], ["--corrupt", "150%"], ["--identity", "Nope=1"],
                    ["--read-only", "x"], ["--delay", "500"], ["--timeout", "1s"], ["--baud", "x"],
                    ["--verbose"], ["--plain-role", "viewer", "--role", "x"],
                ])
                options.append(fault)
        else:
            if rng.random() < 0.9:
                options.append(self.spell(rng, OPTIONS["--listen"], v_listen(rng, command)))
                chosen.add("--listen")
            if rng.random() < 0.9:
                port = rng.choice(["sim", "sim", "/dev/ttyNOPE", "tcp://127.0.0.1:1", "rtu+tcp://127.0.0.1:1",
                                   "tls://127.0.0.1:1", ""])
                options.append(self.spell(rng, OPTIONS["--port"], port))
                chosen.add("--port")
            if rng.random() < 0.8:
                fault = rng.choice([
                    ["--unit-map", rng.choice(["x", "1=300", "1:17"])], ["--role", "viewer=read"],
                    ["--listen", "udp://:1502"], ["--listen", "tls://:" + rng.ports[1]], ["--timeout", "500"],
                    ["--log", "sub/gw.csv"], ["--interface", "lo"], ["--retries", "-1"],
                    ["--default-role", ""], ["--baud", "fast"], ["--map", "pump3.csv"],
                ])
                options.append(fault)

    def sniff_options(self, rng, case, options, chosen):
        r = rng.random()
        if r < 0.75:
            source = v_input(rng, "sniff")
            options.append(self.spell(rng, OPTIONS["--input"], source))
            chosen.add("--input")
            if source == "-":
                case.stdin = random_capture(rng) if rng.random() < 0.7 else load_stdin_capture(rng)
        elif r < 0.85:
            options.append(["--interface", v_interface(rng, "sniff")])
            chosen.add("--interface")
        elif r < 0.95:
            options.append(self.spell(rng, OPTIONS["--port"], rng.choice(["/dev/ttyNOPE", "sim",
                                                                         "tcp://127.0.0.1:1", ""])))
            chosen.add("--port")

    def positionals(self, rng, case, request, command):
        """The arguments of a command (or of encode's request command)."""
        slave = pick(rng, SLAVES_GOOD, SLAVES_BAD, 0.08)
        if request in ("read-coils", "read-inputs", "read-holding", "read-input-registers"):
            good, bad = ADDRESSES[COMMAND_TABLE[request]]
            args = [slave, pick(rng, good, bad, 0.1)]
            if rng.random() < (0.1 if "-" in args[1] else 0.7):
                args.append(pick(rng, COUNTS_GOOD, COUNTS_BAD, 0.1))
            return args
        if request in ("read", "watch"):
            if rng.random() < 0.25:  # by map
                args = [slave] if rng.random() < 0.7 else []
                args += rng.sample(MAP_NAMES, rng.randint(0, 3))
                return ["--map", v_map(rng, request)] + args
            table = rng.choice(list(ADDRESSES))
            good, bad = ADDRESSES[table]
            ref = rng.choice([g for g in good if len(g.split("-")[0].split(".")[0]) >= 5] or good)
            if rng.random() < 0.15:
                ref = pick(rng, good, bad, 0.5)
            args = [slave, ref]
            if rng.random() < 0.6:
                args.append(pick(rng, COUNTS_GOOD, COUNTS_BAD, 0.1))
            return args
        if request == "write-coil":
            return [slave, pick(rng, *ADDRESSES["coil"], 0.1), pick(rng, *COIL_VALUES)]
        if request == "write-coils":
            vals = (["".join(rng.choice("01") for _ in range(rng.randint(1, 12)))] if rng.random() < 0.3
                    else [pick(rng, *COIL_VALUES) for _ in range(rng.randint(1, 5))])
            return [slave, pick(rng, *ADDRESSES["coil"], 0.1)] + vals
        if request == "write-register":
            return [slave, pick(rng, *ADDRESSES["holding"], 0.1), pick(rng, *REGISTER_VALUES)]
        if request == "write-registers":
            return [slave, pick(rng, *ADDRESSES["holding"], 0.1)] + [
                pick(rng, *REGISTER_VALUES) for _ in range(rng.randint(1, 4))]
        if request == "write":
            if rng.random() < 0.2:
                return ["--map", v_map(rng, request), slave] + rng.sample(MAP_WRITES, rng.randint(0, 3))
            if rng.random() < 0.5:
                ref = pick(rng, ["000020", "000001", "000020-000022", "00020"], ["100197", "300009"], 0.15)
                vals = [pick(rng, *COIL_VALUES) for _ in range(rng.randint(1, 3))]
            else:
                ref = pick(rng, ["400108", "400001", "400108.02", "400001-400002", "40001", "400108.15"],
                           ["465537", "300009", "107"], 0.15)
                vals = [pick(rng, *REGISTER_VALUES) for _ in range(rng.randint(1, 3))]
            return [slave, ref] + vals
        if request == "raw":
            pdu = pick(rng, PDUS, PDUS_BAD, 0.1)
            words = pdu.split() if rng.random() < 0.6 else [pdu]
            return [slave] + words
        if command in ("info", "diag"):
            return [slave]
        if command == "dump":
            return [slave] + [pick(rng, *DUMP_RANGES, 0.1) for _ in range(rng.randint(1, 3))]
        if command == "restore":
            return [slave, pick(rng, ["pump3.txt", "dump.txt", "pump3.txt"],
                                ["bad.txt", "nope.txt", "empty.txt", "pump3.csv", "root"], 0.3)]
        if command == "decode":
            if rng.random() < 0.35:
                case.stdin = random_log_text(rng)
                return []
            args = []
            for _ in range(rng.randint(1, 3)):
                text = random_frame_text(rng)
                args += text.split() if rng.random() < 0.6 else [text]
            if rng.random() < 0.05:
                args.append("")
            return args
        if command == "sniff":
            case.files["cap.bin"] = random_capture(rng)
            if rng.random() < 0.25:
                case.files["cap.bin.timing"] = random_timing(rng, len(case.files["cap.bin"]))
            return []
        return []  # scan, serve, gateway, ports

    def environment(self, rng, case):
        p = 0.1 if rng.random() < 0.3 else 0.0
        listens = any(w in ("serve", "gateway") for w in case.argv)
        for name, good, bad in ENVIRONMENT:
            chance = p * (3 if name == "MBTOOL_PORT" else 1)
            if rng.random() < chance:
                if name == "MBTOOL_PORT" and listens:  # never where masters connect
                    good = [g for g in good if "127.0.0.1" not in g]
                case.env[name] = pick(rng, good, bad, 0.15)
        # A bus command without --port that would find none: now and then give it sim.
        if "--port" not in " ".join(case.argv) and rng.random() < 0.5 and "MBTOOL_PORT" not in case.env:
            if any(c in case.argv for c in BUS_COMMANDS):
                case.env["MBTOOL_PORT"] = "sim"
        if listens:
            case.forever = True
        # dump and restore wait for a slave that does not answer in real time, each retry
        # and each try on a path with a secondary again: with retries or a secondary, keep
        # their timeout short (unless one is given), well inside the process timeout.
        secondary = "MBTOOL_SECONDARY_PORT" in case.env or any(w.startswith("--secondary-port") for w in case.argv)
        retries = case.env.get("MBTOOL_RETRIES", "0") not in ("0", "-1") or any(
            w.startswith("--retries") for w in case.argv)
        if (secondary or retries) and ("dump" in case.argv or "restore" in case.argv) \
                and "MBTOOL_TIMEOUT" not in case.env and not any(w.startswith("--timeout") for w in case.argv):
            case.argv += ["--timeout", "100ms"]


def load_stdin_capture(rng):
    path = os.path.join(REPO, REPO_FIXTURES["wizmodbus.bin"])
    if os.path.exists(path):
        with open(path, "rb") as f:
            return f.read()
    return random_capture(rng)


def is_help(argv):
    """Whether a line asks for help or the version. (Lines that name no command, which
    print the short help, come only from Generator.help_line, which marks them.)"""
    return not argv or any(w in ("-h", "--help", "-V", "--version", "help") for w in argv)
