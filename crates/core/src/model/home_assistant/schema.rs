//! The keys of a Home Assistant modbus configuration mbtool reads, as YAML gives them.
//! Every scalar is kept as its text with its tag (`!secret pump_host`), so that a secret
//! or an include is told where it stands; the keys not named here are Home Assistant's
//! own (`scan_interval`, `device_class`, ...) and passed over.

use std::fmt;
use std::marker::PhantomData;

use serde::de::value::{MapAccessDeserializer, SeqAccessDeserializer};
use serde::de::{Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use serde_saphyr::{Spanned, Tagged};

/// A scalar as written, with its tag.
pub(super) type Field = Option<Tagged<String>>;

/// A list of items written in place (one item alone is a list of one, as Home Assistant's
/// `ensure_list` takes it), or the file or folder a tag names (`!include sensors.yaml`).
pub(super) enum Included<T> {
    Items(Vec<T>),
    Named(String),
}

/// Where a list came from: written in place, or named by a tag.
pub(super) type List<T> = Option<Tagged<Included<T>>>;

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Included<T> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Items<T>(PhantomData<T>);
        impl<'de, T: Deserialize<'de>> Visitor<'de> for Items<T> {
            type Value = Included<T>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a list, a mapping or an !include")
            }
            fn visit_str<E: serde::de::Error>(self, name: &str) -> Result<Self::Value, E> {
                Ok(Included::Named(name.to_string()))
            }
            fn visit_unit<E: serde::de::Error>(self) -> Result<Self::Value, E> {
                Ok(Included::Items(Vec::new()))
            }
            fn visit_none<E: serde::de::Error>(self) -> Result<Self::Value, E> {
                Ok(Included::Items(Vec::new()))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
                Vec::<T>::deserialize(SeqAccessDeserializer::new(seq)).map(Included::Items)
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Self::Value, A::Error> {
                T::deserialize(MapAccessDeserializer::new(map))
                    .map(|one| Included::Items(vec![one]))
            }
        }
        deserializer.deserialize_any(Items(PhantomData))
    }
}

/// A configuration's `homeassistant:` section: its packages, each a configuration of its
/// own whose `modbus:` hubs Home Assistant merges with the others.
#[derive(Default, Deserialize)]
pub(super) struct Core {
    pub packages: Option<Tagged<Packages>>,
}

/// Packages by name, written in place, or the file or folder a tag names
/// (`!include_dir_named packages`).
pub(super) enum Packages {
    Inline(std::collections::BTreeMap<String, Hub>),
    Named(String),
}

impl<'de> Deserialize<'de> for Packages {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct ByName;
        impl<'de> Visitor<'de> for ByName {
            type Value = Packages;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("packages by name, or an !include_dir_named")
            }
            fn visit_str<E: serde::de::Error>(self, name: &str) -> Result<Packages, E> {
                Ok(Packages::Named(name.to_string()))
            }
            fn visit_unit<E: serde::de::Error>(self) -> Result<Packages, E> {
                Ok(Packages::Inline(Default::default()))
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Packages, A::Error> {
                Deserialize::deserialize(MapAccessDeserializer::new(map)).map(Packages::Inline)
            }
        }
        deserializer.deserialize_any(ByName)
    }
}

/// A mapping at the top of a file, or in a list of hubs: a configuration with `modbus:`
/// (or packages that have one), or a hub.
#[derive(Default, Deserialize)]
pub(super) struct Hub {
    pub homeassistant: Option<Core>,
    pub modbus: List<Hub>,
    pub name: Option<Spanned<String>>,
    #[serde(rename = "type")]
    pub kind: Field,
    pub host: Field,
    pub port: Field,
    pub baudrate: Field,
    pub parity: Field,
    pub bytesize: Field,
    pub stopbits: Field,
    pub method: Field,
    pub sensors: List<Entity>,
    pub binary_sensors: List<Entity>,
    pub switches: List<Entity>,
    pub lights: List<Entity>,
    pub fans: List<Entity>,
    pub covers: List<Entity>,
    pub climates: List<Entity>,
}

/// What a file holds at its top: a mapping, or a list (of hubs or of entities).
pub(super) enum Top {
    One(Probe),
    Many(Vec<Probe>),
}

/// The keys that tell a hub from an entity.
#[derive(Default, Deserialize)]
pub(super) struct Probe {
    pub homeassistant: Option<serde::de::IgnoredAny>,
    pub modbus: Option<serde::de::IgnoredAny>,
    pub address: Option<serde::de::IgnoredAny>,
    #[serde(rename = "type")]
    pub kind: Option<serde::de::IgnoredAny>,
    pub host: Option<serde::de::IgnoredAny>,
    pub sensors: Option<serde::de::IgnoredAny>,
    pub binary_sensors: Option<serde::de::IgnoredAny>,
    pub switches: Option<serde::de::IgnoredAny>,
    pub lights: Option<serde::de::IgnoredAny>,
    pub fans: Option<serde::de::IgnoredAny>,
    pub covers: Option<serde::de::IgnoredAny>,
    pub climates: Option<serde::de::IgnoredAny>,
}

impl Probe {
    /// Whether it is a hub (or a configuration), not an entity.
    pub(super) fn is_hub(&self) -> bool {
        self.address.is_none()
            && [
                &self.homeassistant,
                &self.modbus,
                &self.kind,
                &self.host,
                &self.sensors,
                &self.binary_sensors,
                &self.switches,
                &self.lights,
                &self.fans,
                &self.covers,
                &self.climates,
            ]
            .iter()
            .any(|key| key.is_some())
    }
}

impl<'de> Deserialize<'de> for Top {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Shape;
        impl<'de> Visitor<'de> for Shape {
            type Value = Top;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a mapping or a list")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Top, A::Error> {
                Vec::<Probe>::deserialize(SeqAccessDeserializer::new(seq)).map(Top::Many)
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Top, A::Error> {
                Probe::deserialize(MapAccessDeserializer::new(map)).map(Top::One)
            }
        }
        deserializer.deserialize_any(Shape)
    }
}

/// An entity of any platform: the keys of each that say where its state is and how it
/// is shown.
#[derive(Deserialize)]
pub(super) struct Entity {
    pub name: Spanned<String>,
    pub address: Field,
    pub slave: Field,
    pub device_address: Field,
    pub input_type: Field,
    pub write_type: Field,
    pub data_type: Field,
    pub swap: Field,
    pub count: Field,
    pub structure: Field,
    pub scale: Field,
    pub offset: Field,
    pub precision: Field,
    pub min_value: Field,
    pub max_value: Field,
    pub nan_value: Field,
    pub zero_suppress: Field,
    pub unit_of_measurement: Field,
    pub slave_count: Field,
    pub virtual_count: Field,
    pub verify: Option<Option<Verify>>,
    pub status_register: Field,
    pub status_register_type: Field,
    pub command_on: Field,
    pub command_off: Field,
    pub target_temp_register: Option<serde::de::IgnoredAny>,
    pub state_open: Field,
    pub state_closed: Field,
    pub state_opening: Field,
    pub state_closing: Field,
    /// How often Home Assistant reads it, in seconds.
    pub scan_interval: Field,
}

/// A switch's `verify:`, where its state is read back.
#[derive(Deserialize)]
pub(super) struct Verify {
    pub address: Field,
    pub input_type: Field,
    pub state_on: Option<Numbers>,
    pub state_off: Option<Numbers>,
}

/// A number or a list of them (`state_on: 1`, `state_on: [1, 2]`).
pub(super) struct Numbers(pub Vec<i64>);

impl<'de> Deserialize<'de> for Numbers {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct OneOrMany;
        impl<'de> Visitor<'de> for OneOrMany {
            type Value = Numbers;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number or a list of numbers")
            }
            fn visit_i64<E: serde::de::Error>(self, n: i64) -> Result<Numbers, E> {
                Ok(Numbers(vec![n]))
            }
            fn visit_u64<E: serde::de::Error>(self, n: u64) -> Result<Numbers, E> {
                i64::try_from(n)
                    .map(|n| Numbers(vec![n]))
                    .map_err(E::custom)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Numbers, A::Error> {
                let mut numbers = Vec::new();
                while let Some(n) = seq.next_element::<i64>()? {
                    numbers.push(n);
                }
                Ok(Numbers(numbers))
            }
        }
        deserializer.deserialize_any(OneOrMany)
    }
}
