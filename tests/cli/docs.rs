//! The completions and man pages in the tree are those the clap definition generates now,
//! and every example they show is one mbtool accepts.

use std::fs;
use std::path::Path;

use crate::support::mbtool;

#[test]
fn the_clap_definition_is_consistent() {
    mbtool::cli::definition().debug_assert();
}

fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<_> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| {
            let path = entry.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            (name, fs::read(&path).unwrap())
        })
        .collect();
    files.sort();
    files
}

#[test]
fn completions_and_man_pages_are_in_step_with_the_cli() {
    let fresh = tempfile::tempdir().unwrap();
    mbtool::docs::generate(fresh.path()).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in ["completions", "man"] {
        let want = files(&fresh.path().join(dir));
        let have = files(&root.join(dir));
        let names =
            |files: &[(String, Vec<u8>)]| files.iter().map(|f| f.0.clone()).collect::<Vec<_>>();
        assert_eq!(
            names(&have),
            names(&want),
            "{dir}/ is out of date: run `cargo run -- generate`"
        );
        for ((name, have), (_, want)) in have.iter().zip(&want) {
            assert!(
                have == want,
                "{dir}/{name} is out of date: run `cargo run -- generate`"
            );
        }
    }
}

#[test]
fn every_man_page_has_exit_status_and_examples() {
    let fresh = tempfile::tempdir().unwrap();
    mbtool::docs::write_man_pages(fresh.path()).unwrap();
    for (name, page) in files(fresh.path()) {
        let page = String::from_utf8(page).unwrap();
        assert!(page.contains(".SH \"EXIT STATUS\""), "{name}");
        assert!(page.contains(".SH EXAMPLES"), "{name} has no examples");
    }
}

/// The SYNOPSIS of a page: the line after `.SH SYNOPSIS`.
fn synopsis(page: &str) -> &str {
    page.split(".SH SYNOPSIS\n")
        .nth(1)
        .and_then(|rest| rest.lines().next())
        .unwrap_or_default()
}

#[test]
fn a_man_synopsis_shows_each_option_it_takes_with_its_value() {
    let fresh = tempfile::tempdir().unwrap();
    mbtool::docs::write_man_pages(fresh.path()).unwrap();
    let page = |name: &str| fs::read_to_string(fresh.path().join(name)).unwrap();
    let read = page("mbtool-read-holding.1");
    let read = synopsis(&read);
    for option in [
        r"[\fB\-b\fR|\fB\-\-baud\fR \fIBAUD\fR]",
        r"[\fB\-t\fR|\fB\-\-type\fR \fITYPE\fR]",
        r"[\fB\-\-poll\fR \fIINTERVAL\fR]",
        r"[\fB\-\-json\fR]",
        r"<\fISLAVE\fR> <\fIADDRESS\fR> [\fICOUNT\fR]",
    ] {
        assert!(read.contains(option), "{option} not in {read}");
    }
    let decode = page("mbtool-decode.1");
    let decode = synopsis(&decode);
    assert!(
        decode.contains(r"[\fB\-m\fR|\fB\-\-mode\fR \fIMODE\fR]"),
        "{decode}"
    );
    assert!(
        !decode.contains("baud") && !decode.contains("poll"),
        "{decode}"
    );
    assert!(decode.ends_with(r"[\fIFRAMES\fR]..."), "{decode}");
}

/// Each example of `--help` and the man pages is accepted as it stands; a request command's
/// is carried out as far as its frames (`encode`), since its port is not here, and one that
/// asks a device about itself asks the built-in slave.
#[test]
fn every_help_example_is_one_the_command_accepts() {
    for example in mbtool::docs::examples() {
        // `decode --json < frames.txt` reads standard input, here empty.
        let line = example.command.split(" < ").next().unwrap();
        let words: Vec<&str> = line.split_whitespace().collect();
        let mut definition = mbtool::cli::definition();
        let os_words: Vec<std::ffi::OsString> = words.iter().map(Into::into).collect();
        let (cli, origins) = mbtool::settings::read(&mut definition, os_words)
            .unwrap_or_else(|e| panic!("{line}: {e}"));
        let resolved = mbtool::settings::resolve(cli, &origins);
        assert_eq!(resolved.err(), None, "{line}");
        let path = origins.path();
        let name = path[0];
        // These need a line or a device of their own (sunspec a SunSpec device); --listen
        // needs a serial line, and --hosts a network. watch needs a terminal: its examples
        // are checked as far as the command line.
        if ["sniff", "serve", "dump", "restore", "watch", "sunspec"].contains(&name)
            || line.contains("--listen")
            || line.contains("--hosts")
        {
            continue;
        }
        let mut args: Vec<&str> = Vec::new();
        let mut rest = words.iter().skip(1);
        while let Some(word) = rest.next() {
            if ["--port", "-p"].contains(word) {
                rest.next();
            } else {
                args.push(word);
            }
        }
        if ["scan", "info", "diag"].contains(&name) {
            args.splice(0..0, ["--port", "sim"]);
        } else if !["decode", "encode", "ports", "poll"].contains(&name) {
            args.insert(0, "encode");
        }
        let output = mbtool().args(&args).output().unwrap();
        assert!(output.status.success(), "{line}: {output:?}");
    }
}

/// What bash offers after `mbtool WORDS --`, from the completions in the tree.
fn bash_offers(words: &str) -> Vec<String> {
    let script = format!(
        "source completions/mbtool.bash; COMP_WORDS=(mbtool {words} --); \
         COMP_CWORD=${{#COMP_WORDS[@]}}; COMP_CWORD=$((COMP_CWORD - 1)); \
         _mbtool mbtool -- x; printf '%s\\n' \"${{COMPREPLY[@]}}\""
    );
    let output = std::process::Command::new("bash")
        .args(["-c", &script])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    String::from_utf8_lossy(&output.stdout)
        .lines()
        .map(str::to_string)
        .collect()
}

#[test]
fn completion_offers_only_the_options_a_command_takes() {
    let decode = bash_offers("decode");
    assert!(decode.contains(&"--direction".to_string()), "{decode:?}");
    assert!(decode.contains(&"--type".to_string()), "{decode:?}");
    assert!(!decode.contains(&"--baud".to_string()), "{decode:?}");
    let coils = bash_offers("read-coils 17");
    assert!(coils.contains(&"--poll".to_string()), "{coils:?}");
    assert!(!coils.contains(&"--type".to_string()), "{coils:?}");
}

/// A command added without the options of its kind takes none: each takes a port, a
/// framing or an output format as its own.
#[test]
fn every_command_says_which_options_it_takes() {
    let mut command = mbtool::cli::definition();
    command.build();
    for sub in command
        .get_subcommands()
        .filter(|sub| !sub.is_hide_set() && sub.get_name() != "help")
    {
        let leaves: Vec<&clap::Command> = if sub.has_subcommands() {
            sub.get_subcommands()
                .filter(|leaf| leaf.get_name() != "help")
                .collect()
        } else {
            vec![sub]
        };
        for leaf in leaves {
            let takes = leaf.get_arguments().any(|arg| {
                !arg.is_global_set() && ["port", "mode", "output"].contains(&arg.get_id().as_str())
            });
            assert!(takes, "{}", leaf.get_name());
        }
    }
}

/// Help a person reads: `mbtool -h` and every command's `-h` fit on a screen; `--help`
/// keeps everything.
#[test]
fn short_help_fits_on_a_screen() {
    let lines = |words: &[&str]| -> usize {
        let output = mbtool().env("NO_COLOR", "1").args(words).output().unwrap();
        assert!(output.status.success(), "{words:?}: {output:?}");
        String::from_utf8(output.stdout).unwrap().lines().count()
    };
    assert!(lines(&["-h"]) <= 50);
    let mut command = mbtool::cli::definition();
    command.build();
    for sub in command
        .get_subcommands()
        .filter(|sub| !sub.is_hide_set() && sub.get_name() != "help")
    {
        let mut paths = vec![vec![sub.get_name()]];
        paths.extend(
            sub.get_subcommands()
                .filter(|leaf| leaf.get_name() != "help")
                .map(|leaf| vec![sub.get_name(), leaf.get_name()]),
        );
        for path in paths {
            let short = lines(&[path.as_slice(), &["-h"]].concat());
            assert!(short <= 40, "{path:?}: {short} lines");
            let long = lines(&[path.as_slice(), &["--help"]].concat());
            assert!(long > short, "{path:?}");
            pointer_names_what_is_left_out(&command, &path);
        }
    }
}

/// The last line of a command's `-h` names the group of every option it leaves out, and
/// no other.
fn pointer_names_what_is_left_out(definition: &clap::Command, path: &[&str]) {
    let leaf = path
        .iter()
        .try_fold(definition, |command, name| command.find_subcommand(name))
        .unwrap();
    let mut left_out: Vec<&str> = leaf
        .get_arguments()
        .filter(|arg| arg.is_hide_short_help_set() && !arg.is_hide_set())
        .map(|arg| arg.get_help_heading().unwrap_or("Options"))
        .collect();
    left_out.sort_unstable();
    left_out.dedup();
    let output = mbtool()
        .env("NO_COLOR", "1")
        .args([path, &["-h"]].concat())
        .output()
        .unwrap();
    let help = String::from_utf8(output.stdout).unwrap().replace('\n', " ");
    let pointer = help
        .split("More options in --help: ")
        .nth(1)
        .map(|rest| rest.trim_end().trim_end_matches('.'))
        .unwrap_or_default();
    let mut named: Vec<&str> = pointer.split(", ").filter(|h| !h.is_empty()).collect();
    named.sort_unstable();
    assert_eq!(named, left_out, "{path:?}");
}

#[test]
fn an_option_value_that_is_a_command_name_is_no_command() {
    // `-o info`: a file named as a command; the command is `dump`.
    let dir = tempfile::tempdir().unwrap();
    let output = crate::support::mbtool()
        .current_dir(dir.path())
        .args(["-o", "info", "--port", "sim", "dump", "17", "400108-400110"])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
    assert!(dir.path().join("info").exists());
    // `encode` without its command lists the commands there are, not one.
    let output = crate::support::mbtool().arg("encode").output().unwrap();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("read-holding"), "{stderr}");
}

/// Help is the whole definition's however it is asked for: `-h` alone or in a cluster of
/// flags, before the command's arguments or after them; `--help` or `help COMMAND`.
#[test]
fn help_is_the_same_however_it_is_asked_for() {
    let help = |line: &str| -> String {
        let output = mbtool()
            .env("NO_COLOR", "1")
            .args(line.split_whitespace())
            .output()
            .unwrap();
        assert!(output.status.success(), "{line}: {output:?}");
        String::from_utf8(output.stdout).unwrap()
    };
    // Clustered with a flag the command takes: -v, or --json for those that take no -v.
    for (command, flag) in [
        ("read-holding", "-v"),
        ("decode", "--json"),
        ("ports", "--json"),
        ("encode read-coils", "--json"),
    ] {
        let short = help(&format!("{command} -h"));
        let lines = [
            format!("{command} {flag} -h"),
            format!("{command} -h {flag}"),
            format!("{flag} {command} -h"),
            format!("{command} -h -p sim"),
        ];
        for line in lines {
            assert_eq!(help(&line), short, "{line}");
        }
        let long = help(&format!("{command} --help"));
        assert_eq!(help(&format!("help {command}")), long, "{command}");
    }
    // The top's too, with its examples.
    assert_eq!(help("-vh"), help("-h"));
    let long = help("--help");
    assert!(long.contains("Examples:"), "{long}");
    assert_eq!(help("help"), long);
    assert_eq!(help("-v --help"), long);
    // What the whole definition shows: the command's own arguments under their heading,
    // and only the options it takes.
    let read = help("read-holding -h");
    assert!(
        read.starts_with("Read holding registers (function 03)"),
        "{read}"
    );
    assert!(read.contains("Arguments:\n  <SLAVE>"), "{read}");
    assert!(!help("decode -h").contains("--port"));
}
