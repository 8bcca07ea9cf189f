//! Function codes and their names.

/// Function 1 (0x01): read 1-2000 coils (read-write bits).
pub const READ_COILS: u8 = 0x01;
/// Function 2 (0x02): read 1-2000 discrete inputs (read-only bits).
pub const READ_DISCRETE_INPUTS: u8 = 0x02;
/// Function 3 (0x03): read 1-125 holding registers (read-write 16-bit words).
pub const READ_HOLDING_REGISTERS: u8 = 0x03;
/// Function 4 (0x04): read 1-125 input registers (read-only 16-bit words).
pub const READ_INPUT_REGISTERS: u8 = 0x04;
/// Function 5 (0x05): set one coil on (FF00) or off (0000).
pub const WRITE_SINGLE_COIL: u8 = 0x05;
/// Function 6 (0x06): write one holding register.
pub const WRITE_SINGLE_REGISTER: u8 = 0x06;
/// Function 7 (0x07): read the eight exception status outputs of a serial-line device.
pub const READ_EXCEPTION_STATUS: u8 = 0x07;
/// Function 8 (0x08): serial-line diagnostics; a sub-function selects the test or counter.
pub const DIAGNOSTICS: u8 = 0x08;
/// Function 11 (0x0B): status word and event counter of a serial-line device.
pub const GET_COMM_EVENT_COUNTER: u8 = 0x0B;
/// Function 12 (0x0C): status word, counters and the latest events of a serial-line device.
pub const GET_COMM_EVENT_LOG: u8 = 0x0C;
/// Function 15 (0x0F): write 1-1968 consecutive coils.
pub const WRITE_MULTIPLE_COILS: u8 = 0x0F;
/// Function 16 (0x10): write 1-123 consecutive holding registers.
pub const WRITE_MULTIPLE_REGISTERS: u8 = 0x10;
/// Function 17 (0x11): a serial-line device's server ID, run indicator and device-specific data.
pub const REPORT_SERVER_ID: u8 = 0x11;
/// Function 20 (0x14): read groups of records from the device's extended-memory files.
pub const READ_FILE_RECORD: u8 = 0x14;
/// Function 21 (0x15): write groups of records to the device's extended-memory files.
pub const WRITE_FILE_RECORD: u8 = 0x15;
/// Function 22 (0x16): change bits of one holding register through an AND mask and an OR mask.
pub const MASK_WRITE_REGISTER: u8 = 0x16;
/// Function 23 (0x17): write 1-121 holding registers, then read 1-125, in one transaction.
pub const READ_WRITE_MULTIPLE_REGISTERS: u8 = 0x17;
/// Function 24 (0x18): read the count and up to 31 registers of a FIFO queue.
pub const READ_FIFO_QUEUE: u8 = 0x18;
/// Function 43 (0x2B): Encapsulated Interface Transport; the MEI type byte picks the service.
pub const ENCAPSULATED_INTERFACE: u8 = 0x2B;

/// The MEI type of "read device identification" inside function 43.
pub const MEI_READ_DEVICE_IDENTIFICATION: u8 = 0x0E;

/// Set in the function code of an exception response.
pub const EXCEPTION_FLAG: u8 = 0x80;

/// Whether the codec reads this request by a layout of its own; an opaque request with such
/// a function code is one that broke its layout.
pub fn has_layout(function: u8, data: &[u8]) -> bool {
    match function {
        READ_COILS..=DIAGNOSTICS
        | WRITE_MULTIPLE_COILS
        | WRITE_MULTIPLE_REGISTERS
        | REPORT_SERVER_ID
        | READ_FILE_RECORD
        | WRITE_FILE_RECORD
        | MASK_WRITE_REGISTER
        | READ_WRITE_MULTIPLE_REGISTERS
        | READ_FIFO_QUEUE => true,
        ENCAPSULATED_INTERFACE => data.first() == Some(&MEI_READ_DEVICE_IDENTIFICATION),
        _ => false,
    }
}

/// Whether a function code (without its exception flag) is one the specification defines,
/// public or user-defined (65-72, 100-110).
pub fn is_defined(function: u8) -> bool {
    matches!(function, 65..=72 | 100..=110) || name(function) != name(0)
}

/// The name of a function code as the Modbus specification gives it.
pub fn name(function: u8) -> &'static str {
    match function & !EXCEPTION_FLAG {
        READ_COILS => "Read Coils",
        READ_DISCRETE_INPUTS => "Read Discrete Inputs",
        READ_HOLDING_REGISTERS => "Read Holding Registers",
        READ_INPUT_REGISTERS => "Read Input Registers",
        WRITE_SINGLE_COIL => "Write Single Coil",
        WRITE_SINGLE_REGISTER => "Write Single Register",
        READ_EXCEPTION_STATUS => "Read Exception Status",
        DIAGNOSTICS => "Diagnostics",
        GET_COMM_EVENT_COUNTER => "Get Comm Event Counter",
        GET_COMM_EVENT_LOG => "Get Comm Event Log",
        WRITE_MULTIPLE_COILS => "Write Multiple Coils",
        WRITE_MULTIPLE_REGISTERS => "Write Multiple Registers",
        REPORT_SERVER_ID => "Report Server ID",
        READ_FILE_RECORD => "Read File Record",
        WRITE_FILE_RECORD => "Write File Record",
        MASK_WRITE_REGISTER => "Mask Write Register",
        READ_WRITE_MULTIPLE_REGISTERS => "Read/Write Multiple Registers",
        READ_FIFO_QUEUE => "Read FIFO Queue",
        ENCAPSULATED_INTERFACE => "Encapsulated Interface Transport",
        _ => "Unknown function",
    }
}
