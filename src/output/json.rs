//! JSON Lines written a field at a time. A sniffer writes millions of frames, and serde's
//! flattening (a map serializer, its keys escaped one by one) cost more than everything
//! else a frame needs: here the keys are written as they are, and only the values go
//! through serde_json.

use std::io;

use serde::Serialize;

/// A JSON object written a field at a time into a line.
pub struct JsonObject<'a> {
    line: &'a mut Vec<u8>,
    empty: bool,
}

impl<'a> JsonObject<'a> {
    pub fn open(line: &'a mut Vec<u8>) -> Self {
        // Room for a whole line of a frame, so that the fields do not grow it one by one.
        line.reserve(512);
        line.push(b'{');
        Self { line, empty: true }
    }

    /// `key` must need no escaping: the keys are mbtool's own. Inlined, so that a key
    /// given as a literal is copied as a constant, not through a call to `memcpy`.
    #[inline(always)]
    fn key(&mut self, key: &str) {
        if !self.empty {
            self.line.push(b',');
        }
        self.empty = false;
        self.line.push(b'"');
        self.line.extend_from_slice(key.as_bytes());
        self.line.extend_from_slice(b"\":");
    }

    #[inline(always)]
    pub fn field(&mut self, key: &str, value: &(impl Serialize + ?Sized)) -> io::Result<()> {
        self.key(key);
        Ok(serde_json::to_writer(&mut *self.line, value)?)
    }

    pub fn field_if(&mut self, key: &str, value: Option<&impl Serialize>) -> io::Result<()> {
        match value {
            Some(value) => self.field(key, value),
            None => Ok(()),
        }
    }

    /// A string that needs no escaping, written as it is: mbtool's own names (a function's,
    /// a kind's) and spaced hex (`push_spaced_hex`).
    #[inline(always)]
    pub fn plain(&mut self, key: &str, text: &str) {
        debug_assert!(!text.bytes().any(|b| b == b'"' || b == b'\\' || b < 0x20));
        self.key(key);
        self.line.push(b'"');
        self.line.extend_from_slice(text.as_bytes());
        self.line.push(b'"');
    }

    /// A socket address as a string, as `Display` writes it (its text needs no escaping).
    /// IPv4, nearly every capture's, digit by digit: the formatter's machinery cost a
    /// tenth of a TCP frame's line.
    pub fn address(&mut self, key: &str, address: &std::net::SocketAddr) {
        use std::io::Write;
        self.key(key);
        self.line.push(b'"');
        match address {
            std::net::SocketAddr::V4(address) => {
                let mut digits = itoa::Buffer::new();
                for (i, octet) in address.ip().octets().into_iter().enumerate() {
                    if i > 0 {
                        self.line.push(b'.');
                    }
                    self.line.extend_from_slice(digits.format(octet).as_bytes());
                }
                self.line.push(b':');
                self.line
                    .extend_from_slice(digits.format(address.port()).as_bytes());
            }
            // Writing into a vector cannot fail.
            std::net::SocketAddr::V6(address) => {
                let _ = write!(self.line, "{address}");
            }
        }
        self.line.push(b'"');
    }

    /// An integer, written digit by digit.
    #[inline(always)]
    pub fn number(&mut self, key: &str, value: impl itoa::Integer) {
        self.key(key);
        self.line
            .extend_from_slice(itoa::Buffer::new().format(value).as_bytes());
    }

    /// An array of integers, written digit by digit.
    pub fn numbers<N: itoa::Integer>(&mut self, key: &str, values: impl IntoIterator<Item = N>) {
        self.key(key);
        self.line.push(b'[');
        let mut digits = itoa::Buffer::new();
        for (i, value) in values.into_iter().enumerate() {
            if i > 0 {
                self.line.push(b',');
            }
            self.line.extend_from_slice(digits.format(value).as_bytes());
        }
        self.line.push(b']');
    }

    /// The fields of `value`, which serializes as an object, as fields of this one: what
    /// `#[serde(flatten)]` does, without its cost.
    pub fn flatten(&mut self, value: &impl Serialize) -> io::Result<()> {
        let start = self.line.len();
        serde_json::to_writer(&mut *self.line, value)?;
        if self.line.len() - start <= 2 {
            // `{}`: nothing to add.
            self.line.truncate(start);
            return Ok(());
        }
        self.line.pop();
        if self.empty {
            self.line.remove(start);
        } else {
            self.line[start] = b',';
        }
        self.empty = false;
        Ok(())
    }

    pub fn close(self) {
        self.line.push(b'}');
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn written(fill: impl FnOnce(&mut JsonObject) -> io::Result<()>) -> String {
        let mut line = Vec::new();
        let mut object = JsonObject::open(&mut line);
        fill(&mut object).unwrap();
        object.close();
        String::from_utf8(line).unwrap()
    }

    #[test]
    fn flattened_objects_join_the_fields_around_them() {
        let inner = serde_json::json!({"b": 2, "c": "x\"y"});
        let empty = serde_json::json!({});
        assert_eq!(
            written(|o| {
                o.flatten(&inner)?;
                o.field("d", &[1, 2])?;
                o.flatten(&empty)?;
                o.field_if("e", None::<&u8>)?;
                o.plain("f", "01 02");
                o.field("g", "a\nb")
            }),
            r#"{"b":2,"c":"x\"y","d":[1,2],"f":"01 02","g":"a\nb"}"#
        );
        assert_eq!(written(|o| o.flatten(&empty)), "{}");
        assert_eq!(
            written(|o| {
                o.field("a", &1)?;
                o.flatten(&inner)
            }),
            r#"{"a":1,"b":2,"c":"x\"y"}"#
        );
    }
}
