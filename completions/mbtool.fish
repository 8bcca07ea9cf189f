# Print an optspec for argparse to handle cmd's options that are independent of any subcommand.
function __fish_mbtool_global_optspecs
    string join \n p/port= m/mode= b/baud= parity= data-bits= stop-bits= rs485 rs485-delay-before= rs485-delay-after= rts-level= rts-toggle timeout= frame-gap= retries= v/verbose cert= key= ca= tls-server-name= retry-non-idempotent o/output= json pdu-addresses address-base= max-per-request= t/type= order= poll= count= log= secondary-port= secondary-baud= secondary-parity= secondary-data-bits= secondary-stop-bits= secondary-mode= switch-on= switch-when= h/help V/version
end

function __fish_mbtool_needs_command
    # Figure out if the current invocation already has a command.
    set -l cmd (commandline -opc)
    set -e cmd[1]
    argparse -s (__fish_mbtool_global_optspecs) -- $cmd 2>/dev/null
    or return
    if set -q argv[1]
        # Also print the command, so this can be used to figure out what it is.
        echo $argv[1]
        return 1
    end
    return 0
end

function __fish_mbtool_using_subcommand
    set -l cmd (__fish_mbtool_needs_command)
    test -z "$cmd"
    and return 1
    contains -- $cmd[1] $argv
end

complete -c mbtool -n "__fish_mbtool_needs_command" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_needs_command" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_needs_command" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_needs_command" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_needs_command" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_needs_command" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_needs_command" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_needs_command" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_needs_command" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_needs_command" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_needs_command" -l poll -d 'Repeat the read every INTERVAL until Ctrl-C or --count' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l count -d 'With --poll: stop after N reads' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l log -d 'With --poll: also append every poll, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_needs_command" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_needs_command" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_needs_command" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_needs_command" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_needs_command" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_needs_command" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_needs_command" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_needs_command" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_needs_command" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_needs_command" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_needs_command" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_needs_command" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-coils" -d 'Read coils (function 01)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-inputs" -d 'Read discrete inputs (function 02)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-discrete-inputs" -d 'Read discrete inputs (function 02)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-holding" -d 'Read holding registers (function 03)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-holding-registers" -d 'Read holding registers (function 03)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-input-registers" -d 'Read input registers (function 04)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-input-regs" -d 'Read input registers (function 04)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read" -d 'Read by reference: its first digit picks the table'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "write-coil" -d 'Write one coil (function 05)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "write-coils" -d 'Write coils (function 15)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "write-register" -d 'Write one holding register (function 06)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "write-registers" -d 'Write holding registers (function 16)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "write" -d 'Write by reference: 05/06 for one value, 15/16 for more'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-file" -d 'Read records of files (function 20)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "write-file" -d 'Write records of a file (function 21)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "mask-write" -d 'Set bits of a register in one request (function 22)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-write" -d 'Write then read registers in one request (function 23)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "read-fifo" -d 'Read a FIFO queue (function 24)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "raw" -d 'Send any PDU and decode the answer'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "scan" -d 'Find the slaves on a line and the settings they use'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "watch" -d 'Watch values live, full screen: min, max, trend, changes'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "info" -d 'Ask a device who it is: identification and server id'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "sunspec" -d 'Read a SunSpec device\'s models: points named, scaled'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "diag" -d 'A device\'s health: round trips, counters, status'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "dump" -d 'Save a device\'s tables to a data file, holes left out'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "restore" -d 'Write a data file back to a device, and check it'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "decode" -d 'Decode frames given as arguments or on standard input'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "encode" -d 'Print the frame a request command would send'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "sniff" -d 'Watch a bus without transmitting; frames decoded, paired'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "serve" -d 'Stand in for a slave on a serial line or TCP'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "gateway" -d 'Bridge Modbus TCP clients to a serial line, shown live'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "poll" -d 'Keep a plant\'s devices read, each at its rate'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "ports" -d 'The serial ports here, and which adapter each one is'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "generate" -d 'Write the shell completions and man pages (for packagers and the project\'s own tree)'
complete -c mbtool -n "__fish_mbtool_needs_command" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l poll -d 'Repeat the read every INTERVAL until Ctrl-C or --count' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l count -d 'With --poll: stop after N reads' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l log -d 'With --poll: also append every poll, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-coils" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l poll -d 'Repeat the read every INTERVAL until Ctrl-C or --count' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l count -d 'With --poll: stop after N reads' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l log -d 'With --poll: also append every poll, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-inputs" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l poll -d 'Repeat the read every INTERVAL until Ctrl-C or --count' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l count -d 'With --poll: stop after N reads' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l log -d 'With --poll: also append every poll, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-discrete-inputs" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l poll -d 'Repeat the read every INTERVAL until Ctrl-C or --count' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l count -d 'With --poll: stop after N reads' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l log -d 'With --poll: also append every poll, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l poll -d 'Repeat the read every INTERVAL until Ctrl-C or --count' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l count -d 'With --poll: stop after N reads' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l log -d 'With --poll: also append every poll, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-holding-registers" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l poll -d 'Repeat the read every INTERVAL until Ctrl-C or --count' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l count -d 'With --poll: stop after N reads' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l log -d 'With --poll: also append every poll, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-registers" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l poll -d 'Repeat the read every INTERVAL until Ctrl-C or --count' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l count -d 'With --poll: stop after N reads' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l log -d 'With --poll: also append every poll, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-input-regs" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l map -d 'The points of a register map (CSV, or Home Assistant YAML), by name' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l expect -d 'The value the device holds (229.0, or a range 228..231): the layouts that give it' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l poll -d 'Repeat the read every INTERVAL until Ctrl-C or --count' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l count -d 'With --poll: stop after N reads' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l log -d 'With --poll: also append every poll, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l layouts -d 'Show the registers read as every type and byte order'
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coil" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-coils" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-register" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-registers" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l map -d 'Write points of a register map by name: NAME=VALUE, scale and offset taken back out' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l function -d 'Force the function: 5 or 15 for coils, 6 or 16 for registers, 22 for a bit' -r -f -a "5\t''
6\t''
15\t''
16\t''
22\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand write" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-file" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand write-file" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand mask-write" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-write" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand read-fifo" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand raw" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l ids -d 'The ids to ask: ranges and single ids, as 1-247 (the default) or 1-10,17,200' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l hosts -d 'Sweep a network for Modbus TCP devices: 10.0.0.0/24,10.0.1.5-20,plc1' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l tcp-port -d 'With --hosts: the TCP ports asked on each host [default: 502]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l parallel -d 'With --hosts: how many hosts are asked at once [default: 16]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l pause -d 'With --hosts: the pause between two requests to one host [default: 20ms]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l probe -d 'What each id is asked: read (03, one register at address 0) or id (17)' -r -f -a "read\t'Read one holding register at protocol address 0 (function 03)'
id\t'Report server id (function 17)'"
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l listen -d 'Listen this long at each setting before sending anything: slaves heard answering another master are found without adding traffic' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l all -d 'Try every setting of the sweep, not only up to the first where a slave answers; with --hosts, ask every id even where 0, 1 and 255 get no answer'
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand scan" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l map -d 'The points of a register map (CSV, or Home Assistant YAML), by name' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l poll -d 'How often to read [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand watch" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand info" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l map-out -d 'Also write the points found as a map (CSV) that read --map, watch and poll take' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l base -d 'Look for the SunS marker only at this register (0-based) [default: 40000, 50000, 0]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand sunspec" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l count -d 'How many round trips of return query data to time [default: 5]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l clear -d 'After reading them, clear the device\'s counters (08/0A)'
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand diag" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -s o -l output -d 'The data file to write [default: standard output]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand dump" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l secondary-port -d 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary\'s unless given below' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l secondary-baud -d 'Serial speed of the secondary path [default: --baud]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l secondary-parity -d 'Serial parity of the secondary path [default: --parity]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l secondary-data-bits -d 'Serial data bits of the secondary path [default: --data-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l secondary-stop-bits -d 'Serial stop bits of the secondary path [default: --stop-bits]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l secondary-mode -d 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l switch-on -d 'When to change paths, counted since the path\'s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l switch-when -d 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]' -r -f -a "any\t'switch as soon as one condition holds'
all\t'switch when every condition has held since the last good answer'"
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l dry-run -d 'Print the frames that would be sent, and send nothing'
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand restore" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand decode" -l direction -d 'Read every frame as a request or as a response instead of inferring it' -r -f -a "request\t''
response\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand decode" -s m -l mode -d 'Framing: rtu, ascii or tcp [default: detected from each frame]' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand decode" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand decode" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand decode" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand decode" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand decode" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand decode" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-coils" -d 'Read coils (function 01)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-inputs" -d 'Read discrete inputs (function 02)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-discrete-inputs" -d 'Read discrete inputs (function 02)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-holding" -d 'Read holding registers (function 03)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-holding-registers" -d 'Read holding registers (function 03)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-input-registers" -d 'Read input registers (function 04)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-input-regs" -d 'Read input registers (function 04)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read" -d 'Read by reference: its first digit picks the table'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "write-coil" -d 'Write one coil (function 05)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "write-coils" -d 'Write coils (function 15)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "write-register" -d 'Write one holding register (function 06)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "write-registers" -d 'Write holding registers (function 16)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "write" -d 'Write by reference: 05/06 for one value, 15/16 for more'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-file" -d 'Read records of files (function 20)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "write-file" -d 'Write records of a file (function 21)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "mask-write" -d 'Set bits of a register in one request (function 22)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-write" -d 'Write then read registers in one request (function 23)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "read-fifo" -d 'Read a FIFO queue (function 24)'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and not __fish_seen_subcommand_from read-coils read-inputs read-discrete-inputs read-holding read-holding-registers read-input-registers read-input-regs read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw" -f -a "raw" -d 'Send any PDU and decode the answer'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-coils" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-coils" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-coils" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-coils" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-coils" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-coils" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-coils" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-coils" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-inputs" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-inputs" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-inputs" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-inputs" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-inputs" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-inputs" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-inputs" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-inputs" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-discrete-inputs" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-discrete-inputs" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-discrete-inputs" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-discrete-inputs" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-discrete-inputs" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-discrete-inputs" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-discrete-inputs" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-discrete-inputs" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-holding-registers" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-registers" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-input-regs" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -l map -d 'The points of a register map (CSV, or Home Assistant YAML), by name' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -l expect -d 'The value the device holds (229.0, or a range 228..231): the layouts that give it' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -l layouts -d 'Show the registers read as every type and byte order'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coil" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coil" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coil" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coil" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coil" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coil" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coil" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coils" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coils" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coils" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coils" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coils" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coils" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coils" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-coils" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-register" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-registers" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -l map -d 'Write points of a register map by name: NAME=VALUE, scale and offset taken back out' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -l function -d 'Force the function: 5 or 15 for coils, 6 or 16 for registers, 22 for a bit' -r -f -a "5\t''
6\t''
15\t''
16\t''
22\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-file" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-file" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-file" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-file" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-file" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-file" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-file" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-file" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-file" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-file" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-file" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-file" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-file" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-file" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-file" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from write-file" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from mask-write" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from mask-write" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from mask-write" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from mask-write" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from mask-write" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from mask-write" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from mask-write" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from mask-write" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-write" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-fifo" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-fifo" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-fifo" -l address-base -d 'What a bare address counts from: 0 (protocol address) or 1 (register number)' -r -f -a "0\t'Protocol addresses, 0-65535'
1\t'Register numbers, 1-65536'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-fifo" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-fifo" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-fifo" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-fifo" -l pdu-addresses -d 'Take every address as a plain number, never as a Modicon reference'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-fifo" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from read-fifo" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from raw" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from raw" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from raw" -s t -l type -d 'Register value type, for values read and values to write' -r -f -a "u16\t''
i16\t''
u32\t''
i32\t''
f32\t''
u64\t''
i64\t''
f64\t''
hex\t''
bin\t''
ascii\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from raw" -l order -d 'Byte order of values wider than 16 bits (A: the most significant byte)' -r -f -a "ABCD\t'Big-endian: high word first, high byte first'
CDAB\t'Low word first (word swap), as many PLCs store 32-bit values'
BADC\t'High word first, bytes swapped within each word'
DCBA\t'Little-endian'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from raw" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from raw" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from raw" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand encode; and __fish_seen_subcommand_from raw" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l input -d 'Read a capture (pcap, pcapng, a line\'s raw bytes; - for stdin) instead of the port' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l interface -d 'Capture Modbus TCP live from a network interface (eth0, lo)' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l tcp-port -d 'The TCP port of the Modbus servers in a capture [default: 502]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l save -d 'Keep every byte seen, to replay it later with --input' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l pcap -d 'Also write the frames shown to a pcap file for Wireshark' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l slave -d 'Show only the frames of this slave; repeatable' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l function -d 'Show only the frames of this function code (3, 0x10); repeatable' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l stats -d 'At the end, statistics per server and unit'
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l low-latency -d 'Ask the USB serial driver for its lowest latency'
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand sniff" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l slave -d 'Answer as this slave id; repeat for several [default: 17]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l data -d 'Initial data and the addresses that exist (see above for the format)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l read-only -d 'Addresses that may not be written (exception 02): a reference or a range; repeatable' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l delay -d 'Wait this long before each answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l drop -d 'Leave this share of requests unanswered: 0 to 1, or 5%' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l corrupt -d 'Corrupt this share of answers (a bad checksum; over TCP a wrong function): 0 to 1, or 5%' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l exception -d 'Answer exception CODE to every request, or to those touching RANGE (CODE@RANGE, as in 2@400100-400120); repeatable' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l seed -d 'Seed for the random choices of --drop, --corrupt and --garbage, to repeat a run' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l role -d 'Over tls://: what clients of role NAME may do, RULES being read and write, each alone or with a range (operator=read,write:400001-400100); repeatable. A request its role does not allow gets exception 01' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l default-role -d 'Over tls://: the role of a client whose certificate carries none [default: such a client is refused, when --role is given]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l plain-role -d 'The role of every client of a plain tcp:// listener, which has no certificate to claim one: with --role, a plain listener is refused without it' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l vendor -d 'Device identification: vendor name' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l product-code -d 'Device identification: product code' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l identity -d 'Device identification: any object, by name or id (VendorUrl=https://example.com, ProductName=Pump, 0x80=serial 4711); repeatable' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l garbage -d 'Send a few noise bytes (00, FE) before each answer, as a bus being handed over does'
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -s q -l quiet -d 'No log line per request'
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand serve" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l listen -d 'Where clients connect: tcp://ADDRESS[:PORT], tls://ADDRESS[:PORT] for Modbus/TCP Security, or udp://ADDRESS[:PORT]; repeatable' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l unit-map -d 'Unit ids mapped to the slave ids they reach on the line: UNIT=SLAVE,...' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l role -d 'Over tls://: what clients of role NAME may do, RULES being read and write, each alone or with a range (operator=read,write:400001-400100); repeatable. A request its role does not allow gets exception 01' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l default-role -d 'Over tls://: the role of a client whose certificate carries none [default: such a client is refused, when --role is given]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l plain-role -d 'The role of every client of a plain tcp:// listener, which has no certificate to claim one: with --role, a plain listener is refused without it' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l log -d 'Also append every transaction, with its time, to FILE' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -s p -l port -d 'Port: /dev/ttyUSB0, tcp://HOST[:PORT], tls://HOST, sim' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -s m -l mode -d 'Framing' -r -f -a "rtu\t''
ascii\t''
tcp\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -s b -l baud -d 'Serial speed [default: 19200]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l parity -d 'Parity [default: even]' -r -f -a "none\t''
even\t''
odd\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l data-bits -d 'Serial data bits [default: 8, 7 in ASCII mode]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l stop-bits -d 'Serial stop bits [default: 1 with parity, 2 without]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l rs485-delay-before -d 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l rs485-delay-after -d 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l rts-level -d 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]' -r -f -a "high\t''
low\t''"
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l cert -d 'This end\'s certificate (PEM), for tls:// ports; a client\'s carries its role' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l key -d 'The private key of --cert (PEM: PKCS#8, RSA or EC)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l ca -d 'The CA certificates (PEM) that sign the other end\'s certificate: the device\'s for a master, the clients\' for serve and gateway' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l tls-server-name -d 'The name the device\'s certificate must hold [default: the host of --port], for a device addressed by IP whose certificate names something else' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l broadcast-reply -d 'Answer a broadcast (unit 0) as a slave answers a write, for clients that wait for one'
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -s q -l quiet -d 'No row per transaction (stderr still tells the line and the clients)'
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l rs485 -d 'RS-485 direction by the kernel\'s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them'
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l rts-toggle -d 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode'
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l retry-non-idempotent -d 'With --retries, retry a request that may do more when sent twice too: mask write (22), read/write multiple (23), file record write (21), user-defined functions'
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand gateway" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l influx -d 'Also write every row to InfluxDB: http://HOST:8086/write?db=NAME (1.x) or http://HOST:8086/api/v2/write?org=ORG&bucket=BUCKET (2.x)' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l mqtt -d 'Also publish every value to an MQTT broker: mqtt://HOST[:PORT] or mqtts://HOST[:PORT]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l mqtt-prefix -d 'The first level of the MQTT topics' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l mqtt-discovery -d 'Announce every point to Home Assistant (MQTT discovery), under PREFIX' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l mqtt-user -d 'The broker\'s user; the password is read from MBTOOL_MQTT_PASSWORD' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l mqtt-ca -d 'The CA certificates (PEM) that sign an mqtts:// broker\'s certificate [default: the system\'s]' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l buffer -d 'Rows kept for a server that is down; past it the oldest give way, counted' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l metrics -d 'Serve Prometheus metrics on http://ADDR/metrics: values, polls, errors, response times' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l log -d 'Also append every row to FILE: CSV for a .csv name (the columns of -o csv), JSON Lines else' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l for -d 'Stop after DURATION [default: until Ctrl-C or SIGTERM]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l timeout -d 'Response timeout: 500ms, 1s [default: 1s]' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l frame-gap -d 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l retries -d 'Retries after a timeout or a bad answer' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l max-per-request -d 'Split reads and writes into requests of at most N coils or registers' -r
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
csv\t'Comma-separated values with a header line'
influx\t'InfluxDB line protocol, for Telegraf\'s execd and exec inputs'"
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l mqtt-retain -d 'Publish the values retained, so that a new subscriber has the last at once'
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -s v -l verbose -d 'Print every frame sent and received, in hex with a timestamp, on stderr'
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand poll" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand ports" -l root -d 'Read sys, dev and proc under DIR instead of / (a copy taken from another machine)' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand ports" -s o -l output -d 'Output format [default: table]' -r -f -a "table\t'A table for people'
json\t'One JSON object per line'
values\t'Only the values, one per line, for $(...) in scripts'
csv\t'Comma-separated values with a header line'"
complete -c mbtool -n "__fish_mbtool_using_subcommand ports" -l json -d 'The same as --output json'
complete -c mbtool -n "__fish_mbtool_using_subcommand ports" -s h -l help -d 'Print help (see more with \'--help\')'
complete -c mbtool -n "__fish_mbtool_using_subcommand ports" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand generate" -l dir -d 'The folder that receives completions/ and man/' -r -F
complete -c mbtool -n "__fish_mbtool_using_subcommand generate" -s h -l help -d 'Print help'
complete -c mbtool -n "__fish_mbtool_using_subcommand generate" -s V -l version -d 'Print version'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "read-coils" -d 'Read coils (function 01)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "read-inputs" -d 'Read discrete inputs (function 02)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "read-holding" -d 'Read holding registers (function 03)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "read-input-registers" -d 'Read input registers (function 04)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "read" -d 'Read by reference: its first digit picks the table'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "write-coil" -d 'Write one coil (function 05)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "write-coils" -d 'Write coils (function 15)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "write-register" -d 'Write one holding register (function 06)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "write-registers" -d 'Write holding registers (function 16)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "write" -d 'Write by reference: 05/06 for one value, 15/16 for more'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "read-file" -d 'Read records of files (function 20)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "write-file" -d 'Write records of a file (function 21)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "mask-write" -d 'Set bits of a register in one request (function 22)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "read-write" -d 'Write then read registers in one request (function 23)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "read-fifo" -d 'Read a FIFO queue (function 24)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "raw" -d 'Send any PDU and decode the answer'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "scan" -d 'Find the slaves on a line and the settings they use'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "watch" -d 'Watch values live, full screen: min, max, trend, changes'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "info" -d 'Ask a device who it is: identification and server id'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "sunspec" -d 'Read a SunSpec device\'s models: points named, scaled'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "diag" -d 'A device\'s health: round trips, counters, status'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "dump" -d 'Save a device\'s tables to a data file, holes left out'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "restore" -d 'Write a data file back to a device, and check it'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "decode" -d 'Decode frames given as arguments or on standard input'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "encode" -d 'Print the frame a request command would send'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "sniff" -d 'Watch a bus without transmitting; frames decoded, paired'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "serve" -d 'Stand in for a slave on a serial line or TCP'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "gateway" -d 'Bridge Modbus TCP clients to a serial line, shown live'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "poll" -d 'Keep a plant\'s devices read, each at its rate'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "ports" -d 'The serial ports here, and which adapter each one is'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "generate" -d 'Write the shell completions and man pages (for packagers and the project\'s own tree)'
complete -c mbtool -n "__fish_mbtool_using_subcommand help; and not __fish_seen_subcommand_from read-coils read-inputs read-holding read-input-registers read write-coil write-coils write-register write-registers write read-file write-file mask-write read-write read-fifo raw scan watch info sunspec diag dump restore decode encode sniff serve gateway poll ports generate help" -f -a "help" -d 'Print this message or the help of the given subcommand(s)'
