//! The examples of the README and of the pages under `docs/`, run as a reader would type
//! them, from the top folder of the repository: every ```console block is one shell
//! session, each `$ ` line a command and the lines under it what it prints (stdout and
//! stderr as a terminal shows them). `[..]` in an expected line stands for what changes
//! from run to run (times, TCP ports) and a line `...` for lines left out.
//!
//! A command ending in `&` runs in the background for the rest of its block (its first
//! lines are checked as it prints them), `kill %1` stops it, and `echo $?` prints the
//! status of the command before. Port 5020 is replaced by a free port. A failure names the
//! file and line of its command.
//!
//! The links between those pages are checked too: each relative link leads to a file of the
//! repository, and each `#anchor` to a heading of that file.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

use crate::support::free_port;

/// One `$ ` line and what it prints.
struct Step {
    command: String,
    expected: String,
}

/// A ```console block: the line it starts on, and its steps.
type Session = (usize, Vec<Step>);

/// The ```console blocks of a Markdown text.
fn sessions(markdown: &str) -> Vec<Session> {
    let mut sessions = Vec::new();
    let mut current: Option<Session> = None;
    for (number, line) in markdown.lines().enumerate() {
        match (&mut current, line) {
            (None, "```console") => current = Some((number + 1, Vec::new())),
            (Some(_), "```") => sessions.extend(current.take()),
            (Some((_, steps)), line) => match line.strip_prefix("$ ") {
                Some(command) => steps.push(Step {
                    command: command.to_string(),
                    expected: String::new(),
                }),
                None => {
                    let step = steps.last_mut().expect("a console block starts with `$ `");
                    step.expected.push_str(line);
                    step.expected.push('\n');
                }
            },
            (None, _) => {}
        }
    }
    sessions
}

/// The directory of the mbtool under test, first on PATH so that `mbtool` is it.
fn path_with_mbtool() -> String {
    let exe = PathBuf::from(env!("CARGO_BIN_EXE_mbtool"));
    let dir = exe.parent().expect("the binary has a directory");
    format!(
        "{}:{}",
        dir.display(),
        std::env::var("PATH").unwrap_or_default()
    )
}

fn shell(command: &str) -> Command {
    shell_running(&format!("{{ {command} ; }} 2>&1"))
}

/// A command run in the background: bash becomes it (`exec`), so that stopping it stops
/// the command itself, not only a shell around it.
fn in_background(command: &str) -> Command {
    shell_running(&format!("exec {command} 2>&1"))
}

fn shell_running(script: &str) -> Command {
    let mut shell = Command::new("bash");
    // Grouped, so that stderr joins stdout for a whole pipeline, as on a terminal.
    shell
        .args(["-c", script])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("PATH", path_with_mbtool())
        .env("NO_COLOR", "1")
        .stdin(Stdio::null());
    for (variable, _) in std::env::vars().filter(|(v, _)| v.starts_with("MBTOOL_")) {
        shell.env_remove(variable);
    }
    shell
}

/// A command left running in the background; stopped when its block ends.
struct Background(Child);

impl Drop for Background {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

fn run_session(file: &str, line: usize, steps: &[Step]) {
    let port = free_port().to_string();
    let mut background: Option<Background> = None;
    let mut status = 0;
    for step in steps {
        let command = step.command.replace("5020", &port);
        let expected = step.expected.replace("5020", &port);
        let place = format!("{file}:{line}: $ {}", step.command);
        let actual = if command == "echo $?" {
            format!("{status}\n")
        } else if command == "kill %1" {
            background = None;
            String::new()
        } else if let Some(command) = command.strip_suffix(" &") {
            let mut child = in_background(command)
                .stdout(Stdio::piped())
                .spawn()
                .expect("bash runs");
            let out = child.stdout.take().expect("piped");
            background = Some(Background(child));
            // Its first lines, as many as the page shows, as it prints them.
            let mut lines = BufReader::new(out).lines();
            let mut seen = String::new();
            for _ in 0..expected.lines().count() {
                match lines.next() {
                    Some(Ok(line)) => seen.push_str(&format!("{line}\n")),
                    _ => break,
                }
            }
            seen
        } else {
            let output = shell(&command).output().expect("bash runs");
            status = output.status.code().unwrap_or(-1);
            String::from_utf8_lossy(&output.stdout).into_owned()
        };
        if let Err(error) = snapbox::Assert::new().try_eq(
            Some(&place),
            snapbox::Data::text(actual),
            snapbox::Data::text(expected),
        ) {
            panic!("{place}\n{error}");
        }
    }
    drop(background);
}

/// The repository's top folder.
fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// README.md and every page of `docs/`, by their names from the top folder, with their text.
fn pages() -> Vec<(String, String)> {
    let mut names = vec!["README.md".to_string()];
    let mut docs: Vec<String> = std::fs::read_dir(root().join("docs"))
        .expect("docs/")
        .map(|entry| entry.expect("a docs/ entry").file_name())
        .map(|name| name.to_string_lossy().into_owned())
        .filter(|name| name.ends_with(".md"))
        .map(|name| format!("docs/{name}"))
        .collect();
    docs.sort();
    names.extend(docs);
    names
        .into_iter()
        .map(|name| {
            let text = std::fs::read_to_string(root().join(&name))
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            (name, text)
        })
        .collect()
}

#[test]
fn every_example_of_the_readme_and_its_docs_prints_what_they_show() {
    let pages: Vec<(String, Vec<Session>)> = pages()
        .into_iter()
        .map(|(name, text)| (name, sessions(&text)))
        .collect();
    for (name, sessions) in &pages {
        // Each page can be tried at once, without hardware.
        assert!(!sessions.is_empty(), "{name} has no example");
    }
    let examples: usize = pages.iter().map(|(_, sessions)| sessions.len()).sum();
    assert!(examples >= 30, "only {examples} examples found");
    for (name, sessions) in &pages {
        for (line, steps) in sessions {
            run_session(name, *line, steps);
        }
    }
}

/// The targets of the inline links `[text](target)` of a Markdown text, with their line
/// number, code spans and blocks left out.
fn links(markdown: &str) -> Vec<(usize, String)> {
    let mut links = Vec::new();
    let mut in_block = false;
    for (number, line) in markdown.lines().enumerate() {
        if line.starts_with("```") {
            in_block = !in_block;
            continue;
        }
        if in_block {
            continue;
        }
        // Code spans are the odd pieces between backticks.
        let prose: String = line
            .split('`')
            .enumerate()
            .filter(|(i, _)| i % 2 == 0)
            .map(|(_, piece)| piece)
            .collect::<Vec<_>>()
            .join(" ");
        let mut rest = prose.as_str();
        while let Some(start) = rest.find("](") {
            let after = &rest[start + 2..];
            let Some(end) = after.find(')') else { break };
            links.push((number + 1, after[..end].to_string()));
            rest = &after[end..];
        }
    }
    links
}

/// The anchor GitHub gives a heading: lower case, spaces as `-`, only letters, digits, `-`
/// and `_` kept.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The anchors of a Markdown text's headings (outside code blocks).
fn anchors(markdown: &str) -> Vec<String> {
    let mut anchors = Vec::new();
    let mut in_block = false;
    for line in markdown.lines() {
        if line.starts_with("```") {
            in_block = !in_block;
        } else if !in_block && line.starts_with('#') {
            anchors.push(anchor(line.trim_start_matches('#')));
        }
    }
    anchors
}

#[test]
fn every_link_of_the_readme_and_its_docs_leads_somewhere() {
    for (name, text) in pages() {
        let folder = Path::new(&name).parent().unwrap_or(Path::new(""));
        for (line, target) in links(&text) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let place = format!("{name}:{line}: {target}");
            assert!(!target.starts_with('/'), "{place}: a link is relative");
            let (path, fragment) = match target.split_once('#') {
                Some((path, fragment)) => (path, Some(fragment)),
                None => (target.as_str(), None),
            };
            let file = if path.is_empty() {
                root().join(&name)
            } else {
                root().join(folder).join(path)
            };
            assert!(file.exists(), "{place}: no such file");
            if let Some(fragment) = fragment {
                let text =
                    std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{place}: {e}"));
                assert!(
                    anchors(&text).iter().any(|a| a == fragment),
                    "{place}: no such heading"
                );
            }
        }
    }
}
