//! One JSON object per line.

use std::collections::BTreeMap;
use std::io::{self, Write};

use serde::Serialize;

use mbtool_core::codec::hex::push_spaced_hex;
use mbtool_core::describe::describe_pdu;
use mbtool_core::sniff::session::{Counts, Record};
use mbtool_core::sniff::stats::{Stats, Times};
use mbtool_core::sniff::tcp::PacketCounts;

use super::super::json::JsonObject;
use super::frame_json::{frame_json, json_line, seconds, JsonSummary, JsonTcp, JsonUnanswered};
use super::{exceptions, FrameWriter};

#[derive(Default)]
pub struct JsonWriter {
    /// One JSON line is put together here and written at once: serde writes token by
    /// token, and each write through the boxed output costs a dynamic call.
    line: Vec<u8>,
    /// One field put together here: no allocation per frame.
    text: String,
}

/// One station's line of `--stats` in JSON.
#[derive(Serialize)]
struct JsonStats {
    #[serde(rename = "type")]
    kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    server: Option<String>,
    unit: u8,
    requests: u64,
    answers: u64,
    exceptions: BTreeMap<String, u64>,
    unanswered: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    response_time_us: Option<Times>,
}

impl FrameWriter for JsonWriter {
    fn record(&mut self, out: &mut dyn Write, record: &Record) -> io::Result<()> {
        match record {
            Record::Frame(frame) => {
                self.line.clear();
                self.text.clear();
                push_spaced_hex(&mut self.text, &frame.found.bytes);
                frame_json(&mut self.line, frame, &self.text)?;
                self.line.push(b'\n');
                out.write_all(&self.line)
            }
            Record::Noise {
                kept,
                len,
                offset,
                at,
                ..
            } => {
                self.line.clear();
                self.text.clear();
                push_spaced_hex(&mut self.text, kept);
                let mut object = JsonObject::open(&mut self.line);
                object.plain("type", "noise");
                object.field("time", &seconds(*at))?;
                object.field("offset", offset)?;
                object.field("count", len)?;
                object.plain("bytes", &self.text);
                object.close();
                self.line.push(b'\n');
                out.write_all(&self.line)
            }
            Record::Unanswered {
                slave,
                request,
                waited,
                capture_ended,
                tcp,
            } => {
                let (_, fields) = describe_pdu(&mbtool_core::codec::Pdu::Request(request.clone()));
                json_line(
                    out,
                    &mut self.line,
                    &JsonUnanswered {
                        kind: "unanswered",
                        slave: *slave,
                        function: request.function(),
                        request: fields,
                        waited: waited.map(seconds),
                        capture_ended: *capture_ended,
                        transaction: tcp.map(|(_, transaction)| transaction),
                        tcp: tcp.as_ref().map(|(place, _)| JsonTcp::from(place)),
                    },
                )
            }
        }
    }

    fn summary(
        &mut self,
        out: &mut dyn Write,
        counts: &Counts,
        packets: Option<&PacketCounts>,
    ) -> io::Result<()> {
        {
            serde_json::to_writer(
                &mut *out,
                &JsonSummary {
                    kind: "summary",
                    counts,
                    packets,
                },
            )?;
            out.write_all(b"\n")
        }
    }

    fn stats(&mut self, out: &mut dyn Write, stats: &Stats) -> io::Result<()> {
        {
            for ((server, unit), tally) in &stats.stations {
                let line = JsonStats {
                    kind: "stats",
                    server: server.map(|s| s.to_string()),
                    unit: *unit,
                    requests: tally.requests,
                    answers: tally.answers,
                    exceptions: exceptions(&tally.exceptions),
                    unanswered: tally.unanswered,
                    response_time_us: tally.times(),
                };
                json_line(out, &mut self.line, &line)?;
            }
            Ok(())
        }
    }
}
