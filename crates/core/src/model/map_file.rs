//! A register map read from its file: Home Assistant YAML or CSV, told by the file's name.

use super::home_assistant;
use super::map::{parse_csv, MapError, RegisterMap};

/// Reads the map at `path`: Home Assistant YAML for a `.yaml` or `.yml` file, CSV otherwise.
pub fn load(path: &std::path::Path) -> Result<RegisterMap, MapError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| MapError::Unreadable {
        file: file.clone(),
        error: e.to_string(),
    })?;
    let yaml = path
        .extension()
        .is_some_and(|ext| ext.eq_ignore_ascii_case("yaml") || ext.eq_ignore_ascii_case("yml"));
    if yaml {
        home_assistant::parse(&file, &text)
    } else {
        parse_csv(&file, &text)
    }
}
