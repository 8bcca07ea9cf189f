//! A serial line captured live: every read handed to the session with its time, and the
//! silences the framer needs to see told to it.

use std::io;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use crate::transport::Transport;

use super::replay::RecordSink;
use super::session::Session;
use super::timing::Saver;

/// How long a read waits for bytes: the longest a silence goes untold, and a stop unseen.
const READ_FOR: Duration = Duration::from_millis(20);

/// Listens on `port` until `stop`, handing its records to `sink` and its bytes to `save`;
/// `bursts` is called once the bytes are seen to come in bursts (a USB adapter's latency
/// timer), which hides the gaps between frames. Returns when the capture ended, in
/// microseconds from its start.
pub fn listen(
    port: &mut dyn Transport,
    session: &mut Session,
    sink: &mut dyn RecordSink,
    mut save: Option<&mut Saver>,
    stop: &AtomicBool,
    mut bursts: impl FnMut(),
) -> io::Result<u64> {
    let start = Instant::now();
    let mut bytes = Vec::with_capacity(4096);
    let mut records = Vec::new();
    let mut told = false;
    while !stop.load(Ordering::SeqCst) {
        bytes.clear();
        let n = port.receive(&mut bytes, Instant::now() + READ_FOR)?;
        let now = start.elapsed().as_micros() as u64;
        if n > 0 {
            if let Some(save) = save.as_mut() {
                save.bytes(&bytes, Some(now))?;
            }
            session.push_at(&bytes, now, &mut records);
        } else if session.idle(now, &mut records) {
            // Only the calls that told the framer something: a replay repeats them.
            if let Some(save) = save.as_mut() {
                save.idle(now)?;
            }
        }
        sink.write(&mut records)?;
        if session.behind_latency_timer && !told {
            told = true;
            bursts();
        }
    }
    let end = start.elapsed().as_micros() as u64;
    if let Some(save) = save.as_mut() {
        save.end(end)?;
    }
    Ok(end)
}
