//! How long a master waits for an answer, for every command in one place: the timeout a
//! command waits unless one is given, a scan's at each setting of its sweep, and the
//! longer waits a scan gives answers heard late.

use std::time::Duration;

use crate::model::line::LineSettings;

/// A request's answer, unless `--timeout` says.
pub const ANSWER: Duration = Duration::from_secs(1);

/// A scan's: it asks many ids that are not there.
pub const SCAN: Duration = Duration::from_millis(100);

/// A gateway's: it answers 0B for a device that is silent before its client's own timeout
/// (mbpoll's and most masters' is 1 s) runs out.
pub const GATEWAY: Duration = Duration::from_millis(800);

/// A scan's at a setting of its sweep: `timeout` as given, or, as the default, after the
/// answer of `answer_bytes` has had time to travel at that baud rate, so that slow lines
/// are not taken for silent ones.
pub fn at_line(timeout: Duration, given: bool, line: &LineSettings, answer_bytes: u32) -> Duration {
    match given {
        true => timeout,
        false => timeout + line.character_time() * answer_bytes,
    }
}

/// How long the first id that times out over TCP is given when asked again: a gateway
/// waits this long or less for a unit id behind it that does not answer (mbusd and
/// mbtool's gateway 1 s, most others less).
pub(crate) const GATEWAY_PATIENCE: Duration = Duration::from_secs(3);

/// How long a slave heard answering late is given when it is asked again: ten timeouts,
/// and a second at least.
pub(crate) fn late(timeout: Duration) -> Duration {
    (timeout * 10).max(Duration::from_secs(1))
}

/// How long the line must be quiet after a scan whose last id was silent before it ends:
/// three timeouts and half a second at least (a late answer is late by a fraction of a
/// second: a slow gateway or device), and with a long timeout one second more than it.
pub(crate) fn straggler(timeout: Duration) -> Duration {
    (timeout * 3)
        .max(Duration::from_millis(500))
        .min(timeout + Duration::from_secs(1))
}
