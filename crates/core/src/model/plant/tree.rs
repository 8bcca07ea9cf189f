//! A plant file's values as a tree, each with the line it stands on, whether the file is
//! YAML or TOML: what the devices are read from, so that a fault names its line in
//! either.

use std::collections::BTreeMap;
use std::fmt;

use serde::de::{Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use serde_saphyr::Spanned;

/// A value and the line it stands on.
pub(super) struct Node {
    pub value: Tree,
    pub line: usize,
}

/// A value of a plant file: a scalar's text, a list, a table of keys, or nothing.
pub(super) enum Tree {
    Text(String),
    List(Vec<Node>),
    Map(BTreeMap<String, Node>),
    Nothing,
}

/// A file's top-level keys read from YAML, or the reader's error: its line and words.
pub(super) fn yaml(text: &str) -> Result<BTreeMap<String, Node>, (usize, String)> {
    // YAML 1.2's booleans: a device named `no` or `y` keeps its name.
    let options = serde_saphyr::options! { strict_booleans: true };
    let top: Option<BTreeMap<String, Spanned<Yaml>>> =
        serde_saphyr::from_str_with_options(text, options).map_err(|e| {
            let line = e
                .location()
                .map_or(1, |l| usize::try_from(l.line()).unwrap_or(1));
            // The reader's first line, without its own `error: line L column C: `.
            let said = e.to_string();
            let first = said.lines().next().unwrap_or_default();
            let first = first.strip_prefix("error: ").unwrap_or(first);
            let first = match first.split_once(": ") {
                Some((place, rest)) if place.starts_with("line ") => rest,
                _ => first,
            };
            (line, first.to_string())
        })?;
    Ok(top
        .unwrap_or_default()
        .into_iter()
        .map(|(key, value)| (key, yaml_node(value)))
        .collect())
}

fn yaml_node(spanned: Spanned<Yaml>) -> Node {
    let line = usize::try_from(spanned.referenced.line()).unwrap_or(1);
    let value = match spanned.value {
        Yaml::Text(text) => Tree::Text(text),
        Yaml::List(items) => Tree::List(items.into_iter().map(yaml_node).collect()),
        Yaml::Map(keys) => Tree::Map(keys.into_iter().map(|(k, v)| (k, yaml_node(v))).collect()),
        Yaml::Nothing => Tree::Nothing,
    };
    Node { value, line }
}

/// A file's top-level keys read from TOML, or the reader's error: its line and words.
pub(super) fn toml(text: &str) -> Result<BTreeMap<String, Node>, (usize, String)> {
    use toml::de::{DeTable, DeValue};
    let line_at = |offset: usize| text[..offset.min(text.len())].matches('\n').count() + 1;
    let top = DeTable::parse(text).map_err(|e| {
        let line = e.span().map_or(1, |span| line_at(span.start));
        // One line, as every fault is told.
        let said = e.message().split_whitespace().collect::<Vec<_>>().join(" ");
        (line, said)
    })?;
    fn node(value: &toml::Spanned<DeValue<'_>>, line_at: &dyn Fn(usize) -> usize) -> Node {
        let tree = match value.get_ref() {
            DeValue::String(text) => Tree::Text(text.to_string()),
            // With its radix (`0x11`), as a slave may be written.
            DeValue::Integer(n) => Tree::Text(n.to_string()),
            DeValue::Float(f) => Tree::Text(f.as_str().to_string()),
            DeValue::Boolean(b) => Tree::Text(b.to_string()),
            DeValue::Datetime(d) => Tree::Text(d.to_string()),
            DeValue::Array(items) => Tree::List(items.iter().map(|i| node(i, line_at)).collect()),
            DeValue::Table(keys) => Tree::Map(table(keys, line_at)),
        };
        Node {
            value: tree,
            line: line_at(value.span().start),
        }
    }
    fn table(keys: &DeTable<'_>, line_at: &dyn Fn(usize) -> usize) -> BTreeMap<String, Node> {
        keys.iter()
            .map(|(key, value)| (key.get_ref().to_string(), node(value, line_at)))
            .collect()
    }
    Ok(table(top.get_ref(), &line_at))
}

/// A value as YAML gives it, with where it stands.
enum Yaml {
    Text(String),
    List(Vec<Spanned<Yaml>>),
    Map(BTreeMap<String, Spanned<Yaml>>),
    Nothing,
}

impl<'de> Deserialize<'de> for Yaml {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Any;
        impl<'de> Visitor<'de> for Any {
            type Value = Yaml;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a value")
            }
            fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Yaml, E> {
                Ok(Yaml::Text(v.to_string()))
            }
            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<Yaml, E> {
                Ok(Yaml::Text(v.to_string()))
            }
            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<Yaml, E> {
                Ok(Yaml::Text(v.to_string()))
            }
            fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<Yaml, E> {
                Ok(Yaml::Text(v.to_string()))
            }
            fn visit_bool<E: serde::de::Error>(self, v: bool) -> Result<Yaml, E> {
                Ok(Yaml::Text(v.to_string()))
            }
            fn visit_unit<E: serde::de::Error>(self) -> Result<Yaml, E> {
                Ok(Yaml::Nothing)
            }
            fn visit_none<E: serde::de::Error>(self) -> Result<Yaml, E> {
                Ok(Yaml::Nothing)
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Yaml, A::Error> {
                let mut items = Vec::new();
                while let Some(item) = seq.next_element::<Spanned<Yaml>>()? {
                    items.push(item);
                }
                Ok(Yaml::List(items))
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Yaml, A::Error> {
                let mut keys = BTreeMap::new();
                while let Some((key, value)) = map.next_entry::<String, Spanned<Yaml>>()? {
                    keys.insert(key, value);
                }
                Ok(Yaml::Map(keys))
            }
        }
        deserializer.deserialize_any(Any)
    }
}
