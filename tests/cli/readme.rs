//! The README's examples, run as a reader would type them: every ```console block is one
//! shell session, each `$ ` line a command and the lines under it what it prints (stdout
//! and stderr as a terminal shows them). `[..]` in an expected line stands for what changes
//! from run to run (times, TCP ports) and a line `...` for lines left out.
//!
//! A command ending in `&` runs in the background for the rest of its block (its first
//! lines are checked as it prints them), `kill %1` stops it, and `echo $?` prints the
//! status of the command before. Port 5020 is replaced by a free port.

use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

use crate::support::free_port;

/// One `$ ` line and what it prints.
struct Step {
    command: String,
    expected: String,
}

/// The ```console blocks of a Markdown text, each a list of steps, with their line number.
fn sessions(markdown: &str) -> Vec<(usize, Vec<Step>)> {
    let mut sessions = Vec::new();
    let mut current: Option<(usize, Vec<Step>)> = None;
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

fn run_session(line: usize, steps: &[Step]) {
    let port = free_port().to_string();
    let mut background: Option<Background> = None;
    let mut status = 0;
    for step in steps {
        let command = step.command.replace("5020", &port);
        let expected = step.expected.replace("5020", &port);
        let place = format!("README.md:{line}: $ {}", step.command);
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
            // Its first lines, as many as the README shows, as it prints them.
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

#[test]
fn every_readme_example_prints_what_the_readme_shows() {
    let readme = Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md");
    let text = std::fs::read_to_string(readme).expect("README.md");
    let sessions = sessions(&text);
    assert!(
        sessions.len() >= 10,
        "only {} examples found",
        sessions.len()
    );
    for (line, steps) in &sessions {
        run_session(*line, steps);
    }
}
