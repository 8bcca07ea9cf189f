//! Watching a bus: the codec's framer finds the frames in what passes; here they are told
//! apart as requests and answers and paired (`pairing`, `session`), and written as pcap
//! (`pcap`); a saved capture keeps its timing beside it (`timing`).

pub mod capture;
pub mod line;
pub mod live;
mod pairing;
pub mod pcap;
pub mod reassembly;
pub mod replay;
pub mod session;
pub mod stats;
pub mod tcp;
pub mod timing;
