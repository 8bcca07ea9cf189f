//! The worker of one port: it opens the port, waits for each device's next poll (or for a
//! write handed over), and hands each poll to the writer of rows.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::sync::Arc;
use std::time::{Duration, Instant, SystemTime};

use mbtool::connection::Connector;
use mbtool_core::codec::Request;
use mbtool_core::master::plant::{Polled, Port, Wake};
use mbtool_core::master::Master;

/// A write asked of a device of the port: its index on the port, the request, and how
/// to name it in what is told (`meter1: setpoint=25`).
pub(super) struct Write {
    pub device: usize,
    pub request: Request,
    pub said: String,
}

pub(super) struct Worker<'a> {
    pub connector: &'a Connector,
    pub verbose: bool,
    /// Set when polling ends (a signal, --for): a wait for an answer over TCP ends too.
    pub ending: Arc<AtomicBool>,
    /// Each device's index in the plant, by its index on the port.
    pub members: &'a [usize],
    pub polls: mpsc::Sender<(usize, Polled, SystemTime)>,
    pub writes: mpsc::Receiver<Write>,
    /// How the write being sent is told.
    pub writing: String,
}

/// How often a waiting worker looks whether polling should end.
const LOOK: Duration = Duration::from_millis(50);

impl Worker<'_> {
    /// Polls until polling ends; a write handed over that was not sent is told.
    pub fn run(mut self, devices: &[mbtool_core::master::plant::Scheduled], max: Option<u16>) {
        mbtool_core::master::plant::keep_read(&mut self, devices, max);
        for write in self.writes.try_iter() {
            mbtool::note!("mbtool: {} not written: polling ended first", write.said);
        }
    }
}

impl Port for Worker<'_> {
    type Refusal = anyhow::Error;

    fn connect(&mut self) -> anyhow::Result<Master> {
        let connection = self.connector.connect()?;
        let mut master = connection.master;
        master.stop_on(Arc::clone(&self.ending));
        if self.verbose {
            master.trace(super::super::shared::tracer(self.connector.mode));
        }
        Ok(master)
    }

    fn wait(&mut self, time: Duration) -> Wake {
        let until = Instant::now() + time;
        loop {
            let now = Instant::now();
            if self.ending.load(Ordering::SeqCst) {
                return Wake::Stop;
            }
            if now >= until {
                return Wake::Due;
            }
            match self.writes.recv_timeout((until - now).min(LOOK)) {
                Ok(write) => {
                    self.writing = write.said;
                    return Wake::Write {
                        device: write.device,
                        request: write.request,
                    };
                }
                Err(RecvTimeoutError::Timeout) => {}
                // No one writes (no MQTT): the time is slept in steps.
                Err(RecvTimeoutError::Disconnected) => {
                    std::thread::sleep((until - now).min(LOOK));
                }
            }
        }
    }

    fn polled(&mut self, polled: Polled) {
        let device = self.members[polled.device];
        let _ = self.polls.send((device, polled, SystemTime::now()));
    }

    fn wrote(&mut self, _: usize, _: &Request, outcome: Result<(), String>) {
        match outcome {
            Ok(()) => mbtool::note!("mbtool: {} written", self.writing),
            Err(why) => mbtool::note!("mbtool: {} not written: {why}", self.writing),
        }
    }
}
