//! What a simulated slave says about itself: its device identification objects, read with
//! function 43/14 across as many requests as they need, and told by function 17 too.

use std::collections::BTreeMap;

use crate::codec::{limits, DeviceIdentification, DeviceObject, ExceptionCode, Response};

/// The vendor name a simulated slave gives by default.
pub const DEFAULT_VENDOR: &str = "mbtool";

/// The longest object a slave keeps: one object must fit in one answer.
pub const MAX_OBJECT_LEN: usize = MAX_OBJECTS_LEN - 2;

/// Room for objects in one answer: the PDU less function, MEI type, read code,
/// conformity, more follows, next object id and the object count.
const MAX_OBJECTS_LEN: usize = limits::MAX_PDU - 7;

/// Device identification objects by id: 00 VendorName, 01 ProductCode, 02
/// MajorMinorRevision (basic), 03-06 (regular), 80-FF (extended, the device's own).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Identity {
    objects: BTreeMap<u8, Vec<u8>>,
}

impl Default for Identity {
    fn default() -> Self {
        let mut identity = Self {
            objects: BTreeMap::new(),
        };
        identity.set(0x00, DEFAULT_VENDOR.as_bytes());
        identity.set(0x01, b"mbtool-sim");
        identity.set(0x02, env!("CARGO_PKG_VERSION").as_bytes());
        identity
    }
}

impl Identity {
    /// Sets object `id`, cut to [`MAX_OBJECT_LEN`] bytes.
    pub fn set(&mut self, id: u8, value: &[u8]) {
        let value = value.get(..MAX_OBJECT_LEN).unwrap_or(value);
        self.objects.insert(id, value.to_vec());
    }

    /// Object `id`, if the slave has it.
    pub fn get(&self, id: u8) -> Option<&[u8]> {
        self.objects.get(&id).map(Vec::as_slice)
    }

    /// The conformity level the objects give: 81 basic, 82 regular, 83 extended, each
    /// with single objects readable too.
    fn conformity(&self) -> u8 {
        match self.objects.keys().next_back() {
            Some(0x80..) => 0x83,
            Some(0x03..) => 0x82,
            _ => 0x81,
        }
    }

    /// The answer to read device identification with `read_code` from `object_id`: the
    /// objects of the category asked for, as many as fit, with where to go on when more
    /// follow. An object id the slave does not have starts the stream over from 00, as the
    /// specification says.
    pub(super) fn answer(&self, read_code: u8, object_id: u8) -> Result<Response, ExceptionCode> {
        let last = match read_code {
            0x01 => 0x02,
            0x02 => 0x7F,
            0x03 => 0xFF,
            0x04 => {
                let value = self
                    .get(object_id)
                    .ok_or(ExceptionCode::ILLEGAL_DATA_ADDRESS)?;
                return Ok(self.response(read_code, None, vec![(object_id, value)]));
            }
            _ => return Err(ExceptionCode::ILLEGAL_DATA_VALUE),
        };
        let first = if self.objects.contains_key(&object_id) && object_id <= last {
            object_id
        } else {
            0
        };
        let mut room = MAX_OBJECTS_LEN;
        let mut chosen = Vec::new();
        let mut next = None;
        for (id, value) in self.objects.range(first..=last) {
            if value.len() + 2 > room {
                next = Some(*id);
                break;
            }
            room -= value.len() + 2;
            chosen.push((*id, value.as_slice()));
        }
        Ok(self.response(read_code, next, chosen))
    }

    fn response(&self, read_code: u8, next: Option<u8>, objects: Vec<(u8, &[u8])>) -> Response {
        Response::ReadDeviceIdentification(DeviceIdentification {
            read_code,
            conformity: self.conformity(),
            more_follows: next.is_some(),
            next_object_id: next.unwrap_or(0),
            objects: objects
                .into_iter()
                .map(|(id, value)| DeviceObject {
                    id,
                    value: value.to_vec(),
                })
                .collect(),
        })
    }

    /// The data of report server id (17): the slave id, run indicator on, then vendor,
    /// product code and revision as text.
    pub(super) fn server_id(&self, slave: u8) -> Vec<u8> {
        let text: Vec<String> = (0x00..=0x02)
            .filter_map(|id| self.get(id))
            .map(|value| String::from_utf8_lossy(value).into_owned())
            .collect();
        let mut data = vec![slave, 0xFF];
        data.extend_from_slice(text.join(" ").as_bytes());
        data.truncate(limits::MAX_PDU - 2);
        data
    }
}

/// An object as `serve --identity` gives it: `NAME=VALUE`, NAME a standard object's name
/// (`VendorUrl`) or an object id (`0x80`).
pub fn parse_object(text: &str) -> Result<(u8, Vec<u8>), String> {
    let (name, value) = text
        .split_once('=')
        .ok_or_else(|| format!("'{text}': give NAME=VALUE, as VendorUrl=https://example.com"))?;
    let name = name.trim();
    let id = DeviceObject::id_named(name)
        .or_else(|| {
            crate::input::number::parse_int(name)
                .ok()
                .and_then(|id| u8::try_from(id).ok())
        })
        .ok_or_else(|| {
            format!(
                "'{name}' is no identification object: give VendorName, ProductCode, \
                 MajorMinorRevision, VendorUrl, ProductName, ModelName, UserApplicationName, \
                 or an id such as 0x80"
            )
        })?;
    if value.len() > MAX_OBJECT_LEN {
        return Err(format!(
            "{name} is {} bytes long; an object holds at most {MAX_OBJECT_LEN}",
            value.len()
        ));
    }
    Ok((id, value.as_bytes().to_vec()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stream(identity: &Identity, read_code: u8) -> Vec<DeviceIdentification> {
        let mut answers = Vec::new();
        let mut object_id = 0;
        loop {
            let Ok(Response::ReadDeviceIdentification(answer)) =
                identity.answer(read_code, object_id)
            else {
                panic!("no answer from {object_id}");
            };
            object_id = answer.next_object_id;
            let more = answer.more_follows;
            answers.push(answer);
            if !more {
                return answers;
            }
        }
    }

    #[test]
    fn objects_too_many_for_one_answer_stream_over_several() {
        let mut identity = Identity::default();
        identity.set(0x03, &[b'u'; 200]);
        identity.set(0x04, &[b'p'; 200]);
        identity.set(0x80, &[b'x'; 200]);
        let answers = stream(&identity, 0x03);
        assert_eq!(answers.len(), 3);
        let ids: Vec<u8> = answers
            .iter()
            .flat_map(|a| a.objects.iter().map(|o| o.id))
            .collect();
        assert_eq!(ids, [0x00, 0x01, 0x02, 0x03, 0x04, 0x80]);
        assert!(answers.iter().all(|a| a.conformity == 0x83));
        // Each answer fits one PDU.
        for answer in answers {
            let mut pdu = Vec::new();
            assert!(Response::ReadDeviceIdentification(answer)
                .encode(&mut pdu)
                .is_ok());
        }
        // The basic level stops at 02.
        let basic = stream(&identity, 0x01);
        assert_eq!(basic.len(), 1);
        assert_eq!(basic[0].objects.len(), 3);
    }

    #[test]
    fn an_unknown_object_restarts_the_stream_and_a_single_one_must_exist() {
        let identity = Identity::default();
        let Ok(Response::ReadDeviceIdentification(answer)) = identity.answer(0x01, 0x05) else {
            panic!()
        };
        assert_eq!(answer.objects[0].id, 0x00);
        assert_eq!(
            identity.answer(0x04, 0x05),
            Err(ExceptionCode::ILLEGAL_DATA_ADDRESS)
        );
        assert_eq!(
            identity.answer(0x09, 0),
            Err(ExceptionCode::ILLEGAL_DATA_VALUE)
        );
    }

    #[test]
    fn objects_by_name_or_id() {
        assert_eq!(
            parse_object("vendorurl=https://example.com"),
            Ok((0x03, b"https://example.com".to_vec()))
        );
        assert_eq!(parse_object("0x80=a=b"), Ok((0x80, b"a=b".to_vec())));
        assert!(parse_object("Colour=red").is_err());
        assert!(parse_object("VendorUrl").is_err());
    }
}
