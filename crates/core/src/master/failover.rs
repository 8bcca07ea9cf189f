//! Redundant paths to one device, as HMI drivers offer them: a primary and a secondary
//! communication path (a gateway and a direct line, say), and the conditions that make
//! the master change from the one in use to the other: so many timeouts or bad frames, an
//! exception code (0B: the gateway's target did not answer), the connection lost; any of
//! them, or all of them. What happened on a path since its last good answer is what the
//! conditions are weighed against; a switch starts the count afresh on the other path, and
//! the same conditions there switch back.

use crate::codec::ExceptionCode;
use crate::input::choice::Choice;

use super::{Master, MasterError, Reply};

/// One of the two paths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PathName {
    /// The path given by `--port`.
    Primary,
    /// The other one.
    Secondary,
}

impl PathName {
    /// `primary` or `secondary`, as a log row names it.
    pub fn name(self) -> &'static str {
        match self {
            PathName::Primary => "primary",
            PathName::Secondary => "secondary",
        }
    }

    /// The path that is not this one.
    pub fn other(self) -> PathName {
        match self {
            PathName::Primary => PathName::Secondary,
            PathName::Secondary => PathName::Primary,
        }
    }
}

/// A condition that counts for changing paths.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SwitchCondition {
    /// This many transactions without an answer (each after its retries).
    Timeouts(u32),
    /// This many bad answers (each after its retries).
    BadFrames(u32),
    /// An answer with this exception code.
    Exception(ExceptionCode),
    /// The port or connection lost, or not to be opened.
    Disconnect,
}

impl SwitchCondition {
    /// Reads `timeout:3`, `bad-frame:3`, `exception:0B` (hex, as the code is written) or
    /// `disconnect`.
    pub fn parse(text: &str) -> Result<SwitchCondition, String> {
        let (name, value) = match text.split_once(':') {
            Some((name, value)) => (name.trim(), Some(value.trim())),
            None => (text.trim(), None),
        };
        let count = |value: Option<&str>| -> Result<u32, String> {
            match value.map(str::parse::<u32>) {
                Some(Ok(n)) if n >= 1 => Ok(n),
                _ => Err(format!("{name} takes a count from 1 up: {name}:3")),
            }
        };
        match (name.to_ascii_lowercase().as_str(), value) {
            ("timeout" | "timeouts", value) => Ok(SwitchCondition::Timeouts(count(value)?)),
            ("bad-frame" | "bad-frames", value) => Ok(SwitchCondition::BadFrames(count(value)?)),
            ("exception", Some(code)) => {
                let digits = code.trim_start_matches("0x").trim_start_matches("0X");
                // `11` reads as eleven to some and as 0x11 to others: only a reading that
                // both agree on, or one written with a hex digit or 0x, is taken.
                let decimal = digits
                    .parse::<u32>()
                    .ok()
                    .filter(|_| digits.len() == code.len());
                if let Some(n) = decimal.filter(|n| *n >= 10) {
                    return Err(format!(
                        "exception:{code} is ambiguous: give the code in hex as the manuals write it ({n:02X} for {n}, or 0x{code})"
                    ));
                }
                match u8::from_str_radix(digits, 16) {
                    Ok(code @ 1..=0x7F) => Ok(SwitchCondition::Exception(ExceptionCode(code))),
                    _ => Err(format!(
                        "exception takes a code in hex, 01 to 7F: exception:0B (gateway target failed to respond), not {code}"
                    )),
                }
            }
            ("exception", None) => Err("exception takes its code: exception:0B".into()),
            ("disconnect", None) => Ok(SwitchCondition::Disconnect),
            ("disconnect", Some(_)) => Err("disconnect takes no value".into()),
            _ => Err(format!(
                "'{text}' is no condition: timeout:N, bad-frame:N, exception:CODE or disconnect"
            )),
        }
    }
}

/// Whether one condition or every one must hold.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum SwitchWhen {
    /// Any condition that holds switches (OR).
    #[default]
    Any,
    /// Every condition must hold since the last good answer (AND).
    All,
}

impl Choice for SwitchWhen {
    const ALL: &'static [Self] = &[SwitchWhen::Any, SwitchWhen::All];

    fn name(self) -> &'static str {
        match self {
            SwitchWhen::Any => "any",
            SwitchWhen::All => "all",
        }
    }

    fn help(self) -> Option<&'static str> {
        Some(match self {
            SwitchWhen::Any => "switch as soon as one condition holds",
            SwitchWhen::All => "switch when every condition has held since the last good answer",
        })
    }
}

/// When to change paths.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SwitchRule {
    /// The conditions, as given.
    pub conditions: Vec<SwitchCondition>,
    /// Whether any or all of them.
    pub when: SwitchWhen,
}

impl Default for SwitchRule {
    /// `timeout:3,disconnect`, any of them.
    fn default() -> Self {
        SwitchRule {
            conditions: vec![SwitchCondition::Timeouts(3), SwitchCondition::Disconnect],
            when: SwitchWhen::Any,
        }
    }
}

/// A change of path, for the log.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Switch {
    /// The path now in use.
    pub to: PathName,
    /// What held on the one left: `3 timeouts`, `exception 0B`, `disconnected`.
    pub why: String,
    /// How the request that made the change ended on the path left, before it was asked
    /// again on this one: for a poll's tally. `None` for a path that could not be opened.
    pub left: Option<Left>,
}

/// How a request ended on the path that was left.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Left {
    /// No answer in time.
    Timeout,
    /// Only bad answers.
    BadFrame,
    /// An exception the rule counts.
    Exception,
    /// The connection or port lost.
    Disconnected,
}

impl Left {
    fn of(outcome: &Result<Reply, MasterError>) -> Option<Left> {
        match outcome {
            Err(MasterError::Timeout { .. } | MasterError::OutOfStep { .. }) => Some(Left::Timeout),
            Err(MasterError::BadFrame { .. }) => Some(Left::BadFrame),
            Err(MasterError::Io(_)) => Some(Left::Disconnected),
            Ok(Reply::Exception(_)) => Some(Left::Exception),
            _ => None,
        }
    }
}

/// Opens the master of a path, or says why it cannot.
pub type OpenPath = Box<dyn FnMut(PathName) -> Result<Master, String> + Send>;

/// What happened on the path in use since its last good answer.
#[derive(Debug, Default)]
struct Seen {
    timeouts: u32,
    bad_frames: u32,
    exceptions: Vec<ExceptionCode>,
    /// Why the connection was lost, when it was.
    disconnected: Option<String>,
}

/// The paths of a master and when to change between them.
pub struct Failover {
    rule: SwitchRule,
    on: PathName,
    open: OpenPath,
    seen: Seen,
    switches: Vec<Switch>,
    /// Ask a failed request again on the same path until the rule decides, for a command
    /// that cannot go on past a failure (a dump, a single read), where a poll would
    /// simply count it and ask at its next interval.
    persistent: bool,
}

/// What a transaction's outcome did to the paths.
#[derive(Debug, PartialEq, Eq)]
pub(super) enum Weighed {
    /// Nothing to weigh (a good answer, or no second path).
    Nothing,
    /// A failure counted toward the rule, which does not hold yet.
    Counted,
    /// The master is on the other path now.
    Switched,
}

/// Why a master on two paths was not opened.
#[derive(Debug)]
pub enum PairError<E> {
    /// A path failed as a setting to correct (a port that cannot switch its RS-485
    /// transceiver as asked), not as a path that is down.
    Setting(E),
    /// Neither path opens: the first's failure, then the other's.
    Neither(E, E),
}

/// A master on the path `first` of the two `open` opens, or on the other where it cannot
/// be opened, changing between them as `rule` says. A failure `is_setting` says is a
/// setting to correct is told as it is, not taken for a path that is down.
pub fn open_pair<E: std::fmt::Display>(
    open: impl Fn(PathName) -> Result<Master, E> + Clone + Send + 'static,
    is_setting: impl Fn(&E) -> bool,
    rule: SwitchRule,
    first: PathName,
) -> Result<Master, PairError<E>> {
    let (master, on, switches) = match open(first) {
        Ok(master) => (master, first, Vec::new()),
        Err(failed) if is_setting(&failed) => return Err(PairError::Setting(failed)),
        Err(failed) => match open(first.other()) {
            Ok(master) => {
                let switch = Switch {
                    to: first.other(),
                    why: format!("the {} path cannot be opened ({failed})", first.name()),
                    left: None,
                };
                (master, first.other(), vec![switch])
            }
            Err(other) if is_setting(&other) => return Err(PairError::Setting(other)),
            Err(other) => return Err(PairError::Neither(failed, other)),
        },
    };
    let reopen = move |path| open(path).map_err(|e| e.to_string());
    Ok(master.with_failover(Failover::new(rule, on, Box::new(reopen), switches)))
}

impl Failover {
    /// Paths opened by `open`, on `on` now; `switches` are those made already (the first
    /// path not to be opened, say), for the log.
    pub fn new(rule: SwitchRule, on: PathName, open: OpenPath, switches: Vec<Switch>) -> Self {
        Failover {
            rule,
            on,
            open,
            seen: Seen::default(),
            switches,
            persistent: false,
        }
    }

    /// Whether the request that failed `asked` times on this path is asked again there:
    /// as often as the rule could need, its largest count for any, every count and one
    /// for each other condition for all.
    pub(super) fn asks_again(&self, asked: u32) -> bool {
        let needs = |condition: &SwitchCondition| match condition {
            SwitchCondition::Timeouts(n) | SwitchCondition::BadFrames(n) => *n,
            _ => 1,
        };
        let conditions = self.rule.conditions.iter();
        let patience = match self.rule.when {
            SwitchWhen::Any => conditions.map(needs).max().unwrap_or(1),
            SwitchWhen::All => conditions.map(needs).sum(),
        };
        self.persistent && asked < patience
    }

    /// Counts a transaction's outcome on the path in use: `None` for a good answer, else
    /// why to switch when the rule now holds (`Some(None)` while it does not).
    fn observe(&mut self, outcome: &Result<Reply, MasterError>) -> Option<Option<String>> {
        let seen = &mut self.seen;
        match outcome {
            Ok(Reply::Exception(exception)) => {
                let code = exception.code;
                let counted = self
                    .rule
                    .conditions
                    .contains(&SwitchCondition::Exception(code));
                if !counted {
                    // The device answered: the path works.
                    *seen = Seen::default();
                    return None;
                }
                if !seen.exceptions.contains(&code) {
                    seen.exceptions.push(code);
                }
            }
            Ok(_) => {
                *seen = Seen::default();
                return None;
            }
            Err(MasterError::Timeout { .. } | MasterError::OutOfStep { .. }) => seen.timeouts += 1,
            Err(MasterError::BadFrame { .. }) => seen.bad_frames += 1,
            Err(MasterError::Io(error)) => seen.disconnected = Some(error.to_string()),
            // Neither says anything of the path.
            Err(MasterError::Encode(_) | MasterError::Interrupted) => return None,
        }
        let held: Vec<String> = self
            .rule
            .conditions
            .iter()
            .filter_map(|condition| self.seen.holds(*condition))
            .collect();
        let enough = match self.rule.when {
            SwitchWhen::Any => !held.is_empty(),
            SwitchWhen::All => held.len() == self.rule.conditions.len(),
        };
        Some(enough.then(|| held.join(" and ")))
    }
}

impl Seen {
    /// What `condition` says has happened, when it holds.
    fn holds(&self, condition: SwitchCondition) -> Option<String> {
        match condition {
            SwitchCondition::Timeouts(n) if self.timeouts >= n => {
                Some(plural(self.timeouts, "timeout"))
            }
            SwitchCondition::BadFrames(n) if self.bad_frames >= n => {
                Some(plural(self.bad_frames, "bad frame"))
            }
            SwitchCondition::Exception(code) if self.exceptions.contains(&code) => {
                Some(format!("exception {:02X}", code.0))
            }
            SwitchCondition::Disconnect => {
                let why = self.disconnected.as_ref()?;
                Some(format!("disconnected ({why})"))
            }
            _ => None,
        }
    }
}

fn plural(n: u32, noun: &str) -> String {
    match n {
        1 => format!("1 {noun}"),
        n => format!("{n} {noun}s"),
    }
}

impl Master {
    /// This master, changing to the other path of `failover` when its rule holds.
    pub fn with_failover(mut self, failover: Failover) -> Master {
        self.failover = Some(Box::new(failover));
        self
    }

    /// This master, asking a failed request again on its path until the rule decides
    /// (for a command that ends at a failure, where a poll would ask again at its next
    /// interval), when `persistent` and there are two paths.
    pub fn persistent(mut self, persistent: bool) -> Master {
        if let Some(failover) = self.failover.as_mut() {
            failover.persistent = persistent;
        }
        self
    }

    /// The path in use, when there are two.
    pub fn path(&self) -> Option<PathName> {
        self.failover.as_ref().map(|failover| failover.on)
    }

    /// The changes of path made since last asked.
    pub fn take_switches(&mut self) -> Vec<Switch> {
        self.failover
            .as_mut()
            .map(|failover| std::mem::take(&mut failover.switches))
            .unwrap_or_default()
    }

    /// Weighs a transaction's outcome; when the rule holds and `may_switch`, changes to
    /// the other path and says so. A path that cannot be opened is no change: the one in
    /// use stays, and its count goes on.
    pub(super) fn weigh(
        &mut self,
        outcome: &Result<Reply, MasterError>,
        may_switch: bool,
    ) -> Weighed {
        let Some(mut failover) = self.failover.take() else {
            return Weighed::Nothing;
        };
        let weighed = match failover.observe(outcome) {
            None => Weighed::Nothing,
            Some(Some(why)) if may_switch => {
                let to = failover.on.other();
                match (failover.open)(to) {
                    Ok(mut other) => {
                        // The trace goes on across the change; the transaction ids too,
                        // so that a capture of both sides never sees one reused.
                        other.tracer = self.tracer.take();
                        other.transaction = self.transaction;
                        failover.on = to;
                        failover.seen = Seen::default();
                        failover.switches.push(Switch {
                            to,
                            why,
                            left: Left::of(outcome),
                        });
                        *self = other;
                        Weighed::Switched
                    }
                    Err(_) => Weighed::Counted,
                }
            }
            Some(_) => Weighed::Counted,
        };
        self.failover = Some(failover);
        weighed
    }

    /// Whether a request that failed `asked` times is asked again on the same path.
    pub(super) fn asks_again(&self, asked: u32) -> bool {
        self.failover
            .as_ref()
            .is_some_and(|failover| failover.asks_again(asked))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conditions_read_as_written() {
        let parsed: Vec<_> = [
            "timeout:3",
            "bad-frame:2",
            "exception:0B",
            "disconnect",
            "exception:0x04",
        ]
        .iter()
        .map(|text| SwitchCondition::parse(text).unwrap())
        .collect();
        assert_eq!(
            parsed,
            [
                SwitchCondition::Timeouts(3),
                SwitchCondition::BadFrames(2),
                SwitchCondition::Exception(ExceptionCode(0x0B)),
                SwitchCondition::Disconnect,
                SwitchCondition::Exception(ExceptionCode(4)),
            ]
        );
        for bad in [
            "timeout",
            "timeout:0",
            "exception",
            "exception:GG",
            "disconnect:1",
            "noise:3",
        ] {
            assert!(SwitchCondition::parse(bad).is_err(), "{bad}");
        }
    }
}
