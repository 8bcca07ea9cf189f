//! `mbtool encode COMMAND ARGS`: the frames a request command would send.

use anyhow::Result;

use mbtool::error::Error;
use mbtool::output::{self, encode::write_frame};
use mbtool::settings::job::RequestWords;
use mbtool::settings::Settings;
use mbtool_core::codec::{Frame, Pdu, Request};

pub fn run(settings: &Settings, words: &RequestWords) -> Result<u8> {
    let mode = super::shared::mode(settings);
    let requests: Vec<(u8, Request)> = match words {
        RequestWords::ByMap(map) => super::map::by_map(settings, map)?.requests(settings),
        RequestWords::Typed(request) => {
            let plan = super::shared::plan_for(settings, request)?;
            plan.requests.into_iter().map(|r| (plan.slave, r)).collect()
        }
    };
    let mut frames = Vec::with_capacity(requests.len());
    for (i, (slave, request)) in requests.iter().enumerate() {
        let frame = Frame {
            mode,
            slave: *slave,
            transaction: (i as u16).wrapping_add(1),
            pdu: Pdu::Request(request.clone()),
        };
        let bytes = frame.encode().map_err(|e| Error::usage(e.to_string()))?;
        frames.push((*slave, request.function(), bytes));
    }
    let mut out = output::stdout();
    for (slave, function, bytes) in frames {
        write_frame(
            &mut out,
            settings.output.format,
            mode,
            slave,
            function,
            &bytes,
        )?;
    }
    out.flush()?;
    Ok(0)
}
