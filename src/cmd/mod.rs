//! One module per command: each wires the library's logic to its output.

mod decode;
mod diag;
mod dump;
mod encode;
mod gateway;
mod info;
mod map;
mod plant;
mod poll;
mod ports;
mod request;
mod restore;
mod scan;
mod serve;
mod shared;
mod sniff;
mod sunspec;
mod watch;

use anyhow::Result;

use mbtool::settings::job::Job;
use mbtool::settings::Settings;

/// Runs the job; `Ok` carries the exit status of a command that finished its work.
pub fn run(settings: &Settings, job: &Job) -> Result<u8> {
    match job {
        Job::Scan(job) => scan::run(settings, job),
        Job::Watch(job) => watch::run(settings, job),
        Job::Info(job) => info::run(settings, job),
        Job::Sunspec(job) => sunspec::run(settings, job),
        Job::Dump(job) => dump::run(settings, job),
        Job::Restore(job) => restore::run(settings, job),
        Job::Diag(job) => diag::run(settings, job),
        Job::Decode(job) => decode::run(settings, job),
        Job::Encode(job) => encode::run(settings, job),
        Job::Request(job) => request::run(settings, job),
        Job::Serve(job) => serve::run(settings, job),
        Job::Gateway(job) => gateway::run(settings, job),
        Job::Sniff(job) => sniff::run(settings, job),
        Job::Plant(job) => plant::run(settings, job),
        Job::Ports(job) => ports::run(settings, job),
        Job::Generate { dir } => {
            mbtool::docs::generate(dir)?;
            Ok(0)
        }
    }
}
