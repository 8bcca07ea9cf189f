//! Read device identification (43/14): the objects a device says of itself.

/// The answer to Read Device Identification (function 43, MEI type 14).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeviceIdentification {
    /// The read device ID code of the request, echoed.
    pub read_code: u8,
    /// Conformity level: 01 basic, 02 regular, 03 extended identification; 81-83 when
    /// single objects can be read too.
    pub conformity: u8,
    /// More objects remain than this answer holds: ask again from `next_object_id`.
    pub more_follows: bool,
    /// The object to ask for next when `more_follows`; 00 otherwise.
    pub next_object_id: u8,
    /// The objects this answer holds, in order.
    pub objects: Vec<DeviceObject>,
}

/// One identification object.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeviceObject {
    /// Object id: 00 VendorName, 01 ProductCode, 02 MajorMinorRevision, 03-06 the regular
    /// objects, 80-FF extended (private).
    pub id: u8,
    /// The object's bytes as sent; text for the standard objects.
    pub value: Vec<u8>,
}

/// The names of the standard identification objects 00-06, by id.
const OBJECT_NAMES: [&str; 7] = [
    "VendorName",
    "ProductCode",
    "MajorMinorRevision",
    "VendorUrl",
    "ProductName",
    "ModelName",
    "UserApplicationName",
];

impl DeviceObject {
    /// The name the specification gives object `id`; "reserved" for 07-7F, "private"
    /// for the extended objects 80-FF.
    pub fn name(id: u8) -> &'static str {
        match OBJECT_NAMES.get(usize::from(id)) {
            Some(name) => name,
            None if id < 0x80 => "reserved",
            None => "private",
        }
    }

    /// The id of a standard object by its name, in any case (`VendorUrl`, `vendorurl`).
    pub fn id_named(name: &str) -> Option<u8> {
        OBJECT_NAMES
            .iter()
            .position(|known| known.eq_ignore_ascii_case(name))
            .and_then(|id| u8::try_from(id).ok())
    }
}
