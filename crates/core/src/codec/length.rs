//! How long a frame is, told from its first bytes: the master knows when an answer is
//! complete, and a sniffer knows where to look for the next frame, without waiting for
//! silence on the line.

use super::direction::Direction;
use super::function::*;

/// The predicted length of a PDU or a frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Length {
    /// Exactly this many bytes.
    Known(usize),
    /// At least this many bytes must be seen before the length can be told.
    AtLeast(usize),
    /// The layout of this function code is not known: only silence or a checksum can tell.
    Unknown,
    /// No frame in this direction starts like this (a request with function 00 or 80-FF).
    Never,
}

/// How a function's PDU tells its length, in one direction.
#[derive(Clone, Copy)]
enum Layout {
    /// `base` bytes, plus the byte count at `index` if `counted`.
    Plain { base: u8, index: u8, counted: bool },
    /// The rest, a length told by the PDU's own rules or not at all.
    Other(Other),
}

#[derive(Clone, Copy)]
enum Other {
    /// A FIFO queue's answer: 3 bytes, plus its two-byte count.
    FifoCount,
    /// Encapsulated interface: by the MEI type, read device identification alone known.
    Mei,
    /// Not known: only silence or a checksum can tell.
    Unknown,
    /// No frame in this direction starts with this function code.
    Never,
}

/// Always `len` bytes: its count's index is the function code's, always there, and not
/// counted.
const fn fixed(len: u8) -> Layout {
    Layout::Plain {
        base: len,
        index: 0,
        counted: false,
    }
}

/// `base` bytes, plus the byte count at `index`.
const fn counted(index: u8, base: u8) -> Layout {
    Layout::Plain {
        base,
        index,
        counted: true,
    }
}

/// The layout of `function`'s PDU travelling in `direction`.
const fn layout(function: u8, direction: Direction) -> Layout {
    if function == 0 {
        return Layout::Other(Other::Never);
    }
    match direction {
        Direction::Request if function & EXCEPTION_FLAG != 0 => Layout::Other(Other::Never),
        Direction::Request => match function {
            READ_COILS..=WRITE_SINGLE_REGISTER | DIAGNOSTICS => fixed(5),
            READ_EXCEPTION_STATUS
            | GET_COMM_EVENT_COUNTER
            | GET_COMM_EVENT_LOG
            | REPORT_SERVER_ID => fixed(1),
            WRITE_MULTIPLE_COILS | WRITE_MULTIPLE_REGISTERS => counted(5, 6),
            READ_FILE_RECORD | WRITE_FILE_RECORD => counted(1, 2),
            MASK_WRITE_REGISTER => fixed(7),
            READ_WRITE_MULTIPLE_REGISTERS => counted(9, 10),
            READ_FIFO_QUEUE => fixed(3),
            ENCAPSULATED_INTERFACE => Layout::Other(Other::Mei),
            _ => Layout::Other(Other::Unknown),
        },
        Direction::Response => match function {
            f if f & EXCEPTION_FLAG != 0 => fixed(2),
            READ_COILS..=READ_INPUT_REGISTERS
            | GET_COMM_EVENT_LOG
            | REPORT_SERVER_ID
            | READ_FILE_RECORD
            | WRITE_FILE_RECORD
            | READ_WRITE_MULTIPLE_REGISTERS => counted(1, 2),
            WRITE_SINGLE_COIL
            | WRITE_SINGLE_REGISTER
            | DIAGNOSTICS
            | GET_COMM_EVENT_COUNTER
            | WRITE_MULTIPLE_COILS
            | WRITE_MULTIPLE_REGISTERS => fixed(5),
            READ_EXCEPTION_STATUS => fixed(2),
            MASK_WRITE_REGISTER => fixed(7),
            READ_FIFO_QUEUE => Layout::Other(Other::FifoCount),
            ENCAPSULATED_INTERFACE => Layout::Other(Other::Mei),
            _ => Layout::Other(Other::Unknown),
        },
    }
}

/// The layouts of every function code, requests first, worked out when compiled: a
/// sniffer asks for a length at every position it looks at, several times a byte.
static LAYOUTS: [[Layout; 256]; 2] = {
    let mut layouts = [[Layout::Other(Other::Never); 256]; 2];
    let mut function = 0;
    while function < 256 {
        layouts[0][function] = layout(function as u8, Direction::Request);
        layouts[1][function] = layout(function as u8, Direction::Response);
        function += 1;
    }
    layouts
};

/// The function codes whose PDU has a layout in at least one direction. Most bytes a
/// noisy line gives are none, and a position whose function byte is one of those is no
/// frame of known layout, whatever follows.
static SIZED: [bool; 256] = {
    let mut sized = [false; 256];
    let mut function = 0;
    while function < 256 {
        sized[function] = has_layout(LAYOUTS[0][function]) || has_layout(LAYOUTS[1][function]);
        function += 1;
    }
    sized
};

const fn has_layout(layout: Layout) -> bool {
    !matches!(layout, Layout::Other(Other::Unknown | Other::Never))
}

/// Whether a PDU of `function` has a layout either way.
#[inline]
pub(crate) fn sized(function: u8) -> bool {
    SIZED[usize::from(function)]
}

/// The length of the PDU that starts `pdu` (function code first).
#[inline]
pub(crate) fn pdu_length(pdu: &[u8], direction: Direction) -> Length {
    let Some(&function) = pdu.first() else {
        return Length::AtLeast(1);
    };
    let layouts = match direction {
        Direction::Request => &LAYOUTS[0],
        Direction::Response => &LAYOUTS[1],
    };
    // Fixed and counted lengths are one arm, told apart by arithmetic: which of the two
    // comes next is the traffic's to say, and a branch on it (or a jump table over every
    // layout) would be mispredicted as often. A sniffer asks at every position it looks at.
    match layouts[usize::from(function)] {
        Layout::Plain {
            base,
            index,
            counted,
        } => match pdu.get(usize::from(index)) {
            Some(&count) => {
                Length::Known(usize::from(base) + usize::from(count) * usize::from(counted))
            }
            None => Length::AtLeast(usize::from(index) + 1),
        },
        // Most function codes have no layout: told here, without a call.
        Layout::Other(Other::Unknown) => Length::Unknown,
        Layout::Other(Other::Never) => Length::Never,
        Layout::Other(other) => other_length(other, pdu, direction),
    }
}

/// The length of a PDU whose layout is not plain.
#[inline(never)]
fn other_length(layout: Other, pdu: &[u8], direction: Direction) -> Length {
    match layout {
        Other::FifoCount => match pdu.get(1..3) {
            Some([hi, lo]) => Length::Known(3 + usize::from(u16::from_be_bytes([*hi, *lo]))),
            _ => Length::AtLeast(3),
        },
        Other::Mei => match (pdu.get(1), direction) {
            (Some(&MEI_READ_DEVICE_IDENTIFICATION), Direction::Request) => Length::Known(4),
            (Some(&MEI_READ_DEVICE_IDENTIFICATION), Direction::Response) => {
                device_identification_length(pdu)
            }
            (Some(_), _) => Length::Unknown,
            (None, _) => Length::AtLeast(2),
        },
        Other::Unknown => Length::Unknown,
        Other::Never => Length::Never,
    }
}

/// Walks the object list of a read-device-identification answer.
fn device_identification_length(pdu: &[u8]) -> Length {
    // function, MEI type, read code, conformity, more follows, next id, object count
    const HEADER: usize = 7;
    let Some(&count) = pdu.get(HEADER - 1) else {
        return Length::AtLeast(HEADER);
    };
    let mut len = HEADER;
    for _ in 0..count {
        match pdu.get(len + 1) {
            Some(value_len) => len += 2 + usize::from(*value_len),
            None => return Length::AtLeast(len + 2),
        }
    }
    Length::Known(len)
}

/// The length of the RTU frame that starts `frame`: address, PDU, CRC.
#[inline]
pub(crate) fn rtu_frame_length(frame: &[u8], direction: Direction) -> Length {
    match frame.get(1..) {
        // The address byte before the PDU; the CRC after it is not needed to tell the length.
        Some(pdu) if !pdu.is_empty() => match pdu_length(pdu, direction) {
            Length::Known(len) => Length::Known(1 + len + 2),
            Length::AtLeast(len) => Length::AtLeast(1 + len),
            other => other,
        },
        _ => Length::AtLeast(2),
    }
}

/// The length of the TCP frame that starts `frame`, from its MBAP length field.
pub(crate) fn tcp_frame_length(frame: &[u8]) -> Length {
    match frame.get(4..6) {
        Some([hi, lo]) => Length::Known(6 + usize::from(u16::from_be_bytes([*hi, *lo]))),
        _ => Length::AtLeast(6),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn read_holding_answer_length_comes_from_its_byte_count() {
        let head = [0x11, 0x03, 0x06];
        assert_eq!(
            rtu_frame_length(&head, Direction::Response),
            Length::Known(11)
        );
        assert_eq!(
            rtu_frame_length(&head[..2], Direction::Response),
            Length::AtLeast(3)
        );
    }

    #[test]
    fn no_request_has_function_00_or_80_and_above() {
        assert_eq!(
            rtu_frame_length(&[0x11, 0x83], Direction::Request),
            Length::Never
        );
        assert_eq!(
            rtu_frame_length(&[0x11, 0x00], Direction::Response),
            Length::Never
        );
    }

    #[test]
    fn an_exception_is_five_bytes() {
        assert_eq!(
            rtu_frame_length(&[0x11, 0x83], Direction::Response),
            Length::Known(5)
        );
    }
}
