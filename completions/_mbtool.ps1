
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
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('generate', 'generate', [CompletionResultType]::ParameterValue, 'Write the shell completions and man pages (for packagers and the project''s own tree)')
            [CompletionResult]::new('read-coils', 'read-coils', [CompletionResultType]::ParameterValue, 'Read coils (function 01)')
            [CompletionResult]::new('read-inputs', 'read-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-discrete-inputs', 'read-discrete-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-holding', 'read-holding', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-holding-registers', 'read-holding-registers', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-input-registers', 'read-input-registers', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read-input-regs', 'read-input-regs', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read', 'read', [CompletionResultType]::ParameterValue, 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)')
            [CompletionResult]::new('write-coil', 'write-coil', [CompletionResultType]::ParameterValue, 'Write one coil (function 05)')
            [CompletionResult]::new('write-coils', 'write-coils', [CompletionResultType]::ParameterValue, 'Write coils (function 15)')
            [CompletionResult]::new('write-register', 'write-register', [CompletionResultType]::ParameterValue, 'Write one holding register (function 06)')
            [CompletionResult]::new('write-registers', 'write-registers', [CompletionResultType]::ParameterValue, 'Write holding registers (function 16)')
            [CompletionResult]::new('write', 'write', [CompletionResultType]::ParameterValue, 'Write by Modicon reference: 05/06 for one value, 15/16 for several')
            [CompletionResult]::new('raw', 'raw', [CompletionResultType]::ParameterValue, 'Send any PDU and decode the answer')
            [CompletionResult]::new('decode', 'decode', [CompletionResultType]::ParameterValue, 'Decode Modbus frames given as arguments, or one per line on standard input')
            [CompletionResult]::new('encode', 'encode', [CompletionResultType]::ParameterValue, 'Print the frame that a request command would send, without sending it')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'mbtool;generate' {
            [CompletionResult]::new('--dir', '--dir', [CompletionResultType]::ParameterName, 'The folder that receives completions/ and man/')
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-coils' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-inputs' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-discrete-inputs' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-holding' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-holding-registers' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-input-registers' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read-input-regs' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;read' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write-coil' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write-coils' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write-register' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write-registers' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;write' {
            [CompletionResult]::new('--function', '--function', [CompletionResultType]::ParameterName, 'Force the function: 5 or 15 for coils, 6 or 16 for registers')
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;raw' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;decode' {
            [CompletionResult]::new('--direction', '--direction', [CompletionResultType]::ParameterName, 'Read every frame as a request or as a response instead of inferring it')
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
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
            [CompletionResult]::new('read', 'read', [CompletionResultType]::ParameterValue, 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)')
            [CompletionResult]::new('write-coil', 'write-coil', [CompletionResultType]::ParameterValue, 'Write one coil (function 05)')
            [CompletionResult]::new('write-coils', 'write-coils', [CompletionResultType]::ParameterValue, 'Write coils (function 15)')
            [CompletionResult]::new('write-register', 'write-register', [CompletionResultType]::ParameterValue, 'Write one holding register (function 06)')
            [CompletionResult]::new('write-registers', 'write-registers', [CompletionResultType]::ParameterValue, 'Write holding registers (function 16)')
            [CompletionResult]::new('write', 'write', [CompletionResultType]::ParameterValue, 'Write by Modicon reference: 05/06 for one value, 15/16 for several')
            [CompletionResult]::new('raw', 'raw', [CompletionResultType]::ParameterValue, 'Send any PDU and decode the answer')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'mbtool;encode;read-coils' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-inputs' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-discrete-inputs' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-holding' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-holding-registers' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-input-registers' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read-input-regs' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;read' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write-coil' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write-coils' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write-register' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write-registers' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;write' {
            [CompletionResult]::new('--function', '--function', [CompletionResultType]::ParameterName, 'Force the function: 5 or 15 for coils, 6 or 16 for registers')
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;raw' {
            [CompletionResult]::new('-p', '-p', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('--port', '--port', [CompletionResultType]::ParameterName, 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim')
            [CompletionResult]::new('-m', '-m', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('--mode', '--mode', [CompletionResultType]::ParameterName, 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]')
            [CompletionResult]::new('-o', '-o', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('--output', '--output', [CompletionResultType]::ParameterName, 'Output format')
            [CompletionResult]::new('-t', '-t', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--type', '--type', [CompletionResultType]::ParameterName, 'Register value type, for showing values read and for converting values to write')
            [CompletionResult]::new('--order', '--order', [CompletionResultType]::ParameterName, 'Byte order of values wider than 16 bits: A is the most significant byte')
            [CompletionResult]::new('--max-per-request', '--max-per-request', [CompletionResultType]::ParameterName, 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows')
            [CompletionResult]::new('--json', '--json', [CompletionResultType]::ParameterName, 'The same as --output json')
            [CompletionResult]::new('--pdu-addresses', '--pdu-addresses', [CompletionResultType]::ParameterName, 'Take every address as a 0-based protocol address, never as a Modicon reference')
            [CompletionResult]::new('-h', '-h', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('--help', '--help', [CompletionResultType]::ParameterName, 'Print help (see more with ''--help'')')
            [CompletionResult]::new('-V', '-V ', [CompletionResultType]::ParameterName, 'Print version')
            [CompletionResult]::new('--version', '--version', [CompletionResultType]::ParameterName, 'Print version')
            break
        }
        'mbtool;encode;help' {
            [CompletionResult]::new('read-coils', 'read-coils', [CompletionResultType]::ParameterValue, 'Read coils (function 01)')
            [CompletionResult]::new('read-inputs', 'read-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-holding', 'read-holding', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-input-registers', 'read-input-registers', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read', 'read', [CompletionResultType]::ParameterValue, 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)')
            [CompletionResult]::new('write-coil', 'write-coil', [CompletionResultType]::ParameterValue, 'Write one coil (function 05)')
            [CompletionResult]::new('write-coils', 'write-coils', [CompletionResultType]::ParameterValue, 'Write coils (function 15)')
            [CompletionResult]::new('write-register', 'write-register', [CompletionResultType]::ParameterValue, 'Write one holding register (function 06)')
            [CompletionResult]::new('write-registers', 'write-registers', [CompletionResultType]::ParameterValue, 'Write holding registers (function 16)')
            [CompletionResult]::new('write', 'write', [CompletionResultType]::ParameterValue, 'Write by Modicon reference: 05/06 for one value, 15/16 for several')
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
        'mbtool;help' {
            [CompletionResult]::new('generate', 'generate', [CompletionResultType]::ParameterValue, 'Write the shell completions and man pages (for packagers and the project''s own tree)')
            [CompletionResult]::new('read-coils', 'read-coils', [CompletionResultType]::ParameterValue, 'Read coils (function 01)')
            [CompletionResult]::new('read-inputs', 'read-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-holding', 'read-holding', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-input-registers', 'read-input-registers', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read', 'read', [CompletionResultType]::ParameterValue, 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)')
            [CompletionResult]::new('write-coil', 'write-coil', [CompletionResultType]::ParameterValue, 'Write one coil (function 05)')
            [CompletionResult]::new('write-coils', 'write-coils', [CompletionResultType]::ParameterValue, 'Write coils (function 15)')
            [CompletionResult]::new('write-register', 'write-register', [CompletionResultType]::ParameterValue, 'Write one holding register (function 06)')
            [CompletionResult]::new('write-registers', 'write-registers', [CompletionResultType]::ParameterValue, 'Write holding registers (function 16)')
            [CompletionResult]::new('write', 'write', [CompletionResultType]::ParameterValue, 'Write by Modicon reference: 05/06 for one value, 15/16 for several')
            [CompletionResult]::new('raw', 'raw', [CompletionResultType]::ParameterValue, 'Send any PDU and decode the answer')
            [CompletionResult]::new('decode', 'decode', [CompletionResultType]::ParameterValue, 'Decode Modbus frames given as arguments, or one per line on standard input')
            [CompletionResult]::new('encode', 'encode', [CompletionResultType]::ParameterValue, 'Print the frame that a request command would send, without sending it')
            [CompletionResult]::new('help', 'help', [CompletionResultType]::ParameterValue, 'Print this message or the help of the given subcommand(s)')
            break
        }
        'mbtool;help;generate' {
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
        'mbtool;help;decode' {
            break
        }
        'mbtool;help;encode' {
            [CompletionResult]::new('read-coils', 'read-coils', [CompletionResultType]::ParameterValue, 'Read coils (function 01)')
            [CompletionResult]::new('read-inputs', 'read-inputs', [CompletionResultType]::ParameterValue, 'Read discrete inputs (function 02)')
            [CompletionResult]::new('read-holding', 'read-holding', [CompletionResultType]::ParameterValue, 'Read holding registers (function 03)')
            [CompletionResult]::new('read-input-registers', 'read-input-registers', [CompletionResultType]::ParameterValue, 'Read input registers (function 04)')
            [CompletionResult]::new('read', 'read', [CompletionResultType]::ParameterValue, 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)')
            [CompletionResult]::new('write-coil', 'write-coil', [CompletionResultType]::ParameterValue, 'Write one coil (function 05)')
            [CompletionResult]::new('write-coils', 'write-coils', [CompletionResultType]::ParameterValue, 'Write coils (function 15)')
            [CompletionResult]::new('write-register', 'write-register', [CompletionResultType]::ParameterValue, 'Write one holding register (function 06)')
            [CompletionResult]::new('write-registers', 'write-registers', [CompletionResultType]::ParameterValue, 'Write holding registers (function 16)')
            [CompletionResult]::new('write', 'write', [CompletionResultType]::ParameterValue, 'Write by Modicon reference: 05/06 for one value, 15/16 for several')
            [CompletionResult]::new('raw', 'raw', [CompletionResultType]::ParameterValue, 'Send any PDU and decode the answer')
            break
        }
        'mbtool;help;encode;read-coils' {
            break
        }
        'mbtool;help;encode;read-inputs' {
            break
        }
        'mbtool;help;encode;read-holding' {
            break
        }
        'mbtool;help;encode;read-input-registers' {
            break
        }
        'mbtool;help;encode;read' {
            break
        }
        'mbtool;help;encode;write-coil' {
            break
        }
        'mbtool;help;encode;write-coils' {
            break
        }
        'mbtool;help;encode;write-register' {
            break
        }
        'mbtool;help;encode;write-registers' {
            break
        }
        'mbtool;help;encode;write' {
            break
        }
        'mbtool;help;encode;raw' {
            break
        }
        'mbtool;help;help' {
            break
        }
    })

    $completions.Where{ $_.CompletionText -like "$wordToComplete*" } |
        Sort-Object -Property ListItemText
}
