//! `--port sim`: the simulated slave, in process. Requests go through the codec both ways,
//! as they would on a wire, and are answered by the answer path of `serve`.

use std::io;
use std::time::Instant;

use crate::codec::Mode;
use crate::slave::faults::FaultInjection;
use crate::slave::server::Server;
use crate::slave::{DataModel, Slave, EXAMPLE_SLAVE};
use crate::transport::Transport;

/// The slave id of the built-in slave, as in the manuals' examples.
pub const SIM_SLAVE: u8 = EXAMPLE_SLAVE;

/// The built-in slave as a transport: a request sent is answered at once, in process.
pub struct SimTransport {
    server: Server,
    /// No faults are injected, so nothing is drawn from it; the answer path asks for one.
    rng: fastrand::Rng,
    pending: Vec<u8>,
}

impl SimTransport {
    /// The sim, framing as `mode` does, holding the manuals' example data.
    pub fn new(mode: Mode) -> Self {
        Self::standing_in_for(mode, Slave::new(&[SIM_SLAVE], DataModel::manual_examples()))
    }

    /// The sim standing in for `slave`: a device for the tests of what reads one.
    pub(crate) fn standing_in_for(mode: Mode, slave: Slave) -> Self {
        Self {
            server: Server::new(slave, FaultInjection::default(), mode, 0, None),
            rng: fastrand::Rng::with_seed(0),
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
        // Each send is one whole frame: a sound frame with a bad PDU gets an exception, a
        // broken frame no answer.
        if let Some(answer) = self.server.answer_frame(frame, "sim", &mut self.rng) {
            self.pending.extend(answer);
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
