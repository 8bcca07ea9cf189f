//! Frames as a pcap file that Wireshark opens: link type DLT_USER0 (147), which Wireshark
//! decodes as Modbus RTU once told to (Preferences > Protocols > DLT_USER: DLT 147, payload
//! protocol "mbrtu").

use std::io::{self, Write};

use crate::codec::checksum::crc16;
use crate::codec::{Envelope, Mode};

/// DLT_USER0.
pub const LINK_TYPE: u32 = 147;

/// The frame as Wireshark reads it, Modbus RTU: an ASCII or MBAP frame is written as the
/// RTU frame it carries.
pub fn rtu_form(mode: Mode, bytes: &[u8]) -> Vec<u8> {
    match (mode, Envelope::open(mode, bytes)) {
        (Mode::Ascii | Mode::Tcp, Ok(envelope)) => {
            let mut frame = vec![envelope.slave];
            frame.extend_from_slice(&envelope.pdu);
            let crc = crc16(&frame);
            frame.extend_from_slice(&crc.to_le_bytes());
            frame
        }
        _ => bytes.to_vec(),
    }
}

/// Writes frames to a pcap file that Wireshark opens.
pub struct PcapWriter<W: Write> {
    out: W,
}

impl<W: Write> PcapWriter<W> {
    /// Writes the file header.
    pub fn new(mut out: W) -> io::Result<Self> {
        out.write_all(&0xA1B2_C3D4u32.to_le_bytes())?; // microsecond timestamps
        out.write_all(&2u16.to_le_bytes())?;
        out.write_all(&4u16.to_le_bytes())?;
        out.write_all(&0i32.to_le_bytes())?; // time zone: UTC
        out.write_all(&0u32.to_le_bytes())?; // timestamp accuracy
        out.write_all(&65535u32.to_le_bytes())?; // snapshot length
        out.write_all(&LINK_TYPE.to_le_bytes())?;
        Ok(Self { out })
    }

    /// One frame, at `time_us` microseconds since 1970.
    pub fn frame(&mut self, time_us: u64, bytes: &[u8]) -> io::Result<()> {
        let seconds = u32::try_from(time_us / 1_000_000).unwrap_or(u32::MAX);
        let micros = (time_us % 1_000_000) as u32;
        let len = u32::try_from(bytes.len()).unwrap_or(u32::MAX);
        self.out.write_all(&seconds.to_le_bytes())?;
        self.out.write_all(&micros.to_le_bytes())?;
        self.out.write_all(&len.to_le_bytes())?;
        self.out.write_all(&len.to_le_bytes())?;
        self.out.write_all(bytes)
    }

    /// Writes out what is buffered.
    pub fn flush(&mut self) -> io::Result<()> {
        self.out.flush()
    }
}

/// Writes packets as they were captured to a pcapng file: one interface, microsecond times.
pub struct PcapNgWriter<W: Write> {
    out: W,
}

impl<W: Write> PcapNgWriter<W> {
    /// Writes the section header and the interface of link type `link`.
    pub fn new(mut out: W, link: u32) -> io::Result<Self> {
        // Section header: byte-order magic, version 1.0, section length unknown.
        out.write_all(&0x0A0D_0D0Au32.to_le_bytes())?;
        out.write_all(&28u32.to_le_bytes())?;
        out.write_all(&0x1A2B_3C4Du32.to_le_bytes())?;
        out.write_all(&1u16.to_le_bytes())?;
        out.write_all(&0u16.to_le_bytes())?;
        out.write_all(&(-1i64).to_le_bytes())?;
        out.write_all(&28u32.to_le_bytes())?;
        // Interface description: link type, snap length; times in microseconds by default.
        out.write_all(&1u32.to_le_bytes())?;
        out.write_all(&20u32.to_le_bytes())?;
        out.write_all(&u16::try_from(link).unwrap_or(u16::MAX).to_le_bytes())?;
        out.write_all(&0u16.to_le_bytes())?;
        out.write_all(&65535u32.to_le_bytes())?;
        out.write_all(&20u32.to_le_bytes())?;
        Ok(Self { out })
    }

    /// One packet, captured at `time_us` microseconds since 1970, `original_len` long on
    /// the wire.
    pub fn packet(&mut self, time_us: u64, data: &[u8], original_len: u32) -> io::Result<()> {
        let padded = data.len().div_ceil(4) * 4;
        let total = u32::try_from(32 + padded).unwrap_or(u32::MAX);
        let captured = u32::try_from(data.len()).unwrap_or(u32::MAX);
        self.out.write_all(&6u32.to_le_bytes())?;
        self.out.write_all(&total.to_le_bytes())?;
        self.out.write_all(&0u32.to_le_bytes())?;
        self.out
            .write_all(&((time_us >> 32) as u32).to_le_bytes())?;
        self.out.write_all(&(time_us as u32).to_le_bytes())?;
        self.out.write_all(&captured.to_le_bytes())?;
        self.out.write_all(&original_len.to_le_bytes())?;
        self.out.write_all(data)?;
        self.out.write_all(&[0; 3][..padded - data.len()])?;
        self.out.write_all(&total.to_le_bytes())
    }

    /// Writes out what is buffered.
    pub fn flush(&mut self) -> io::Result<()> {
        self.out.flush()
    }
}
