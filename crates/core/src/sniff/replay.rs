//! A capture of a serial line replayed from a file or a pipe: with its timing, the bytes
//! handed to the session as the live session was handed them; without, framed by content
//! alone, a file on every core (blocks framed ahead by workers, caught up with in order).
//! A packet capture (pcap, pcapng) is read through a TCP session.
//! The frames are handed to a [`RecordSink`] on the caller's thread, in batches, while the
//! replay goes on on another: framing and writing run side by side.

use std::fs::File;
use std::io::{self, Read};
use std::path::{Path, PathBuf};
use std::sync::{mpsc, Arc};
use std::thread;

use crate::codec::framing::{Ahead, Event, FoundAhead, Framer};

use super::capture::{read_packets, CaptureError};
use super::session::{Record, Session};
use super::tcp::TcpSession;
use super::timing;

/// Where the records of a replay go, a batch at a time: the batch is left empty.
pub trait RecordSink {
    /// Writes `records` and clears them.
    fn write(&mut self, records: &mut Vec<Record>) -> io::Result<()>;
}

/// What stopped a replay.
#[derive(Debug, thiserror::Error)]
pub enum ReplayError {
    /// The capture could not be read.
    #[error(transparent)]
    Capture(io::Error),
    /// The sink could not write (a closed pipe, a full disk).
    #[error(transparent)]
    Output(io::Error),
    /// The timing file beside the capture is not one.
    #[error("{path}: {fault}")]
    Timing {
        /// The timing file.
        path: PathBuf,
        /// What is wrong with it.
        fault: TimingFault,
    },
    /// The capture holds fewer bytes than its timing file gives reads.
    #[error("the capture is shorter than its .timing file says")]
    ShorterThanTiming,
}

/// What is wrong with a timing file.
#[derive(Debug, thiserror::Error)]
pub enum TimingFault {
    /// A directory or a FIFO of the name (a FIFO would hold the replay until written to).
    #[error("not a file")]
    NotAFile,
    /// It could not be read, or what it holds is no timing.
    #[error(transparent)]
    Read(#[from] timing::TimingError),
}

/// A capture's timing file, read through once when opened: a replay must not show frames
/// and then find its timing bad. It is read again, an event at a time, as the capture is
/// replayed.
pub struct TimingFile {
    path: PathBuf,
    capture_len: u64,
    line: Option<timing::RecordedLine>,
    cut_off: Option<usize>,
}

impl TimingFile {
    /// The timing file beside the capture at `capture`, when there is one.
    pub fn beside(capture: &Path) -> Result<Option<TimingFile>, ReplayError> {
        let path = timing::beside(capture);
        if capture.as_os_str() == "-" || !path.exists() {
            return Ok(None);
        }
        let fault = |fault| ReplayError::Timing {
            path: path.clone(),
            fault,
        };
        if !std::fs::metadata(&path)
            .map_err(|e| fault(TimingFault::Read(timing::TimingError::Io(e))))?
            .is_file()
        {
            return Err(fault(TimingFault::NotAFile));
        }
        // The reads may not add up to more than the capture holds: a count that does is
        // a file written by someone else, and must not make the replay allocate it.
        let capture_len = std::fs::metadata(capture)
            .map_err(ReplayError::Capture)?
            .len();
        let mut file = TimingFile {
            path: path.clone(),
            capture_len,
            line: None,
            cut_off: None,
        };
        let mut events = file.open()?;
        while file.next(&mut events)?.is_some() {}
        file.line = events.recorded_line();
        file.cut_off = events.cut_off();
        Ok(Some(file))
    }

    /// Where it is.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The line the capture was taken on, when the file records it.
    pub fn line(&self) -> Option<timing::RecordedLine> {
        self.line
    }

    /// The number of its last line, when that line was cut off (the capture stopped as it
    /// was written) and is passed over.
    pub fn cut_off(&self) -> Option<usize> {
        self.cut_off
    }

    fn open(&self) -> Result<timing::Reader<io::BufReader<File>>, ReplayError> {
        let file = File::open(&self.path)
            .map_err(|e| self.fault(TimingFault::Read(timing::TimingError::Io(e))))?;
        Ok(timing::Reader::new(
            io::BufReader::new(file),
            self.capture_len,
        ))
    }

    fn fault(&self, fault: TimingFault) -> ReplayError {
        ReplayError::Timing {
            path: self.path.clone(),
            fault,
        }
    }

    fn next(
        &self,
        events: &mut timing::Reader<io::BufReader<File>>,
    ) -> Result<Option<timing::Event>, ReplayError> {
        events
            .next_event()
            .map_err(|error| self.fault(TimingFault::Read(error)))
    }
}

/// How a capture is framed.
pub enum Pace<'a> {
    /// With its timing.
    Timed(&'a TimingFile),
    /// By content alone, as it comes (a pipe, maybe a live line).
    AsItComes,
    /// By content alone, a file on every core.
    Ahead,
}

/// How a replay ended.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Replayed {
    /// How many bytes of the capture were read.
    pub bytes: u64,
    /// With timing: the time of its last event, when the capture ended.
    pub end: Option<u64>,
    /// With timing: the bytes at the capture's end that its timing does not cover (a
    /// capture appended to later), framed without timing.
    pub untimed: u64,
}

/// Replays the capture `input` through `session` at `pace`, handing the records to `sink`
/// on this thread while the framing goes on on another. When the sink fails (a closed
/// pipe), the replay stops at its next batch and the sink's error is the one told.
pub fn replay(
    input: &mut (dyn Read + Send),
    pace: Pace<'_>,
    session: &mut Session,
    sink: &mut dyn RecordSink,
) -> Result<Replayed, ReplayError> {
    write_alongside(sink, |found| match pace {
        Pace::Timed(timing) => replay_timed(input, timing, session, found),
        Pace::AsItComes => Ok(Replayed {
            bytes: replay_as_it_comes(input, session, found)?,
            ..Replayed::default()
        }),
        Pace::Ahead => Ok(Replayed {
            bytes: replay_ahead(input, session, found)?,
            ..Replayed::default()
        }),
    })
}

/// Replays the pcap or pcapng capture `input` through `session`, handing the records to
/// `sink` on this thread while the packets are read, reassembled and framed on another.
/// `as_it_comes`: the capture may be another program's live one (`tcpdump -w -` piped in),
/// and each packet's records are handed over at once, not in batches. Returns how many
/// packets were read, or why the capture could not be read on (the records before that
/// are written); when the sink fails, the replay stops at its next batch and the sink's
/// error is the one told.
pub fn replay_packets(
    input: impl Read + Send,
    as_it_comes: bool,
    session: &mut TcpSession,
    sink: &mut dyn RecordSink,
) -> Result<Result<u64, CaptureError>, ReplayError> {
    let batch = if as_it_comes { 1 } else { BATCH };
    write_alongside(sink, |found| {
        let mut handed = Ok(());
        let read = read_packets(input, |packet| {
            session.packet(&packet, &mut found.records);
            handed = found.hand_over(batch);
            handed.is_ok()
        });
        handed.map(|()| read)
    })
}

/// How many batches of records may wait to be written while the next are framed.
const BATCHES_IN_FLIGHT: usize = 2;

/// How many records make a batch worth handing over: a timed replay frames a read at a
/// time, often a byte, and a hand-over per frame would cost more than the frame.
const BATCH: usize = 256;

/// The records a replay finds, handed over in batches to be written on another thread.
struct Batches {
    records: Vec<Record>,
    to_write: mpsc::SyncSender<Vec<Record>>,
    written: mpsc::Receiver<Vec<Record>>,
}

impl Batches {
    /// Hands the records found so far over, once there are `at_least` of them (1 or more).
    /// An error is the writer gone: its own error is the one told.
    fn hand_over(&mut self, at_least: usize) -> Result<(), ReplayError> {
        if self.records.len() < at_least.max(1) {
            return Ok(());
        }
        let empty = self.written.try_recv().unwrap_or_default();
        self.to_write
            .send(std::mem::replace(&mut self.records, empty))
            .map_err(|_| ReplayError::Output(io::Error::other("the output stopped")))
    }

    /// Hands a batch over when there are enough records for one.
    fn found(&mut self) -> Result<(), ReplayError> {
        self.hand_over(BATCH)
    }
}

/// Runs a replay on a thread of its own while its records are written on this one: a
/// capture is framed and written at the pace of the slower of the two, not of both added
/// up. Written batches come back to be filled again, so that their memory is taken once.
/// When the output fails (a closed pipe), the replay stops at its next batch and the
/// output's error is the one told.
fn write_alongside<T: Send>(
    sink: &mut dyn RecordSink,
    replay: impl FnOnce(&mut Batches) -> Result<T, ReplayError> + Send,
) -> Result<T, ReplayError> {
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
            written = sink.write(&mut batch);
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
        written.map_err(ReplayError::Output)?;
        replayed
    })
}

/// A capture without timing: framed by content alone. Returns how many bytes it read.
fn replay_as_it_comes(
    input: &mut dyn Read,
    session: &mut Session,
    found: &mut Batches,
) -> Result<u64, ReplayError> {
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
            Err(e) => return Err(ReplayError::Capture(e)),
        };
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
/// enough that handing a block over and catching up with it cost little beside framing
/// it (on a real recording filtered, blocks of 64 kB took a sixth longer than these), small
/// enough that the blocks in flight and their frames hold a few tens of megabytes (1 MB
/// blocks were no quicker, and held over 100).
const AHEAD_BLOCK: usize = 1 << 18;

/// A block of a capture file to frame ahead, with a framer that starts where it does, a
/// vector to put its frames in (one read before, its memory kept: a block's frames fill
/// megabytes, which would be mapped, zeroed and unmapped again for every block), and
/// where to hand what it found.
type AheadJob = (Framer, Arc<[u8]>, Vec<Event>, mpsc::SyncSender<Ahead>);

/// A capture file without timing, framed on every core: blocks are framed ahead by a
/// worker on every other core while this thread catches up with them (see
/// `Framer::catch_up`) and reads their frames, finding the same frames as [`replay`]
/// would. Returns how many bytes it read.
fn replay_ahead(
    input: &mut (dyn Read + Send),
    session: &mut Session,
    found: &mut Batches,
) -> Result<u64, ReplayError> {
    let cores = thread::available_parallelism().map_or(1, |n| n.get());
    if cores < 2 {
        return replay_as_it_comes(input, session, found);
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
        let replayed = read_ahead(input, session, found, &jobs, cores - 1);
        // The workers end once no more blocks can come.
        drop(jobs);
        replayed
    })
}

/// The reading side of [`replay_ahead`]: blocks handed to `workers` workers through
/// `jobs`, taken back in order. Of every few blocks this thread frames one itself, in
/// order, so that it works while the workers do: reading a frame costs about a third of
/// framing it, so with one worker it frames one block in three, with more fewer; where the
/// blocks hold few frames (a noisy line), reading costs next to nothing, and it frames as
/// many blocks as a worker. While most frames are shown, the writer needs a core of its
/// own, and one worker fewer frames ahead.
/// Where a block framed ahead was never met (traffic whose frames read both ways, such as
/// echoed writes, leaves a framer that started without the conversation out of its turn;
/// garbage holds no frame to meet at), the next blocks are framed in order: one, then two,
/// then four, up to 64 while it goes on.
fn read_ahead(
    input: &mut dyn Read,
    session: &mut Session,
    found: &mut Batches,
    jobs: &mpsc::Sender<AheadJob>,
    workers: usize,
) -> Result<u64, ReplayError> {
    let mut in_flight = std::collections::VecDeque::new();
    let mut read = 0u64;
    let mut blocks = 0usize;
    let mut ended = false;
    // Until the first block shows how many of its frames are shown, the writer is taken to
    // be busy: blocks framed ahead then would take the core it needs.
    let mut writer_busy = true;
    let mut few_frames = false;
    let mut in_order_for = 0usize;
    let mut missed = 0u32;
    let mut events = Vec::new();
    let mut read_already: Vec<Vec<Event>> = Vec::new();
    loop {
        let framing_ahead = if writer_busy { workers - 1 } else { workers };
        let cycle = match few_frames {
            true => framing_ahead + 1,
            false => framing_ahead * framing_ahead + 2,
        };
        while !ended && in_flight.len() < 2 * cycle {
            let block = read_block(input).map_err(ReplayError::Capture)?;
            if block.is_empty() {
                ended = true;
                break;
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
                let mut framed = events.len();
                shown += read_batches(session, found, events.drain(..))?;
                if let Some(FoundAhead {
                    events: mut found_ahead,
                    from,
                }) = found_ahead
                {
                    framed += found_ahead.len() - from;
                    shown += read_batches(session, found, found_ahead.drain(from..))?;
                    read_already.push(found_ahead);
                }
                // Fewer than one frame or run of noise in 64 bytes.
                few_frames = framed * 64 < block.len();
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
) -> Result<usize, ReplayError> {
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
/// session was given them, so the same frames come out.
fn replay_timed(
    input: &mut dyn Read,
    timing: &TimingFile,
    session: &mut Session,
    found: &mut Batches,
) -> Result<Replayed, ReplayError> {
    let mut events = timing.open()?;
    let mut chunk = Vec::new();
    while let Some(event) = timing.next(&mut events)? {
        match event {
            timing::Event::Bytes { time, count } => {
                chunk.resize(count, 0);
                input
                    .read_exact(&mut chunk)
                    .map_err(|_| ReplayError::ShorterThanTiming)?;
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
    let untimed = replay_as_it_comes(input, session, found)?;
    Ok(Replayed {
        bytes: events.covered() + untimed,
        end: events.last_time(),
        untimed,
    })
}
