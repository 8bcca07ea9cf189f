//! `mbtool watch`: a live, full-screen view of a range or of a map's points.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};

use anyhow::Result;
use ratatui::crossterm::event::{self, Event, KeyCode, KeyEventKind, KeyModifiers};

use mbtool::connection::{Connector, Role};
use mbtool::error::Error;
use mbtool::output::watch::WatchState;
use mbtool::settings::job::RequestWords;
use mbtool::settings::Settings;
use mbtool_core::master::failover::Left;
use mbtool_core::master::map::{read_points, Refused};
use mbtool_core::master::plan::plan;
use mbtool_core::master::poll::{poll, PollOptions, Tick};
use mbtool_core::master::run::RunError;
use mbtool_core::master::Master;
use mbtool_core::model::address::Access;
use mbtool_core::model::map::{range_points, Kind, Point};
use mbtool_core::model::values::Value;

/// How often watch reads when --poll does not say.
const DEFAULT_INTERVAL: Duration = Duration::from_secs(1);

/// The points of the command line: a map's, or those of a range.
fn points(
    settings: &Settings,
    request: &RequestWords,
    target: &Connector,
) -> Result<(u8, Vec<Point>), Error> {
    let typed = match request {
        RequestWords::ByMap(map) => {
            let names: Vec<&str> = map.words.iter().map(String::as_str).collect();
            let plan = super::map::plan(
                settings,
                &map.file,
                map.slave.as_deref(),
                &names,
                target.is_tcp(),
                Access::Read,
            )?;
            return Ok((plan.slave, plan.points));
        }
        RequestWords::Typed(typed) => typed,
    };
    let operation = typed.operation();
    let mut options = super::shared::plan_options(settings);
    options.tcp = target.is_tcp();
    let read = plan(&operation, options)?;
    let Some((table, address)) = read.reads else {
        return Err(Error::usage("watch reads: give a reference to read"));
    };
    let quantity: u32 = read
        .requests
        .iter()
        .map(|request| u32::from(request.read_quantity()))
        .sum();
    let points = match read.bits {
        Some(bits) => range_points(
            table,
            address,
            bits.count,
            Some(bits.first),
            Kind::Bool,
            settings.data.order,
        ),
        None if table.is_bits() => range_points(
            table,
            address,
            quantity,
            None,
            Kind::Bool,
            settings.data.order,
        ),
        None => {
            let kind = Kind::Number(settings.data.value_type);
            range_points(
                table,
                address,
                quantity / u32::from(kind.width()),
                None,
                kind,
                settings.data.order,
            )
        }
    };
    Ok((read.slave, points))
}

/// What the polling thread tells the screen.
enum Update {
    Values(Vec<(usize, Value)>, Duration),
    Failed(RunError),
    Disconnected(String),
    /// The master changed paths: the new title, and how the request ended on the path
    /// left.
    Switched(String, Option<Left>),
}

pub fn run(settings: &Settings, request: &RequestWords) -> Result<u8> {
    if !std::io::stdout().is_terminal() {
        return Err(Error::usage(
            "watch draws on a terminal; to log values give read ... --poll INTERVAL -o csv (or --log FILE)",
        )
        .into());
    }
    // A map's file may say where its device is, where the command line does not.
    let placed = match request {
        RequestWords::ByMap(by_map) => {
            let path = &by_map.file;
            // Its warnings are told once, when its points are planned.
            let map = mbtool_core::model::map_file::load(path).map_err(Error::from)?;
            super::map::with_place(
                settings,
                path,
                map.connection.as_ref(),
                map.unknown_place.as_deref(),
            )?
        }
        RequestWords::Typed(_) => settings.clone(),
    };
    let settings = &placed;
    let target = Connector::new(&settings.connection, Role::Master)?;
    let (slave, points) = points(settings, request, &target)?;
    let title = format!(
        " slave {slave} on {} ",
        settings.connection.port.as_deref().unwrap_or_default()
    );
    let interval = settings.poll.interval.unwrap_or(DEFAULT_INTERVAL);
    let stop = Arc::new(AtomicBool::new(false));
    // Ctrl-C from outside the terminal (kill -INT) ends watch as q does.
    let on_signal = stop.clone();
    ctrlc::set_handler(move || on_signal.store(true, Ordering::SeqCst))
        .map_err(|e| anyhow::anyhow!("cannot catch Ctrl-C: {e}"))?;
    let (updates, received) = mpsc::channel();
    let mut state = WatchState::new(title, &points);
    let poller = {
        let (settings, points, stop) = (settings.clone(), points.clone(), stop.clone());
        let target = target.clone();
        std::thread::spawn(move || {
            poll_thread(
                &settings, &target, slave, &points, interval, &stop, &updates,
            );
        })
    };
    // A terminal that goes away (its window closed, its session killed) takes the shell
    // that started watch with it, and leaves the terminal library waiting on a line that
    // is gone: watch ends when its parent does, with no terminal left to give back.
    let parent = std::os::unix::process::parent_id();
    std::thread::spawn(move || loop {
        std::thread::sleep(Duration::from_millis(250));
        if std::os::unix::process::parent_id() != parent {
            std::process::exit(1);
        }
    });
    let mut terminal = ratatui::init();
    let outcome = screen(&mut terminal, &mut state, &received, &stop);
    let _ = terminal.show_cursor();
    ratatui::restore();
    // The polling thread ends at its next wait; a read still waiting for its answer is
    // not waited for, so that q is quick whatever the timeout.
    stop.store(true, Ordering::SeqCst);
    let deadline = Instant::now() + Duration::from_millis(200);
    while !poller.is_finished() && Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(10));
    }
    outcome?;
    Ok(0)
}

/// Draws until q, Esc or Ctrl-C.
fn screen(
    terminal: &mut ratatui::DefaultTerminal,
    state: &mut WatchState,
    received: &mpsc::Receiver<Update>,
    stop: &AtomicBool,
) -> Result<()> {
    while !stop.load(Ordering::SeqCst) {
        for update in received.try_iter() {
            match update {
                Update::Values(values, took) => {
                    state.stats.record(Ok(()), took);
                    state.update(values);
                }
                Update::Failed(error) => {
                    state.stats.record(Err(&error), Duration::ZERO);
                    state.failed(error.to_string());
                }
                Update::Disconnected(why) => {
                    state.stats.disconnected += 1;
                    state.failed(why);
                }
                Update::Switched(title, left) => state.switched(title, left),
            }
        }
        terminal.draw(|frame| state.render(frame))?;
        if event::poll(Duration::from_millis(100))? {
            if let Event::Key(key) = event::read()? {
                if key.kind != KeyEventKind::Press {
                    continue;
                }
                match key.code {
                    KeyCode::Char('q') | KeyCode::Esc => break,
                    KeyCode::Char('c') if key.modifiers.contains(KeyModifiers::CONTROL) => break,
                    KeyCode::Char('p') => state.paused = !state.paused,
                    KeyCode::Char('r') => state.reset(),
                    _ => {}
                }
            }
        }
    }
    Ok(())
}

/// Polls on its own thread, so that the screen answers keys between reads.
fn poll_thread(
    settings: &Settings,
    target: &Connector,
    slave: u8,
    points: &[Point],
    interval: Duration,
    stop: &AtomicBool,
    updates: &mpsc::Sender<Update>,
) {
    let refs: Vec<&Point> = points.iter().collect();
    let connect = |path| -> Result<Master, Error> { target.master_on(path) };
    let read = |master: &mut Master| {
        let began = Instant::now();
        read_points(
            master,
            &refs,
            slave,
            settings.data.max_per_request,
            Refused::Around,
        )
        .map(|read| (read, began.elapsed()))
    };
    let wait = |time: Duration| {
        let until = Instant::now() + time;
        while Instant::now() < until {
            if stop.load(Ordering::SeqCst) {
                return true;
            }
            std::thread::sleep(
                Duration::from_millis(20).min(until.saturating_duration_since(Instant::now())),
            );
        }
        stop.load(Ordering::SeqCst)
    };
    let _ = poll(
        connect,
        read,
        PollOptions {
            interval,
            count: None,
        },
        wait,
        |tick| {
            let update = match tick {
                // An address the device does not have, or a point that failed, is said so
                // in its row.
                Tick::Read((read, took)) => {
                    let failed = read.failed.iter().flat_map(|failure| {
                        let error = Value::Text(failure.error.to_string());
                        failure
                            .points
                            .iter()
                            .map(move |index| (*index, error.clone()))
                    });
                    let missing = read
                        .missing
                        .iter()
                        .map(|index| (*index, Value::Text("no such address".into())));
                    let values = read.values.into_iter().map(|v| (v.point, v.value));
                    Update::Values(values.chain(missing).chain(failed).collect(), took)
                }
                Tick::Failed(error) => Update::Failed(error),
                Tick::Disconnected(why) => Update::Disconnected(why),
                Tick::Switched(switch) => Update::Switched(
                    format!(
                        " slave {slave} on {} ({} path: {}) ",
                        super::shared::path_name(settings, switch.to),
                        switch.to.name(),
                        switch.why
                    ),
                    switch.left,
                ),
            };
            updates
                .send(update)
                .map_err(|_| std::io::Error::other("the screen is gone"))
        },
    );
}
