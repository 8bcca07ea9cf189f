//! Driving an RS-485 transceiver from the host: the transceivers of single-board computers,
//! industrial PCs and some USB adapters listen unless RTS tells them to send. Either the
//! kernel's RS-485 mode switches RTS around every write (the UART driver knows when the
//! last bit has left), or the transport toggles RTS itself around each frame.
//!
//! The kernel's mode is set with an ioctl that serialport does not offer, the one other
//! place besides calling libpcap where mbtool needs `unsafe`: each call says why it holds.
#![allow(unsafe_code)]

use std::io;
use std::time::Duration;

use crate::input::choice::Choice;
use crate::model::line::{RtsLevel, RtsTiming};

/// The kernel's RS-485 mode on an open port, with its settings as they were before, to be
/// put back.
#[cfg(target_os = "linux")]
pub(super) struct KernelMode {
    fd: i32,
    before: SerialRs485,
}

/// `struct serial_rs485` of <linux/serial.h>.
#[cfg(target_os = "linux")]
#[repr(C)]
#[derive(Clone, Copy, Default)]
struct SerialRs485 {
    flags: u32,
    delay_rts_before_send: u32,
    delay_rts_after_send: u32,
    padding: [u32; 5],
}

#[cfg(target_os = "linux")]
const SER_RS485_ENABLED: u32 = 1 << 0;
#[cfg(target_os = "linux")]
const SER_RS485_RTS_ON_SEND: u32 = 1 << 1;
#[cfg(target_os = "linux")]
const SER_RS485_RTS_AFTER_SEND: u32 = 1 << 2;

#[cfg(target_os = "linux")]
impl KernelMode {
    /// Turns the kernel's RS-485 mode on for the open port `fd` (named `path`), with
    /// `timing`. A port whose driver has no RS-485 mode is told as `Unsupported`.
    pub(super) fn set(fd: Option<i32>, path: &str, timing: &RtsTiming) -> io::Result<Self> {
        // A driver without the mode answers ENOTTY, which says nothing more; any other
        // refusal (EPERM, EINVAL) is worth showing.
        let unsupported = |error: io::Error| {
            let why = match error.raw_os_error() {
                Some(libc::ENOTTY) | None => String::new(),
                Some(_) => format!(" ({error})"),
            };
            io::Error::new(
                io::ErrorKind::Unsupported,
                format!("{path} does not support RS-485 mode{why}"),
            )
        };
        let Some(fd) = fd else {
            return Err(unsupported(io::ErrorKind::Unsupported.into()));
        };
        let mut before = SerialRs485::default();
        // SAFETY: TIOCGRS485 fills a `struct serial_rs485`, which `before` is.
        if unsafe { libc::ioctl(fd, libc::TIOCGRS485, &mut before as *mut SerialRs485) } < 0 {
            return Err(unsupported(io::Error::last_os_error()));
        }
        let (on_send, after_send) = match timing.sending {
            RtsLevel::High => (SER_RS485_RTS_ON_SEND, 0),
            RtsLevel::Low => (0, SER_RS485_RTS_AFTER_SEND),
        };
        let mut wanted = SerialRs485 {
            flags: SER_RS485_ENABLED | on_send | after_send,
            delay_rts_before_send: millis(timing.before),
            delay_rts_after_send: millis(timing.after),
            ..before
        };
        // SAFETY: TIOCSRS485 reads (and may adjust) a `struct serial_rs485`.
        if unsafe { libc::ioctl(fd, libc::TIOCSRS485, &mut wanted as *mut SerialRs485) } < 0 {
            return Err(unsupported(io::Error::last_os_error()));
        }
        // The driver writes back what it does: a mode it left off, or RTS kept at the
        // other level (hardware wired one way), would send with the transceiver wrong.
        let mode = KernelMode { fd, before };
        let level = if wanted.flags & SER_RS485_RTS_ON_SEND != 0 {
            RtsLevel::High
        } else {
            RtsLevel::Low
        };
        if wanted.flags & SER_RS485_ENABLED == 0 {
            return Err(unsupported(io::ErrorKind::Unsupported.into()));
        }
        if level != timing.sending {
            return Err(io::Error::new(
                io::ErrorKind::Unsupported,
                format!(
                    "{path} keeps RTS {} while sending in RS-485 mode, not {}",
                    level.name(),
                    timing.sending.name()
                ),
            ));
        }
        Ok(mode)
    }
}

#[cfg(target_os = "linux")]
fn millis(duration: Duration) -> u32 {
    u32::try_from(duration.as_millis()).unwrap_or(u32::MAX)
}

#[cfg(target_os = "linux")]
impl Drop for KernelMode {
    /// The port's RS-485 settings as they were: the mode outlives the process otherwise.
    fn drop(&mut self) {
        // SAFETY: as in `set`; the port is still open, since `Serial` drops this first.
        unsafe {
            libc::ioctl(
                self.fd,
                libc::TIOCSRS485,
                &mut self.before as *mut SerialRs485,
            )
        };
    }
}

/// Elsewhere than Linux there is no kernel RS-485 mode to set.
#[cfg(not(target_os = "linux"))]
pub(super) struct KernelMode;

#[cfg(not(target_os = "linux"))]
impl KernelMode {
    pub(super) fn set(_: Option<i32>, path: &str, _: &RtsTiming) -> io::Result<Self> {
        Err(io::Error::new(
            io::ErrorKind::Unsupported,
            format!("{path} does not support RS-485 mode (a Linux kernel feature)"),
        ))
    }
}
