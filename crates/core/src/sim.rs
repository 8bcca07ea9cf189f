//! `--port sim`: the simulated slave, in process. Requests go through the codec both ways,
//! as they would on a wire.

use std::io;
use std::time::Instant;

use crate::codec::adu::wrap;
use crate::codec::framing::{Event, Framer};
use crate::codec::Mode;
use crate::server::request_in;
use crate::slave::{DataModel, Slave};
use crate::transport::Transport;

/// The slave id of the built-in slave, as in the manuals' examples.
pub const SIM_SLAVE: u8 = 17;

pub struct SimTransport {
    slave: Slave,
    mode: Mode,
    pending: Vec<u8>,
}

impl SimTransport {
    pub fn new(mode: Mode) -> Self {
        Self {
            slave: Slave::new(&[SIM_SLAVE], DataModel::manual_examples()),
            mode,
            pending: Vec::new(),
        }
    }
}

impl Transport for SimTransport {
    fn discard_input(&mut self) -> io::Result<()> {
        self.pending.clear();
        Ok(())
    }

    fn send(&mut self, frame: &[u8]) -> io::Result<()> {
        // Framed as a slave on a line frames it: a sound frame with a bad PDU gets an
        // exception, a broken frame no answer.
        let mut framer = Framer::new(self.mode, 0.0, 0);
        let mut events = Vec::new();
        framer.push(frame, &mut events);
        framer.finish(&mut events);
        for event in events {
            let Event::Frame(found) = event else { continue };
            let Some(frame) = request_in(self.mode, &found) else {
                continue;
            };
            if let crate::codec::Pdu::Request(request) = &frame.pdu {
                if let Some(answer) = self.slave.handle(frame.slave, request) {
                    let mut pdu = Vec::new();
                    if answer.encode(&mut pdu).is_ok() {
                        wrap(
                            self.mode,
                            frame.slave,
                            frame.transaction,
                            &pdu,
                            &mut self.pending,
                        );
                    }
                }
            }
        }
        Ok(())
    }

    /// What the slave answered; nothing else will ever come, so no waiting.
    fn receive(&mut self, buf: &mut Vec<u8>, _deadline: Instant) -> io::Result<usize> {
        let n = self.pending.len();
        buf.append(&mut self.pending);
        Ok(n)
    }

    fn is_serial_line(&self) -> bool {
        false
    }
}
