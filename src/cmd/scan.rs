//! `mbtool scan`: the slaves on a line, and the serial settings they answer at.

use std::io::{IsTerminal, Write};
use std::time::{Duration, Instant};

use anyhow::Result;

use mbtool::connection::{Connector, Patience, Role};
use mbtool::error::Error;
use mbtool::output::encode::frame_text;
use mbtool::output::progress::ProgressLine;
use mbtool::output::scan::{write_scan, Where};
use mbtool::output::{self, colour_wanted};
use mbtool::settings::{job, Settings};
use mbtool_core::codec::Mode;
use mbtool_core::master::hosts::{self, SweepOptions, SweepTracer};
use mbtool_core::master::scan::{scan, sweep, Probe, Progress, ScanOptions, ScanReport};
use mbtool_core::master::timeouts;
use mbtool_core::master::Traffic;
use mbtool_core::model::line::LineSettings;
use mbtool_core::transport::serial;
use mbtool_core::transport::tls::{ClientTls, MODBUS_TLS_PORT};
use mbtool_core::transport::Endpoint;

pub fn run(settings: &Settings, job: &job::Scan) -> Result<u8> {
    if let Some(sweep) = &job.hosts {
        return sweep_hosts(settings, job, sweep);
    }
    let connector = Connector::new(&settings.connection, Role::Master)?;
    let (endpoint, mode) = (&connector.endpoint, connector.mode);
    let ids = &job.ids;
    if mode != Mode::Tcp {
        if let Some(id) = ids.iter().find(|id| !(1..=247).contains(*id)) {
            return Err(Error::usage(format!(
                "--ids: {id} is no slave id on a serial line: give ids from 1 to 247"
            ))
            .into());
        }
    }
    // Only a serial line of our own has settings to sweep, and other masters to hear.
    let serial = matches!(endpoint, Endpoint::Serial(_));
    if job.listen.is_some() && !serial {
        return Err(Error::usage(
            "--listen hears other masters on a serial line; over TCP or sim their traffic never reaches mbtool",
        )
        .into());
    }
    let lines: Vec<_> = if serial {
        sweep(&settings.connection.bauds, &settings.connection.parities)
            .into_iter()
            .map(|(baud, parity)| connector.line_at(baud, parity))
            .collect()
    } else {
        vec![connector.line()]
    };
    let options = ScanOptions {
        ids: ids.clone(),
        probe: job.probe,
        listen: job.listen,
        all: job.all,
        tell_unit_ids: mode == Mode::Tcp,
    };
    let total = (ids.len() * lines.len()) as u64;
    // On a terminal only; a trace on stderr (`--verbose`) would be drawn over.
    let mut bar = ProgressLine::new(
        total,
        "ids asked",
        std::io::stderr().is_terminal() && !settings.output.verbose,
    );
    bar.set_message("0 found");
    let place = Where {
        mode,
        settings: &lines,
        serial,
    };
    let stop = super::shared::stop_on_signal()?;
    let started = Instant::now();
    let report = scan(
        &lines,
        &options,
        |line| {
            let answer = Patience {
                timeout: timeout_at(settings, *line, options.probe),
                retries: 0,
            };
            let mut master = connector.master_with(line, answer)?;
            if settings.output.verbose {
                master.trace(super::shared::tracer(mode));
            }
            Ok::<_, Error>(master)
        },
        |progress| match progress {
            Progress::Setting(index) => {
                if serial {
                    bar.set_message(format!("at {}", place.describe(index)));
                }
            }
            Progress::Listening => bar.set_message("listening"),
            Progress::Asked(found) => {
                bar.advance(format!("{found} found"));
            }
        },
        &stop.flag,
    )?;
    bar.clear();
    let mut out = output::stdout();
    write_scan(
        &mut out,
        settings.output.format,
        &report,
        &place,
        colour_wanted(),
    )?;
    out.flush()?;
    for garbled in &report.garbled {
        mbtool::note!(
            "mbtool: id {} at {}: something answered, maybe at other settings ({})",
            garbled.slave,
            place.describe(garbled.setting),
            garbled.detail
        );
    }
    let late: Vec<_> = report.hits.iter().filter(|hit| hit.late).collect();
    if let Some(first) = late.first() {
        let ids: Vec<String> = late.iter().map(|hit| hit.slave.to_string()).collect();
        mbtool::note!(
            "mbtool: {} {} answered after the scan's timeout of {} ms: give a longer --timeout to read {}",
            if late.len() == 1 { "slave" } else { "slaves" },
            ids.join(", "),
            timeout_at(settings, lines[first.setting], options.probe).as_millis(),
            if late.len() == 1 { "it" } else { "them" },
        );
    }
    if let Some(took) = report.waited_longer {
        mbtool::note!(
            "mbtool: answers came after the timeout, the slowest after {} ms (a gateway waiting for unit ids it lacks): the scan waited as long from then on; give --timeout {}ms to wait so from the start",
            took.as_millis(),
            (took + took / 2).as_millis()
        );
    }
    if let Some(first) = report.reconnected.first() {
        mbtool::note!(
            "mbtool: the device closed the connection after unit id {first} ({} times in all), and it was opened again",
            report.reconnected.len()
        );
    }
    if let Some(why) = &report.interrupted {
        mbtool::note!("mbtool: the scan stopped early: {why}");
    }
    if report.stopped {
        mbtool::note!(
            "mbtool: scan interrupted; so far {}",
            summary(&report, &place, started.elapsed())
        );
        return Ok(stop.exit_status());
    }
    mbtool::note!("mbtool: {}", summary(&report, &place, started.elapsed()));
    if matches!(&endpoint, Endpoint::Serial(path) if serial::is_pseudo_terminal(path)) {
        mbtool::note!(
            "mbtool: {} is a pseudo-terminal, which carries any baud and parity: the settings shown were tried, not found",
            endpoint
        );
    }
    Ok(if report.hits.is_empty() { 3 } else { 0 })
}

/// `3 slaves found (3, 17, 200) at 19200 baud, even parity; 1 setting tried, 250
/// requests in 25.1 s`.
fn summary(report: &ScanReport, place: &Where, elapsed: std::time::Duration) -> String {
    let mut at_settings: Vec<(usize, Vec<String>)> = Vec::new();
    for hit in &report.hits {
        match at_settings
            .iter_mut()
            .find(|(setting, _)| *setting == hit.setting)
        {
            Some((_, ids)) => ids.push(hit.slave.to_string()),
            None => at_settings.push((hit.setting, vec![hit.slave.to_string()])),
        }
    }
    let found = match report.hits.len() {
        _ if report.ignores_unit_id.is_some() => {
            let telling: Vec<String> = report
                .telling_hits()
                .map(|hit| hit.slave.to_string())
                .collect();
            match telling.as_slice() {
                [] => "one device, answering every unit id alike".to_string(),
                ids => format!(
                    "one device, answering every unit id; {} answered otherwise",
                    ids.join(", ")
                ),
            }
        }
        0 => "no slave found".to_string(),
        n => {
            let groups: Vec<String> = at_settings
                .iter()
                .map(|(setting, ids)| match place.serial {
                    true => format!("{} at {}", ids.join(", "), place.describe(*setting)),
                    false => ids.join(", "),
                })
                .collect();
            let noun = if n == 1 { "slave" } else { "slaves" };
            format!("{n} {noun} found: {}", groups.join("; "))
        }
    };
    format!(
        "{found}; {} tried, {} in {:.1} s",
        output::plural(report.settings_tried, "setting"),
        output::plural(report.requests as usize, "request"),
        elapsed.as_secs_f64()
    )
}

/// The timeout at a setting of the sweep.
fn timeout_at(settings: &Settings, line: LineSettings, probe: Probe) -> Duration {
    let connection = &settings.connection;
    timeouts::at_line(
        connection.timeout,
        connection.timeout_given,
        &line,
        probe.answer_bytes(),
    )
}

/// `-v` of a sweep: every frame, with the host and port it went to or came from.
fn sweep_tracer() -> SweepTracer {
    let start = std::time::Instant::now();
    SweepTracer(std::sync::Arc::new(move |place, traffic, bytes| {
        let arrow = match traffic {
            Traffic::Sent => '>',
            Traffic::Received => '<',
        };
        mbtool::note!(
            "[{:>12.6}] {place} {arrow} {}",
            start.elapsed().as_secs_f64(),
            frame_text(Mode::Rtu, bytes)
        );
    }))
}

/// `scan --hosts`: the hosts of a network asked politely; what was found, also when a
/// signal ends the sweep.
fn sweep_hosts(settings: &Settings, job: &job::Scan, sweep: &job::HostSweep) -> Result<u8> {
    if settings.connection.port.is_some() {
        return Err(Error::usage(
            "--hosts sweeps a network: leave out --port (and MBTOOL_PORT), or scan the line of --port without --hosts",
        )
        .into());
    }
    if job.listen.is_some() {
        return Err(Error::usage(
            "--listen is for a serial line's settings; --hosts asks over TCP",
        )
        .into());
    }
    let options = SweepOptions {
        ports: sweep.ports.clone(),
        ids: job.ids.clone(),
        parallel: sweep.parallel,
        timeout: settings.connection.timeout,
        pause: sweep.pause,
        probe: job.probe.request(),
        ask_silent: job.all,
        trace: settings.output.verbose.then(sweep_tracer),
        tls: match settings.connection.tls_typed {
            true => Some(ClientTls::new(&settings.connection.tls).map_err(Error::from)?),
            false => None,
        },
    };
    if sweep.ports.contains(&MODBUS_TLS_PORT) && options.tls.is_none() {
        mbtool::note!(
            "mbtool: port {MODBUS_TLS_PORT} is Modbus/TCP Security: give --cert, --key and --ca to ask what answers there over TLS"
        );
    }
    let stop = super::shared::stop_on_signal()?;
    let reports = std::sync::Mutex::new(Vec::new());
    hosts::sweep(&sweep.hosts, &options, &stop.flag, |report| {
        if let Ok(mut reports) = reports.lock() {
            reports.push(report);
        }
    });
    let mut reports = reports.into_inner().unwrap_or_else(|p| p.into_inner());
    // In the order given: hosts, then ports; each host's place looked up once.
    let order: std::collections::HashMap<String, usize> = sweep
        .hosts
        .iter()
        .enumerate()
        .map(|(i, host)| (host.to_string(), i))
        .collect();
    reports.sort_by_cached_key(|report| {
        let port = sweep.ports.iter().position(|p| *p == report.port);
        (order.get(&report.host).copied(), port)
    });
    let mut out = output::stdout();
    output::hosts::write_hosts(
        &mut out,
        settings.output.format,
        colour_wanted(),
        &reports,
        job.ids.len(),
    )?;
    out.flush()?;
    let in_part = reports.iter().filter(|report| report.interrupted).count();
    let asked = (reports.len() - in_part) / sweep.ports.len().max(1);
    if stop.flag.load(std::sync::atomic::Ordering::SeqCst) && asked < sweep.hosts.len() {
        mbtool::note!(
            "mbtool: sweep stopped: {asked} of {} hosts asked{}",
            sweep.hosts.len(),
            match in_part {
                0 => String::new(),
                n => format!(
                    ", {} asked in part (marked interrupted)",
                    output::plural(n, "host port")
                ),
            }
        );
        return Ok(stop.exit_status());
    }
    Ok(if reports.iter().any(hosts::HostReport::found) {
        0
    } else {
        3
    })
}
