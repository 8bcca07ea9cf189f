//! Standard input that a signal ends.

use std::io::{self, Read};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::thread;
use std::time::Duration;

/// Standard input that ends, as at the end of the input, on Ctrl-C or SIGTERM: `--input -`
/// may be a line being captured by another program (`socat ... | mbtool sniff --input -`),
/// and then ends as a live capture does, its frames and the summary shown. The reads
/// happen on a thread of their own, since a read from a quiet pipe would not return for
/// the signal.
pub struct StoppableStdin {
    chunks: mpsc::Receiver<io::Result<Vec<u8>>>,
    stop: Arc<AtomicBool>,
    /// What is left of the last chunk.
    pending: Vec<u8>,
    at: usize,
}

impl StoppableStdin {
    pub fn new(stop: Arc<AtomicBool>) -> Self {
        let (send, chunks) = mpsc::sync_channel(4);
        thread::spawn(move || {
            let mut stdin = io::stdin().lock();
            loop {
                let mut chunk = vec![0u8; 1 << 16];
                let read = match stdin.read(&mut chunk) {
                    Ok(n) => {
                        chunk.truncate(n);
                        Ok(chunk)
                    }
                    Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                    Err(e) => Err(e),
                };
                let end = !matches!(&read, Ok(chunk) if !chunk.is_empty());
                if send.send(read).is_err() || end {
                    return;
                }
            }
        });
        Self {
            chunks,
            stop,
            pending: Vec::new(),
            at: 0,
        }
    }
}

impl Read for StoppableStdin {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        while self.at == self.pending.len() {
            if self.stop.load(Ordering::SeqCst) {
                return Ok(0);
            }
            match self.chunks.recv_timeout(Duration::from_millis(50)) {
                Ok(chunk) => {
                    self.pending = chunk?;
                    self.at = 0;
                    if self.pending.is_empty() {
                        return Ok(0);
                    }
                }
                Err(mpsc::RecvTimeoutError::Timeout) => {}
                Err(mpsc::RecvTimeoutError::Disconnected) => return Ok(0),
            }
        }
        let n = buf.len().min(self.pending.len() - self.at);
        buf[..n].copy_from_slice(&self.pending[self.at..self.at + n]);
        self.at += n;
        Ok(n)
    }
}
