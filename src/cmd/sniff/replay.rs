//! Replaying a capture of a serial line from a file or standard input: with its timing,
//! the bytes handed over as the live session was handed them; without, framed by content
//! alone, a file on every core. The records are written on another thread as they are found.

use std::fs::File;
use std::io::{self, Read};
use std::path::Path;
use std::sync::{mpsc, Arc};
use std::thread;

use anyhow::{Context, Result};

use mbtool::connection::{line_at, line_settings, mode, Role};
use mbtool::error::Error;
use mbtool::settings::Settings;
use mbtool_core::codec::framing::{Ahead, Event, FoundAhead, Framer};
use mbtool_core::codec::Mode;
use mbtool_core::model::line::LineSettings;
use mbtool_core::sniff::session::{Record, Session};
use mbtool_core::sniff::timing;

use super::{Save, Sinks};

/// The timing file beside a capture, when there is one, read through once to check it: a
/// replay must not show frames and then find its timing bad. It is read again, an event
/// at a time, as the capture is replayed.
pub(super) fn replay_timing(path: &Path) -> Result<Option<TimingFile>> {
    let beside = timing::beside(path);
    if path.as_os_str() == "-" || !beside.exists() {
        return Ok(None);
    }
    // A directory or a FIFO of that name is no timing written by `--save`, and a FIFO
    // would hold the replay until someone writes to it.
    let is_file = std::fs::metadata(&beside)
        .with_context(|| format!("cannot read {}", beside.display()))?
        .is_file();
    if !is_file {
        return Err(Error::usage(format!(
            "{} is not a file, so no .timing file: move it away to replay without timing",
            beside.display()
        ))
        .into());
    }
    let mut timing = TimingFile {
        // The reads may not add up to more than the capture holds: a count that does is
        // a file written by someone else, and must not make the replay allocate it.
        capture_len: std::fs::metadata(path)
            .with_context(|| format!("cannot read {}", path.display()))?
            .len(),
        path: beside,
        line: None,
    };
    let mut events = timing.open()?;
    while timing.next(&mut events)?.is_some() {}
    timing.line = events.recorded_line();
    if let Some(line) = events.cut_off() {
        mbtool::note!(
            "mbtool: {}:{line} is cut off before its end (the capture was stopped as it was \
             written): replaying the capture with the timing before it",
            timing.path.display()
        );
    }
    Ok(Some(timing))
}

/// The mode and line the bytes were sent on: as the options give them, but for a capture
/// whose `timing` file records the line it was taken on, which a replay takes (so that a
/// silence is what it was live) save where an option is typed (or set in the
/// environment), and then says so.
pub(super) fn sniffed_line(
    settings: &Settings,
    timing: Option<&TimingFile>,
) -> Result<(Mode, LineSettings)> {
    let options = &settings.connection;
    let Some((timing, recorded)) = timing.and_then(|timing| Some((timing, timing.line?))) else {
        let mode = mode(options, None, Role::Sniff)?;
        let line = line_settings(options, mode);
        if let Some(timing) = timing.filter(|_| !options.baud_given && !options.parity_given) {
            mbtool::note!(
                "mbtool: {} does not say which line the capture was taken on: replaying it as \
                 {}; give -b and --parity if it was another",
                timing.path.display(),
                timing::RecordedLine::of(mode, &line)
            );
        }
        return Ok((mode, line));
    };
    let mode = match options.mode {
        Some(_) => mode(options, None, Role::Sniff)?,
        None => recorded.mode,
    };
    let baud = match options.baud_given {
        true => options.baud(),
        false => recorded.baud,
    };
    let parity = match options.parity_given {
        true => options.parity(),
        false => recorded.parity,
    };
    // The character as recorded, unless the mode or the parity given changes it: then the
    // data and stop bits that go with those, as on a port.
    let mut line = line_at(options, mode, baud, parity);
    if options.data_bits.is_none() && mode == recorded.mode {
        line.data_bits = recorded.data_bits;
    }
    if options.stop_bits.is_none() && parity == recorded.parity {
        line.stop_bits = recorded.stop_bits;
    }
    let replayed = timing::RecordedLine::of(mode, &line);
    if replayed != recorded {
        mbtool::note!(
            "mbtool: {} records the line as {recorded}; replaying it as {replayed}, as the \
             options say",
            timing.path.display()
        );
    }
    Ok((mode, line))
}

/// A capture's timing file, and the length of the capture it times.
pub(super) struct TimingFile {
    path: std::path::PathBuf,
    capture_len: u64,
    /// The line the capture was taken on, when the file records it.
    line: Option<timing::RecordedLine>,
}

impl TimingFile {
    fn open(&self) -> Result<timing::Reader<io::BufReader<File>>> {
        let file = File::open(&self.path)
            .with_context(|| format!("cannot read {}", self.path.display()))?;
        Ok(timing::Reader::new(
            io::BufReader::new(file),
            self.capture_len,
        ))
    }

    /// The next event of `events`, its faults told as what to do.
    fn next(
        &self,
        events: &mut timing::Reader<io::BufReader<File>>,
    ) -> Result<Option<timing::Event>> {
        let path = self.path.display();
        events.next_event().map_err(|error| match error {
            timing::TimingError::Io(error) => {
                anyhow::Error::new(error).context(format!("cannot read {path}"))
            }
            timing::TimingError::NotText => Error::usage(format!(
                "{path} is not text, so no .timing file: move it away to replay without timing"
            ))
            .into(),
            timing::TimingError::Line { line, message } => Error::usage(format!(
                "{path}:{line}: {message}; move the file away to replay without timing"
            ))
            .into(),
        })
    }
}

/// How many batches of records may wait to be written while the next are framed.
const BATCHES_IN_FLIGHT: usize = 2;

/// How many records make a batch worth handing over: a timed replay frames a read at a
/// time, often a byte, and a hand-over per frame would cost more than the frame.
const BATCH: usize = 256;

/// The records a replay finds, handed over in batches to be written on another thread.
pub(super) struct Batches {
    records: Vec<Record>,
    to_write: mpsc::SyncSender<Vec<Record>>,
    written: mpsc::Receiver<Vec<Record>>,
}

impl Batches {
    /// Hands the records found so far over, once there are `at_least` of them (1 or more).
    fn hand_over(&mut self, at_least: usize) -> io::Result<()> {
        if self.records.len() < at_least.max(1) {
            return Ok(());
        }
        let empty = self.written.try_recv().unwrap_or_default();
        self.to_write
            .send(std::mem::replace(&mut self.records, empty))
            .map_err(|_| io::Error::other("the output stopped"))
    }

    /// Hands a batch over when there are enough records for one.
    fn found(&mut self) -> io::Result<()> {
        self.hand_over(BATCH)
    }
}

/// Runs a replay on a thread of its own while its records are written on this one: a
/// capture is framed and written at the pace of the slower of the two, not of both added
/// up. Written batches come back to be filled again, so that their memory is taken once.
/// When the output fails (a closed pipe), the replay stops at its next batch and the
/// output's error is the one told.
pub(super) fn write_alongside<T: Send>(
    sinks: &mut Sinks,
    replay: impl FnOnce(&mut Batches) -> Result<T> + Send,
) -> Result<T> {
    let (to_write, batches) = mpsc::sync_channel(BATCHES_IN_FLIGHT);
    let (give_back, written) = mpsc::channel();
    thread::scope(|scope| {
        let replaying = scope.spawn(move || {
            let mut found = Batches {
                records: Vec::new(),
                to_write,
                written,
            };
            let replayed = replay(&mut found);
            // What came before an error in the capture is shown all the same.
            found.hand_over(1)?;
            replayed
        });
        let mut written = Ok(());
        for mut batch in &batches {
            written = sinks.write(&mut batch);
            if written.is_err() {
                break;
            }
            // The replay may have ended and gone: then the batch is not needed.
            let _ = give_back.send(batch);
        }
        drop(batches);
        let replayed = replaying
            .join()
            .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
        written?;
        replayed
    })
}

/// A capture without timing: framed by content alone. Returns how many bytes it read.
pub(super) fn replay(
    input: &mut dyn Read,
    session: &mut Session,
    found: &mut Batches,
    save: &mut Option<Save>,
) -> Result<u64> {
    // A few kilobytes at a time, so that few records are alive at once: the frames of a
    // 64 kB read, written only after all of them were found, made the allocator give its
    // memory back and take it again, a page fault a page, for every read.
    let mut chunk = vec![0u8; 1 << 12];
    let mut read = 0;
    loop {
        let n = match input.read(&mut chunk) {
            Ok(0) => return Ok(read),
            Ok(n) => n,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e.into()),
        };
        if let Some(save) = save.as_mut() {
            save.bytes(&chunk[..n], None)?;
        }
        read += n as u64;
        session.push(&chunk[..n], &mut found.records);
        // A read short of the buffer is a pipe that had no more yet, maybe a live line:
        // what it brought is shown now, not once a batch has gathered.
        if n < chunk.len() {
            found.hand_over(1)?;
        } else {
            found.found()?;
        }
    }
}

/// How many bytes of a capture file are framed ahead at a time on another core: large
/// enough that starting a thread and catching up cost little beside them, small enough
/// that the frames of the blocks in flight stay in the cores' caches.
const AHEAD_BLOCK: usize = 1 << 16;

/// A block of a capture file to frame ahead, with a framer that starts where it does, a
/// vector to put its frames in (one read before, its memory kept: a block's frames fill
/// a megabyte, which would be mapped, zeroed and unmapped again for every block), and
/// where to hand what it found.
type AheadJob = (Framer, Arc<[u8]>, Vec<Event>, mpsc::SyncSender<Ahead>);

/// A capture file without timing, framed on every core: blocks are framed ahead by a
/// worker on every other core while this thread catches up with them (see
/// `Framer::catch_up`) and reads their frames, finding the same frames as [`replay`]
/// would. Returns how many bytes it read.
pub(super) fn replay_ahead(
    input: &mut dyn Read,
    session: &mut Session,
    found: &mut Batches,
    save: &mut Option<Save>,
) -> Result<u64> {
    let cores = thread::available_parallelism().map_or(1, |n| n.get());
    if cores < 2 {
        return replay(input, session, found, save);
    }
    let (jobs, queue) = mpsc::channel::<AheadJob>();
    let queue = std::sync::Mutex::new(queue);
    thread::scope(|scope| {
        // Owned here, so that it goes, and the workers with it, however this thread stops.
        let jobs = jobs;
        for _ in 1..cores {
            let queue = &queue;
            scope.spawn(move || loop {
                // Whoever holds the queue waits for the next block; the others wait for it.
                let job = queue.lock().map(|queue| queue.recv());
                let Ok(Ok((framer, block, events, done))) = job else {
                    return;
                };
                // This thread may have stopped (the output closed): then nobody waits.
                let _ = done.send(framer.frame_ahead(&block, events));
            });
        }
        let replayed = read_ahead(input, session, found, save, &jobs, cores - 1);
        // The workers end once no more blocks can come.
        drop(jobs);
        replayed
    })
}

/// The reading side of [`replay_ahead`]: blocks handed to `workers` workers through
/// `jobs`, taken back in order. Of every few blocks this thread frames one itself, in
/// order, so that it works while the workers do: reading a frame costs about a third of
/// framing it, so with one worker it frames one block in three, with more fewer. While most
/// frames are shown, the writer needs a core of its own, and one worker fewer frames ahead.
/// Where a block framed ahead was never met (traffic whose frames read both ways, such as
/// echoed writes, leaves a framer that started without the conversation out of its turn;
/// garbage holds no frame to meet at), the next blocks are framed in order: one, then two,
/// then four, up to 64 while it goes on.
fn read_ahead(
    input: &mut dyn Read,
    session: &mut Session,
    found: &mut Batches,
    save: &mut Option<Save>,
    jobs: &mpsc::Sender<AheadJob>,
    workers: usize,
) -> Result<u64> {
    let mut in_flight = std::collections::VecDeque::new();
    let mut read = 0u64;
    let mut blocks = 0usize;
    let mut ended = false;
    let mut writer_busy = false;
    let mut in_order_for = 0usize;
    let mut missed = 0u32;
    let mut events = Vec::new();
    let mut read_already: Vec<Vec<Event>> = Vec::new();
    loop {
        let framing_ahead = if writer_busy { workers - 1 } else { workers };
        let cycle = framing_ahead * framing_ahead + 2;
        while !ended && in_flight.len() < 2 * cycle {
            let block = read_block(input)?;
            if block.is_empty() {
                ended = true;
                break;
            }
            if let Some(save) = save.as_mut() {
                save.bytes(&block, None)?;
            }
            let block: Arc<[u8]> = block.into();
            // The first block is framed in order: there is nothing before it to catch up
            // with.
            let in_order = in_order_for > 0 || framing_ahead == 0 || blocks % cycle == 0;
            in_order_for = in_order_for.saturating_sub(1);
            let ahead = (!in_order).then(|| {
                let (done, ahead) = mpsc::sync_channel(1);
                let job = (
                    session.framer_ahead(read),
                    Arc::clone(&block),
                    read_already.pop().unwrap_or_default(),
                    done,
                );
                // No worker left to take it (none can go, short of a panic): in order.
                jobs.send(job).is_ok().then_some(ahead)
            });
            read += block.len() as u64;
            blocks += 1;
            in_flight.push_back((block, ahead.flatten()));
        }
        let Some((block, ahead)) = in_flight.pop_front() else {
            return Ok(read);
        };
        let mut shown = 0;
        // A block whose worker is gone (it cannot be, short of a panic) is framed here.
        match ahead.and_then(|ahead| ahead.recv().ok()) {
            Some(ahead) => {
                let found_ahead = session.catch_up(&block, ahead, &mut events);
                if found_ahead.is_some() {
                    missed = 0;
                } else {
                    in_order_for = 1 << missed.min(6);
                    missed += 1;
                }
                shown += read_batches(session, found, events.drain(..))?;
                if let Some(FoundAhead {
                    events: mut found_ahead,
                    from,
                }) = found_ahead
                {
                    shown += read_batches(session, found, found_ahead.drain(from..))?;
                    read_already.push(found_ahead);
                }
            }
            None => {
                for piece in block.chunks(1 << 12) {
                    let before = found.records.len();
                    session.push(piece, &mut found.records);
                    shown += found.records.len() - before;
                    found.found()?;
                }
            }
        }
        // A record in 16 bytes or more keeps a writer busy: every frame of a busy line.
        writer_busy = shown * 16 > block.len();
    }
}

/// Reads `events` a batch at a time, so that few records are alive at once. Returns how
/// many records they gave.
fn read_batches(
    session: &mut Session,
    found: &mut Batches,
    mut events: impl ExactSizeIterator<Item = Event>,
) -> io::Result<usize> {
    let mut shown = 0;
    while events.len() > 0 {
        let before = found.records.len();
        session.read_framed(events.by_ref().take(BATCH), &mut found.records);
        shown += found.records.len() - before;
        found.found()?;
    }
    Ok(shown)
}

/// The next block of a capture file, as long as [`AHEAD_BLOCK`] unless the file ends first
/// (empty at its end).
fn read_block(input: &mut dyn Read) -> io::Result<Vec<u8>> {
    let mut block = Vec::with_capacity(AHEAD_BLOCK);
    input.take(AHEAD_BLOCK as u64).read_to_end(&mut block)?;
    Ok(block)
}

/// A capture with its timing: the bytes are given to the session exactly as the live
/// session was given them, so the same frames come out. Returns the time of the timing's
/// last event, when the capture ended.
pub(super) fn replay_timed(
    input: &mut dyn Read,
    timing: &TimingFile,
    session: &mut Session,
    found: &mut Batches,
    save: &mut Option<Save>,
) -> Result<Option<u64>> {
    let mut events = timing.open()?;
    let mut chunk = Vec::new();
    while let Some(event) = timing.next(&mut events)? {
        match event {
            timing::Event::Bytes { time, count } => {
                chunk.resize(count, 0);
                input.read_exact(&mut chunk).map_err(|_| {
                    Error::usage(
                        "the capture is shorter than its .timing file says: move the .timing file away to replay without timing",
                    )
                })?;
                if let Some(save) = save.as_mut() {
                    save.bytes(&chunk, None)?;
                }
                session.push_at(&chunk, time, &mut found.records);
            }
            timing::Event::Idle { time } => {
                session.idle(time, &mut found.records);
            }
            // The capture ended there, as the live session was told: nothing else to do.
            timing::Event::End { .. } => {}
        }
        found.found()?;
    }
    // Bytes the timing does not cover (a capture appended to later) come untimed.
    let untimed = replay(input, session, found, save)?;
    if untimed > 0 {
        mbtool::note!(
            "mbtool: the .timing file covers the capture's first {} bytes; the last {untimed} are framed without timing",
            events.covered()
        );
    }
    Ok(events.last_time())
}
