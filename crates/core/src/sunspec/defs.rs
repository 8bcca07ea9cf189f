//! The SunSpec Alliance's model definitions, as they publish them (`models/`, their JSON,
//! unchanged): each model's groups of points, with types, sizes, scale factors, units and
//! symbols. A definition is read from its JSON when a device has that model.

use serde::Deserialize;

/// One model's definition.
#[derive(Clone, Debug, Deserialize, PartialEq)]
pub struct ModelDef {
    /// The model's id.
    pub id: u16,
    /// Its top group: the model's own points, then its groups.
    pub group: GroupDef,
}

/// A group of points, maybe repeated.
#[derive(Clone, Debug, Deserialize, PartialEq)]
pub struct GroupDef {
    /// Its name (`inverter_three_phase`, `module`).
    pub name: String,
    /// Its name for people.
    #[serde(default)]
    pub label: Option<String>,
    /// Its points, in register order.
    #[serde(default)]
    pub points: Vec<PointDef>,
    /// Its groups, after its points.
    #[serde(default)]
    pub groups: Vec<GroupDef>,
    /// How many times it repeats; absent for a group that is there once.
    #[serde(default)]
    pub count: Option<Count>,
}

/// How many times a group repeats.
#[derive(Clone, Debug, Deserialize, PartialEq, Eq)]
#[serde(untagged)]
pub enum Count {
    /// A fixed number; 0 repeats it to fill the model's length.
    Fixed(u16),
    /// The value of the point of this name, before the group.
    Point(String),
}

/// A scale factor: a point's name, or a fixed power of ten.
#[derive(Clone, Debug, Deserialize, PartialEq, Eq)]
#[serde(untagged)]
pub enum ScaleFactor {
    /// A fixed power of ten.
    Fixed(i16),
    /// The value of the `sunssf` point of this name.
    Point(String),
}

/// One point's definition.
#[derive(Clone, Debug, Deserialize, PartialEq)]
pub struct PointDef {
    /// Its name, unique in its group.
    pub name: String,
    /// Its name for people.
    #[serde(default)]
    pub label: Option<String>,
    /// Its type, as SunSpec names it (`uint16`, `acc32`, `sunssf`, `string`...).
    #[serde(rename = "type")]
    pub point_type: PointType,
    /// Registers it takes.
    pub size: u16,
    /// Its scale factor.
    #[serde(default)]
    pub sf: Option<ScaleFactor>,
    /// Its unit.
    #[serde(default)]
    pub units: Option<String>,
    /// `RW` where it may be written.
    #[serde(default)]
    pub access: Option<String>,
    /// The names of its values (an enum) or of its bits (a bitfield).
    #[serde(default)]
    pub symbols: Vec<Symbol>,
}

/// A value of an enum, or a bit of a bitfield, by name.
#[derive(Clone, Debug, Deserialize, PartialEq)]
pub struct Symbol {
    /// Its name.
    pub name: String,
    /// The value, or the bit's number.
    pub value: u64,
}

/// SunSpec's point types.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
#[allow(missing_docs)]
pub enum PointType {
    Int16,
    Uint16,
    Count,
    Acc16,
    Enum16,
    Bitfield16,
    Pad,
    Int32,
    Uint32,
    Acc32,
    Enum32,
    Bitfield32,
    Ipaddr,
    Int64,
    Uint64,
    Acc64,
    Float32,
    Float64,
    String,
    Sunssf,
    Eui48,
    Ipv6addr,
}

/// A model definition that does not read: the published file has changed shape.
#[derive(Debug, thiserror::Error)]
#[error("the SunSpec definition of model {id} does not read: {reason}")]
pub struct DefError {
    /// The model.
    pub id: u16,
    /// What is wrong with it.
    pub reason: String,
}

macro_rules! published {
    ($($id:literal),* $(,)?) => {
        /// The published definitions: each model's id and its JSON.
        const PUBLISHED: &[(u16, &str)] = &[
            $(($id, include_str!(concat!("models/model_", stringify!($id), ".json"))),)*
        ];
    };
}

published!(
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 101, 102, 103, 111, 112,
    113, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137,
    138, 139, 140, 141, 142, 143, 144, 145, 160, 201, 202, 203, 204, 211, 212, 213, 214, 220, 302,
    303, 304, 305, 306, 307, 308, 401, 402, 403, 404, 501, 502, 601, 701, 702, 703, 704, 705, 706,
    707, 708, 709, 710, 711, 712, 713, 714, 715, 801, 802, 803, 804, 805, 806, 807, 808, 809,
    63001, 63002, 64001, 64020, 64101, 64111, 64112, 64410, 64411, 64412, 64413, 64414, 64415,
);

/// The definition of model `id`; `None` for a model SunSpec has not published (a vendor's
/// own, 64000 and up, or one newer than these files).
pub fn definition(id: u16) -> Option<Result<ModelDef, DefError>> {
    let (_, json) = PUBLISHED.iter().find(|(known, _)| *known == id)?;
    Some(
        serde_json::from_str::<ModelDef>(json).map_err(|error| DefError {
            id,
            reason: error.to_string(),
        }),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_published_file_is_listed_and_reads() {
        let folder = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/sunspec/models");
        let mut files: Vec<u16> = std::fs::read_dir(folder)
            .unwrap()
            .filter_map(|entry| {
                let name = entry.unwrap().file_name().into_string().unwrap();
                name.strip_prefix("model_")?
                    .strip_suffix(".json")?
                    .parse()
                    .ok()
            })
            .collect();
        files.sort_unstable();
        let listed: Vec<u16> = PUBLISHED.iter().map(|(id, _)| *id).collect();
        assert_eq!(listed, files);
        for id in listed {
            let model = definition(id).unwrap().unwrap();
            assert_eq!(model.id, id);
            assert_eq!(model.group.points[0].name, "ID");
            assert_eq!(model.group.points[1].name, "L");
        }
    }

    #[test]
    fn the_common_model_and_an_inverter() {
        let common = definition(1).unwrap().unwrap();
        assert_eq!(common.group.name, "common");
        let manufacturer = &common.group.points[2];
        assert_eq!((manufacturer.name.as_str(), manufacturer.size), ("Mn", 16));
        assert_eq!(manufacturer.point_type, PointType::String);
        let mppt = definition(160).unwrap().unwrap();
        assert_eq!(mppt.group.groups[0].count, Some(Count::Fixed(0)));
        let current = &mppt.group.groups[0].points[2];
        assert_eq!(current.sf, Some(ScaleFactor::Point("DCA_SF".into())));
        assert!(definition(64999).is_none());
    }
}
