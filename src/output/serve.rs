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
    #[serde(skip_serializing_if = "Option::is_none")]
    role: Option<&'a str>,
    slave: u8,
    function: u8,
    #[serde(flatten)]
    request: Fields,
    answer: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    exception: Option<u8>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fault: Option<&'static str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    refused: Option<&'a str>,
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
                role: entry.role,
                slave: entry.slave,
                function,
                request,
                answer,
                exception,
                fault,
                refused: entry.refusal,
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
    let refused = entry
        .refusal
        .map(|why| format!(": {why}"))
        .unwrap_or_default();
    let role = entry
        .role
        .map(|role| format!(" ({role})"))
        .unwrap_or_default();
    writeln!(
        out,
        "[{:>12.6}] {}{role} slave {}: {} {} {} -> {result}{refused}{fault}",
        entry.elapsed.as_secs_f64(),
        entry.peer,
        entry.slave,
        function,
        function::name(function),
        super::fields_summary(&request),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use mbtool_core::codec::{Exception, ExceptionCode, Request};
    use std::time::Duration;

    fn logged(json: bool, outcome: &Outcome) -> String {
        let request = Request::ReadHoldingRegisters {
            address: 107,
            quantity: 3,
        };
        let entry = LogEntry {
            elapsed: Duration::from_millis(1500),
            peer: "127.0.0.1:5020",
            role: None,
            slave: 17,
            request: &request,
            outcome,
            refusal: None,
        };
        let mut out = Vec::new();
        write_entry(&mut out, json, &entry).unwrap();
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn a_line_for_people_names_the_request_and_what_came_of_it() {
        let exception = Outcome::Answered(Pdu::Exception(Exception {
            function: 3,
            code: ExceptionCode::ILLEGAL_DATA_ADDRESS,
        }));
        let line = logged(false, &exception);
        assert!(line.starts_with("[    1.500000] 127.0.0.1:5020 slave 17: 3 Read Holding Registers 400108 x3 -> exception 02"), "{line}");
        assert!(logged(false, &Outcome::Dropped).ends_with("-> none [dropped]\n"));
    }

    #[test]
    fn json_lines_carry_the_request_fields_and_the_fault() {
        let json: serde_json::Value =
            serde_json::from_str(logged(true, &Outcome::Dropped).trim()).unwrap();
        assert_eq!(json["slave"], 17);
        assert_eq!(json["ref"], "400108");
        assert_eq!(json["answer"], "none");
        assert_eq!(json["fault"], "dropped");
    }
}
