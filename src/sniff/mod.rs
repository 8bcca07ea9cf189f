//! Watching a bus: finding frames in what passes (`framer`), telling requests from
//! answers and pairing them (`pairing`), and writing what was seen as pcap (`pcap`).

pub mod framer;
pub mod pairing;
pub mod pcap;
pub mod session;
