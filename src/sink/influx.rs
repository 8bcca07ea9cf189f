//! Rows as InfluxDB line protocol, written to an InfluxDB server over HTTP: the 1.x
//! `/write?db=NAME` API as the URL gives it. Batches of at most 5000 lines; a server that
//! is down or refuses is asked again, waiting longer each time up to 10 s, the rows kept in
//! the buffer meanwhile.

use std::time::{Duration, Instant};

use super::{Buffer, Delivered};

/// Lines a request carries at most, as InfluxDB advises.
const BATCH: usize = 5000;

/// How long a request may take.
const REQUEST_TIMEOUT: Duration = Duration::from_secs(5);

/// The longest wait before asking a server that failed again.
const LONGEST_WAIT: Duration = Duration::from_secs(10);

/// How long the rows left at the end are tried for, with a server that is down.
const LAST_TRY: Duration = Duration::from_secs(3);

/// Checks the URL of `--influx`: `http://HOST:PORT/write?db=NAME` (or https://).
pub fn check_url(url: &str) -> Result<(), String> {
    let scheme = url.starts_with("http://") || url.starts_with("https://");
    if !scheme || !url.contains("/write?") || !url.contains("db=") {
        return Err(format!(
            "--influx {url}: give the server's write URL, http://HOST:8086/write?db=NAME"
        ));
    }
    Ok(())
}

/// Sends the buffer's rows to `url` until the buffer is closed and empty (or its last rows
/// could not be sent within a few seconds); `tell` is told when the server goes down and
/// comes back.
pub fn send(url: &str, buffer: &Buffer<String>, tell: impl Fn(&str)) -> Delivered {
    let config = ureq::Agent::config_builder()
        .timeout_global(Some(REQUEST_TIMEOUT))
        .build();
    let agent: ureq::Agent = config.into();
    let mut delivered = Delivered::default();
    let mut wait = Duration::from_millis(250);
    let mut down_since: Option<Instant> = None;
    let mut closed_at: Option<Instant> = None;
    loop {
        let (rows, closing) = buffer.oldest(BATCH, Duration::from_secs(1));
        if closing {
            closed_at.get_or_insert_with(Instant::now);
        }
        if rows.is_empty() {
            if closing {
                break;
            }
            continue;
        }
        let body = rows.join("\n") + "\n";
        match agent.post(url).send(body.as_bytes()) {
            Ok(_) => {
                buffer.sent(rows.len());
                delivered.sent += rows.len() as u64;
                wait = Duration::from_millis(250);
                if down_since.take().is_some() {
                    tell(&format!("InfluxDB at {url} takes rows again"));
                }
            }
            // A server that refuses the rows themselves (a field of another type than
            // before, a database that is not there) would refuse them again: they are
            // dropped, counted and told.
            Err(ureq::Error::StatusCode(code)) if (400..500).contains(&code) => {
                buffer.sent(rows.len());
                delivered.refused += rows.len() as u64;
                tell(&format!(
                    "InfluxDB at {url} refused {} with status {code}",
                    crate::output::plural(rows.len(), "row")
                ));
            }
            Err(error) => {
                if down_since.is_none() {
                    down_since = Some(Instant::now());
                    tell(&format!(
                        "InfluxDB at {url} does not take rows ({error}); keeping them to send when it does"
                    ));
                }
                if closed_at.is_some_and(|at| at.elapsed() >= LAST_TRY) {
                    break;
                }
                std::thread::sleep(wait);
                // At the end the rows left are tried again soon, for a few seconds.
                let longest = match closed_at {
                    Some(_) => Duration::from_millis(500),
                    None => LONGEST_WAIT,
                };
                wait = (wait * 2).min(longest);
            }
        }
    }
    let (dropped, unsent) = buffer.counts();
    delivered.dropped = dropped;
    delivered.unsent = unsent;
    delivered
}
