
use builtin;
use str;

set edit:completion:arg-completer[mbtool] = {|@words|
    fn spaces {|n|
        builtin:repeat $n ' ' | str:join ''
    }
    fn cand {|text desc|
        edit:complex-candidate $text &display=$text' '(spaces (- 14 (wcswidth $text)))$desc
    }
    var command = 'mbtool'
    for word $words[1..-1] {
        if (str:has-prefix $word '-') {
            break
        }
        set command = $command';'$word
    }
    var completions = [
        &'mbtool'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
            cand generate 'Write the shell completions and man pages (for packagers and the project''s own tree)'
            cand read-coils 'Read coils (function 01)'
            cand read-inputs 'Read discrete inputs (function 02)'
            cand read-discrete-inputs 'Read discrete inputs (function 02)'
            cand read-holding 'Read holding registers (function 03)'
            cand read-holding-registers 'Read holding registers (function 03)'
            cand read-input-registers 'Read input registers (function 04)'
            cand read-input-regs 'Read input registers (function 04)'
            cand read 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)'
            cand write-coil 'Write one coil (function 05)'
            cand write-coils 'Write coils (function 15)'
            cand write-register 'Write one holding register (function 06)'
            cand write-registers 'Write holding registers (function 16)'
            cand write 'Write by Modicon reference: 05/06 for one value, 15/16 for several'
            cand raw 'Send any PDU and decode the answer'
            cand decode 'Decode Modbus frames given as arguments, or one per line on standard input'
            cand encode 'Print the frame that a request command would send, without sending it'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'mbtool;generate'= {
            cand --dir 'The folder that receives completions/ and man/'
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;read-coils'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;read-inputs'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;read-discrete-inputs'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;read-holding'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;read-holding-registers'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;read-input-registers'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;read-input-regs'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;read'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;write-coil'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;write-coils'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;write-register'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;write-registers'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;write'= {
            cand --function 'Force the function: 5 or 15 for coils, 6 or 16 for registers'
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;raw'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;decode'= {
            cand --direction 'Read every frame as a request or as a response instead of inferring it'
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
            cand read-coils 'Read coils (function 01)'
            cand read-inputs 'Read discrete inputs (function 02)'
            cand read-discrete-inputs 'Read discrete inputs (function 02)'
            cand read-holding 'Read holding registers (function 03)'
            cand read-holding-registers 'Read holding registers (function 03)'
            cand read-input-registers 'Read input registers (function 04)'
            cand read-input-regs 'Read input registers (function 04)'
            cand read 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)'
            cand write-coil 'Write one coil (function 05)'
            cand write-coils 'Write coils (function 15)'
            cand write-register 'Write one holding register (function 06)'
            cand write-registers 'Write holding registers (function 16)'
            cand write 'Write by Modicon reference: 05/06 for one value, 15/16 for several'
            cand raw 'Send any PDU and decode the answer'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'mbtool;encode;read-coils'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;read-inputs'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;read-discrete-inputs'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;read-holding'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;read-holding-registers'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;read-input-registers'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;read-input-regs'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;read'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;write-coil'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;write-coils'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;write-register'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;write-registers'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;write'= {
            cand --function 'Force the function: 5 or 15 for coils, 6 or 16 for registers'
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;raw'= {
            cand -p 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand --port 'Where the slave is: a serial device (/dev/ttyUSB0, COM3), tcp://HOST[:PORT], rtu+tcp://HOST:PORT, or sim'
            cand -m 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand --mode 'Framing: rtu or ascii on a serial line, tcp for MBAP [default: rtu, tcp for tcp:// ports; decode detects it]'
            cand -o 'Output format'
            cand --output 'Output format'
            cand -t 'Register value type, for showing values read and for converting values to write'
            cand --type 'Register value type, for showing values read and for converting values to write'
            cand --order 'Byte order of values wider than 16 bits: A is the most significant byte'
            cand --max-per-request 'Split reads and writes into requests of at most N coils or registers, for devices that take fewer than the protocol allows'
            cand --json 'The same as --output json'
            cand --pdu-addresses 'Take every address as a 0-based protocol address, never as a Modicon reference'
            cand -h 'Print help (see more with ''--help'')'
            cand --help 'Print help (see more with ''--help'')'
            cand -V 'Print version'
            cand --version 'Print version'
        }
        &'mbtool;encode;help'= {
            cand read-coils 'Read coils (function 01)'
            cand read-inputs 'Read discrete inputs (function 02)'
            cand read-holding 'Read holding registers (function 03)'
            cand read-input-registers 'Read input registers (function 04)'
            cand read 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)'
            cand write-coil 'Write one coil (function 05)'
            cand write-coils 'Write coils (function 15)'
            cand write-register 'Write one holding register (function 06)'
            cand write-registers 'Write holding registers (function 16)'
            cand write 'Write by Modicon reference: 05/06 for one value, 15/16 for several'
            cand raw 'Send any PDU and decode the answer'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'mbtool;encode;help;read-coils'= {
        }
        &'mbtool;encode;help;read-inputs'= {
        }
        &'mbtool;encode;help;read-holding'= {
        }
        &'mbtool;encode;help;read-input-registers'= {
        }
        &'mbtool;encode;help;read'= {
        }
        &'mbtool;encode;help;write-coil'= {
        }
        &'mbtool;encode;help;write-coils'= {
        }
        &'mbtool;encode;help;write-register'= {
        }
        &'mbtool;encode;help;write-registers'= {
        }
        &'mbtool;encode;help;write'= {
        }
        &'mbtool;encode;help;raw'= {
        }
        &'mbtool;encode;help;help'= {
        }
        &'mbtool;help'= {
            cand generate 'Write the shell completions and man pages (for packagers and the project''s own tree)'
            cand read-coils 'Read coils (function 01)'
            cand read-inputs 'Read discrete inputs (function 02)'
            cand read-holding 'Read holding registers (function 03)'
            cand read-input-registers 'Read input registers (function 04)'
            cand read 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)'
            cand write-coil 'Write one coil (function 05)'
            cand write-coils 'Write coils (function 15)'
            cand write-register 'Write one holding register (function 06)'
            cand write-registers 'Write holding registers (function 16)'
            cand write 'Write by Modicon reference: 05/06 for one value, 15/16 for several'
            cand raw 'Send any PDU and decode the answer'
            cand decode 'Decode Modbus frames given as arguments, or one per line on standard input'
            cand encode 'Print the frame that a request command would send, without sending it'
            cand help 'Print this message or the help of the given subcommand(s)'
        }
        &'mbtool;help;generate'= {
        }
        &'mbtool;help;read-coils'= {
        }
        &'mbtool;help;read-inputs'= {
        }
        &'mbtool;help;read-holding'= {
        }
        &'mbtool;help;read-input-registers'= {
        }
        &'mbtool;help;read'= {
        }
        &'mbtool;help;write-coil'= {
        }
        &'mbtool;help;write-coils'= {
        }
        &'mbtool;help;write-register'= {
        }
        &'mbtool;help;write-registers'= {
        }
        &'mbtool;help;write'= {
        }
        &'mbtool;help;raw'= {
        }
        &'mbtool;help;decode'= {
        }
        &'mbtool;help;encode'= {
            cand read-coils 'Read coils (function 01)'
            cand read-inputs 'Read discrete inputs (function 02)'
            cand read-holding 'Read holding registers (function 03)'
            cand read-input-registers 'Read input registers (function 04)'
            cand read 'Read by Modicon reference; the first digit picks the table (0, 1, 3, 4)'
            cand write-coil 'Write one coil (function 05)'
            cand write-coils 'Write coils (function 15)'
            cand write-register 'Write one holding register (function 06)'
            cand write-registers 'Write holding registers (function 16)'
            cand write 'Write by Modicon reference: 05/06 for one value, 15/16 for several'
            cand raw 'Send any PDU and decode the answer'
        }
        &'mbtool;help;encode;read-coils'= {
        }
        &'mbtool;help;encode;read-inputs'= {
        }
        &'mbtool;help;encode;read-holding'= {
        }
        &'mbtool;help;encode;read-input-registers'= {
        }
        &'mbtool;help;encode;read'= {
        }
        &'mbtool;help;encode;write-coil'= {
        }
        &'mbtool;help;encode;write-coils'= {
        }
        &'mbtool;help;encode;write-register'= {
        }
        &'mbtool;help;encode;write-registers'= {
        }
        &'mbtool;help;encode;write'= {
        }
        &'mbtool;help;encode;raw'= {
        }
        &'mbtool;help;help'= {
        }
    ]
    $completions[$command]
}
