//! The completions and man pages in the tree are those the clap definition generates now,
//! and every example they show is one mbtool accepts.

use std::fs;
use std::path::Path;

use crate::support::mbtool;

#[test]
fn the_clap_definition_is_consistent() {
    mbtool::docs::command().debug_assert();
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
        let mut definition = mbtool::docs::command();
        let os_words: Vec<std::ffi::OsString> = words.iter().map(Into::into).collect();
        let (cli, origins) = mbtool::settings::read(&mut definition, &os_words)
            .unwrap_or_else(|e| panic!("{line}: {e}"));
        let resolved = mbtool::settings::resolve(&cli, &definition, &origins);
        assert_eq!(resolved.err(), None, "{line}");
        let path = origins.path();
        let name = path[0];
        // These need a line or a device of their own; --listen needs a serial line.
        // watch needs a terminal: its examples are checked as far as the command line.
        if ["sniff", "serve", "dump", "restore", "watch"].contains(&name)
            || line.contains("--listen")
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
        } else if !["decode", "encode", "ports"].contains(&name) {
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

/// A command added without saying which global options it takes would take none.
#[test]
fn every_command_says_which_options_it_takes() {
    let command = mbtool::docs::command();
    let commands = command.get_subcommands();
    for sub in commands.filter(|sub| !sub.is_hide_set() && sub.get_name() != "help") {
        let leaves: Vec<Vec<&str>> = if sub.has_subcommands() {
            sub.get_subcommands()
                .filter(|leaf| leaf.get_name() != "help")
                .map(|leaf| vec![sub.get_name(), leaf.get_name()])
                .collect()
        } else {
            vec![vec![sub.get_name()]]
        };
        for path in &leaves {
            let takes = ["port", "mode", "output"]
                .iter()
                .any(|id| mbtool::cli::takes_option(path, id));
            assert!(takes, "{path:?}");
        }
    }
}

/// The options every command shares are known by name where they are read (which a
/// command takes, where a value came from): the names are those of the definition.
#[test]
fn the_common_options_by_name_are_those_of_the_definition() {
    let common = <mbtool::cli::Common as clap::Args>::augment_args(clap::Command::new("mbtool"));
    let ids: Vec<&str> = common
        .get_arguments()
        .map(|arg| arg.get_id().as_str())
        .collect();
    assert!(ids.len() > 30, "{ids:?}");
    for id in &ids {
        assert!(mbtool::cli::is_common_option(id), "{id}");
    }
    for own in ["slave", "address", "count", "values", "pdu", "bogus"] {
        assert!(!mbtool::cli::is_common_option(own), "{own}");
    }
}

/// A command line is parsed without building every command's definition first: deriving
/// every command's arguments, and copying every global option into every command, cost
/// each run more than its work.
#[test]
fn a_command_line_is_parsed_without_building_every_command() {
    use clap::CommandFactory;
    let args = |line: &str| -> Vec<std::ffi::OsString> {
        line.split_whitespace().map(Into::into).collect()
    };
    // The definition as derived names every command, and derives none's arguments.
    let derived = mbtool::cli::Cli::command();
    assert!(derived.get_subcommands().count() > 20);
    assert!(derived
        .get_subcommands()
        .all(|sub| sub.get_arguments().next().is_none()));
    // A command line is parsed with the command it names alone, its own arguments still
    // not derived: the parse derives what it goes through. The command takes the common
    // options itself, not as globals, and those typed before its name are moved after it.
    let (parser, words) = mbtool::docs::parser(&args("mbtool --port sim read-coils 17 1"));
    assert_eq!(words, args("mbtool read-coils --port sim 17 1"));
    let names: Vec<&str> = parser.get_subcommands().map(|sub| sub.get_name()).collect();
    assert_eq!(names, ["read-coils"]);
    assert_eq!(parser.get_arguments().count(), 0);
    let named = parser.find_subcommand("read-coils").unwrap();
    assert!(named.get_arguments().all(|arg| !arg.is_global_set()));
    let ids = |command: &clap::Command| -> Vec<String> {
        command
            .get_arguments()
            .map(|arg| arg.get_id().to_string())
            .collect()
    };
    assert_eq!(ids(named), ids(&derived));
    let matches = parser
        .clone()
        .try_get_matches_from(args("mbtool read-coils --port sim 17 1 --timeout 1s"))
        .unwrap();
    let (_, leaf) = matches.subcommand().unwrap();
    assert_eq!(
        leaf.get_one::<String>("address").map(String::as_str),
        Some("1")
    );
    // Only the commands that hold commands keep the options global, to pass them on.
    let mut built = mbtool::cli::Cli::command();
    built.build();
    for sub in built
        .get_subcommands()
        .filter(|sub| sub.get_name() != "help")
    {
        let holds = sub.get_subcommands().any(|sub| sub.get_name() != "help");
        let listed = mbtool::cli::COMMANDS_OF_COMMANDS.contains(&sub.get_name());
        assert_eq!(holds, listed, "{}", sub.get_name());
    }
    // Where the words before the command cannot be moved for sure (a cluster of flags),
    // the common options stay global, on the top, as derived.
    let (parser, words) = mbtool::docs::parser(&args("mbtool -vp sim read-coils 17 1"));
    assert_eq!(words, args("mbtool -vp sim read-coils 17 1"));
    assert_eq!(ids(&parser), ids(&derived));
    assert!(parser.get_arguments().all(|arg| arg.is_global_set()));
    let named = parser.find_subcommand("read-coils").unwrap();
    assert!(named.get_arguments().next().is_none());
    // The parser's top is the derived top: the same settings.
    let top = mbtool::docs::top_of_parse();
    assert_eq!(top.get_version(), derived.get_version());
    assert_eq!(
        top.is_propagate_version_set(),
        derived.is_propagate_version_set()
    );
    assert_eq!(
        top.is_subcommand_required_set(),
        derived.is_subcommand_required_set()
    );
    assert_eq!(
        top.is_arg_required_else_help_set(),
        derived.is_arg_required_else_help_set()
    );
    // An alias names its command too; no command (`--version`) builds none, nor the
    // common options.
    let (parser, words) = mbtool::docs::parser(&args("mbtool -p sim read-holding-registers 17 1"));
    let names: Vec<&str> = parser.get_subcommands().map(|sub| sub.get_name()).collect();
    assert_eq!(names, ["read-holding"]);
    assert_eq!(words, args("mbtool read-holding-registers -p sim 17 1"));
    let (parser, _) = mbtool::docs::parser(&args("mbtool --version"));
    assert_eq!(parser.get_subcommands().count(), 0);
    assert_eq!(parser.get_arguments().count(), 0);
    // A refused command line is told with every command, the one named described.
    let whole = mbtool::docs::whole_parser(&args("mbtool read-coils"));
    assert!(whole.get_subcommands().count() > 20);
    let address = whole
        .find_subcommand("read-coils")
        .and_then(|sub| sub.get_arguments().find(|a| a.get_id() == "address"))
        .unwrap();
    assert!(address
        .get_help()
        .unwrap()
        .to_string()
        .starts_with("First coil"));
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

/// The first parse of a command line (the command named alone, the options typed before
/// its name moved after it) reads every line as the whole definition does: what it
/// accepts, with the same values from the same places and the same settings, and what it
/// refuses. A line it refuses is read again with the whole definition, so refusing more
/// costs time, never a different answer; accepting one the whole definition refuses
/// would be a different answer.
#[test]
fn the_first_parse_reads_every_command_line_as_the_whole_definition_does() {
    use proptest::prelude::*;
    use proptest::test_runner::{Config, TestRunner};
    const OPTIONS: &[&str] = &[
        "-p sim",
        "--port=sim",
        "-psim",
        "--port tcp://127.0.0.1:1502",
        "-b 9600",
        "--baud 9600,19200",
        "-b9600",
        "--parity=odd",
        "--parity none",
        "-t f32",
        "--type u16",
        "-tu32",
        "--order CDAB",
        "-v",
        "--verbose",
        "--json",
        "-o csv",
        "-o=json",
        "--output values",
        "-o info",
        "--timeout 2s",
        "--timeout=0",
        "--retries 2",
        "--retries -1",
        "--rs485",
        "--rs485-delay-before 3",
        "--rts-toggle",
        "--rts-level low",
        "--address-base 1",
        "--pdu-addresses",
        "--secondary-port tcp://127.0.0.1:1",
        "--switch-on timeout:2",
        "--poll 1s",
        "--count 3",
        "-m ascii",
        "--mode=tcp",
        "--cert x.pem",
        "--frame-gap 0",
        "--max-per-request 10",
        "--data-bits 7",
        "--stop-bits 2",
        "--bogus",
        "-x",
        "-vp sim",
        "-pv",
        "--json=1",
        "--port",
        "--",
        "-V",
        "read-holding",
        "17",
    ];
    const COMMANDS: &[&str] = &[
        "read-holding 17 108 3",
        "read-holding-registers 17 400108",
        "read-coils 1 0 8",
        "read-inputs 1 10",
        "read-input-registers 1 300001-300004",
        "read 17 400108 2",
        "write-register 17 108 5",
        "write-registers 17 108 1 2 3",
        "write-coil 17 5 on",
        "write-coils 17 0 1 0 1",
        "write 17 400108 7",
        "raw 17 0300000001",
        "info 17",
        "diag 17",
        "scan",
        "decode 11 03 00 6B 00 03 76 87",
        "sniff",
        "dump 17 400108-400110",
        "ports",
        "encode read-holding 17 1",
        "encode write-coil 1 2 on",
        "watch 17 400001",
        "serve --slave 17",
        "restore 17 x.csv",
        "gateway --listen 127.0.0.1:1502",
    ];
    fn outcome(definition: &mut clap::Command, words: &[std::ffi::OsString]) -> String {
        match mbtool::settings::read(definition, words) {
            Ok((cli, origins)) => {
                let settings = mbtool::settings::resolve(&cli, definition, &origins);
                format!("{cli:?}\n{origins:?}\n{settings:?}")
            }
            Err(error) => format!("refused: {:?}", error.kind()),
        }
    }
    let moved = std::cell::Cell::new(0);
    let line = (
        prop::collection::vec(prop::sample::select(OPTIONS), 0..4),
        prop::sample::select(COMMANDS),
        prop::collection::vec(prop::sample::select(OPTIONS), 0..3),
    );
    let mut runner = TestRunner::new(Config {
        cases: 400,
        failure_persistence: None,
        ..Config::default()
    });
    runner
        .run(&line, |(before, command, after)| {
            let text = format!("mbtool {} {command} {}", before.join(" "), after.join(" "));
            let words: Vec<std::ffi::OsString> = text.split_whitespace().map(Into::into).collect();
            let (mut first, first_words) = mbtool::docs::parser(&words);
            let first = outcome(&mut first, &first_words);
            let whole = outcome(&mut mbtool::docs::whole_parser(&words), &words);
            if !first.starts_with("refused") {
                prop_assert_eq!(&first, &whole, "{}", text);
                if first_words != words {
                    moved.set(moved.get() + 1);
                }
            } else {
                // Refused first, read again whole: only help and the version are final.
                prop_assert!(!first.contains("Display") || whole == first, "{}", text);
            }
            Ok(())
        })
        .unwrap();
    // The lines above are mostly plain ones: most of them must take the short way.
    assert!(moved.get() > 100, "{} of 400 lines moved", moved.get());
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
    for command in ["read-holding", "decode", "ports", "encode read-coils"] {
        let short = help(&format!("{command} -h"));
        for line in [
            format!("{command} -vh"),
            format!("{command} -hv"),
            format!("-v {command} -h"),
            format!("{command} -hp sim"),
        ] {
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
    let read = help("read-holding -vh");
    assert!(
        read.starts_with("Read holding registers (function 03)"),
        "{read}"
    );
    assert!(read.contains("Arguments:\n  <SLAVE>"), "{read}");
    assert!(!help("decode -vh").contains("--port"));
}
