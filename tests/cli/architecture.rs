//! The rules of ARCHITECTURE.md that the sources can be checked against: no import circle
//! between files, no file too long to hold one job, only `main.rs` and the settings module
//! know the command line's types, and the core knows nothing of the binary.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// A module by its crate-qualified path: `["mbtool_core", "codec", "framing"]`.
type ModulePath = Vec<String>;
/// Which modules each module imports from.
type Imports = BTreeMap<ModulePath, BTreeSet<ModulePath>>;

/// A source file and the module path it holds (`codec::framing::rtu`).
struct Module {
    file: PathBuf,
    path: Vec<String>,
}

/// The modules of the crate whose `lib.rs`/`main.rs` sit in `src`, named from `crate`.
fn modules(src: &Path) -> Vec<Module> {
    let mut found = Vec::new();
    let mut stack = vec![src.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let file = entry.unwrap().path();
            if file.is_dir() {
                stack.push(file);
                continue;
            }
            if file.extension().is_none_or(|e| e != "rs") {
                continue;
            }
            let relative = file.strip_prefix(src).unwrap().with_extension("");
            let mut path: Vec<String> = relative
                .components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect();
            if matches!(
                path.last().map(String::as_str),
                Some("mod" | "lib" | "main")
            ) {
                path.pop();
            }
            found.push(Module { file, path });
        }
    }
    found
}

/// The module paths a file's text names (`crate::a::b`, `super::c`, `mbtool_core::d`),
/// one level of braces expanded, made absolute from the file's own module.
fn named_paths(text: &str, module: &[String], crate_name: &str) -> Vec<Vec<String>> {
    let code: String = text
        .lines()
        .filter(|line| !line.trim_start().starts_with("//"))
        .take_while(|line| !line.starts_with("#[cfg(test)]"))
        .collect::<Vec<_>>()
        .join("\n");
    let mut paths = Vec::new();
    let starts = ["crate::", "super::", "mbtool_core::", "mbtool::"];
    let bytes = code.as_bytes();
    let mut i = 0;
    while i < code.len() {
        let Some(start) = starts.iter().find(|s| bytes[i..].starts_with(s.as_bytes())) else {
            i += 1;
            continue;
        };
        let boundary = i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_');
        if !boundary {
            i += start.len();
            continue;
        }
        let mut end = i;
        while end < code.len()
            && (bytes[end].is_ascii_alphanumeric() || bytes[end] == b'_' || bytes[end] == b':')
        {
            end += 1;
        }
        let head = code[i..end].trim_end_matches(':').to_string();
        let mut items = vec![head.clone()];
        if code[end..].starts_with('{') {
            if let Some(close) = code[end..].find('}') {
                items = code[end + 1..end + close]
                    .split(',')
                    .map(|item| format!("{head}::{}", item.trim()))
                    .collect();
            }
        }
        for item in items {
            let words: Vec<&str> = item.split("::").filter(|w| !w.is_empty()).collect();
            let mut absolute: Vec<String> = match words.first() {
                Some(&"crate") => vec![crate_name.to_string()],
                Some(&"mbtool_core") => vec!["mbtool_core".to_string()],
                Some(&"mbtool") => vec!["mbtool".to_string()],
                Some(&"super") => {
                    // The parent of the file's module: `a` for `a/b.rs`, the root for `a/mod.rs`.
                    let mut path = vec![crate_name.to_string()];
                    path.extend(module.iter().cloned());
                    path.pop();
                    path
                }
                _ => continue,
            };
            let mut rest = words.iter().skip(1).peekable();
            while rest.peek() == Some(&&"super") {
                absolute.pop();
                rest.next();
            }
            absolute.extend(rest.map(|w| w.to_string()));
            paths.push(absolute);
        }
        i = end;
    }
    paths
}

/// Every file of both crates, keyed by its crate-qualified module path.
fn graph() -> (BTreeMap<ModulePath, PathBuf>, Imports) {
    let mut files = BTreeMap::new();
    let mut sources = Vec::new();
    for (crate_name, src) in [
        ("mbtool", Path::new(ROOT).join("src")),
        ("mbtool_core", Path::new(ROOT).join("crates/core/src")),
    ] {
        for module in modules(&src) {
            let mut key = vec![crate_name.to_string()];
            key.extend(module.path.clone());
            // main.rs is the binary: a crate of its own that uses `mbtool`.
            if module.file.ends_with("src/main.rs") {
                key = vec!["main".to_string()];
            }
            files.insert(key.clone(), module.file.clone());
            sources.push((crate_name, key, module));
        }
    }
    let mut edges: Imports = BTreeMap::new();
    // Unit tests beside a module (`tests.rs`, `tests/`) are the module's, not a room's.
    let is_test = |module: &Module| module.path.iter().any(|part| part == "tests");
    for (crate_name, key, module) in sources.iter().filter(|(_, _, m)| !is_test(m)) {
        let text = std::fs::read_to_string(&module.file).unwrap();
        // Files under src/cmd belong to the binary: `crate` there is the binary's.
        let in_binary = module.file.starts_with(Path::new(ROOT).join("src/cmd"))
            || module.file.ends_with("src/main.rs");
        let own = if in_binary { "main" } else { crate_name };
        for named in named_paths(&text, &module.path, own) {
            let named = if named.first().map(String::as_str) == Some("main") {
                let mut path = vec!["mbtool".to_string()];
                path.extend(named[1..].iter().cloned());
                path
            } else {
                named
            };
            // The longest prefix that is a file.
            let target = (1..=named.len())
                .rev()
                .map(|n| named[..n].to_vec())
                .find(|prefix| files.contains_key(prefix));
            let Some(target) = target else { continue };
            // A module's own file re-exporting its children is a facade, not a dependency.
            let descendant = target.len() > key.len() && target.starts_with(key);
            if &target != key && !descendant {
                edges.entry(key.clone()).or_default().insert(target);
            }
        }
    }
    (files, edges)
}

/// The files that import each other, directly or around a circle (Tarjan's algorithm).
fn circles(edges: &Imports) -> Vec<Vec<ModulePath>> {
    struct State<'a> {
        edges: &'a Imports,
        index: BTreeMap<&'a Vec<String>, usize>,
        low: BTreeMap<&'a Vec<String>, usize>,
        stack: Vec<&'a Vec<String>>,
        on_stack: BTreeSet<&'a Vec<String>>,
        found: Vec<Vec<Vec<String>>>,
    }
    fn visit<'a>(state: &mut State<'a>, node: &'a Vec<String>) {
        let n = state.index.len();
        state.index.insert(node, n);
        state.low.insert(node, n);
        state.stack.push(node);
        state.on_stack.insert(node);
        let edges = state.edges;
        for next in edges.get(node).into_iter().flatten() {
            if !state.index.contains_key(next) {
                visit(state, next);
                let low = state.low[node].min(state.low[next]);
                state.low.insert(node, low);
            } else if state.on_stack.contains(next) {
                let low = state.low[node].min(state.index[next]);
                state.low.insert(node, low);
            }
        }
        if state.low[node] == state.index[node] {
            let mut component = Vec::new();
            while let Some(top) = state.stack.pop() {
                state.on_stack.remove(top);
                component.push(top.clone());
                if top == node {
                    break;
                }
            }
            if component.len() > 1 {
                state.found.push(component);
            }
        }
    }
    let mut state = State {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        found: Vec::new(),
    };
    for node in edges.keys() {
        if !state.index.contains_key(node) {
            visit(&mut state, node);
        }
    }
    state.found
}

#[test]
fn no_two_files_import_each_other_even_around_a_circle() {
    let (files, edges) = graph();
    assert!(files.len() > 40, "{} files found", files.len());
    // The checker sees imports: cmd/request uses cmd/shared.
    assert!(edges
        .get(&vec!["mbtool".into(), "cmd".into(), "request".into()])
        .is_some_and(|targets| targets.contains(&vec![
            "mbtool".to_string(),
            "cmd".into(),
            "shared".into()
        ])));
    let found: Vec<String> = circles(&edges)
        .iter()
        .map(|component| {
            component
                .iter()
                .map(|module| {
                    files[module]
                        .strip_prefix(ROOT)
                        .unwrap()
                        .display()
                        .to_string()
                })
                .collect::<Vec<_>>()
                .join(" <-> ")
        })
        .collect();
    assert!(found.is_empty(), "import circles:\n{}", found.join("\n"));
}

/// The folders (rooms) of both crates: `mbtool_core::codec`, `mbtool::cmd`, `main`.
fn room(module: &ModulePath) -> ModulePath {
    module.iter().take(2).cloned().collect()
}

#[test]
fn no_two_rooms_import_each_other_even_around_a_circle() {
    let (_, edges) = graph();
    let mut rooms: Imports = BTreeMap::new();
    for (from, targets) in &edges {
        for to in targets {
            let (from, to) = (room(from), room(to));
            if from != to {
                rooms.entry(from).or_default().insert(to);
            }
        }
    }
    assert!(rooms.len() > 15, "{} rooms found", rooms.len());
    let found: Vec<String> = circles(&rooms)
        .iter()
        .map(|component| {
            let names: Vec<String> = component.iter().map(|room| room.join("::")).collect();
            names.join(" <-> ")
        })
        .collect();
    assert!(
        found.is_empty(),
        "rooms importing each other:\n{}",
        found.join("\n")
    );
}

/// Commands never depend on each other: only on the modules they share.
#[test]
fn commands_import_no_other_command() {
    let (_, edges) = graph();
    let shared = ["shared", "map", "poll"];
    let command = |module: &ModulePath| -> Option<String> {
        match module.as_slice() {
            [krate, cmd, name, ..] if krate == "mbtool" && cmd == "cmd" => Some(name.clone()),
            _ => None,
        }
    };
    let mut crossing = Vec::new();
    for (from, targets) in &edges {
        let Some(from_command) = command(from) else {
            continue;
        };
        for to in targets.iter().filter_map(command) {
            if to != from_command && !shared.contains(&to.as_str()) {
                crossing.push(format!("cmd::{from_command} -> cmd::{to}"));
            }
        }
    }
    assert!(crossing.is_empty(), "{crossing:#?}");
}

#[test]
fn no_source_file_is_longer_than_800_lines() {
    let mut long = Vec::new();
    // The tests and the benches count too: a large suite is a folder of topics.
    let folders = [
        "src",
        "crates/core/src",
        "tests",
        "crates/core/tests",
        "crates/core/benches",
        "bench",
    ];
    let mut stack: Vec<PathBuf> = folders.iter().map(|f| Path::new(ROOT).join(f)).collect();
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for file in entries.map(|entry| entry.unwrap().path()) {
            // Public files kept as they were found are not ours to split.
            if file.ends_with("tests/corpus") {
                continue;
            }
            if file.is_dir() {
                stack.push(file);
                continue;
            }
            let source = ["rs", "py", "sh", "c"];
            if file
                .extension()
                .is_none_or(|e| !source.iter().any(|s| e == *s))
            {
                continue;
            }
            // Unit tests count: a large module's sit in a tests.rs beside it.
            let lines = std::fs::read_to_string(&file).unwrap().lines().count();
            if lines > 800 {
                long.push(format!("{}: {lines}", file.display()));
            }
        }
    }
    assert!(long.is_empty(), "{long:#?}");
}

#[test]
fn commands_and_output_never_see_the_clap_definition() {
    let mut knowing = Vec::new();
    for dir in ["src/cmd", "src/output"] {
        for module in modules(&Path::new(ROOT).join(dir)) {
            let text = std::fs::read_to_string(&module.file).unwrap();
            let words = text.split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'));
            // Commands receive plain settings and their job, never clap's types.
            if words
                .into_iter()
                .any(|w| w == "Cli" || w.ends_with("::Cli") || w.contains("cli::"))
            {
                knowing.push(module.file.display().to_string());
            }
        }
    }
    assert!(knowing.is_empty(), "{knowing:#?}");
}
