//! mbtool as its users and the peers it talks to meet it, in one test binary: each module
//! one part of the tool, all sharing `support`.
#![allow(clippy::unwrap_used, clippy::expect_used)] // a test stops at what it did not expect
#![allow(clippy::print_stderr)] // a skipped test says why

mod support;

mod architecture;
mod backup;
mod bits;
mod decode;
mod device;
mod docs;
mod encode;
mod first_contact;
mod full_disk;
mod gateway;
mod golden;
mod home_assistant;
mod hosts;
mod hosts_sweep;
mod interrupt;
mod layouts;
mod map;
mod master_faults;
mod master_pymodbus;
mod master_sim;
mod master_tcp;
mod master_tokio;
mod plant;
mod poll;
mod ports;
mod protocol;
mod readme;
mod redundancy;
mod rs485;
mod scan;
mod serve;
mod serve_framing;
mod sniff;
mod sniff_faults;
mod sniff_tcp;
mod sunspec;
mod tls;
mod watch;
