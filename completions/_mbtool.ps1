
using namespace System.Management.Automation
using namespace System.Management.Automation.Language

Register-ArgumentCompleter -Native -CommandName 'mbtool' -ScriptBlock {
    param($wordToComplete, $commandAst, $cursorPosition)

    $commandElements = $commandAst.CommandElements
    $command = @(
        'mbtool'
        for ($i = 1; $i -lt $commandElements.Count; $i++) {
            $element = $commandElements[$i]
            if ($element -isnot [StringConstantExpressionAst] -or
                $element.StringConstantType -ne [StringConstantType]::BareWord -or
                $element.Value.StartsWith('-') -or
                $element.Value -eq $wordToComplete) {
                break
        }
        $element.Value
    }) -join ';'

    $completions = @(switch ($command) {
        'mbtool' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing what changed, with a summary on stderr at the end; a failed read is a row of its own, a range with holes is read around them (each hole a "no such address" row), and a connection that drops is opened again')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'With --poll: stop after N reads')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'With --poll: also append every row, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('read-coils', 'read-coils', [CompletionResultType]::ParameterValue, 'Read coils (function 01)')
            [CompletionResult]::new('read-inputs', 'read-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-discrete-inputs', 'read-discrete-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-holding', 'read-holding', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-holding-registers', 'read-holding-registers', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-input-registers', 'read-input-registers', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read-input-regs', 'read-input-regs', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read', 'read', [CompletionResultType]::ParameterValue, 'Read by reference: its first digit picks the table')
            [CompletionResult]::new('write-coil', 'write-coil', [CompletionResultType]::ParameterValue, 'Write one coil (function 05)')
            [CompletionResult]::new('write-coils', 'write-coils', [CompletionResultType]::ParameterValue, 'Write coils (function 15)')
            [CompletionResult]::new('write-register', 'write-register', [CompletionResultType]::ParameterValue, 'Write one holding register (function 06)')
            [CompletionResult]::new('write-registers', 'write-registers', [CompletionResultType]::ParameterValue, 'Write holding registers (function 16)')
            [CompletionResult]::new('write', 'write', [CompletionResultType]::ParameterValue, 'Write by reference: 05/06 for one value, 15/16 for more')
            [CompletionResult]::new('raw', 'raw', [CompletionResultType]::ParameterValue, 'Send any PDU and decode the answer')
            [CompletionResult]::new('scan', 'scan', [CompletionResultType]::ParameterValue, 'Find the slaves on a line and the settings they use')
            [CompletionResult]::new('watch', 'watch', [CompletionResultType]::ParameterValue, 'Watch values live, full screen: min, max, trend, changes')
            [CompletionResult]::new('info', 'info', [CompletionResultType]::ParameterValue, 'Ask a device who it is: identification and server id')
            [CompletionResult]::new('diag', 'diag', [CompletionResultType]::ParameterValue, 'A device''s health: round trips, counters, status')
            [CompletionResult]::new('dump', 'dump', [CompletionResultType]::ParameterValue, 'Save a device''s tables to a data file, holes left out')
            [CompletionResult]::new('restore', 'restore', [CompletionResultType]::ParameterValue, 'Write a data file back to a device, and check it')
            [CompletionResult]::new('decode', 'decode', [CompletionResultType]::ParameterValue, 'Decode frames given as arguments or on standard input')
            [CompletionResult]::new('encode', 'encode', [CompletionResultType]::ParameterValue, 'Print the frame a request command would send')
            [CompletionResult]::new('sniff', 'sniff', [CompletionResultType]::ParameterValue, 'Watch a bus without transmitting; frames decoded, paired')
            [CompletionResult]::new('serve', 'serve', [CompletionResultType]::ParameterValue, 'Stand in for a slave on a serial line or TCP')
            [CompletionResult]::new('gateway', 'gateway', [CompletionResultType]::ParameterValue, 'Bridge Modbus TCP clients to a serial line, shown live')
            [CompletionResult]::new('ports', 'ports', [CompletionResultType]::ParameterValue, 'The serial ports here, and which adapter each one is')
            [CompletionResult]::new('generate', 'generate', [CompletionResultType]::ParameterValue, 'Write the shell completions and man pages (for packagers and the project''s own tree)')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'mbtool;read-coils' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing what changed, with a summary on stderr at the end; a failed read is a row of its own, a range with holes is read around them (each hole a "no such address" row), and a connection that drops is opened again')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'With --poll: stop after N reads')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'With --poll: also append every row, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-inputs' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing what changed, with a summary on stderr at the end; a failed read is a row of its own, a range with holes is read around them (each hole a "no such address" row), and a connection that drops is opened again')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'With --poll: stop after N reads')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'With --poll: also append every row, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-discrete-inputs' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing what changed, with a summary on stderr at the end; a failed read is a row of its own, a range with holes is read around them (each hole a "no such address" row), and a connection that drops is opened again')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'With --poll: stop after N reads')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'With --poll: also append every row, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-holding' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing what changed, with a summary on stderr at the end; a failed read is a row of its own, a range with holes is read around them (each hole a "no such address" row), and a connection that drops is opened again')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'With --poll: stop after N reads')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'With --poll: also append every row, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-holding-registers' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing what changed, with a summary on stderr at the end; a failed read is a row of its own, a range with holes is read around them (each hole a "no such address" row), and a connection that drops is opened again')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'With --poll: stop after N reads')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'With --poll: also append every row, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-input-registers' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing what changed, with a summary on stderr at the end; a failed read is a row of its own, a range with holes is read around them (each hole a "no such address" row), and a connection that drops is opened again')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'With --poll: stop after N reads')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'With --poll: also append every row, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-input-regs' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing what changed, with a summary on stderr at the end; a failed read is a row of its own, a range with holes is read around them (each hole a "no such address" row), and a connection that drops is opened again')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'With --poll: stop after N reads')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'With --poll: also append every row, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'Repeat a read every INTERVAL (0 for back to back) until Ctrl-C or --count, showing what changed, with a summary on stderr at the end; a failed read is a row of its own, a range with holes is read around them (each hole a "no such address" row), and a connection that drops is opened again')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'With --poll: stop after N reads')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'With --poll: also append every row, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--map', '--map', [CompletionResultType]::ParameterName, 'Read the points of a register map (CSV, or Home Assistant YAML), by name')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write-coil' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write-coils' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write-register' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write-registers' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--map', '--map', [CompletionResultType]::ParameterName, 'Write points of a register map by name: NAME=VALUE, scale and offset taken back out')
            [CompletionResult]::new('--function', '--function', [CompletionResultType]::ParameterName, 'Force the function: 5 or 15 for coils, 6 or 16 for registers')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;raw' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;scan' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--ids', '--ids', [CompletionResultType]::ParameterName, 'The ids to ask: ranges and single ids, as 1-247 (the default) or 1-10,17,200')
            [CompletionResult]::new('--probe', '--probe', [CompletionResultType]::ParameterName, 'What each id is asked: read (03, one register at address 0) or id (17)')
            [CompletionResult]::new('--listen', '--listen', [CompletionResultType]::ParameterName, 'Listen this long at each setting before sending anything: slaves heard answering another master are found without adding traffic')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--all', '--all', [CompletionResultType]::ParameterName, 'Try every setting of the sweep, not only up to the first where a slave answers')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;watch' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--poll', '--poll', [CompletionResultType]::ParameterName, 'How often to read [default: 1s]')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--map', '--map', [CompletionResultType]::ParameterName, 'Watch the points of a register map (CSV, or Home Assistant YAML)')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;info' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;diag' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--count', '--count', [CompletionResultType]::ParameterName, 'How many round trips of return query data to time [default: 5]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--clear', '--clear', [CompletionResultType]::ParameterName, 'After reading them, clear the device''s counters (08/0A)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;dump' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'The data file to write [default: standard output]')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'The data file to write [default: standard output]')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;restore' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--secondary-port', '--secondary-port', [CompletionResultType]::ParameterName, 'A second path to the same device (any --port), used when the --switch-on conditions hold on the one in use; its line settings are the primary''s unless given below')
            [CompletionResult]::new('--secondary-baud', '--secondary-baud', [CompletionResultType]::ParameterName, 'Serial speed of the secondary path [default: --baud]')
            [CompletionResult]::new('--secondary-parity', '--secondary-parity', [CompletionResultType]::ParameterName, 'Serial parity of the secondary path [default: --parity]')
            [CompletionResult]::new('--secondary-data-bits', '--secondary-data-bits', [CompletionResultType]::ParameterName, 'Serial data bits of the secondary path [default: --data-bits]')
            [CompletionResult]::new('--secondary-stop-bits', '--secondary-stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits of the secondary path [default: --stop-bits]')
            [CompletionResult]::new('--secondary-mode', '--secondary-mode', [CompletionResultType]::ParameterName, 'Framing of the secondary path [default: --mode, tcp for tcp:// ports]')
            [CompletionResult]::new('--switch-on', '--switch-on', [CompletionResultType]::ParameterName, 'When to change paths, counted since the path''s last good answer: timeout:N, bad-frame:N, exception:CODE (hex), disconnect [default: timeout:3,disconnect]')
            [CompletionResult]::new('--switch-when', '--switch-when', [CompletionResultType]::ParameterName, 'Whether any of the --switch-on conditions changes paths, or only all of them together [default: any]')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--dry-run', '--dry-run', [CompletionResultType]::ParameterName, 'Print the frames that would be sent, and send nothing')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;decode' {
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--direction', '--direction', [CompletionResultType]::ParameterName, 'Read every frame as a request or as a response instead of inferring it')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--address-base', '--address-base', [CompletionResultType]::ParameterName, 'What a bare address number counts from, in what is typed and in the address column shown: 0, the protocol address (107 is 400108), or 1, the register number as manuals and mbpoll count (108 is 400108). References (400108) are the same either way; decode, sniff and serve show a frame''s address field as it is on the wire')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a plain number, never as a Modicon reference: 40001 is then protocol address 40001 (register number 40001 with --address-base 1)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('read-coils', 'read-coils', [CompletionResultType]::ParameterValue, 'Read coils (function 01)')
            [CompletionResult]::new('read-inputs', 'read-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-discrete-inputs', 'read-discrete-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-holding', 'read-holding', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-holding-registers', 'read-holding-registers', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-input-registers', 'read-input-registers', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read-input-regs', 'read-input-regs', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read', 'read', [CompletionResultType]::ParameterValue, 'Read by reference: its first digit picks the table')
            [CompletionResult]::new('write-coil', 'write-coil', [CompletionResultType]::ParameterValue, 'Write one coil (function 05)')
            [CompletionResult]::new('write-coils', 'write-coils', [CompletionResultType]::ParameterValue, 'Write coils (function 15)')
            [CompletionResult]::new('write-register', 'write-register', [CompletionResultType]::ParameterValue, 'Write one holding register (function 06)')
            [CompletionResult]::new('write-registers', 'write-registers', [CompletionResultType]::ParameterValue, 'Write holding registers (function 16)')
            [CompletionResult]::new('write', 'write', [CompletionResultType]::ParameterValue, 'Write by reference: 05/06 for one value, 15/16 for more')
            [CompletionResult]::new('raw', 'raw', [CompletionResultType]::ParameterValue, 'Send any PDU and decode the answer')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'mbtool;encode;read-coils' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-inputs' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-discrete-inputs' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-holding' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-holding-registers' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-input-registers' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-input-regs' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read' {
            [CompletionResult]::new('--map', '--map', [CompletionResultType]::ParameterName, 'Read the points of a register map (CSV, or Home Assistant YAML), by name')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write-coil' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write-coils' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write-register' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write-registers' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write' {
            [CompletionResult]::new('--map', '--map', [CompletionResultType]::ParameterName, 'Write points of a register map by name: NAME=VALUE, scale and offset taken back out')
            [CompletionResult]::new('--function', '--function', [CompletionResultType]::ParameterName, 'Force the function: 5 or 15 for coils, 6 or 16 for registers')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;raw' {
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;help' {
            [CompletionResult]::new('read-coils', 'read-coils', [CompletionResultType]::ParameterValue, 'Read coils (function 01)')
            [CompletionResult]::new('read-inputs', 'read-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-holding', 'read-holding', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-input-registers', 'read-input-registers', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read', 'read', [CompletionResultType]::ParameterValue, 'Read by reference: its first digit picks the table')
            [CompletionResult]::new('write-coil', 'write-coil', [CompletionResultType]::ParameterValue, 'Write one coil (function 05)')
            [CompletionResult]::new('write-coils', 'write-coils', [CompletionResultType]::ParameterValue, 'Write coils (function 15)')
            [CompletionResult]::new('write-register', 'write-register', [CompletionResultType]::ParameterValue, 'Write one holding register (function 06)')
            [CompletionResult]::new('write-registers', 'write-registers', [CompletionResultType]::ParameterValue, 'Write holding registers (function 16)')
            [CompletionResult]::new('write', 'write', [CompletionResultType]::ParameterValue, 'Write by reference: 05/06 for one value, 15/16 for more')
            [CompletionResult]::new('raw', 'raw', [CompletionResultType]::ParameterValue, 'Send any PDU and decode the answer')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'mbtool;encode;help;read-coils' {
            break
        }
        'mbtool;encode;help;read-inputs' {
            break
        }
        'mbtool;encode;help;read-holding' {
            break
        }
        'mbtool;encode;help;read-input-registers' {
            break
        }
        'mbtool;encode;help;read' {
            break
        }
        'mbtool;encode;help;write-coil' {
            break
        }
        'mbtool;encode;help;write-coils' {
            break
        }
        'mbtool;encode;help;write-register' {
            break
        }
        'mbtool;encode;help;write-registers' {
            break
        }
        'mbtool;encode;help;write' {
            break
        }
        'mbtool;encode;help;raw' {
            break
        }
        'mbtool;encode;help;help' {
            break
        }
        'mbtool;sniff' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--input', '--input', [CompletionResultType]::ParameterName, 'Read a capture instead of the port (''-'' for standard input): a pcap or pcapng file of Modbus TCP (tcpdump, dumpcap, Wireshark), or the raw bytes of a serial line')
            [CompletionResult]::new('--interface', '--interface', [CompletionResultType]::ParameterName, 'Capture Modbus TCP live from a network interface (eth0, lo) through libpcap; needs capture privileges. With --save FILE the packets are kept as pcapng')
            [CompletionResult]::new('--tcp-port', '--tcp-port', [CompletionResultType]::ParameterName, 'In a pcap or pcapng capture: the TCP port of the Modbus servers [default: 502]; repeatable. With --mode rtu the streams carry RTU frames (a transparent gateway)')
            [CompletionResult]::new('--save', '--save', [CompletionResultType]::ParameterName, 'Keep every byte seen, exactly as received, to replay it later with --input; live, their times go to FILE.timing beside it. With --interface, the packets, as pcapng')
            [CompletionResult]::new('--pcap', '--pcap', [CompletionResultType]::ParameterName, 'Also write the frames to a pcap file for Wireshark (link type 147, see above)')
            [CompletionResult]::new('--slave', '--slave', [CompletionResultType]::ParameterName, 'Show only the frames of this slave; repeatable')
            [CompletionResult]::new('--function', '--function', [CompletionResultType]::ParameterName, 'Show only the frames of this function code (3, 0x10); repeatable')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--stats', '--stats', [CompletionResultType]::ParameterName, 'At the end, a table (or JSON lines of "type":"stats") per server and unit: requests, answers, exceptions by code, unanswered, and response time min, mean, p95 and max')
            [CompletionResult]::new('--low-latency', '--low-latency', [CompletionResultType]::ParameterName, 'Ask the USB serial driver for its lowest latency (the FTDI latency timer to 1 ms), so that gaps between frames can be seen')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;serve' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--slave', '--slave', [CompletionResultType]::ParameterName, 'Answer as this slave id; repeat for several [default: 17]')
            [CompletionResult]::new('--data', '--data', [CompletionResultType]::ParameterName, 'Initial data and the addresses that exist (see above for the format)')
            [CompletionResult]::new('--read-only', '--read-only', [CompletionResultType]::ParameterName, 'Addresses that may not be written (exception 02): a reference or a range; repeatable')
            [CompletionResult]::new('--delay', '--delay', [CompletionResultType]::ParameterName, 'Wait this long before each answer')
            [CompletionResult]::new('--drop', '--drop', [CompletionResultType]::ParameterName, 'Leave this share of requests unanswered: 0 to 1, or 5%')
            [CompletionResult]::new('--corrupt', '--corrupt', [CompletionResultType]::ParameterName, 'Corrupt this share of answers (a bad checksum; over TCP a wrong function): 0 to 1, or 5%')
            [CompletionResult]::new('--exception', '--exception', [CompletionResultType]::ParameterName, 'Answer exception CODE to every request, or to those touching RANGE (CODE@RANGE, as in 2@400100-400120); repeatable')
            [CompletionResult]::new('--seed', '--seed', [CompletionResultType]::ParameterName, 'Seed for the random choices of --drop, --corrupt and --garbage, to repeat a run')
            [CompletionResult]::new('--vendor', '--vendor', [CompletionResultType]::ParameterName, 'Device identification: vendor name')
            [CompletionResult]::new('--product-code', '--product-code', [CompletionResultType]::ParameterName, 'Device identification: product code')
            [CompletionResult]::new('--identity', '--identity', [CompletionResultType]::ParameterName, 'Device identification: any object, by name or id (VendorUrl=https://example.com, ProductName=Pump, 0x80=serial 4711); repeatable')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--garbage', '--garbage', [CompletionResultType]::ParameterName, 'Send a few noise bytes (00, FE) before each answer, as a bus being handed over does')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'No log line per request')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'No log line per request')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;gateway' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT] (a bare 192.168.1.10 or HOST:PORT is Modbus TCP too), rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-b', '-b', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--baud', '--baud', [CompletionResultType]::ParameterName, 'Serial speed; scan takes a list to sweep (9600,19200,38400), else tries this one')
            [CompletionResult]::new('--parity', '--parity', [CompletionResultType]::ParameterName, 'Serial parity; scan takes a list to sweep (none,even,odd), else tries this one')
            [CompletionResult]::new('--data-bits', '--data-bits', [CompletionResultType]::ParameterName, 'Serial data bits [default: 8, 7 in ASCII mode]')
            [CompletionResult]::new('--stop-bits', '--stop-bits', [CompletionResultType]::ParameterName, 'Serial stop bits [default: 1 with parity, 2 without]')
            [CompletionResult]::new('--timeout', '--timeout', [CompletionResultType]::ParameterName, 'Response timeout for a whole answer: 500ms, 1s, 2.5s (a bare number is seconds, up to 60) [default: 1s; 100ms for scan]')
            [CompletionResult]::new('--retries', '--retries', [CompletionResultType]::ParameterName, 'Retries after a timeout or a bad answer (never after an exception)')
            [CompletionResult]::new('--frame-gap', '--frame-gap', [CompletionResultType]::ParameterName, 'Silence kept between RTU transactions [default: 3.5 characters, 1.75 ms above 19200 baud]; 0 for gateways and devices that need none')
            [CompletionResult]::new('--rs485-delay-before', '--rs485-delay-before', [CompletionResultType]::ParameterName, 'Milliseconds from RTS raised to the first byte sent, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rs485-delay-after', '--rs485-delay-after', [CompletionResultType]::ParameterName, 'Milliseconds from the last byte gone to RTS dropped, with --rs485 or --rts-toggle')
            [CompletionResult]::new('--rts-level', '--rts-level', [CompletionResultType]::ParameterName, 'The level of RTS while sending, with --rs485 or --rts-toggle (high: asserted) [default: high]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--log', '--log', [CompletionResultType]::ParameterName, 'Also append every transaction, with its time, to FILE: CSV for a .csv name, JSON Lines for any other')
            [CompletionResult]::new('--listen', '--listen', [CompletionResultType]::ParameterName, 'Where clients connect: tcp://ADDRESS[:PORT]; repeatable')
            [CompletionResult]::new('--unit-map', '--unit-map', [CompletionResultType]::ParameterName, 'Unit ids mapped to the slave ids they reach on the line: UNIT=SLAVE,...')
            [CompletionResult]::new('--rs485', '--rs485', [CompletionResultType]::ParameterName, 'RS-485 direction by the kernel''s RS-485 mode (Linux): the UART driver raises RTS while sending, for transceivers that need the host to switch them')
            [CompletionResult]::new('--rts-toggle', '--rts-toggle', [CompletionResultType]::ParameterName, 'RS-485 direction by mbtool itself: RTS raised before each frame sent and dropped once its last byte has left (tcdrain), for drivers without RS-485 mode')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-v', '-v', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--verbose', '--verbose', [CompletionResultType]::ParameterName, 'Print every frame sent and received, in hex with a timestamp, on stderr')
            [CompletionResult]::new('--broadcast-reply', '--broadcast-reply', [CompletionResultType]::ParameterName, 'Answer a broadcast (unit 0) as a slave answers a write, for clients that wait for one')
            [CompletionResult]::new('-q', '-q', [CompletionResultType]::ParameterName, 'No row per transaction (stderr still tells the line and the clients)')
            [CompletionResult]::new('--quiet', '--quiet', [CompletionResultType]::ParameterName, 'No row per transaction (stderr still tells the line and the clients)')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;ports' {
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format [default: table]; for dump, the file to write')
            [CompletionResult]::new('--root', '--root', [CompletionResultType]::ParameterName, 'Read sys, dev and proc under DIR instead of / (a copy taken from another machine)')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;generate' {
            [CompletionResult]::new('--dir', '--dir', [CompletionResultType]::ParameterName, 'The folder that receives completions/ and man/')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;help' {
            [CompletionResult]::new('read-coils', 'read-coils', [CompletionResultType]::ParameterValue, 'Read coils (function 01)')
            [CompletionResult]::new('read-inputs', 'read-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-holding', 'read-holding', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-input-registers', 'read-input-registers', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read', 'read', [CompletionResultType]::ParameterValue, 'Read by reference: its first digit picks the table')
            [CompletionResult]::new('write-coil', 'write-coil', [CompletionResultType]::ParameterValue, 'Write one coil (function 05)')
            [CompletionResult]::new('write-coils', 'write-coils', [CompletionResultType]::ParameterValue, 'Write coils (function 15)')
            [CompletionResult]::new('write-register', 'write-register', [CompletionResultType]::ParameterValue, 'Write one holding register (function 06)')
            [CompletionResult]::new('write-registers', 'write-registers', [CompletionResultType]::ParameterValue, 'Write holding registers (function 16)')
            [CompletionResult]::new('write', 'write', [CompletionResultType]::ParameterValue, 'Write by reference: 05/06 for one value, 15/16 for more')
            [CompletionResult]::new('raw', 'raw', [CompletionResultType]::ParameterValue, 'Send any PDU and decode the answer')
            [CompletionResult]::new('scan', 'scan', [CompletionResultType]::ParameterValue, 'Find the slaves on a line and the settings they use')
            [CompletionResult]::new('watch', 'watch', [CompletionResultType]::ParameterValue, 'Watch values live, full screen: min, max, trend, changes')
            [CompletionResult]::new('info', 'info', [CompletionResultType]::ParameterValue, 'Ask a device who it is: identification and server id')
            [CompletionResult]::new('diag', 'diag', [CompletionResultType]::ParameterValue, 'A device''s health: round trips, counters, status')
            [CompletionResult]::new('dump', 'dump', [CompletionResultType]::ParameterValue, 'Save a device''s tables to a data file, holes left out')
            [CompletionResult]::new('restore', 'restore', [CompletionResultType]::ParameterValue, 'Write a data file back to a device, and check it')
            [CompletionResult]::new('decode', 'decode', [CompletionResultType]::ParameterValue, 'Decode frames given as arguments or on standard input')
            [CompletionResult]::new('encode', 'encode', [CompletionResultType]::ParameterValue, 'Print the frame a request command would send')
            [CompletionResult]::new('sniff', 'sniff', [CompletionResultType]::ParameterValue, 'Watch a bus without transmitting; frames decoded, paired')
            [CompletionResult]::new('serve', 'serve', [CompletionResultType]::ParameterValue, 'Stand in for a slave on a serial line or TCP')
            [CompletionResult]::new('gateway', 'gateway', [CompletionResultType]::ParameterValue, 'Bridge Modbus TCP clients to a serial line, shown live')
            [CompletionResult]::new('ports', 'ports', [CompletionResultType]::ParameterValue, 'The serial ports here, and which adapter each one is')
            [CompletionResult]::new('generate', 'generate', [CompletionResultType]::ParameterValue, 'Write the shell completions and man pages (for packagers and the project''s own tree)')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'mbtool;help;read-coils' {
            break
        }
        'mbtool;help;read-inputs' {
            break
        }
        'mbtool;help;read-holding' {
            break
        }
        'mbtool;help;read-input-registers' {
            break
        }
        'mbtool;help;read' {
            break
        }
        'mbtool;help;write-coil' {
            break
        }
        'mbtool;help;write-coils' {
            break
        }
        'mbtool;help;write-register' {
            break
        }
        'mbtool;help;write-registers' {
            break
        }
        'mbtool;help;write' {
            break
        }
        'mbtool;help;raw' {
            break
        }
        'mbtool;help;scan' {
            break
        }
        'mbtool;help;watch' {
            break
        }
        'mbtool;help;info' {
            break
        }
        'mbtool;help;diag' {
            break
        }
        'mbtool;help;dump' {
            break
        }
        'mbtool;help;restore' {
            break
        }
        'mbtool;help;decode' {
            break
        }
        'mbtool;help;encode' {
            break
        }
        'mbtool;help;sniff' {
            break
        }
        'mbtool;help;serve' {
            break
        }
        'mbtool;help;gateway' {
            break
        }
        'mbtool;help;ports' {
            break
        }
        'mbtool;help;generate' {
            break
        }
        'mbtool;help;help' {
            break
        }
    })

    $completions.Where{ $_.CompletionText -like "$wordToComplete*" } |
        Sort-Object -Property ListItemText
}
