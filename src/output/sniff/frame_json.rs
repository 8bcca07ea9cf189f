//! `sniff`'s JSON Lines: a frame written a field at a time, and the other records as
//! serde writes them.

use std::io::{self, Write};

use serde::Serialize;

use crate::output::json::JsonObject;
use mbtool_core::describe::FrameReport;
use mbtool_core::sniff::session::{Counts, FrameRecord, TcpPlace};
use mbtool_core::sniff::tcp::PacketCounts;

pub(super) fn seconds(us: u64) -> f64 {
    us as f64 / 1e6
}

/// Where a frame of a TCP capture was, as JSON says it.
#[derive(Serialize)]
pub(super) struct JsonTcp {
    client: String,
    server: String,
    /// "udp" for Modbus/UDP; left out for a TCP connection.
    #[serde(skip_serializing_if = "Option::is_none")]
    transport: Option<&'static str>,
    packet: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    request_packet: Option<u64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    response_time_us: Option<u64>,
}

impl From<&TcpPlace> for JsonTcp {
    fn from(place: &TcpPlace) -> Self {
        Self {
            client: place.client.to_string(),
            server: place.server.to_string(),
            transport: place.udp.then_some("udp"),
            packet: place.packet,
            request_packet: place.request_packet,
            response_time_us: place.response_time,
        }
    }
}

#[derive(Serialize)]
pub(super) struct JsonUnanswered {
    #[serde(rename = "type")]
    pub(super) kind: &'static str,
    pub(super) slave: u8,
    pub(super) function: u8,
    #[serde(flatten)]
    pub(super) request: mbtool_core::describe::Fields,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) waited: Option<f64>,
    /// The capture ended while the request waited.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub(super) capture_ended: bool,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) transaction: Option<u16>,
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    pub(super) tcp: Option<JsonTcp>,
}

#[derive(Serialize)]
pub(super) struct JsonSummary<'a> {
    #[serde(rename = "type")]
    pub(super) kind: &'static str,
    #[serde(flatten)]
    pub(super) counts: &'a Counts,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub(super) packets: Option<&'a PacketCounts>,
}

/// A frame as one JSON object: the record's place and bytes, then the report's fields in
/// the order `FrameReport` serializes them (a unit test holds the two equal), then the
/// pairing and the TCP place.
/// `hex`: the frame's bytes as spaced hex.
pub(super) fn frame_json(line: &mut Vec<u8>, frame: &FrameRecord, hex: &str) -> io::Result<()> {
    let report = frame.report();
    let mut object = JsonObject::open(line);
    object.plain("type", "frame");
    object.field("number", &frame.number)?;
    object.field("time", &seconds(frame.at))?;
    object.field_if("gap", frame.gap.map(seconds).as_ref())?;
    object.field("offset", &frame.found.offset)?;
    // Always hex, whatever the mode: a JSON reader gets the bytes as they were.
    object.plain("bytes", hex);
    report_fields(&mut object, report)?;
    if frame.paired {
        object.field("paired", &true)?;
    }
    object.field_if(
        "mismatch",
        frame.mismatch.as_ref().map(ToString::to_string).as_ref(),
    )?;
    if let Some(place) = &frame.tcp {
        tcp_fields(&mut object, place);
    }
    object.close();
    Ok(())
}

/// The fields of `JsonTcp`, in its order, written by hand: a frame of a TCP capture would
/// otherwise make two strings and go through serde's flattening.
pub(super) fn tcp_fields(object: &mut JsonObject, place: &TcpPlace) {
    object.address("client", &place.client);
    object.address("server", &place.server);
    if place.udp {
        object.plain("transport", "udp");
    }
    object.number("packet", place.packet);
    if let Some(packet) = place.request_packet {
        object.number("request_packet", packet);
    }
    if let Some(time) = place.response_time {
        object.number("response_time_us", time);
    }
}

/// The fields of a `FrameReport`, as its `Serialize` gives them.
pub(super) fn report_fields(object: &mut JsonObject, report: &FrameReport) -> io::Result<()> {
    object.plain("mode", report.mode);
    object.plain("kind", report.kind.name());
    object.field("slave", &report.slave)?;
    object.field("function", &report.function)?;
    object.field("valid", &report.valid)?;
    object.field_if("transaction", report.transaction.as_ref())?;
    object.plain("function_name", report.function_name);
    pdu_fields(object, &report.fields)?;
    object.field_if("error", report.error.as_ref())?;
    if report.ambiguous {
        object.field("ambiguous", &true)?;
    }
    object.field_if("alternative", report.alternative.as_ref())
}

/// The fields of a PDU, as `Fields` serializes them. Those of reads, writes and exceptions,
/// nearly every frame on a line, are written by hand: serde's machinery for a struct of
/// optional fields cost a sniffer's JSON an eighth of its time. A frame with any other
/// field goes through serde whole, so that the order of the fields stays the struct's.
fn pdu_fields(object: &mut JsonObject, fields: &mbtool_core::describe::Fields) -> io::Result<()> {
    use mbtool_core::describe::{Fields, Values};
    let Fields {
        address,
        reference,
        count,
        max_count,
        values,
        last_packed: _,
        exception,
        exception_name,
        read_address: None,
        read_count: None,
        and_mask: None,
        or_mask: None,
        sub_function: None,
        status: None,
        read_code: None,
        object_id: None,
        conformity: None,
        more_follows: None,
        next_object_id: None,
        objects: None,
        files: None,
        data: None,
        text: None,
    } = fields
    else {
        return object.flatten(fields);
    };
    if let Some(address) = address {
        object.number("address", *address);
    }
    if let Some(reference) = reference {
        object.plain("ref", reference);
    }
    if let Some(count) = count {
        object.number("count", *count);
    }
    if let Some(max_count) = max_count {
        object.number("max_count", *max_count);
    }
    match values {
        Some(Values::Registers(registers)) => object.numbers("values", registers.iter().copied()),
        Some(Values::Bits(bits)) => object.numbers("values", bits.iter().copied()),
        None => {}
    }
    if let Some(exception) = exception {
        object.number("exception", *exception);
    }
    if let Some(name) = exception_name {
        object.plain("exception_name", name);
    }
    Ok(())
}

/// Serializes `value` as one line into `line`, then writes it.
pub(super) fn json_line(
    out: &mut dyn Write,
    line: &mut Vec<u8>,
    value: &impl Serialize,
) -> io::Result<()> {
    line.clear();
    serde_json::to_writer(&mut *line, value)?;
    line.push(b'\n');
    out.write_all(line)
}
