//! A Home Assistant modbus configuration read as a register map, as Home Assistant reads
//! it. The file may hold a configuration with its `modbus:` key (other keys passed over),
//! one hub, a list of hubs (written for `modbus: !include`), or a list of entities (for
//! `sensors: !include`, each a sensor unless its keys are another platform's). `!secret`
//! values are looked up as Home Assistant looks them up, `!include` and the
//! `!include_dir_list` / `!include_dir_merge_list` tags read the files they name, and
//! anchors and merge keys are YAML's. Every platform's entities are points: sensors,
//! binary sensors, switches, lights, fans, covers and climates. Names are kept per
//! platform: a second entity of one platform with a name taken is left out with a
//! warning, as Home Assistant leaves it out, and a name two platforms use is given as
//! `platform.name` (`switch.pump`). Entities may overlap.

mod entity;
mod schema;

use std::collections::{HashMap, HashSet};
use std::time::Duration;

use serde::de::DeserializeOwned;
use serde_saphyr::Tagged;

use self::entity::{Platform, Values};
use self::schema::{Entity, Field, Hub, Included, List, Packages, Top};
use super::faults::Faults;
use super::map::{at, check_name, MapConnection, MapError, MapHub, Point, RegisterMap};

/// Where the files and secrets a configuration names are found.
pub trait Sources {
    /// The files a tag in file `from` names: for `!include`, the one file; for the
    /// `!include_dir_*` tags, each `.yaml` file of the folder, in the order of their names.
    /// Each as its name for messages and its text; or why they cannot be read.
    fn include(
        &mut self,
        from: &str,
        tag: &str,
        spec: &str,
    ) -> Result<Vec<(String, String)>, String>;
    /// The value of secret `name` for file `from`, found as Home Assistant finds it; or
    /// where it was looked for.
    fn secret(&mut self, from: &str, name: &str) -> Result<String, String>;
    /// The environment variable `name`, for `!env_var`; none where there is no environment.
    fn env(&mut self, _name: &str) -> Option<String> {
        None
    }
}

/// Text with no files around it: includes and secrets are not found.
pub struct NoSources;

impl Sources for NoSources {
    fn include(&mut self, _: &str, tag: &str, spec: &str) -> Result<Vec<(String, String)>, String> {
        Err(format!(
            "{tag} {spec}: the text has no folder to read it from"
        ))
    }

    fn secret(&mut self, _: &str, _: &str) -> Result<String, String> {
        Err("the text has no secrets.yaml beside it".into())
    }
}

/// How deep includes may nest: deeper is a file that includes itself.
const DEEPEST_INCLUDE: usize = 8;

/// Reads a Home Assistant modbus configuration; `file` names it in messages.
pub fn parse(file: &str, text: &str, sources: &mut dyn Sources) -> Result<RegisterMap, MapError> {
    let mut reader = Reader {
        sources,
        faults: Faults::default(),
        warnings: Vec::new(),
        points: Vec::new(),
        names: HashMap::new(),
        hub_places: HashSet::new(),
        hub_names: HashSet::new(),
        places: Vec::new(),
        hubs: Vec::new(),
        of_hub: Vec::new(),
    };
    reader.file(file, text, 0);
    reader.finish(file)
}

struct Reader<'a> {
    sources: &'a mut dyn Sources,
    faults: Faults<MapError>,
    warnings: Vec<String>,
    /// Each point with its platform.
    points: Vec<(Platform, Point)>,
    /// The entity names taken, per platform, and where.
    names: HashMap<(Platform, String), (String, usize)>,
    hub_places: HashSet<String>,
    hub_names: HashSet<String>,
    /// Where each hub loaded says its device is, or why that is not known.
    places: Vec<Result<Option<MapConnection>, String>>,
    /// The hubs loaded, their points gathered in `finish`.
    hubs: Vec<MapHub>,
    /// For each point, the hub it is an entity of and its `scan_interval`.
    of_hub: Vec<(Option<usize>, Option<Duration>)>,
}

/// A document read as YAML; `.nan` and `.inf` kept as text, so that the key that holds
/// them is told; comments passed over unread, however many lines of entities a user has
/// commented out.
fn yaml<T: DeserializeOwned>(text: &str) -> Result<T, serde_saphyr::Error> {
    let options = serde_saphyr::options! {
        reject_non_finite_typeless_float: false,
        emit_comments: false,
    };
    serde_saphyr::from_str_with_options(text, options)
}

/// A YAML reader's error at its line.
fn unreadable(file: &str, error: &serde_saphyr::Error) -> MapError {
    let line = error
        .location()
        .map_or(1, |l| usize::try_from(l.line()).unwrap_or(1));
    let message = match error.without_snippet() {
        // The YAML reader's guard against files that expand without end (aliases of
        // aliases); a real configuration is far below it.
        serde_saphyr::Error::Budget { .. } => {
            "larger than a YAML map may be (about 40,000 points): give a CSV map".to_string()
        }
        e => format!(
            "not a Home Assistant modbus configuration: {}",
            e.to_string().lines().next().unwrap_or_default()
        ),
    };
    at(file, line, message)
}

impl Reader<'_> {
    fn file(&mut self, file: &str, text: &str, depth: usize) {
        let top = match yaml::<Option<Top>>(text) {
            Ok(Some(top)) => top,
            Ok(None) => return,
            Err(e) => return self.faults.add(unreadable(file, &e)),
        };
        let hubs = match &top {
            Top::One(probe) => probe.is_hub(),
            Top::Many(probes) => probes.iter().any(schema::Probe::is_hub),
        };
        if !hubs {
            return match yaml::<Included<Entity>>(text) {
                Ok(Included::Items(entities)) => self.entities(file, None, entities, None),
                Ok(Included::Named(_)) => {}
                Err(e) => self.faults.add(unreadable(file, &e)),
            };
        }
        let hubs = match yaml::<Included<Hub>>(text) {
            Ok(Included::Items(hubs)) => hubs,
            Ok(Included::Named(_)) => return,
            Err(e) => return self.faults.add(unreadable(file, &e)),
        };
        for hub in hubs {
            self.configuration(file, hub, depth);
        }
    }

    /// A configuration (its hubs, wherever they are written, and its packages'), or a hub.
    fn configuration(&mut self, file: &str, mut hub: Hub, depth: usize) {
        let packages = hub.homeassistant.take().and_then(|core| core.packages);
        let configuration = hub.modbus.is_some() || packages.is_some();
        if let Some(packages) = packages {
            for (file, package) in self.packages(file, packages, depth) {
                self.configuration(&file, package, depth + 1);
            }
        }
        if !configuration {
            return self.hub(file, hub, depth);
        }
        for (file, hub) in self.list(file, hub.modbus, depth) {
            self.hub(&file, hub, depth);
        }
    }

    /// The packages of a configuration, each with the file it is written in: in place, a
    /// file of them (`!include`), a folder of one a file (`!include_dir_named`) or of
    /// several a file (`!include_dir_merge_named`).
    fn packages(
        &mut self,
        file: &str,
        packages: Tagged<Packages>,
        depth: usize,
    ) -> Vec<(String, Hub)> {
        let Tagged(packages, tag) = packages;
        let spec = match packages {
            Packages::Inline(packages) => {
                return packages
                    .into_values()
                    .map(|hub| (file.to_string(), hub))
                    .collect()
            }
            Packages::Named(spec) => spec,
        };
        let tag = tag.unwrap_or_default();
        if depth >= DEEPEST_INCLUDE || !tag.starts_with("!include") {
            self.faults.add(at(
                file,
                1,
                format!(
                    "packages: {tag} {spec}: give the packages in place or with !include_dir_named"
                ),
            ));
            return Vec::new();
        }
        let files = match self.sources.include(file, &tag, &spec) {
            Ok(files) => files,
            Err(why) => {
                self.faults.add(at(file, 1, format!("{tag} {spec}: {why}")));
                return Vec::new();
            }
        };
        let mut found = Vec::new();
        for (name, text) in files {
            let read: Result<Vec<Hub>, _> = match tag.as_str() {
                "!include_dir_named" => {
                    yaml::<Option<Hub>>(&text).map(|hub| hub.into_iter().collect())
                }
                _ => yaml::<Option<std::collections::BTreeMap<String, Hub>>>(&text)
                    .map(|packages| packages.unwrap_or_default().into_values().collect()),
            };
            match read {
                Ok(hubs) => found.extend(hubs.into_iter().map(|hub| (name.clone(), hub))),
                Err(e) => self.faults.add(unreadable(&name, &e)),
            }
        }
        found
    }

    /// The items of a list, each with the file it is written in.
    fn list<T: DeserializeOwned>(
        &mut self,
        file: &str,
        list: List<T>,
        depth: usize,
    ) -> Vec<(String, T)> {
        let Some(list) = list else {
            return Vec::new();
        };
        let tag = list.1.clone();
        match (list.0, tag.as_deref()) {
            (Included::Items(items), _) => items
                .into_iter()
                .map(|item| (file.to_string(), item))
                .collect(),
            (
                Included::Named(spec),
                Some(tag @ ("!include" | "!include_dir_list" | "!include_dir_merge_list")),
            ) => {
                if depth >= DEEPEST_INCLUDE {
                    self.faults.add(at(file, 1, format!("{tag} {spec}: includes nest deeper than {DEEPEST_INCLUDE}; does a file include itself?")));
                    return Vec::new();
                }
                let files = match self.sources.include(file, tag, &spec) {
                    Ok(files) => files,
                    Err(why) => {
                        self.faults.add(at(file, 1, format!("{tag} {spec}: {why}")));
                        return Vec::new();
                    }
                };
                let mut items = Vec::new();
                for (name, text) in files {
                    match yaml::<List<T>>(&text) {
                        Ok(inner) => items.extend(self.list(&name, inner, depth + 1)),
                        Err(e) => self.faults.add(unreadable(&name, &e)),
                    }
                }
                items
            }
            (Included::Named(spec), Some(tag)) => {
                self.faults.add(at(
                    file,
                    1,
                    format!("{tag} {spec}: a list is read here; give it in place or with !include"),
                ));
                Vec::new()
            }
            (Included::Named(text), None) => {
                self.faults.add(at(
                    file,
                    1,
                    format!("'{text}' where a list is read: give the list, or !include FILE"),
                ));
                Vec::new()
            }
        }
    }

    /// A hub: where it is, and its entities; a hub Home Assistant would not load (another
    /// of the same name or place, or one without entities) is left out with a warning.
    fn hub(&mut self, file: &str, hub: Hub, depth: usize) {
        let line = hub
            .name
            .as_ref()
            .map_or(1, |n| usize::try_from(n.referenced.line()).unwrap_or(1));
        let place = self.place(file, &hub, line);
        let key = match &place {
            Ok(Some(connection)) => connection.port.clone(),
            _ => format!("{line}@{file}"),
        };
        // Home Assistant names every hub without a name `modbus_hub`, so that a second
        // one is a duplicate.
        let name = hub
            .name
            .as_ref()
            .map_or_else(|| "modbus_hub".to_string(), |name| name.value.clone());
        if self.hub_places.contains(&key) || self.hub_names.contains(&name) {
            self.warnings.push(format!(
                "{file}:{line}: hub {name} at {key} is a duplicate; Home Assistant does not load it, so its entities are left out"
            ));
            return;
        }
        let lists = [
            (Platform::Sensor, hub.sensors),
            (Platform::BinarySensor, hub.binary_sensors),
            (Platform::Switch, hub.switches),
            (Platform::Light, hub.lights),
            (Platform::Fan, hub.fans),
            (Platform::Cover, hub.covers),
            (Platform::Climate, hub.climates),
        ];
        if lists.iter().all(|(_, list)| list.is_none()) {
            self.warnings.push(format!(
                "{file}:{line}: hub {name} has no entities; Home Assistant does not load it"
            ));
            return;
        }
        self.hub_places.insert(key);
        self.hub_names.insert(name.clone());
        self.hubs.push(MapHub {
            name: name.clone(),
            place: match &place {
                Ok(Some(connection)) => Ok(MapConnection {
                    hub: name.clone(),
                    ..connection.clone()
                }),
                Ok(None) => Err(format!("hub {name} is of a kind mbtool does not open")),
                Err(why) => Err(why.clone()),
            },
            points: Vec::new(),
        });
        let hub = self.hubs.len() - 1;
        self.places.push(place.map(|p| {
            p.map(|connection| MapConnection {
                hub: name.clone(),
                ..connection
            })
        }));
        for (platform, list) in lists {
            let entities = self.list(file, list, depth);
            for (file, entity) in entities {
                self.entities(&file, Some(platform), vec![entity], Some(hub));
            }
        }
    }

    /// Where a hub's device is, as `--port` and the line options would say it; `None` for
    /// a kind of hub mbtool does not open; an error for a place kept in a secret it cannot
    /// find, told only when the command line does not give the place.
    fn place(
        &mut self,
        file: &str,
        hub: &Hub,
        line: usize,
    ) -> Result<Option<MapConnection>, String> {
        let mut values = FileValues {
            sources: &mut *self.sources,
            file,
        };
        let mut text = |field: &Field, key: &str| values.text(field, key);
        let kind = text(&hub.kind, "type")?;
        let port = text(&hub.port, "port")?;
        let connection = match kind.as_deref() {
            Some(kind @ ("tcp" | "rtuovertcp")) => {
                let host = text(&hub.host, "host")?.unwrap_or_default();
                let scheme = if kind == "tcp" { "tcp" } else { "rtu+tcp" };
                let port = port.unwrap_or_else(|| "502".to_string());
                MapConnection {
                    port: format!("{scheme}://{host}:{port}"),
                    ..MapConnection::default()
                }
            }
            Some("serial") => {
                let whole = |text: Option<String>, key: &str| -> Result<Option<u32>, String> {
                    text.map(|t| {
                        t.trim()
                            .parse::<u32>()
                            .map_err(|_| format!("{key} '{t}' is not a number"))
                    })
                    .transpose()
                };
                let faulty = |e: String| format!("{file}:{line}: {e}");
                // What a serial line of Modbus can be (Home Assistant refuses more).
                let within = |bits: Option<u32>, key: &str, low: u32, high: u32| match bits {
                    Some(n) if !(low..=high).contains(&n) => {
                        Err(format!("{key} {n}: give {low} or {high}"))
                    }
                    bits => Ok(bits.map(|n| n as u8)),
                };
                MapConnection {
                    port: port.unwrap_or_default(),
                    mode: text(&hub.method, "method")?,
                    baud: whole(text(&hub.baudrate, "baudrate")?, "baudrate").map_err(faulty)?,
                    // Home Assistant takes E, O or N, and refuses any other.
                    parity: match text(&hub.parity, "parity")?.as_deref().map(str::trim) {
                        None => None,
                        Some(p @ ("E" | "O" | "N")) => p.chars().next(),
                        Some(other) => {
                            return Err(faulty(format!(
                                "parity '{other}': give E, O or N, as Home Assistant does"
                            )))
                        }
                    },
                    data_bits: whole(text(&hub.bytesize, "bytesize")?, "bytesize")
                        .and_then(|bits| within(bits, "bytesize", 7, 8))
                        .map_err(faulty)?,
                    stop_bits: whole(text(&hub.stopbits, "stopbits")?, "stopbits")
                        .and_then(|bits| within(bits, "stopbits", 1, 2))
                        .map_err(faulty)?,
                    ..MapConnection::default()
                }
            }
            _ => return Ok(None),
        };
        Ok(Some(connection))
    }

    /// Entities of a platform (or, for a bare list, of the platform each seems to be).
    fn entities(
        &mut self,
        file: &str,
        platform: Option<Platform>,
        entities: Vec<Entity>,
        hub: Option<usize>,
    ) {
        for entity in entities {
            let platform = platform.unwrap_or_else(|| Platform::guessed(&entity));
            let line = usize::try_from(entity.name.referenced.line()).unwrap_or(1);
            let name = entity.name.value.clone();
            if let Err(error) = check_name(&name) {
                self.faults.add(at(file, line, error));
                continue;
            }
            let key = (platform, name.clone());
            if let Some((first_file, first_line)) = self.names.get(&key) {
                self.warnings.push(format!(
                    "{file}:{line}: {} {name} is a duplicate of {first_file}:{first_line}; Home Assistant loads the first, so this one is left out",
                    platform.entity()
                ));
                continue;
            }
            self.names.insert(key, (file.to_string(), line));
            let mut values = FileValues {
                sources: &mut *self.sources,
                file,
            };
            let every = match values.text(&entity.scan_interval, "scan_interval") {
                Ok(every) => every,
                Err(error) => {
                    self.faults.add(at(file, line, format!("{name}: {error}")));
                    continue;
                }
            };
            let every = match every.map(|text| text.trim().parse::<u64>()) {
                None => None,
                Some(Ok(seconds)) => Some(Duration::from_secs(seconds)),
                Some(Err(_)) => {
                    self.faults.add(at(
                        file,
                        line,
                        format!("{name}: scan_interval is a whole number of seconds"),
                    ));
                    continue;
                }
            };
            match entity::points(platform, &entity, &mut values) {
                Ok(points) => {
                    self.of_hub.extend(points.iter().map(|_| (hub, every)));
                    self.points
                        .extend(points.into_iter().map(|point| (platform, point)));
                }
                Err(error) => self.faults.add(at(file, line, format!("{name}: {error}"))),
            }
        }
    }

    fn finish(self, file: &str) -> Result<RegisterMap, MapError> {
        let mut faults = self.faults;
        let mut hubs = self.hubs;
        for (point, (hub, every)) in self.of_hub.iter().enumerate() {
            if let Some(hub) = hub.and_then(|hub| hubs.get_mut(hub)) {
                hub.points.push((point, *every));
            }
        }
        // A name two platforms use is told apart by its platform, as Home Assistant's
        // entity ids are (`sensor.pump`, `switch.pump`).
        let mut platforms: HashMap<&str, HashSet<Platform>> = HashMap::new();
        for (platform, point) in &self.points {
            platforms
                .entry(point.name.as_str())
                .or_default()
                .insert(*platform);
        }
        let shared: HashSet<String> = platforms
            .into_iter()
            .filter(|(_, platforms)| platforms.len() > 1)
            .map(|(name, _)| name.to_string())
            .collect();
        let points: Vec<Point> = self
            .points
            .into_iter()
            .map(|(platform, mut point)| {
                if shared.contains(&point.name) {
                    point.name = format!("{}.{}", platform.entity(), point.name);
                }
                point
            })
            .collect();
        if points.is_empty() && faults.is_empty() {
            faults.add(at(file, 1, "the map names no point: no entity of sensors, binary_sensors, switches, lights, fans, covers or climates"));
        }
        // Several hubs that say different places are several devices, and a point does not
        // say which it is on: none is taken, and --port says which is meant.
        let mut places: Vec<Result<Option<MapConnection>, String>> = self.places;
        places.dedup();
        let (connection, unknown_place) = match places.as_slice() {
            [Ok(one)] => (one.clone(), None),
            [Err(why)] => (None, Some(why.clone())),
            [] => (None, None),
            several => {
                let at: Vec<String> = several
                    .iter()
                    .map(|place| match place {
                        Ok(Some(connection)) => {
                            format!("{} at {}", connection.hub, connection.port)
                        }
                        _ => "one whose place is not in the file".to_string(),
                    })
                    .collect();
                (
                    None,
                    Some(format!("its hubs are several devices ({})", at.join(", "))),
                )
            }
        };
        faults.or(
            RegisterMap {
                points,
                connection,
                hubs,
                unknown_place,
                warnings: self.warnings,
                // Home Assistant asks slave 1 of an entity without slave or device_address.
                default_slave: Some(1),
            },
            |errors, more| MapError::Several { errors, more },
        )
    }
}

/// The values of a file's fields, its secrets looked up for it.
struct FileValues<'a> {
    sources: &'a mut dyn Sources,
    file: &'a str,
}

impl Values for FileValues<'_> {
    fn text(&mut self, field: &Field, key: &str) -> Result<Option<String>, String> {
        let Some(Tagged(value, tag)) = field else {
            return Ok(None);
        };
        match tag.as_deref() {
            None => Ok(Some(value.clone())),
            Some(core) if core.starts_with("tag:yaml.org,2002:") => Ok(Some(value.clone())),
            Some("!secret") => self
                .sources
                .secret(self.file, value)
                .map(Some)
                .map_err(|looked| format!("{key} is !secret {value}, and {looked}")),
            // `!env_var NAME [DEFAULT]`, as Home Assistant reads it.
            Some("!env_var") => {
                let (name, default) = value
                    .split_once(char::is_whitespace)
                    .map_or((value.as_str(), None), |(name, default)| {
                        (name, Some(default.trim()))
                    });
                match (self.sources.env(name), default) {
                    (Some(set), _) => Ok(Some(set)),
                    (None, Some(default)) => Ok(Some(default.to_string())),
                    (None, None) => Err(format!("{key} is !env_var {name}, which is not set")),
                }
            }
            Some(tag) => Err(format!(
                "{key} is {tag} {value}, which is not read here: give the value"
            )),
        }
    }
}

#[cfg(test)]
mod tests;
