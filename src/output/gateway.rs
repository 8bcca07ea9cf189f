//! How `gateway` shows its transactions: a line each for people, JSON Lines or CSV, and
//! the summary per client and per unit at the end.

use std::io::{self, Write};
use std::time::Duration;

use serde::Serialize;

use super::{csv_field, fields_summary, Format, PollRows};
use mbtool_core::codec::{function, Pdu, Request, Response};
use mbtool_core::describe::{describe_pdu, locate_fields, Fields, Kind};
use mbtool_core::gateway::{Outcome, Summary, Tally, Transaction};
use mbtool_core::input::duration::show;
use mbtool_core::model::spread::Spread;

const RED: &str = "\x1b[31m";
const YELLOW: &str = "\x1b[33m";
const RESET: &str = "\x1b[0m";

pub struct GatewayWriter {
    format: Format,
    colour: bool,
    csv_header_written: bool,
}

/// What went back to the client, as JSON says it.
#[derive(Serialize)]
struct JsonAnswer {
    kind: Kind,
    #[serde(flatten)]
    fields: Fields,
}

#[derive(Serialize)]
struct JsonTransaction<'a> {
    time: &'a str,
    client: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    role: Option<&'a str>,
    unit: u8,
    slave: u8,
    transaction: u16,
    function: u8,
    request: Fields,
    answer: Option<JsonAnswer>,
    queued_us: u64,
    response_time_us: u64,
    tries: u32,
    outcome: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    why: Option<&'a str>,
    /// Only when the client had left before its answer.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    client_gone: bool,
}

const CSV_HEADER: &str = "time,client,unit,slave,transaction,function,request,answer,queued_us,response_time_us,tries,outcome,why,role\n";

/// The fields of an answer in the light of its request: a read's values at the addresses
/// asked (a read/write's at its read), a file record read's files and records, and of
/// coils and inputs only as many as asked (the last byte's padding is not a coil).
fn answer_fields(request: &Request, answer: &Pdu) -> (Kind, Fields) {
    let (kind, mut fields) = describe_pdu(answer);
    if let Pdu::Response(response) = answer {
        let packed = match response {
            Response::ReadCoils { packed } | Response::ReadDiscreteInputs { packed } => {
                packed.as_slice()
            }
            _ => &[],
        };
        locate_fields(&mut fields, request, packed);
    }
    (kind, fields)
}

/// What a transaction's answer says, in a few words.
fn answer_summary(request: &Request, answer: Option<&Pdu>) -> String {
    match answer {
        None => "-".to_string(),
        Some(Pdu::Exception(exception)) => format!("exception {}", exception.code),
        Some(pdu) => {
            let (_, fields) = answer_fields(request, pdu);
            match fields_summary(&fields) {
                shown if shown.is_empty() => "ok".to_string(),
                shown => shown,
            }
        }
    }
}

fn why(outcome: &Outcome) -> Option<&str> {
    match outcome {
        Outcome::BadFrame(why) | Outcome::LineDown(why) | Outcome::Refused(why) => Some(why),
        _ => None,
    }
}

impl GatewayWriter {
    pub fn new(format: Format, colour: bool) -> Self {
        Self {
            format,
            colour,
            csv_header_written: false,
        }
    }

    fn row_line(&self, t: &Transaction, time: &str) -> String {
        let function = t.request.function();
        let (_, request) = describe_pdu(&Pdu::Request(t.request.clone()));
        let unit = if t.unit == t.slave {
            t.unit.to_string()
        } else {
            format!("{}>{}", t.unit, t.slave)
        };
        let tries = match t.tries {
            1 => "1 try".to_string(),
            n => format!("{n} tries"),
        };
        let mut outcome = t.outcome.name().to_string();
        if let Some(why) = why(&t.outcome) {
            outcome = format!("{outcome}: {why}");
        }
        if !t.delivered && t.answer.is_some() {
            outcome.push_str(" (client gone)");
        }
        // A TLS client's role, last: the columns stay in line.
        if let Some(role) = &t.role {
            outcome.push_str(&format!("  [role {role}]"));
        }
        let colour = match t.outcome {
            _ if !self.colour => "",
            Outcome::Answer | Outcome::Broadcast => "",
            Outcome::Exception | Outcome::Refused(_) => YELLOW,
            _ => RED,
        };
        let reset = if colour.is_empty() { "" } else { RESET };
        // The time of day of an RFC 3339 time: the date is the same all day.
        let clock = super::time_of_day(time);
        format!(
            "{clock}  {:<21} {unit:>7}  {function:02} {:<26} {:<28} -> {:<32} {:>9}  {tries:<7} {colour}{outcome}{reset}\n",
            t.client,
            function::name(function),
            fields_summary(&request),
            answer_summary(&t.request, t.answer.as_ref()),
            show(t.response_time),
        )
    }

    fn json_row(t: &Transaction, time: &str) -> serde_json::Result<Vec<u8>> {
        let (_, request) = describe_pdu(&Pdu::Request(t.request.clone()));
        let answer = t.answer.as_ref().map(|pdu| {
            let (kind, fields) = answer_fields(&t.request, pdu);
            JsonAnswer { kind, fields }
        });
        let mut line = serde_json::to_vec(&JsonTransaction {
            time,
            client: &t.client,
            role: t.role.as_deref(),
            unit: t.unit,
            slave: t.slave,
            transaction: t.transaction,
            function: t.request.function(),
            request,
            answer,
            queued_us: t.queued.as_micros() as u64,
            response_time_us: t.response_time.as_micros() as u64,
            tries: t.tries,
            outcome: t.outcome.name(),
            why: why(&t.outcome),
            client_gone: !t.delivered && t.answer.is_some(),
        })?;
        line.push(b'\n');
        Ok(line)
    }

    fn csv_row(t: &Transaction, time: &str) -> String {
        let (_, request) = describe_pdu(&Pdu::Request(t.request.clone()));
        let fields = [
            time.to_string(),
            t.client.to_string(),
            t.unit.to_string(),
            t.slave.to_string(),
            t.transaction.to_string(),
            t.request.function().to_string(),
            fields_summary(&request),
            answer_summary(&t.request, t.answer.as_ref()),
            t.queued.as_micros().to_string(),
            t.response_time.as_micros().to_string(),
            t.tries.to_string(),
            t.outcome.name().to_string(),
            why(&t.outcome).unwrap_or_default().to_string(),
            t.role.as_deref().unwrap_or_default().to_string(),
        ];
        let mut line = fields.map(|f| csv_field(&f)).join(",");
        line.push('\n');
        line
    }

    /// The summary per client and per unit: a table, or a JSON line each.
    pub fn summary(&self, out: &mut dyn Write, summary: &Summary) -> io::Result<()> {
        if self.format == Format::Json {
            for (client, tally) in &summary.clients {
                json_summary(out, "client", ("client", client.as_str().into()), tally)?;
            }
            if let Some((count, tally)) = &summary.earlier {
                json_summary(out, "earlier_clients", ("clients", (*count).into()), tally)?;
            }
            for (unit, tally) in &summary.units {
                json_summary(out, "unit", ("unit", (*unit).into()), tally)?;
            }
            if summary.bad_clients > 0 {
                let line =
                    serde_json::json!({ "summary": "bad_clients", "closed": summary.bad_clients });
                writeln!(out, "{line}")?;
            }
            if summary.bad_datagrams > 0 {
                let line = serde_json::json!({
                    "summary": "bad_datagrams",
                    "passed_over": summary.bad_datagrams
                });
                writeln!(out, "{line}")?;
            }
            if summary.refused > 0 {
                let line =
                    serde_json::json!({ "summary": "refused_clients", "refused": summary.refused });
                writeln!(out, "{line}")?;
            }
            return Ok(());
        }
        if summary.clients.is_empty() {
            writeln!(out, "no transactions")?;
        } else {
            summary_table(out, summary)?;
        }
        let closed = [
            (
                summary.bad_clients,
                "closed for sending what is not Modbus TCP",
            ),
            (
                summary.refused,
                "refused over TLS (handshake failed or not finished, or role not allowed)",
            ),
        ];
        for (count, why) in closed.into_iter().filter(|(count, _)| *count > 0) {
            writeln!(out, "{} {why}", super::plural(count as usize, "client"))?;
        }
        if summary.bad_datagrams > 0 {
            writeln!(
                out,
                "{} passed over: no Modbus/UDP request",
                super::plural(summary.bad_datagrams as usize, "datagram")
            )?;
        }
        Ok(())
    }
}

/// The summary's rows, a client or a unit each, as a table.
fn summary_table(out: &mut dyn Write, summary: &Summary) -> io::Result<()> {
    let mut table = super::new_table(false);
    table.set_header(vec![
        "",
        "requests",
        "answers",
        "exceptions",
        "timeouts",
        "bad frames",
        "line down",
        "min",
        "mean",
        "p95",
        "max",
    ]);
    let earlier = summary.earlier.as_ref().map(|(count, tally)| {
        let name = format!("{} before", super::plural(*count as usize, "client"));
        (name, tally)
    });
    let rows = summary
        .clients
        .iter()
        .map(|(client, tally)| (format!("client {client}"), tally))
        .chain(earlier)
        .chain(
            summary
                .units
                .iter()
                .map(|(unit, tally)| (format!("unit {unit}"), tally)),
        );
    for (name, tally) in rows {
        let mut row = vec![
            name,
            tally.requests.to_string(),
            tally.answers.to_string(),
            tally.exceptions.to_string(),
            tally.timeouts.to_string(),
            tally.bad_frames.to_string(),
            tally.line_down.to_string(),
        ];
        let ms = |us: u64| show(Duration::from_micros(us));
        match tally.times() {
            Some(Spread {
                min,
                mean,
                p95,
                max,
            }) => row.extend([min, mean, p95, max].map(ms)),
            None => row.extend(["-", "-", "-", "-"].map(String::from)),
        }
        table.add_row(row);
    }
    writeln!(out, "{table}")?;
    Ok(())
}

/// One line of the summary in JSON.
#[derive(Serialize)]
struct JsonTally {
    requests: u64,
    answers: u64,
    exceptions: u64,
    timeouts: u64,
    bad_frames: u64,
    line_down: u64,
    #[serde(skip_serializing_if = "Option::is_none")]
    response_time_us: Option<Spread>,
}

fn json_summary(
    out: &mut dyn Write,
    kind: &str,
    (key, value): (&str, serde_json::Value),
    tally: &Tally,
) -> io::Result<()> {
    let mut line = serde_json::json!({ "summary": kind, key: value });
    let counts = serde_json::to_value(JsonTally {
        requests: tally.requests,
        answers: tally.answers,
        exceptions: tally.exceptions,
        timeouts: tally.timeouts,
        bad_frames: tally.bad_frames,
        line_down: tally.line_down,
        response_time_us: tally.times(),
    })?;
    if let (Some(line), serde_json::Value::Object(counts)) = (line.as_object_mut(), counts) {
        line.extend(counts);
    }
    writeln!(out, "{line}")
}

impl PollRows for GatewayWriter {
    type Item = Transaction;

    fn row(&mut self, out: &mut dyn Write, t: &Transaction, time: &str) -> io::Result<()> {
        match self.format {
            Format::Json => out.write_all(&Self::json_row(t, time)?),
            Format::Csv => {
                if !self.csv_header_written {
                    self.csv_header_written = true;
                    out.write_all(CSV_HEADER.as_bytes())?;
                }
                out.write_all(Self::csv_row(t, time).as_bytes())
            }
            Format::Table | Format::Values => out.write_all(self.row_line(t, time).as_bytes()),
        }
    }

    /// The gateway has no failed polls: what goes wrong is a transaction's outcome.
    fn failure(&mut self, _: &mut dyn Write, _: &str, _: &str) -> io::Result<()> {
        Ok(())
    }

    fn continuing(&mut self) {
        self.csv_header_written = true;
    }

    fn format(&self) -> Format {
        self.format
    }
}
