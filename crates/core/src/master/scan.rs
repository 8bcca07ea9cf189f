//! Finding the slaves on a line: every id asked once at each serial setting, the most
//! common settings first, each id that answers asked again to confirm it, and, before
//! anything is sent, an ear on the line for slaves another master is already talking to.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use super::timeouts;
use super::{BadAnswer, Master, MasterError, Reply};
use crate::codec::{ExceptionCode, Mode, Request};
use crate::model::line::Parity;

/// What each id is asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Probe {
    /// Read one holding register at protocol address 0 (03).
    Read,
    /// Report server id (17).
    Id,
}

impl Probe {
    /// How many bytes the answer to the probe takes on a line: 7 for a read, a 32-byte
    /// server id.
    pub fn answer_bytes(self) -> u32 {
        match self {
            Probe::Read => 7,
            Probe::Id => 32,
        }
    }

    /// The request each id is asked.
    pub fn request(self) -> Request {
        match self {
            Probe::Read => Request::ReadHoldingRegisters {
                address: 0,
                quantity: 1,
            },
            Probe::Id => Request::ReportServerId,
        }
    }
}

/// What a scan asks.
#[derive(Clone, Debug)]
pub struct ScanOptions {
    /// The ids to ask, in order.
    pub ids: Vec<u8>,
    /// The request each id is asked.
    pub probe: Probe,
    /// Listen this long at each setting before sending anything.
    pub listen: Option<Duration>,
    /// Go on through every setting instead of stopping at the first where a slave answers.
    pub all: bool,
    /// Over TCP: when every id answered, tell a device that answers every unit id from one
    /// that has exactly those (by an id outside the scan, or a reserved one inside it).
    pub tell_unit_ids: bool,
}

/// How a slave answered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Answer {
    /// A normal answer.
    Ok,
    /// An exception: the slave is there, and says no to the probe.
    Exception(ExceptionCode),
}

/// A slave found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Hit {
    /// Its id.
    pub slave: u8,
    /// The index of the setting it answered at.
    pub setting: usize,
    /// How it answered; `None` when it was only heard answering another master.
    pub answer: Option<Answer>,
    /// It answered when asked again (or was heard on the line).
    pub confirmed: bool,
    /// Its answer came after the scan's timeout, while another id was being asked: it is
    /// there, but slower than the timeout. `answer` and `confirmed` tell how it answered
    /// when asked again and given longer.
    pub late: bool,
}

/// Bytes that came back for an id but were no valid answer: something is there, maybe
/// at other settings.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Garbled {
    /// The id asked.
    pub slave: u8,
    /// The index of the setting.
    pub setting: usize,
    /// What was wrong with what came.
    pub detail: String,
}

/// What a scan found.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ScanReport {
    /// The slaves found, in the order found.
    pub hits: Vec<Hit>,
    /// The ids that drew bytes that were no answer.
    pub garbled: Vec<Garbled>,
    /// How many settings were tried.
    pub settings_tried: usize,
    /// How many requests were sent.
    pub requests: u64,
    /// Every id asked answered, and so did the control id: the device does not tell unit
    /// ids apart (it ignores the unit id, or refuses the ones it lacks with an exception
    /// of its own). The control id's answer; the hits that answered otherwise are the
    /// ones that tell.
    pub ignores_unit_id: Option<Answer>,
    /// It was stopped before every id was asked: the hits are those found so far.
    pub stopped: bool,
    /// The ids after which the connection was closed by the other end, and opened again.
    pub reconnected: Vec<u8>,
    /// Why the scan stopped before its end, when it did: what it found so far stands.
    pub interrupted: Option<String>,
    /// Over TCP, answers came after the timeout (a gateway that waits longer for a unit id
    /// it lacks than the scan did): the longest they took. From then on the scan waited as
    /// long, so that no answer passed it by.
    pub waited_longer: Option<Duration>,
}

/// What the scan is doing, for a progress display.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Progress {
    /// Starting on the setting of this index.
    Setting(usize),
    /// Listening before sending, at the current setting.
    Listening,
    /// One more id asked; how many slaves were found so far.
    Asked(usize),
}

/// How one probe came out.
enum Outcome {
    Present(Answer),
    Absent,
    Garbled(String),
    /// A whole answer came, from another slave: a late answer to an earlier request.
    Other(u8),
}

/// How many times an id is asked again when its answer was lost: garbled, or crowded out
/// by another slave's late answer.
const ASK_AGAIN: usize = 2;

fn probe(master: &mut Master, slave: u8, request: &Request) -> Result<Outcome, MasterError> {
    Ok(match master.transact(slave, request) {
        Ok(Reply::Response(_)) => Outcome::Present(Answer::Ok),
        // A gateway's "no such device": nothing there.
        Ok(Reply::Exception(exception))
            if matches!(
                exception.code,
                ExceptionCode::GATEWAY_PATH_UNAVAILABLE | ExceptionCode::GATEWAY_TARGET_FAILED
            ) =>
        {
            Outcome::Absent
        }
        Ok(Reply::Exception(exception)) => Outcome::Present(Answer::Exception(exception.code)),
        Ok(Reply::Broadcast) | Err(MasterError::Timeout { .. } | MasterError::OutOfStep { .. }) => {
            Outcome::Absent
        }
        Err(MasterError::BadFrame {
            reason: BadAnswer::OtherSlave(other),
            ..
        }) => Outcome::Other(other),
        Err(MasterError::BadFrame { reason, .. }) => Outcome::Garbled(reason.to_string()),
        Err(error) => return Err(error),
    })
}

/// Asks `slave`, and asks again after the line is quiet when the answer was lost to
/// noise or to another slave's late answer: an answer from another id is never evidence
/// for the id asked. The ids heard answering late are added to `late`.
fn ask(
    master: &mut Master,
    slave: u8,
    request: &Request,
    late: &mut Vec<u8>,
) -> Result<Outcome, MasterError> {
    let mut outcome = probe(master, slave, request)?;
    for _ in 0..ASK_AGAIN {
        match outcome {
            Outcome::Other(other) => late.push(other),
            Outcome::Garbled(_) => {}
            Outcome::Present(_) | Outcome::Absent => break,
        }
        let quiet = master.timeout();
        late.extend(master.wait_quiet(quiet, timeouts::late(quiet))?);
        outcome = probe(master, slave, request)?;
    }
    Ok(match outcome {
        Outcome::Other(other) => {
            late.push(other);
            Outcome::Absent
        }
        outcome => outcome,
    })
}

/// Asks a slave heard answering late once more, waiting long enough for it.
fn ask_late(master: &mut Master, slave: u8, request: &Request) -> Result<Outcome, MasterError> {
    let timeout = master.timeout();
    master.set_timeout(timeouts::late(timeout));
    let outcome = probe(master, slave, request);
    master.set_timeout(timeout);
    outcome
}

/// Scans `settings` in order. `open` gives a master at a setting (with the scan's timeout
/// and no retries); `progress` is told what is going on. A connection the other end
/// closes is opened again (many TCP devices close on a unit id they lack); when it cannot
/// be, the scan stops there and the report says why. `stop`, once set (by a signal
/// handler, say), ends the scan before the next id, with what was found so far.
pub fn scan<S, E>(
    settings: &[S],
    options: &ScanOptions,
    mut open: impl FnMut(&S) -> Result<Master, E>,
    mut progress: impl FnMut(Progress),
    stop: &AtomicBool,
) -> Result<ScanReport, E>
where
    E: From<MasterError> + std::fmt::Display,
{
    let mut report = ScanReport::default();
    let request = options.probe.request();
    'settings: for (index, setting) in settings.iter().enumerate() {
        progress(Progress::Setting(index));
        report.settings_tried += 1;
        let mut master = open(setting)?;
        let found_before = report.hits.len();
        let heard = match options.listen {
            Some(duration) => {
                progress(Progress::Listening);
                master.listen(duration).map_err(MasterError::Io)?
            }
            None => Vec::new(),
        };
        // Slaves heard talking to a master: found without adding traffic to its bus.
        for slave in heard.into_iter().filter(|id| options.ids.contains(id)) {
            report.hits.push(Hit {
                slave,
                setting: index,
                answer: None,
                confirmed: true,
                late: false,
            });
        }
        let probing = report.hits.len() == found_before;
        // Whether the last id asked was silent: its answer may still be on its way.
        let mut last_silent = false;
        let mut gateway_asked = false;
        for slave in options.ids.iter().filter(|_| probing) {
            if stop.load(Ordering::SeqCst) {
                report.stopped = true;
                break 'settings;
            }
            report.requests += 1;
            let mut late = Vec::new();
            let outcome = match ask(&mut master, *slave, &request, &mut late) {
                // What is not Modbus at all (a TLS port on tcp://) ends the scan, told.
                Err(MasterError::Io(e)) if e.kind() == std::io::ErrorKind::InvalidData => {
                    return Err(MasterError::Io(e).into())
                }
                Err(MasterError::Io(_)) => {
                    report.reconnected.push(*slave);
                    match open(setting) {
                        Ok(again) => master = again,
                        Err(error) => {
                            report.interrupted = Some(error.to_string());
                            break 'settings;
                        }
                    }
                    Outcome::Absent
                }
                Err(error) => return Err(error.into()),
                Ok(outcome) => outcome,
            };
            // Over TCP, the first id that times out is asked once more with the patience
            // of a gateway, which may wait longer for a unit id it lacks than the scan
            // does: its answer, or its 0B, tells how long it takes.
            let outcome = match outcome {
                Outcome::Absent
                    if master.options.mode == Mode::Tcp && master.timed_out && !gateway_asked =>
                {
                    gateway_asked = true;
                    report.requests += 1;
                    let timeout = master.timeout();
                    master.set_timeout(timeout.max(timeouts::GATEWAY_PATIENCE));
                    let again = probe(&mut master, *slave, &request);
                    master.set_timeout(timeout);
                    match again {
                        Ok(outcome) => outcome,
                        Err(MasterError::Io(_)) => Outcome::Absent,
                        Err(error) => return Err(error.into()),
                    }
                }
                outcome => outcome,
            };
            // Over TCP an answer after the timeout is told by its transaction id: its id
            // is there when a device answered it, and the scan waits as long as it took
            // from then on (half as long again), as the gateway does.
            for answer in master.take_late_answers() {
                if answer.present {
                    late.push(answer.slave);
                }
                report.waited_longer = report.waited_longer.max(Some(answer.after));
                let needed = answer.after + answer.after / 2;
                if needed > master.timeout() {
                    master.set_timeout(needed);
                }
            }
            last_silent = matches!(outcome, Outcome::Absent | Outcome::Other(_));
            match outcome {
                Outcome::Present(answer) => {
                    report.requests += 1;
                    let again = ask(&mut master, *slave, &request, &mut late);
                    report.hits.push(Hit {
                        slave: *slave,
                        setting: index,
                        answer: Some(answer),
                        confirmed: matches!(again, Ok(Outcome::Present(_))),
                        late: false,
                    });
                }
                Outcome::Garbled(detail) => report.garbled.push(Garbled {
                    slave: *slave,
                    setting: index,
                    detail,
                }),
                Outcome::Absent | Outcome::Other(_) => {}
            }
            note_late(&mut master, late, &mut report, index, options, &request);
            progress(Progress::Asked(report.hits.len()));
        }
        // The last id's answer may still be on its way when it was silent; when it
        // answered, nothing is awaited.
        if probing && last_silent {
            let quiet = timeouts::straggler(master.timeout());
            if let Ok(stragglers) = master.wait_quiet(quiet, quiet) {
                note_late(
                    &mut master,
                    stragglers,
                    &mut report,
                    index,
                    options,
                    &request,
                );
            }
        }
        if probing && options.tell_unit_ids {
            report.ignores_unit_id = control_answer(&mut master, &request, &report, options, index);
        }
        if report.hits.len() > found_before && !options.all {
            break;
        }
    }
    Ok(report)
}

/// Adds the slaves heard answering `late` at setting `index` to the report, each asked
/// again with time enough to answer; ids outside the scan and ids found already are left.
fn note_late(
    master: &mut Master,
    late: Vec<u8>,
    report: &mut ScanReport,
    index: usize,
    options: &ScanOptions,
    request: &Request,
) {
    for slave in late {
        let known = report
            .hits
            .iter()
            .any(|hit| hit.slave == slave && hit.setting == index);
        if known || !options.ids.contains(&slave) {
            continue;
        }
        report.requests += 1;
        let answer = match ask_late(master, slave, request) {
            Ok(Outcome::Present(answer)) => Some(answer),
            _ => None,
        };
        report.hits.push(Hit {
            slave,
            setting: index,
            answer,
            confirmed: answer.is_some(),
            late: true,
        });
    }
}

/// When every id asked answered at setting `index`: how an id that no device behind a
/// gateway can have answers, if it does. That is a reserved id (248-254) outside the scan,
/// else any id outside it; when the scan asked all 256, the reserved ids it asked (0 and
/// 248-255) answered already.
fn control_answer(
    master: &mut Master,
    request: &Request,
    report: &ScanReport,
    options: &ScanOptions,
    index: usize,
) -> Option<Answer> {
    let answered: Vec<&Hit> = report
        .hits
        .iter()
        .filter(|hit| hit.setting == index)
        .collect();
    if options.ids.len() < 2 || answered.len() < options.ids.len() {
        return None;
    }
    let outside = (248..=254)
        .chain((1..=247).rev())
        .chain([0, 255])
        .find(|id| !options.ids.contains(id));
    match outside {
        Some(control) => match probe(master, control, request) {
            Ok(Outcome::Present(answer)) => Some(answer),
            _ => None,
        },
        None => answered
            .iter()
            .find(|hit| hit.slave == 0 || hit.slave >= 248)
            .and_then(|hit| hit.answer),
    }
}

impl ScanReport {
    /// The hits worth listing: all of them, or, when the device does not tell unit ids
    /// apart, those that answered otherwise than the control id.
    pub fn telling_hits(&self) -> impl Iterator<Item = &Hit> {
        self.hits
            .iter()
            .filter(|hit| self.ignores_unit_id.is_none() || hit.answer != self.ignores_unit_id)
    }
}

/// Baud rates by how often devices use them.
const COMMON_BAUDS: [u32; 8] = [19200, 9600, 38400, 115_200, 57600, 4800, 2400, 1200];

/// The settings field devices use most, in that order; the rest follow by baud rate.
const COMMON_SETTINGS: [(u32, Parity); 4] = [
    (19200, Parity::Even),
    (9600, Parity::None),
    (9600, Parity::Even),
    (19200, Parity::None),
];

/// Every pairing of `bauds` and `parities`, the most common first: 19200 even (the
/// specification's default), 9600 none, 9600 even, 19200 none, then by how common the
/// baud rate is, even before none before odd.
pub fn sweep(bauds: &[u32], parities: &[Parity]) -> Vec<(u32, Parity)> {
    let mut settings: Vec<(u32, Parity)> = bauds
        .iter()
        .flat_map(|baud| parities.iter().map(move |parity| (*baud, *parity)))
        .collect();
    let rank = |setting: &(u32, Parity)| {
        let common = COMMON_SETTINGS.iter().position(|known| known == setting);
        let baud = COMMON_BAUDS.iter().position(|known| *known == setting.0);
        let parity = [Parity::Even, Parity::None, Parity::Odd]
            .iter()
            .position(|known| *known == setting.1);
        (
            common.unwrap_or(usize::MAX),
            baud.unwrap_or(usize::MAX),
            parity,
        )
    };
    settings.sort_by_key(rank);
    let mut seen = Vec::with_capacity(settings.len());
    settings.retain(|setting| {
        let new = !seen.contains(setting);
        seen.push(*setting);
        new
    });
    settings
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_most_common_settings_come_first() {
        let settings = sweep(
            &[1200, 9600, 19200, 38400],
            &[Parity::Odd, Parity::None, Parity::Even],
        );
        assert_eq!(
            &settings[..6],
            [
                (19200, Parity::Even),
                (9600, Parity::None),
                (9600, Parity::Even),
                (19200, Parity::None),
                (19200, Parity::Odd),
                (9600, Parity::Odd),
            ]
        );
        assert_eq!(settings.len(), 12);
        // A setting listed twice is tried once.
        assert_eq!(sweep(&[600, 300, 600], &[Parity::Even]).len(), 2);
        assert_eq!(settings[11], (1200, Parity::Odd));
    }
}
