//! A register map read from its file: Home Assistant YAML or CSV, told by the file's name;
//! for YAML, the files it includes and the secrets it names found beside it.

use std::path::{Path, PathBuf};

use super::home_assistant::{self, Sources};
use super::map::{parse_csv, MapError, RegisterMap};

/// Reads the map at `path`: Home Assistant YAML for a `.yaml` or `.yml` file, CSV otherwise.
pub fn load(path: &Path) -> Result<RegisterMap, MapError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| MapError::Unreadable {
        file: file.clone(),
        error: e.to_string(),
    })?;
    if is_yaml(path) {
        home_assistant::parse(&file, &text, &mut Folder)
    } else {
        parse_csv(&file, &text)
    }
}

fn is_yaml(path: &Path) -> bool {
    path.extension()
        .is_some_and(|ext| ext.eq_ignore_ascii_case("yaml") || ext.eq_ignore_ascii_case("yml"))
}

/// The YAML files in `folder` and the folders in it, as Home Assistant walks them for the
/// `!include_dir_*` tags: hidden files and folders passed over, and no deeper than a
/// configuration is kept.
fn yaml_files(folder: &Path, found: &mut Vec<PathBuf>, depth: usize) {
    let Ok(entries) = std::fs::read_dir(folder) else {
        return;
    };
    for path in entries.filter_map(Result::ok).map(|entry| entry.path()) {
        let hidden = path
            .file_name()
            .is_some_and(|name| name.to_string_lossy().starts_with('.'));
        if hidden {
            continue;
        }
        if path.is_dir() && depth < 8 {
            yaml_files(&path, found, depth + 1);
        } else if is_yaml(&path) {
            found.push(path);
        }
    }
}

/// The files beside a configuration, as Home Assistant reads them.
struct Folder;

/// The folder a file named `from` is in.
fn folder_of(from: &str) -> PathBuf {
    Path::new(from)
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

impl Sources for Folder {
    fn include(
        &mut self,
        from: &str,
        tag: &str,
        spec: &str,
    ) -> Result<Vec<(String, String)>, String> {
        let target = folder_of(from).join(spec);
        let read = |path: &Path| {
            std::fs::read_to_string(path)
                .map(|text| (path.display().to_string(), text))
                .map_err(|e| format!("cannot read {}: {e}", path.display()))
        };
        if tag == "!include" {
            return read(&target).map(|one| vec![one]);
        }
        std::fs::read_dir(&target)
            .map_err(|e| format!("cannot read the folder {}: {e}", target.display()))?;
        let mut paths = Vec::new();
        yaml_files(&target, &mut paths, 0);
        paths.sort();
        paths.iter().map(|path| read(path)).collect()
    }

    fn env(&mut self, name: &str) -> Option<String> {
        std::env::var(name).ok()
    }

    /// The `secrets.yaml` beside the file, then in each folder above it, the first that
    /// has the name, as Home Assistant looks up from an included file to its configuration.
    fn secret(&mut self, from: &str, name: &str) -> Result<String, String> {
        let start = folder_of(from);
        let mut looked = Vec::new();
        for folder in start.ancestors() {
            let path = folder.join("secrets.yaml");
            let Ok(text) = std::fs::read_to_string(&path) else {
                continue;
            };
            looked.push(path.display().to_string());
            let secrets: Result<
                std::collections::HashMap<String, serde_saphyr::Tagged<String>>,
                _,
            > = serde_saphyr::from_str(&text);
            if let Some(value) = secrets.ok().and_then(|mut s| s.remove(name)) {
                return Ok(value.0);
            }
        }
        Err(match looked.as_slice() {
            [] => format!(
                "no secrets.yaml was found in {} or a folder above it",
                start.display()
            ),
            files => format!("{} does not have it", files.join(" nor ")),
        })
    }
}
