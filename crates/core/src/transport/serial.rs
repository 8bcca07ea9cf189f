//! A serial line (RS-485/RS-232 adapter, or a pseudo-terminal in tests).

use std::io::{self, Read, Write};
use std::time::{Duration, Instant};

use serialport::{ClearBuffer, SerialPort};

use super::rs485::KernelMode;
use super::{time_left, Transport};
use crate::model::line::{DirectionControl, LineSettings, Parity, RtsTiming};

/// A serial port as a transport.
pub struct Serial {
    /// Declared first, so that the kernel's RS-485 settings are put back while the port is
    /// still open.
    _kernel_mode: Option<KernelMode>,
    port: Box<dyn SerialPort>,
    /// RTS moved around each frame sent, when the transport toggles it itself.
    toggle: Option<RtsTiming>,
}

impl Serial {
    /// Opens the device at `path` with `settings`. A port that cannot switch its
    /// transceiver the way `settings.direction` asks is `Unsupported`, and nothing has
    /// been sent.
    pub fn open(path: &str, settings: &LineSettings) -> io::Result<Serial> {
        let builder = serialport::new(path, settings.baud)
            .data_bits(match settings.data_bits {
                7 => serialport::DataBits::Seven,
                _ => serialport::DataBits::Eight,
            })
            .parity(match settings.parity {
                Parity::None => serialport::Parity::None,
                Parity::Even => serialport::Parity::Even,
                Parity::Odd => serialport::Parity::Odd,
            })
            .stop_bits(match settings.stop_bits {
                2 => serialport::StopBits::Two,
                _ => serialport::StopBits::One,
            })
            .flow_control(serialport::FlowControl::None)
            .timeout(Duration::from_millis(100));
        let cannot_open =
            |e: serialport::Error| io::Error::other(format!("cannot open {path}: {e}"));
        #[cfg(unix)]
        let (mut port, fd): (Box<dyn SerialPort>, Option<i32>) = {
            use std::os::fd::AsRawFd;
            let native = builder.open_native().map_err(cannot_open)?;
            let fd = native.as_raw_fd();
            (Box::new(native), Some(fd))
        };
        #[cfg(not(unix))]
        let (mut port, fd) = (builder.open().map_err(cannot_open)?, None);
        let (mut kernel_mode, mut toggle) = (None, None);
        match settings.direction {
            DirectionControl::Automatic => {}
            DirectionControl::Kernel(timing) => {
                kernel_mode = Some(KernelMode::set(fd, path, &timing)?);
            }
            DirectionControl::Toggle(timing) => {
                // Listening from the start, which also shows that the driver moves RTS.
                // The refusal of a driver without modem lines (ENOTTY) says nothing more.
                port.write_request_to_send(!timing.sending.asserted())
                    .map_err(|_| {
                        io::Error::new(
                            io::ErrorKind::Unsupported,
                            format!("{path} cannot drive RTS"),
                        )
                    })?;
                toggle = Some(timing);
            }
        }
        Ok(Serial {
            _kernel_mode: kernel_mode,
            port,
            toggle,
        })
    }
}

impl Transport for Serial {
    fn discard_input(&mut self) -> io::Result<()> {
        self.port.clear(ClearBuffer::Input).map_err(io::Error::from)
    }

    fn send(&mut self, frame: &[u8]) -> io::Result<()> {
        let Some(timing) = self.toggle else {
            self.port.write_all(frame)?;
            return self.port.flush();
        };
        self.port
            .write_request_to_send(timing.sending.asserted())
            .map_err(io::Error::from)?;
        std::thread::sleep(timing.before);
        // flush() waits until the last byte has left the UART (tcdrain); RTS goes back to
        // listening whatever became of the write, so the answer is heard.
        let sent = self.port.write_all(frame).and_then(|()| self.port.flush());
        std::thread::sleep(timing.after);
        let listening = self
            .port
            .write_request_to_send(!timing.sending.asserted())
            .map_err(io::Error::from);
        sent.and(listening)
    }

    fn receive(&mut self, buf: &mut Vec<u8>, deadline: Instant) -> io::Result<usize> {
        let mut chunk = [0u8; 512];
        loop {
            let Some(left) = time_left(deadline) else {
                return Ok(0);
            };
            self.port.set_timeout(left).map_err(io::Error::from)?;
            match self.port.read(&mut chunk) {
                Ok(0) => continue,
                Ok(n) => {
                    buf.extend_from_slice(&chunk[..n]);
                    return Ok(n);
                }
                Err(e) if e.kind() == io::ErrorKind::TimedOut => return Ok(0),
                Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            }
        }
    }

    fn is_serial_line(&self) -> bool {
        true
    }
}

/// Whether `path` is a pseudo-terminal (`/dev/pts/N` on Linux, `/dev/ttysNNN` on macOS),
/// which carries bytes at any baud rate and parity: settings are not told apart there.
pub fn is_pseudo_terminal(path: &str) -> bool {
    let real = std::fs::canonicalize(path).unwrap_or_else(|_| path.into());
    let real = real.to_string_lossy();
    real.starts_with("/dev/pts/")
        || real
            .strip_prefix("/dev/ttys")
            .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
}

/// The serial ports of this machine, by their device names, as the system lists them.
pub fn ports_here() -> Vec<String> {
    super::ports::devices(std::path::Path::new("/"))
}

/// `--low-latency`: the FTDI latency timer of the USB serial adapter behind `path` to 1 ms,
/// through sysfs, so that the gaps between frames can be seen.
pub fn set_low_latency(path: &str) -> Result<(), String> {
    let device = std::fs::canonicalize(path).map_err(|e| format!("{path}: {e}"))?;
    let name = device
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let adapter = format!("/sys/bus/usb-serial/devices/{name}");
    if !std::path::Path::new(&adapter).is_dir() {
        return Err(format!(
            "{path} is no USB serial adapter (there is no {adapter}), so it has no latency \
             timer to set: leave out --low-latency"
        ));
    }
    let timer = format!("{adapter}/latency_timer");
    std::fs::write(&timer, "1")
        .map_err(|e| format!("cannot set {timer} ({e}): run `echo 1 | sudo tee {timer}` once"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_gap_is_three_and_a_half_characters_up_to_19200() {
        let line = LineSettings {
            baud: 9600,
            parity: Parity::Even,
            data_bits: 8,
            stop_bits: 1,
            direction: DirectionControl::Automatic,
        };
        // 11 bits at 9600 baud: 1.1458 ms a character, 4.010 ms for 3.5.
        assert_eq!(line.frame_gap().as_micros(), 4010);
        let fast = LineSettings {
            baud: 115200,
            ..line
        };
        assert_eq!(fast.frame_gap(), Duration::from_micros(1750));
    }
}
