//! Codec throughput: frames decoded and described per second, without any I/O.
//!
//! cargo bench --bench codec
#![allow(clippy::unwrap_used, clippy::expect_used)] // a test stops at what it did not expect

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use mbtool_core::codec::framing::Framer;
use mbtool_core::codec::{Direction, Frame, Mode, Pdu, Request};
use mbtool_core::describe::describe_frame;

/// The worked frames of the manuals: requests and answers of functions 01-06 and 16.
const FRAMES: &[&[u8]] = &[
    &[0x11, 0x01, 0x00, 0x13, 0x00, 0x25, 0x0E, 0x84],
    &[0x11, 0x01, 0x05, 0xCD, 0x6B, 0xB2, 0x0E, 0x1B, 0x45, 0xE6],
    &[0x11, 0x02, 0x00, 0xC4, 0x00, 0x16, 0xBA, 0xA9],
    &[0x11, 0x02, 0x03, 0xAC, 0xDB, 0x35, 0x20, 0x18],
    &[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87],
    &[
        0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
    ],
    &[0x11, 0x04, 0x00, 0x08, 0x00, 0x01, 0xB2, 0x98],
    &[0x11, 0x04, 0x02, 0x00, 0x0A, 0xF8, 0xF4],
    &[0x11, 0x05, 0x00, 0xAC, 0xFF, 0x00, 0x4E, 0x8B],
    &[0x11, 0x06, 0x00, 0x01, 0x00, 0x03, 0x9A, 0x9B],
    &[
        0x11, 0x10, 0x00, 0x01, 0x00, 0x02, 0x04, 0x00, 0x0A, 0x01, 0x02, 0xC6, 0xF0,
    ],
    &[0x11, 0x10, 0x00, 0x01, 0x00, 0x02, 0x12, 0x98],
];

fn codec(c: &mut Criterion) {
    let mut group = c.benchmark_group("codec");
    group.throughput(Throughput::Elements(FRAMES.len() as u64));

    // Direction known, as the master and the simulator decode.
    let answer = FRAMES[5];
    group.bench_function("decode read-holding answer x12", |b| {
        b.iter(|| {
            for _ in FRAMES {
                std::hint::black_box(Frame::decode(Mode::Rtu, answer, Direction::Response).ok());
            }
        });
    });

    // Direction inferred and every field described, as `decode` does.
    group.bench_function("describe the 12 worked frames", |b| {
        b.iter(|| {
            for frame in FRAMES {
                std::hint::black_box(describe_frame(frame, None, None));
            }
        });
    });

    // The worked frames glued into one stream, as a sniffer or a slave receives them.
    let stream: Vec<u8> = FRAMES.concat();
    group.bench_function("frame a stream of the 12 worked frames", |b| {
        let mut events = Vec::with_capacity(FRAMES.len());
        b.iter(|| {
            let mut framer = Framer::new(Mode::Rtu, 573.0, 2005);
            framer.push(&stream, &mut events);
            framer.finish(&mut events);
            std::hint::black_box(events.len());
            events.clear();
        });
    });

    // A real recording (9600 8N1, turnaround noise between frames) framed in 64 KiB reads,
    // as `sniff --input` frames a capture file: 88 frames in 804 bytes, repeated.
    let recording = include_bytes!("../tests/captures/wizmodbus.bin").repeat(80);
    group.throughput(Throughput::Bytes(recording.len() as u64));
    group.bench_function("frame a real recording, per byte", |b| {
        let mut events = Vec::new();
        b.iter(|| {
            let mut framer = Framer::new(Mode::Rtu, 1145.8, 4010);
            for chunk in recording.chunks(1 << 16) {
                framer.push(chunk, &mut events);
                events.clear();
            }
            framer.finish(&mut events);
            std::hint::black_box(events.len());
            events.clear();
        });
    });
    group.throughput(Throughput::Elements(FRAMES.len() as u64));

    let frame = Frame {
        mode: Mode::Rtu,
        slave: 17,
        transaction: 0,
        pdu: Pdu::Request(Request::ReadHoldingRegisters {
            address: 107,
            quantity: 3,
        }),
    };
    group.bench_function("encode read-holding request x12", |b| {
        b.iter_batched(
            || frame.clone(),
            |frame| {
                for _ in FRAMES {
                    std::hint::black_box(frame.encode().ok());
                }
            },
            BatchSize::SmallInput,
        );
    });
    group.finish();
}

/// CRC-16/MODBUS, ours (slice-by-16, short frames in one pass of independent lookups)
/// against the `crc` crate's, table-driven and slice-by-16: the framer checks a CRC at
/// every candidate frame, most of them under 16 bytes.
fn crc(c: &mut Criterion) {
    const CRATE_BYTEWISE: crc::Crc<u16> = crc::Crc::<u16>::new(&crc::CRC_16_MODBUS);
    const CRATE_SLICED: crc::Crc<u16, crc::Table<16>> =
        crc::Crc::<u16, crc::Table<16>>::new(&crc::CRC_16_MODBUS);
    let request = &FRAMES[4][..6];
    let long: Vec<u8> = (0..253u8).collect();
    let mut group = c.benchmark_group("crc16");
    for (name, bytes) in [("6 bytes", request), ("253 bytes", long.as_slice())] {
        group.throughput(Throughput::Bytes(bytes.len() as u64));
        group.bench_function(format!("ours, {name}"), |b| {
            b.iter(|| mbtool_core::codec::checksum::crc16(std::hint::black_box(bytes)));
        });
        group.bench_function(format!("crc crate, table, {name}"), |b| {
            b.iter(|| CRATE_BYTEWISE.checksum(std::hint::black_box(bytes)));
        });
        group.bench_function(format!("crc crate, slice-by-16, {name}"), |b| {
            b.iter(|| CRATE_SLICED.checksum(std::hint::black_box(bytes)));
        });
    }
    group.finish();
}

criterion_group!(benches, codec, crc);
criterion_main!(benches);
