//! Asking a device who it is and how it is doing: device identification (43/14) and
//! report server id (17) for `info`; return query data, the counters and clear counters
//! (08) and the exception status (07) for `diag`. Results are data; printing is the
//! binary's.

use std::time::{Duration, Instant};

use super::{Master, MasterError, Reply};
use crate::codec::answer::Mismatch;
use crate::codec::{DeviceObject, ExceptionCode, Request, Response};

/// What a device said to one function: its answer, or that it does not do it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Asked<T> {
    /// The device answered.
    Answered(T),
    /// The device refused with an exception (01: it lacks the function).
    Refused(ExceptionCode),
}

/// Asks `request` and picks the answer out of the response. The master lets through
/// only an answer to the request's function; one of another shape is told as the
/// mismatch it is.
fn ask<T>(
    master: &mut Master,
    slave: u8,
    request: &Request,
    pick: impl FnOnce(Response) -> Option<T>,
) -> Result<Asked<T>, MasterError> {
    let function = request.function();
    let misfit = |answered| MasterError::BadFrame {
        slave,
        reason: Mismatch::Function {
            asked: function,
            answered,
        }
        .into(),
    };
    match master.transact(slave, request)? {
        Reply::Response(response) => {
            let answered = response.function();
            pick(response)
                .map(Asked::Answered)
                .ok_or_else(|| misfit(answered))
        }
        Reply::Exception(exception) => Ok(Asked::Refused(exception.code)),
        Reply::Broadcast => Err(misfit(0)),
    }
}

/// A device's identification objects, every level it has, each object once.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Identification {
    /// The conformity level the device gave: 01-03, 81-83 with single objects readable.
    pub conformity: u8,
    /// The objects by id, in order.
    pub objects: Vec<DeviceObject>,
    /// How many 43/14 requests it took.
    pub requests: usize,
    /// The device kept saying "more follows" without moving on: the stream was cut there.
    pub cut_short: bool,
}

/// The answer to report server id (17). Its layout is the device's: most send an id byte,
/// the run indicator and their own data; some send a text id and the run indicator last.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ServerId {
    /// The server id byte, when the answer starts with one.
    pub id: Option<u8>,
    /// The run indicator: on (FF) or off (00); `None` where no byte reads as one.
    pub running: Option<bool>,
    /// The rest: the device's own data, or its text id.
    pub data: Vec<u8>,
}

impl ServerId {
    /// Reads the bytes after the byte count.
    pub fn parse(data: &[u8]) -> ServerId {
        let run = |byte: u8| match byte {
            0xFF => Some(true),
            0x00 => Some(false),
            _ => None,
        };
        let printable = |bytes: &[u8]| bytes.iter().all(|b| (0x20..=0x7E).contains(b));
        match data {
            [id, indicator, rest @ ..] if run(*indicator).is_some() => ServerId {
                id: Some(*id),
                running: run(*indicator),
                data: rest.to_vec(),
            },
            [text @ .., indicator] if run(*indicator).is_some() && printable(text) => ServerId {
                id: None,
                running: run(*indicator),
                data: text.to_vec(),
            },
            _ => ServerId {
                id: data.first().copied(),
                running: None,
                data: data.get(1..).unwrap_or_default().to_vec(),
            },
        }
    }
}

/// The most requests one identification stream may take: 256 objects can not need more.
const MAX_STREAM_REQUESTS: usize = 256;

/// Read device identification: the basic level, then the highest level the device's
/// conformity gives, following "more follows" across as many requests as it takes. What
/// goes wrong in the second stream (a timeout, a refusal) costs only that stream: the
/// basic objects are kept, and the identification is marked cut short.
pub fn identification(
    master: &mut Master,
    slave: u8,
) -> Result<Asked<Identification>, MasterError> {
    let mut found = Identification {
        conformity: 0,
        objects: Vec::new(),
        requests: 0,
        cut_short: false,
    };
    if let Some(code) = stream(master, slave, 0x01, &mut found)? {
        return Ok(Asked::Refused(code));
    }
    let level = found.conformity & 0x7F;
    if (0x02..=0x03).contains(&level) {
        match stream(master, slave, level, &mut found) {
            Ok(None) => {}
            Ok(Some(_))
            | Err(
                MasterError::Timeout { .. }
                | MasterError::OutOfStep { .. }
                | MasterError::BadFrame { .. },
            ) => {
                found.cut_short = true;
            }
            Err(error) => return Err(error),
        }
    }
    found.objects.sort_by_key(|object| object.id);
    Ok(Asked::Answered(found))
}

/// Reads one stream (read code 1-3) into `found`; `Some(code)` when the device refused it.
fn stream(
    master: &mut Master,
    slave: u8,
    read_code: u8,
    found: &mut Identification,
) -> Result<Option<ExceptionCode>, MasterError> {
    let mut object_id = 0;
    for _ in 0..MAX_STREAM_REQUESTS {
        let request = Request::ReadDeviceIdentification {
            read_code,
            object_id,
        };
        found.requests += 1;
        let answer = match ask(master, slave, &request, |response| match response {
            Response::ReadDeviceIdentification(answer) => Some(answer),
            _ => None,
        })? {
            Asked::Answered(answer) => answer,
            Asked::Refused(code) => return Ok(Some(code)),
        };
        found.conformity = found.conformity.max(answer.conformity);
        for object in answer.objects {
            if !found.objects.iter().any(|known| known.id == object.id) {
                found.objects.push(object);
            }
        }
        if !answer.more_follows {
            return Ok(None);
        }
        // A stream that does not move on would never end.
        if answer.next_object_id <= object_id {
            found.cut_short = true;
            return Ok(None);
        }
        object_id = answer.next_object_id;
    }
    found.cut_short = true;
    Ok(None)
}

/// Report server id (17).
pub fn server_id(master: &mut Master, slave: u8) -> Result<Asked<ServerId>, MasterError> {
    ask(
        master,
        slave,
        &Request::ReportServerId,
        |response| match response {
            Response::ReportServerId { data } => Some(ServerId::parse(&data)),
            _ => None,
        },
    )
}

/// Round trips of return query data (08/00).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RoundTrips {
    /// The time of each answered round trip, request sent to answer received.
    pub times: Vec<Duration>,
    /// Round trips that got no answer in time.
    pub lost: usize,
    /// Whether every answer echoed its query data byte for byte.
    pub intact: bool,
}

impl RoundTrips {
    /// The shortest, mean and longest round trip, when any was answered.
    pub fn min_mean_max(&self) -> Option<(Duration, Duration, Duration)> {
        let min = *self.times.iter().min()?;
        let max = *self.times.iter().max()?;
        let total: Duration = self.times.iter().sum();
        let mean = total / u32::try_from(self.times.len()).ok()?;
        Some((min, mean, max))
    }
}

/// `count` round trips of return query data (08/00), each with its own query data. A
/// timeout costs that round trip; when none is answered the timeout is the error.
pub fn round_trips(
    master: &mut Master,
    slave: u8,
    count: u64,
) -> Result<Asked<RoundTrips>, MasterError> {
    let mut trips = RoundTrips {
        times: Vec::new(),
        lost: 0,
        intact: true,
    };
    let mut last_timeout = None;
    for i in 0..count {
        let query = (0xA537_u16 ^ (i as u16).wrapping_mul(0x1F1F))
            .to_be_bytes()
            .to_vec();
        let request = Request::Diagnostics {
            sub_function: 0x0000,
            data: query.clone(),
        };
        let start = Instant::now();
        match master.transact(slave, &request) {
            Ok(Reply::Response(Response::Diagnostics { data, .. })) => {
                trips.times.push(start.elapsed());
                trips.intact &= data == query;
            }
            Ok(Reply::Exception(exception)) => return Ok(Asked::Refused(exception.code)),
            // The master lets only a diagnostics answer through.
            Ok(_) => trips.intact = false,
            Err(timeout @ MasterError::Timeout { .. }) => {
                trips.lost += 1;
                last_timeout = Some(timeout);
            }
            Err(error) => return Err(error),
        }
    }
    match last_timeout {
        Some(timeout) if trips.times.is_empty() => Err(timeout),
        _ => Ok(Asked::Answered(trips)),
    }
}

/// The counters of the diagnostics function, by sub-function, with their names.
pub const COUNTERS: [(u16, &str); 8] = [
    (0x000B, "bus messages"),
    (0x000C, "bus communication errors"),
    (0x000D, "bus exception errors"),
    (0x000E, "slave messages"),
    (0x000F, "slave no response"),
    (0x0010, "slave NAK"),
    (0x0011, "slave busy"),
    (0x0012, "bus character overruns"),
];

/// One counter as read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Counter {
    /// The sub-function that reads it (0B-12).
    pub sub_function: u16,
    /// Its name.
    pub name: &'static str,
    /// Its value, or the exception of a device that does not keep it; `Err` holds the
    /// data of an answer that is no 16-bit counter.
    pub value: Result<Asked<u16>, Vec<u8>>,
}

/// Reads every counter of [`COUNTERS`].
pub fn counters(master: &mut Master, slave: u8) -> Result<Vec<Counter>, MasterError> {
    COUNTERS
        .iter()
        .map(|(sub_function, name)| {
            let value = match diagnostic(master, slave, *sub_function)? {
                Asked::Answered(data) => match data.as_slice() {
                    [high, low] => Ok(Asked::Answered(u16::from_be_bytes([*high, *low]))),
                    _ => Err(data),
                },
                Asked::Refused(code) => Ok(Asked::Refused(code)),
            };
            Ok(Counter {
                sub_function: *sub_function,
                name,
                value,
            })
        })
        .collect()
}

/// Clear counters and diagnostic register (08/0A).
pub fn clear_counters(master: &mut Master, slave: u8) -> Result<Asked<()>, MasterError> {
    Ok(match diagnostic(master, slave, 0x000A)? {
        Asked::Answered(_) => Asked::Answered(()),
        Asked::Refused(code) => Asked::Refused(code),
    })
}

/// One diagnostics sub-function with data 0000; the data of its answer.
fn diagnostic(
    master: &mut Master,
    slave: u8,
    sub_function: u16,
) -> Result<Asked<Vec<u8>>, MasterError> {
    let request = Request::Diagnostics {
        sub_function,
        data: vec![0, 0],
    };
    ask(master, slave, &request, |response| match response {
        Response::Diagnostics { data, .. } => Some(data),
        _ => None,
    })
}

/// Read exception status (07): the eight exception status outputs.
pub fn exception_status(master: &mut Master, slave: u8) -> Result<Asked<u8>, MasterError> {
    ask(
        master,
        slave,
        &Request::ReadExceptionStatus,
        |response| match response {
            Response::ReadExceptionStatus { status } => Some(status),
            _ => None,
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn server_id_layouts() {
        assert_eq!(
            ServerId::parse(&[0x11, 0xFF, b'o', b'k']),
            ServerId {
                id: Some(0x11),
                running: Some(true),
                data: b"ok".to_vec()
            }
        );
        assert_eq!(
            ServerId::parse(b"ACME-PX-7\x00"),
            ServerId {
                id: None,
                running: Some(false),
                data: b"ACME-PX-7".to_vec()
            }
        );
        assert_eq!(
            ServerId::parse(&[0x05, 0x5A, 0x01]),
            ServerId {
                id: Some(0x05),
                running: None,
                data: vec![0x5A, 0x01]
            }
        );
        assert_eq!(ServerId::parse(&[]).id, None);
    }
}
