//! What a frame says, as plain fields: the one description that every output format
//! (table, JSON, values, CSV) renders. Building it is logic; rendering lives in `output`.

use serde::Serialize;
use smallvec::{smallvec, SmallVec};

use crate::codec::adu::hex_digit;
use crate::codec::checksum::{crc16, lrc};
use crate::codec::function::{self, EXCEPTION_FLAG};
use crate::codec::hex::spaced_hex;
use crate::codec::length::pdu_length;
use crate::codec::DeviceIdentification;
use crate::codec::{
    bits, Checksum, Direction, Envelope, Exception, FrameError, Mode, Pdu, Reading, Request,
    Response,
};
use crate::model::address::{reference, Reference, Table};
use crate::model::values::escape_text;

/// Which kind of PDU a frame carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// A request, master to slave.
    Request,
    /// A normal response.
    Response,
    /// An exception response (function code with 0x80 set).
    Exception,
}

impl Kind {
    /// The lower-case name ("request", "response", "exception"), as JSON gives it.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Request => "request",
            Kind::Response => "response",
            Kind::Exception => "exception",
        }
    }
}

/// Register values as numbers, bits as 0/1. Inline up to a few words, as most frames
/// carry: no allocation per frame a sniffer describes.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(untagged)]
pub enum Values {
    /// 16-bit register values, first address first.
    Registers(SmallVec<[u16; 8]>),
    /// Coil or input states, 0 or 1, first address first.
    Bits(SmallVec<[u8; 16]>),
}

impl Values {
    pub(crate) fn bits(bits: &[bool]) -> Values {
        Values::Bits(bits.iter().map(|b| u8::from(*b)).collect())
    }

    /// How many values: registers or bits.
    pub fn len(&self) -> usize {
        match self {
            Values::Registers(v) => v.len(),
            Values::Bits(v) => v.len(),
        }
    }

    /// Whether there are no values.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// One device identification object, described.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct DeviceObjectField {
    /// The object id (00 VendorName, 01 ProductCode, ...).
    pub id: u8,
    /// The object's name in the specification; "reserved" for 07-7F, "private" for 80-FF.
    pub name: &'static str,
    /// The object's bytes as text, control characters escaped.
    pub value: String,
}

/// One group of a file record frame (functions 20, 21): which records, and their values.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct FileGroupField {
    /// The file; absent in a read answer whose request was not seen.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub file: Option<u16>,
    /// The first record; absent in a read answer whose request was not seen.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub record: Option<u16>,
    /// How many records (registers).
    pub count: u16,
    /// The records' values, where the frame carries them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub values: Option<Vec<u16>>,
}

/// The fields a PDU carries; absent ones are left out of JSON.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Fields {
    /// First address, 0-based as on the wire; for function 23, the write address.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub address: Option<u16>,
    /// The Modicon reference of `address` (holding register 107 is "400108"), where the
    /// function names a table.
    #[serde(rename = "ref", skip_serializing_if = "Option::is_none")]
    pub reference: Option<Reference>,
    /// How many coils or registers are asked, written or carried; unknown (absent) for a
    /// bit answer whose request was not seen.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub count: Option<u16>,
    /// A bit answer whose request was not seen: the most values its bytes can hold. The
    /// high bits of its last byte are values or padding, as the quantity asked decides, so
    /// `values` holds only the bits sure to be values: those of every byte but the last,
    /// and the first of the last.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_count: Option<u16>,
    /// The values written or read.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub values: Option<Values>,
    /// The last byte that carries the bits of a coil or input frame, as the frame has it:
    /// its bits past the values are padding (or not known to be values), so it cannot be
    /// made up from the values, as the bytes before it can. For a table of the bytes.
    #[serde(skip)]
    pub last_packed: Option<u8>,
    /// The exception code of an exception response.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exception: Option<u8>,
    /// The exception code's name, such as "illegal data address".
    #[serde(skip_serializing_if = "Option::is_none")]
    pub exception_name: Option<&'static str>,
    /// Function 23: the first register to read, 0-based as on the wire.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub read_address: Option<u16>,
    /// Function 23: how many registers to read.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub read_count: Option<u16>,
    /// Function 22: the AND mask (bits that keep their value).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub and_mask: Option<u16>,
    /// Function 22: the OR mask (bits set where the AND mask is 0).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub or_mask: Option<u16>,
    /// Function 8: the diagnostic sub-function.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sub_function: Option<u16>,
    /// Function 7: the eight exception status outputs, one per bit.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub status: Option<u8>,
    /// Function 43/14: the read device ID code (01 basic, 02 regular, 03 extended, 04 one
    /// object).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub read_code: Option<u8>,
    /// Function 43/14 request: the object to start from, or the one object to read.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub object_id: Option<u8>,
    /// Function 43/14 answer: the device's conformity level.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conformity: Option<u8>,
    /// Function 43/14 answer: more objects remain to be asked for.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub more_follows: Option<bool>,
    /// Function 43/14 answer: the object to ask for next when more follow.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub next_object_id: Option<u8>,
    /// Function 43/14 answer: the identification objects.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub objects: Option<Vec<DeviceObjectField>>,
    /// Functions 20 and 21: the groups of file records, in order.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub files: Option<Vec<FileGroupField>>,
    /// Bytes the frame carries without a layout mbtool knows, as spaced hex.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub data: Option<String>,
    /// Text from the device (report server id), control characters escaped.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub text: Option<String>,
}

/// The other reading of a frame that reads both ways.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Alternative {
    /// The kind of PDU this other reading makes.
    pub kind: Kind,
    /// The fields as this other reading has them.
    #[serde(flatten)]
    pub fields: Fields,
}

/// One frame, described.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct FrameReport {
    /// The framing: "rtu", "ascii" or "tcp".
    pub mode: &'static str,
    /// Request, normal response or exception.
    pub kind: Kind,
    /// The slave address (RTU, ASCII) or unit identifier (TCP).
    pub slave: u8,
    /// The function code as on the wire, with the 0x80 flag of an exception.
    pub function: u8,
    /// Whether the frame opens, its checksum holds and its PDU follows its layout.
    pub valid: bool,
    /// The MBAP transaction identifier; TCP frames only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub transaction: Option<u16>,
    /// The function's name in the specification, such as "Read Holding Registers".
    pub function_name: &'static str,
    /// What the PDU carries.
    #[serde(flatten)]
    pub fields: Fields,
    /// Why the frame is not valid; a checksum mismatch comes first.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    /// The checksum found and expected, for the table view.
    #[serde(skip)]
    pub checksum: Checksum,
    /// The PDU reads both as a request and as a response; `fields` give the request and
    /// `alternative` the response.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub ambiguous: bool,
    /// The response reading of an ambiguous frame. Boxed: it is rare, and a report is
    /// moved several times on its way to the printer.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alternative: Option<Box<Alternative>>,
}

/// Gives a read answer (`pdu`, as on the wire) the addresses of the request it answers,
/// and the bits of a bit answer to the quantity asked.
pub fn locate_answer(report: &mut FrameReport, request: &Request, pdu: &[u8]) {
    // Function, byte count, then the bits packed.
    locate_fields(
        &mut report.fields,
        request,
        pdu.get(2..).unwrap_or_default(),
    );
}

/// The fields of a read answer given the addresses (or files and records) of the request
/// it answers, and a bit answer's bits (`packed`, as its PDU carries them) cut to the
/// quantity asked.
pub fn locate_fields(fields: &mut Fields, request: &Request, packed: &[u8]) {
    let (address, quantity) = match request {
        Request::ReadCoils { address, quantity }
        | Request::ReadDiscreteInputs { address, quantity }
        | Request::ReadHoldingRegisters { address, quantity }
        | Request::ReadInputRegisters { address, quantity } => (*address, *quantity),
        Request::ReadWriteMultipleRegisters {
            read_address,
            read_quantity,
            ..
        } => (*read_address, *read_quantity),
        Request::ReadFileRecord { groups } => {
            if let Some(files) = &mut fields.files {
                for (field, asked) in files.iter_mut().zip(groups) {
                    field.file = Some(asked.file);
                    field.record = Some(asked.record);
                }
            }
            return;
        }
        _ => return,
    };
    let table = Table::of_function(request.function()).unwrap_or(Table::HoldingRegisters);
    fields.address = Some(address);
    fields.reference = Some(reference(table, address));
    fields.count = Some(quantity);
    if let Some(values @ Values::Bits(_)) = &mut fields.values {
        *values = Values::bits(&bits::unpack(packed, usize::from(quantity)));
        fields.max_count = None;
    }
}

/// A request, and who it asked: what the frame after it may answer.
#[derive(Clone, Debug)]
pub struct Asked {
    slave: u8,
    /// The MBAP transaction identifier; 0 on serial lines.
    transaction: u16,
    request: Request,
    /// The request's PDU as it travelled, which the answer is checked against.
    pdu: Vec<u8>,
}

/// The request a frame described as `report` makes. `None` for anything else, or a frame
/// that is not valid.
pub fn request_made(bytes: &[u8], report: &FrameReport) -> Option<Asked> {
    if !report.valid || report.kind != Kind::Request {
        return None;
    }
    let envelope = Envelope::open(mode_named(report.mode)?, bytes).ok()?;
    let request = Request::decode(&envelope.pdu).ok()?;
    Some(Asked {
        slave: envelope.slave,
        transaction: envelope.transaction,
        request,
        pdu: envelope.pdu.into_owned(),
    })
}

/// Describes the answer `bytes` (described as `report`) as the answer to `asked`, the
/// request of the frame before it, where it fits that request (same slave, and on TCP the
/// same transaction): a read answer gets the request's addresses, and a bit answer the
/// quantity asked.
pub fn pair_answer(report: &mut FrameReport, bytes: &[u8], asked: &Asked) {
    let request = &asked.request;
    if !report.valid || report.kind == Kind::Request || report.slave != asked.slave {
        return;
    }
    let Some(envelope) = mode_named(report.mode).and_then(|m| Envelope::open(m, bytes).ok()) else {
        return;
    };
    if envelope.transaction != asked.transaction {
        return;
    }
    let Ok(pdu) = Pdu::decode(&envelope.pdu, Direction::Response) else {
        return;
    };
    if crate::codec::answer::check(&asked.pdu, &envelope.pdu).is_err() {
        return;
    }
    if matches!(pdu, Pdu::Response(_)) {
        locate_answer(report, request, &envelope.pdu);
    }
}

fn mode_named(name: &str) -> Option<Mode> {
    [Mode::Rtu, Mode::Ascii, Mode::Tcp]
        .into_iter()
        .find(|mode| mode.name() == name)
}

fn with_reference(function: u8, address: u16) -> (Option<u16>, Option<Reference>) {
    let reference = Table::of_function(function).map(|table| reference(table, address));
    (Some(address), reference)
}

fn request_fields(request: &Request) -> Fields {
    let function = request.function();
    let mut f = Fields::default();
    match request {
        Request::ReadCoils { address, quantity }
        | Request::ReadDiscreteInputs { address, quantity }
        | Request::ReadHoldingRegisters { address, quantity }
        | Request::ReadInputRegisters { address, quantity } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.count = Some(*quantity);
        }
        Request::WriteSingleCoil { address, value } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.values = Some(Values::bits(&[*value]));
        }
        Request::WriteSingleRegister { address, value } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.values = Some(Values::Registers(smallvec![*value]));
        }
        Request::WriteMultipleCoils { address, values } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.count = u16::try_from(values.len()).ok();
            f.values = Some(Values::bits(values));
        }
        Request::WriteMultipleRegisters { address, values } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.count = u16::try_from(values.len()).ok();
            f.values = Some(Values::Registers(SmallVec::from_slice(values)));
        }
        Request::ReadExceptionStatus | Request::ReportServerId => {}
        Request::Diagnostics { sub_function, data } => {
            f.sub_function = Some(*sub_function);
            f.data = Some(spaced_hex(data));
        }
        Request::MaskWriteRegister {
            address,
            and_mask,
            or_mask,
        } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.and_mask = Some(*and_mask);
            f.or_mask = Some(*or_mask);
        }
        Request::ReadWriteMultipleRegisters {
            read_address,
            read_quantity,
            write_address,
            values,
        } => {
            f.read_address = Some(*read_address);
            f.read_count = Some(*read_quantity);
            (f.address, f.reference) = with_reference(function, *write_address);
            f.count = u16::try_from(values.len()).ok();
            f.values = Some(Values::Registers(SmallVec::from_slice(values)));
        }
        Request::ReadDeviceIdentification {
            read_code,
            object_id,
        } => {
            f.read_code = Some(*read_code);
            f.object_id = Some(*object_id);
        }
        Request::ReadFileRecord { groups } => {
            f.files = Some(
                groups
                    .iter()
                    .map(|group| FileGroupField {
                        file: Some(group.file),
                        record: Some(group.record),
                        count: group.count,
                        values: None,
                    })
                    .collect(),
            );
        }
        Request::WriteFileRecord { groups } => f.files = Some(written_files(groups)),
        Request::ReadFifoQueue { address } => {
            f.address = Some(*address);
            f.reference = Some(reference(Table::HoldingRegisters, *address));
        }
        Request::Other { data, .. } => f.data = Some(spaced_hex(data)),
    }
    f
}

fn written_files(groups: &[crate::codec::FileRecords]) -> Vec<FileGroupField> {
    groups
        .iter()
        .map(|group| FileGroupField {
            file: Some(group.file),
            record: Some(group.record),
            count: group.values.len() as u16,
            values: Some(group.values.clone()),
        })
        .collect()
}

fn identification_fields(f: &mut Fields, id: &DeviceIdentification) {
    f.read_code = Some(id.read_code);
    f.conformity = Some(id.conformity);
    f.more_follows = Some(id.more_follows);
    f.next_object_id = Some(id.next_object_id);
    f.objects = Some(
        id.objects
            .iter()
            .map(|object| DeviceObjectField {
                id: object.id,
                name: crate::codec::DeviceObject::name(object.id),
                value: escape_text(&object.value),
            })
            .collect(),
    );
}

fn response_fields(response: &Response) -> Fields {
    let function = response.function();
    let mut f = Fields::default();
    match response {
        Response::ReadCoils { packed } | Response::ReadDiscreteInputs { packed } => {
            // Without the request the count is unknown: only the bits sure to be values are
            // shown, since a padding bit taken for a coil would be a value invented.
            let sure = packed.len().saturating_sub(1) * 8 + usize::from(!packed.is_empty());
            f.max_count = u16::try_from(packed.len() * 8).ok();
            f.values = Some(Values::bits(&bits::unpack(packed, sure)));
            f.last_packed = packed.last().copied();
        }
        Response::ReadHoldingRegisters { values }
        | Response::ReadInputRegisters { values }
        | Response::ReadWriteMultipleRegisters { values } => {
            f.count = u16::try_from(values.len()).ok();
            f.values = Some(Values::Registers(SmallVec::from_slice(values)));
        }
        Response::WriteSingleCoil { address, value } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.values = Some(Values::bits(&[*value]));
        }
        Response::WriteSingleRegister { address, value } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.values = Some(Values::Registers(smallvec![*value]));
        }
        Response::ReadExceptionStatus { status } => f.status = Some(*status),
        Response::Diagnostics { sub_function, data } => {
            f.sub_function = Some(*sub_function);
            f.data = Some(spaced_hex(data));
        }
        Response::WriteMultipleCoils { address, quantity }
        | Response::WriteMultipleRegisters { address, quantity } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.count = Some(*quantity);
        }
        Response::ReportServerId { data } => {
            f.data = Some(spaced_hex(data));
            f.text = Some(escape_text(data));
        }
        Response::MaskWriteRegister {
            address,
            and_mask,
            or_mask,
        } => {
            (f.address, f.reference) = with_reference(function, *address);
            f.and_mask = Some(*and_mask);
            f.or_mask = Some(*or_mask);
        }
        Response::ReadDeviceIdentification(id) => identification_fields(&mut f, id),
        Response::ReadFileRecord { groups } => {
            f.files = Some(
                groups
                    .iter()
                    .map(|values| FileGroupField {
                        file: None,
                        record: None,
                        count: values.len() as u16,
                        values: Some(values.clone()),
                    })
                    .collect(),
            );
        }
        Response::WriteFileRecord { groups } => f.files = Some(written_files(groups)),
        Response::ReadFifoQueue { values } => {
            f.count = u16::try_from(values.len()).ok();
            f.values = Some(Values::Registers(SmallVec::from_slice(values)));
        }
        Response::Other { data, .. } => f.data = Some(spaced_hex(data)),
    }
    f
}

fn exception_fields(exception: Exception) -> Fields {
    Fields {
        exception: Some(exception.code.0),
        exception_name: Some(exception.code.name()),
        ..Fields::default()
    }
}

/// The kind and fields of a typed PDU.
pub fn describe_pdu(pdu: &Pdu) -> (Kind, Fields) {
    let fields = match pdu {
        Pdu::Request(request) => request_fields(request),
        Pdu::Response(response) => response_fields(response),
        Pdu::Exception(exception) => exception_fields(*exception),
    };
    (Kind::of(pdu), fields)
}

/// Describes a whole frame. `mode` and `direction` are detected when not given; a frame
/// that fails its checksum is still described, marked not valid.
pub fn describe_frame(
    bytes: &[u8],
    mode: Option<Mode>,
    direction: Option<Direction>,
) -> FrameReport {
    let mode = mode.unwrap_or_else(|| Mode::detect(bytes));
    let report = describe_as(bytes, mode, direction);
    if report.valid || report.checksum.error().is_none() && report.mode != "ascii" {
        return report;
    }
    without_checksum(bytes, mode, direction).unwrap_or(report)
}

/// The longest message that a frame pasted without its checksum gets, so that it shows
/// whole in a table on an 80-column terminal.
const WITHOUT_CHECKSUM_MESSAGE: usize = 65;

/// A frame pasted without its CRC (or LRC): when the bytes with one appended read as a
/// valid frame, that frame is described, with a short error that gives it whole.
fn without_checksum(bytes: &[u8], mode: Mode, direction: Option<Direction>) -> Option<FrameReport> {
    let (name, whole, shown) = match mode {
        Mode::Rtu => {
            let whole = [bytes, &crc16(bytes).to_le_bytes()].concat();
            let shown = spaced_hex(&whole);
            ("CRC", whole, shown)
        }
        Mode::Ascii => {
            let body = bytes.strip_prefix(b":")?;
            let body = body.strip_suffix(b"\r\n").unwrap_or(body);
            if body.len() % 2 != 0 {
                return None;
            }
            let data = body
                .chunks_exact(2)
                .map(|pair| Some(hex_digit(pair[0])? << 4 | hex_digit(pair[1])?))
                .collect::<Option<Vec<u8>>>()?;
            let text = format!(":{}{:02X}", String::from_utf8_lossy(body), lrc(&data));
            ("LRC", format!("{text}\r\n").into_bytes(), text)
        }
        Mode::Tcp => return None,
    };
    let mut report = describe_as(&whole, mode, direction);
    if !report.valid {
        return None;
    }
    let message = format!("without its {name}? With it: {shown}");
    let end = &shown[shown
        .len()
        .saturating_sub(if mode == Mode::Rtu { 5 } else { 2 })..];
    report.error = Some(if message.len() <= WITHOUT_CHECKSUM_MESSAGE {
        message
    } else {
        format!("without its {name}? It would end {end}")
    });
    report.valid = false;
    report.checksum = Checksum::None;
    Some(report)
}

/// Describes a frame as `mode` gives it, its checksum where that mode puts it: a frame the
/// framer found, which cannot be a frame pasted without its checksum.
pub(crate) fn describe_as(bytes: &[u8], mode: Mode, direction: Option<Direction>) -> FrameReport {
    let envelope = match Envelope::open(mode, bytes) {
        Ok(envelope) => envelope,
        Err(error) => return unreadable(mode, bytes, error),
    };
    let reading = match direction {
        Some(direction) => match Pdu::decode(&envelope.pdu, direction) {
            Ok(pdu) => Reading::One(pdu),
            Err(error) => {
                let mut report = opened(mode, &envelope);
                report.kind = Kind::travelling(direction, report.function);
                report.valid = false;
                report.error = Some(error.to_string());
                if report.kind == Kind::Exception {
                    with_trailing_bytes(&mut report, &envelope.pdu);
                }
                return with_checksum(report, envelope.checksum);
            }
        },
        None => Reading::infer(&envelope.pdu),
    };
    describe_reading(mode, &envelope, reading)
}

/// What an opened frame carries before its PDU is read.
fn opened(mode: Mode, envelope: &Envelope) -> FrameReport {
    let function = envelope.pdu.first().copied().unwrap_or_default();
    FrameReport {
        mode: mode.name(),
        kind: Kind::Request,
        slave: envelope.slave,
        function,
        valid: true,
        transaction: (mode == Mode::Tcp).then_some(envelope.transaction),
        function_name: function::name(function),
        fields: Fields::default(),
        error: None,
        checksum: envelope.checksum,
        ambiguous: false,
        alternative: None,
    }
}

/// Describes a frame whose PDU was already read, so that nothing is parsed twice (the
/// sniffer reads each PDU once, to pair it, and describes that reading).
pub fn describe_reading(mode: Mode, envelope: &Envelope, reading: Reading) -> FrameReport {
    let mut report = opened(mode, envelope);
    let function = report.function;
    match reading {
        Reading::One(Pdu::Request(request @ Request::WriteMultipleCoils { .. })) => {
            report.fields = request_fields(&request);
            // Its bits are packed at the end of its PDU.
            report.fields.last_packed = envelope.pdu.last().copied();
        }
        Reading::One(pdu) => (report.kind, report.fields) = describe_pdu(&pdu),
        Reading::Both { request, response } => {
            report.kind = Kind::Request;
            report.fields = request_fields(&request);
            report.ambiguous = true;
            report.alternative = Some(Box::new(Alternative {
                kind: Kind::Response,
                fields: response_fields(&response),
            }));
        }
        Reading::Neither {
            as_request,
            as_response,
        } => {
            // The kind shown is the reading whose length fits the frame; the error gives
            // what is wrong with both readings, since either may be what was meant.
            let as_response_fits = matches!(
                pdu_length(&envelope.pdu, Direction::Response),
                crate::codec::length::Length::Known(n) if n == envelope.pdu.len()
            );
            let (kind, error) = if function & EXCEPTION_FLAG != 0 {
                (Kind::Exception, as_response.to_string())
            } else {
                let kind = if as_response_fits {
                    Kind::Response
                } else {
                    Kind::Request
                };
                (
                    kind,
                    format!("not a valid request ({as_request}) nor response ({as_response})"),
                )
            };
            report.kind = kind;
            report.valid = false;
            report.error = Some(error);
            if kind == Kind::Exception {
                with_trailing_bytes(&mut report, &envelope.pdu);
            }
        }
    }
    with_checksum(report, envelope.checksum)
}

/// An exception with bytes after its code still says why: its code is kept, and what
/// follows it told.
fn with_trailing_bytes(report: &mut FrameReport, pdu: &[u8]) {
    if let [function, code, after @ ..] = pdu {
        report.fields = exception_fields(Exception {
            function: function & !EXCEPTION_FLAG,
            code: crate::codec::ExceptionCode(*code),
        });
        if !after.is_empty() {
            report.error = Some(format!(
                "{} after the exception code: {}",
                match after.len() {
                    1 => "1 byte".to_string(),
                    n => format!("{n} bytes"),
                },
                spaced_hex(after)
            ));
        }
    }
}

impl Kind {
    /// What a frame with `function` travelling in `direction` is.
    pub fn travelling(direction: Direction, function: u8) -> Kind {
        match direction {
            Direction::Request => Kind::Request,
            Direction::Response if function & EXCEPTION_FLAG != 0 => Kind::Exception,
            Direction::Response => Kind::Response,
        }
    }

    /// What a PDU is, as its description says.
    pub fn of(pdu: &Pdu) -> Kind {
        match pdu {
            Pdu::Request(_) => Kind::Request,
            Pdu::Response(_) => Kind::Response,
            Pdu::Exception(_) => Kind::Exception,
        }
    }
}

/// A checksum mismatch outranks any other error: it means the bytes themselves are bad.
fn with_checksum(mut report: FrameReport, checksum: Checksum) -> FrameReport {
    if let Some(error) = checksum.error() {
        report.valid = false;
        report.error = Some(match report.error.take() {
            Some(other) => format!("{error}; {other}"),
            None => error.to_string(),
        });
    }
    report
}

fn unreadable(mode: Mode, bytes: &[u8], error: FrameError) -> FrameReport {
    // Where the frame's own slave and function would stand: an ASCII frame spells them in
    // hex after its ':'.
    let hex = |at: usize| {
        let pair = std::str::from_utf8(bytes.get(at..at + 2)?).ok()?;
        u8::from_str_radix(pair, 16).ok()
    };
    let (slave, function) = match mode {
        Mode::Tcp => (bytes.get(6).copied(), bytes.get(7).copied()),
        Mode::Ascii => (hex(1), hex(3)),
        Mode::Rtu => (bytes.first().copied(), bytes.get(1).copied()),
    };
    let function = function.unwrap_or_default();
    FrameReport {
        mode: mode.name(),
        kind: if function & EXCEPTION_FLAG != 0 {
            Kind::Exception
        } else {
            Kind::Request
        },
        slave: slave.unwrap_or_default(),
        function,
        valid: false,
        transaction: None,
        function_name: function::name(function),
        fields: Fields::default(),
        error: Some(error.to_string()),
        checksum: Checksum::None,
        ambiguous: false,
        alternative: None,
    }
}

#[cfg(test)]
mod tests;
