//! `read --map` and `write --map`: a device's points by name, from a register map.

use std::io::Write;

use anyhow::Result;

use mbtool::connection::{Connection, Connector, Role};
use mbtool::error::Error;
use mbtool::output::{self, map::MapRows, map::MapWriter};
use mbtool::settings::job::MapWords;
use mbtool::settings::Settings;
use mbtool_core::codec::{Mode, Request};
use mbtool_core::master::map::{groups, read_points, write_request, written_value, Group, Refused};
use mbtool_core::master::plan::{parse_slave, Plan};
use mbtool_core::model::address::Access;
use mbtool_core::model::map::{MapConnection, Point, RegisterMap};
use mbtool_core::model::map_file::load;

/// A map read or write, checked whole before anything is sent.
pub struct MapPlan {
    pub slave: u8,
    pub points: Vec<Point>,
    /// Where the device is, as the map's file says.
    pub connection: Option<MapConnection>,
    /// Why the file's place for the device is not known, where it has one.
    pub unknown_place: Option<String>,
    /// The map's file.
    pub path: std::path::PathBuf,
}

/// The map at `path`, what its reader warns of told on stderr.
pub fn load_map(path: &std::path::Path) -> Result<RegisterMap, Error> {
    let map = load(path)?;
    for warning in &map.warnings {
        mbtool::note!("mbtool: warning: {warning}");
    }
    Ok(map)
}

/// The settings with the device where the map's file says, unless the command line says
/// otherwise; a place the file keeps in a secret not found is an error only when the
/// command line gives none.
pub fn with_place(
    settings: &Settings,
    path: &std::path::Path,
    connection: Option<&MapConnection>,
    unknown_place: Option<&str>,
) -> Result<Settings, Error> {
    if let (None, Some(why)) = (&settings.connection.port, unknown_place) {
        return Err(Error::usage(format!(
            "{}: where the device is is not known: {why}; give --port",
            path.display()
        )));
    }
    Ok(Settings {
        connection: settings.connection.with_map(connection),
        ..settings.clone()
    })
}

/// Loads the map and picks the points named (every point when none is).
pub fn plan(
    settings: &Settings,
    path: &std::path::Path,
    slave: Option<&str>,
    names: &[&str],
    tcp: bool,
    access: Access,
) -> Result<MapPlan, Error> {
    let map = load_map(path)?;
    let points = pick(&map, names, path)?;
    // A read goes to one slave; only a write may broadcast. Without SLAVE, the map's own:
    // every point's, or the slave its format gives a point without one.
    let slave = match (slave, map.default_slave) {
        (Some(slave), _) => parse_slave(slave, access == Access::WriteOne, tcp)?,
        (None, Some(default)) => default,
        (None, None) => match points.iter().find(|p| p.slave.is_none()) {
            Some(point) => {
                let example = match access {
                    Access::Read => "read SLAVE --map {} ...",
                    _ => "write SLAVE --map {} NAME=VALUE",
                }
                .replace("{}", &path.display().to_string());
                return Err(Error::usage(format!(
                    "{} gives {} no slave: give SLAVE ({example})",
                    path.display(),
                    point.name,
                )));
            }
            None => points.iter().find_map(|p| p.slave).unwrap_or_default(),
        },
    };
    if let Some(max) = settings.data.max_per_request {
        if let Some(wide) = points.iter().find(|p| p.kind.width() > max) {
            return Err(Error::usage(format!(
                "--max-per-request {max} is less than {} takes ({} registers): give at least {}",
                wide.name,
                wide.kind.width(),
                wide.kind.width()
            )));
        }
    }
    // Entities of a Home Assistant file carry their own slave: those are asked, and the
    // user is told, so that the SLAVE typed is not taken for the one that answered.
    let mut own: Vec<u8> = points
        .iter()
        .filter_map(|p| p.slave)
        .filter(|own| *own != slave)
        .collect();
    own.sort_unstable();
    own.dedup();
    if !own.is_empty() {
        let list: Vec<String> = own.iter().map(ToString::to_string).collect();
        mbtool::note!(
            "mbtool: {} gives points their own slave ({}): those are asked, slave {slave} only for the others",
            path.display(),
            list.join(", ")
        );
    }
    Ok(MapPlan {
        slave,
        points,
        connection: map.connection,
        unknown_place: map.unknown_place,
        path: path.to_path_buf(),
    })
}

fn pick(map: &RegisterMap, names: &[&str], path: &std::path::Path) -> Result<Vec<Point>, Error> {
    if names.is_empty() {
        return Ok(map.points.clone());
    }
    names
        .iter()
        .map(|name| find(&map.points, name, path).cloned())
        .collect()
}

/// The point named `name`, or a message that offers the nearest name.
fn find<'a>(points: &'a [Point], name: &str, path: &std::path::Path) -> Result<&'a Point, Error> {
    points.iter().find(|p| p.name == name).ok_or_else(|| {
        let nearest = mbtool::nearest(name, points.iter().map(|p| p.name.as_str()));
        let hint = nearest.map_or(String::new(), |n| format!(": did you mean '{n}'?"));
        Error::usage(format!(
            "{} has no point named '{name}'{hint}",
            path.display()
        ))
    })
}

impl MapPlan {
    /// The read requests, grouped as the manuals' driver groups them.
    pub fn groups(&self, settings: &Settings) -> Vec<Group> {
        let points: Vec<&Point> = self.points.iter().collect();
        groups(&points, self.slave, settings.data.max_per_request)
    }

    /// The write requests of `NAME=VALUE` words, each point's own slave or the command's,
    /// with what each writes in words.
    pub fn writes(
        &self,
        assignments: &[(&str, &str)],
        path: &std::path::Path,
    ) -> Result<Vec<MapWrite>, Error> {
        assignments
            .iter()
            .map(|&(name, value)| {
                let point = find(&self.points, name, path)?;
                let request = write_request(point, value).map_err(Error::usage)?;
                // What the point holds of the value asked, when it holds less (2.56 in
                // steps of 0.1 is 2.6).
                let written = written_value(point, &request).map(|v| v.to_string());
                let asked =
                    |written: &str| match (written.parse::<f64>(), value.trim().parse::<f64>()) {
                        (Ok(a), Ok(b)) if a != b => format!(" (asked {value})"),
                        _ => String::new(),
                    };
                let shown = written.as_deref().unwrap_or(value);
                Ok(MapWrite {
                    slave: point.slave.unwrap_or(self.slave),
                    request,
                    said: format!(
                        "{name} = {shown}{} ({}){}",
                        unit(point),
                        point.reference(),
                        asked(shown)
                    ),
                })
            })
            .collect()
    }
}

/// One point's write.
pub struct MapWrite {
    pub slave: u8,
    pub request: Request,
    /// `setpoint = 21.5 °C (400001)`.
    pub said: String,
}

fn unit(point: &Point) -> String {
    match point.unit.as_str() {
        "" => String::new(),
        unit => format!(" {unit}"),
    }
}

/// Reads the plan's points and shows them.
pub fn read(settings: &Settings, plan: &MapPlan, connection: &mut Connection) -> Result<u8> {
    let points: Vec<&Point> = plan.points.iter().collect();
    let read = read_points(
        &mut connection.master,
        &points,
        plan.slave,
        settings.data.max_per_request,
        Refused::Error,
    )
    .map_err(|e| connection.explain(Error::from(e)))?;
    if read.fell_back {
        mbtool::note!(
            "mbtool: a request spanning addresses no point names was refused; its points were read again one run at a time"
        );
    }
    let mut out = output::stdout();
    MapWriter::new(settings.output.format, output::colour_wanted())
        .write(&mut out, plan.slave, &points, &read)?;
    out.flush()?;
    let Some((index, error)) = read.first_failure() else {
        return Ok(0);
    };
    mbtool::note!(
        "mbtool: {}: {error} ({} of {} points without a value)",
        points[index].name,
        read.failed_points(),
        points.len()
    );
    Ok(mbtool::error::run_exit_code(error))
}

/// Writes the points, then says what was written.
pub fn write(writes: &[MapWrite], connection: &mut Connection) -> Result<u8> {
    let mut out = output::stdout();
    for write in writes {
        // Through a plan of its own, so that a bit is written as every bit is (22, or 03
        // and 06 where the slave lacks 22).
        let plan = Plan {
            slave: write.slave,
            requests: vec![write.request.clone()],
            reads: None,
            bits: None,
        };
        let written = connection
            .master
            .write(&plan)
            .map_err(|e| connection.explain(Error::from(e)))?;
        if written.mask_write_emulated {
            super::shared::note_mask_write_emulated(write.slave, &write.said);
        }
        writeln!(out, "wrote {}", write.said)?;
    }
    out.flush()?;
    Ok(0)
}

/// `read --map --poll`: the map's points read every interval, as the rows of a log.
pub fn poll(
    settings: &Settings,
    plan: &MapPlan,
    target: &Connector,
    interval: std::time::Duration,
) -> Result<u8> {
    let points: Vec<&Point> = plan.points.iter().collect();
    let writer = |format| {
        MapRows::new(
            MapWriter::new(format, output::colour_wanted()),
            plan.slave,
            points.clone(),
        )
    };
    super::poll::run(
        settings,
        target,
        interval,
        |master| {
            read_points(
                master,
                &points,
                plan.slave,
                settings.data.max_per_request,
                Refused::Error,
            )
        },
        writer,
    )
}

/// A read or write by register map, checked whole.
pub enum ByMap {
    Read(MapPlan),
    Write(Vec<MapWrite>, MapPlan),
}

/// The map work of `read --map` or `write --map`, with nothing opened yet.
pub fn by_map(settings: &Settings, request: &MapWords) -> Result<ByMap> {
    let tcp = super::shared::mode(settings) == Mode::Tcp;
    let path = &request.file;
    let slave = request.slave.as_deref();
    let words: Vec<&str> = request.words.iter().map(String::as_str).collect();
    if request.access == Access::Read {
        let plan = plan(settings, path, slave, &words, tcp, Access::Read)?;
        return Ok(ByMap::Read(plan));
    }
    let assignments = assignments(&words)?;
    let names: Vec<&str> = assignments.iter().map(|(name, _)| *name).collect();
    let plan = plan(settings, path, slave, &names, tcp, request.access)?;
    let writes = plan.writes(&assignments, path)?;
    Ok(ByMap::Write(writes, plan))
}

/// The `NAME=VALUE` words of `write --map`, split.
fn assignments<'a>(words: &[&'a str]) -> Result<Vec<(&'a str, &'a str)>, Error> {
    if words.is_empty() {
        return Err(Error::usage(
            "write --map needs NAME=VALUE, as setpoint=21.5",
        ));
    }
    words
        .iter()
        .map(|word| {
            word.split_once('=')
                .ok_or_else(|| Error::usage(format!("'{word}': give NAME=VALUE, as setpoint=21.5")))
        })
        .collect()
}

impl ByMap {
    pub fn run(&self, settings: &Settings) -> Result<u8> {
        // The device is where the map's file says, unless the command line says otherwise.
        let (ByMap::Read(plan) | ByMap::Write(_, plan)) = self;
        let settings = &with_place(
            settings,
            &plan.path,
            plan.connection.as_ref(),
            plan.unknown_place.as_deref(),
        )?;
        if let (ByMap::Read(plan), Some(interval)) = (self, settings.poll.interval) {
            return poll(
                settings,
                plan,
                &Connector::new(&settings.connection, Role::Master)?,
                interval,
            );
        }
        if let ByMap::Write(writes, _) = self {
            let requests: Vec<Request> = writes.iter().map(|w| w.request.clone()).collect();
            super::shared::refuse_unsafe_retries(settings, &requests)?;
        }
        let mut connection = Connector::new(&settings.connection, Role::Master)?.connect()?;
        if settings.output.verbose {
            let mode = connection.connector.mode;
            connection.master.trace(super::shared::tracer(mode));
        }
        match self {
            ByMap::Read(plan) => read(settings, plan, &mut connection),
            ByMap::Write(writes, _) => {
                let written = write(writes, &mut connection);
                super::shared::tell_after_requests(&mut connection.master);
                written
            }
        }
    }

    /// The requests it sends, with their slaves, for `encode`.
    pub fn requests(&self, settings: &Settings) -> Vec<(u8, Request)> {
        match self {
            ByMap::Read(plan) => plan
                .groups(settings)
                .iter()
                .map(|group| (group.slave, group.request()))
                .collect(),
            ByMap::Write(writes, _) => writes
                .iter()
                .map(|write| (write.slave, write.request.clone()))
                .collect(),
        }
    }
}
