//! How `serve` logs each request: a line for people, or JSON Lines.

use std::io::{self, Write};

use serde::Serialize;

use mbtool_core::codec::function;
use mbtool_core::codec::Pdu;
use mbtool_core::describe::{describe_pdu, Fields};
use mbtool_core::slave::server::{LogEntry, Outcome};

#[derive(Serialize)]
struct JsonEntry<'a> {
    time: f64,
    peer: &'a str,
    slave: u8,
    function: u8,
    #[serde(flatten)]
    request: Fields,
    answer: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    exception: Option<u8>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fault: Option<&'static str>,
}

fn answer_of(outcome: &Outcome) -> (&'static str, Option<u8>, Option<&'static str>) {
    let pdu_kind = |pdu: &Pdu| match pdu {
        Pdu::Exception(e) => ("exception", Some(e.code.0)),
        _ => ("response", None),
    };
    match outcome {
        Outcome::Answered(pdu) => {
            let (kind, code) = pdu_kind(pdu);
            (kind, code, None)
        }
        Outcome::Corrupted(pdu) => {
            let (kind, code) = pdu_kind(pdu);
            (kind, code, Some("corrupted"))
        }
        Outcome::Dropped => ("none", None, Some("dropped")),
        Outcome::Broadcast => ("none", None, None),
    }
}

pub fn write_entry(out: &mut dyn Write, json: bool, entry: &LogEntry) -> io::Result<()> {
    let (_, request) = describe_pdu(&Pdu::Request(entry.request.clone()));
    let (answer, exception, fault) = answer_of(entry.outcome);
    let function = entry.request.function();
    if json {
        serde_json::to_writer(
            &mut *out,
            &JsonEntry {
                time: entry.elapsed.as_secs_f64(),
                peer: entry.peer,
                slave: entry.slave,
                function,
                request,
                answer,
                exception,
                fault,
            },
        )?;
        return writeln!(out);
    }
    let result = match (answer, exception) {
        ("exception", Some(code)) => {
            format!("exception {}", mbtool_core::codec::ExceptionCode(code))
        }
        ("none", _) if fault.is_none() => "no answer (broadcast)".to_string(),
        (other, _) => other.to_string(),
    };
    let fault = fault.map(|f| format!(" [{f}]")).unwrap_or_default();
    writeln!(
        out,
        "[{:>12.6}] {} slave {}: {:02} {} {} -> {result}{fault}",
        entry.elapsed.as_secs_f64(),
        entry.peer,
        entry.slave,
        function,
        function::name(function),
        super::fields_summary(&request),
    )
}
