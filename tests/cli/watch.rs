//! `watch` in a real terminal (tmux): a map's points live, values changing in place as the
//! device's data changes, the keys, and the terminal given back as it was.

use std::time::Duration;

use crate::support::{mbtool, serve_tcp, Terminal};

const PUMP: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/pump3.txt");
const MAP: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/examples/pump3.csv");

/// The row of the screen that shows `name`, its cells.
fn row(screen: &[String], name: &str) -> Vec<String> {
    screen
        .iter()
        .find(|line| line.trim_start_matches('│').starts_with(name))
        .map(|line| {
            line.trim_matches('│')
                .split("  ")
                .map(str::trim)
                .filter(|cell| !cell.is_empty())
                .map(str::to_string)
                .collect()
        })
        .unwrap_or_default()
}

fn write_speed(port: &[String], speed: u32) {
    let output = mbtool()
        .args(port)
        .args(["write", "17", "--map", MAP, &format!("speed={speed}")])
        .output()
        .unwrap();
    assert!(output.status.success(), "{output:?}");
}

#[test]
fn watch_shows_a_map_live_and_gives_the_terminal_back() {
    let (_device, port, _) = serve_tcp(&["--data", PUMP]);
    let args = format!("{} watch 17 --map {MAP} --poll 100ms", port.join(" "));
    let Some(terminal) = Terminal::run(&args, 100, 30) else {
        return;
    };
    let within = Duration::from_secs(20);
    let screen = terminal.wait_for(within, |s| row(s, "flow").len() >= 6);
    // Every point, with its value, minimum, maximum and a trend.
    assert_eq!(
        row(&screen, "voltage")[..5],
        ["voltage", "400001", "230.5 V", "230.5", "230.5"]
    );
    assert_eq!(row(&screen, "flow")[..3], ["flow", "300001", "4.5 m3/h"]);
    assert!(
        row(&screen, "speed")[5]
            .chars()
            .all(|c| "▁▂▃▄▅▆▇█".contains(c)),
        "{screen:#?}"
    );
    // The statistics line counts what was asked and answered (one poll or more by now).
    assert!(
        screen
            .iter()
            .any(|l| l.contains(" answer") && l.contains(" timeouts, ")),
        "{screen:#?}"
    );

    // Another process changes the device: the value changes in place, min and max follow.
    write_speed(&port, 1600);
    let screen = terminal.wait_for(within, |s| {
        row(s, "speed").get(2).is_some_and(|v| v == "1600 rpm")
    });
    assert_eq!(
        row(&screen, "speed")[2..5],
        ["1600 rpm", "1450", "1600"],
        "{screen:#?}"
    );
    // Redrawn in place: the header is still the first row, nothing scrolled.
    assert!(
        screen[1].contains("name") && screen[1].contains("trend"),
        "{screen:#?}"
    );

    // p freezes what is shown while the device changes.
    terminal.keys(&["p"]);
    terminal.wait_for(within, |s| s.iter().any(|l| l.contains("PAUSED")));
    write_speed(&port, 1700);
    std::thread::sleep(Duration::from_millis(600));
    assert_eq!(row(&terminal.screen(), "speed")[2], "1600 rpm");
    // p again resumes, and r starts minimum and maximum afresh.
    terminal.keys(&["p"]);
    terminal.wait_for(within, |s| {
        row(s, "speed").get(2).is_some_and(|v| v == "1700 rpm")
    });
    terminal.keys(&["r"]);
    let screen = terminal.wait_for(within, |s| {
        row(s, "speed").get(3).is_some_and(|v| v == "1700")
    });
    assert_eq!(
        row(&screen, "speed")[2..5],
        ["1700 rpm", "1700", "1700"],
        "{screen:#?}"
    );

    // q ends with status 0, and the screen before watch is back.
    terminal.keys(&["q"]);
    let screen = terminal.wait_for(within, |_| terminal.done());
    assert_eq!(terminal.status(), Some(0));
    assert!(!screen.iter().any(|l| l.contains("voltage")), "{screen:#?}");
}

#[test]
fn ctrl_c_gives_the_terminal_back_too() {
    let (_device, port, _) = serve_tcp(&["--data", PUMP]);
    let args = format!("{} watch 17 400001 2 --type f32", port.join(" "));
    let Some(terminal) = Terminal::run(&args, 100, 30) else {
        return;
    };
    let within = Duration::from_secs(20);
    terminal.wait_for(within, |s| {
        row(s, "400001").get(2).is_some_and(|v| v == "230.5")
    });
    terminal.keys(&["C-c"]);
    let screen = terminal.wait_for(within, |_| terminal.done());
    assert_eq!(terminal.status(), Some(0));
    assert!(!screen.iter().any(|l| l.contains("400001")), "{screen:#?}");
}

#[test]
fn watch_refuses_when_stdout_is_not_a_terminal() {
    let output = mbtool()
        .args(["--port", "sim", "watch", "17", "400108", "3"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&output.stderr).contains("--poll INTERVAL -o csv"),
        "{output:?}"
    );
}

#[test]
fn a_small_terminal_keeps_names_and_values_and_says_what_it_cannot_show() {
    let (_device, port, _) = serve_tcp(&["--data", PUMP]);
    let args = format!("{} watch 17 400001 10", port.join(" "));
    let Some(terminal) = Terminal::run(&args, 60, 10) else {
        return;
    };
    let screen = terminal.wait_for(Duration::from_secs(20), |s| {
        row(s, "400001").get(2).is_some_and(|v| v == "17254")
    });
    assert_eq!(
        row(&screen, "400001")[..3],
        ["400001", "400001", "17254"],
        "{screen:#?}"
    );
    // The rows that fit are shown, and the title says how many of the ten.
    assert!(
        screen[0].contains("(showing ") && screen[0].contains(" of 10"),
        "{screen:#?}"
    );
    terminal.keys(&["q"]);
    terminal.wait_for(Duration::from_secs(20), |_| terminal.done());
    assert_eq!(terminal.status(), Some(0));
}

#[test]
fn a_terminal_that_goes_away_ends_watch() {
    let (_device, port, tcp) = serve_tcp(&["--data", PUMP]);
    let args = format!("{} watch 17 400001 2", port.join(" "));
    let Some(terminal) = Terminal::run(&args, 100, 30) else {
        return;
    };
    terminal.wait_for(Duration::from_secs(20), |s| {
        row(s, "400001").get(2).is_some_and(|v| v == "17254")
    });
    let running = || {
        std::process::Command::new("pgrep")
            .args(["-f", &format!("127.0.0.1:{tcp} watch")])
            .output()
            .is_ok_and(|o| o.status.success())
    };
    assert!(running());
    // The window is closed: the session and its terminal are gone.
    drop(terminal);
    let deadline = std::time::Instant::now() + Duration::from_secs(20);
    while running() && std::time::Instant::now() < deadline {
        std::thread::sleep(Duration::from_millis(50));
    }
    assert!(!running(), "watch went on without its terminal");
}

/// A range with a hole is read around it, as dump and maps read: every address that exists
/// shows its value, the one that does not says so, and the status line shows whole.
#[test]
fn watch_reads_around_a_hole_and_shows_the_whole_status() {
    let dir = tempfile::tempdir().unwrap();
    let data = dir.path().join("holey.txt");
    std::fs::write(&data, "400003 = 1\n400004 = 2\n400006 = 4\n400007 = 5\n").unwrap();
    let (_device, port, _) = serve_tcp(&["--data", data.to_str().unwrap()]);
    let args = format!("{} watch 17 400003 5 --poll 100ms", port.join(" "));
    let Some(terminal) = Terminal::run(&args, 100, 30) else {
        return;
    };
    let screen = terminal.wait_for(Duration::from_secs(20), |s| {
        row(s, "400007").get(2).is_some_and(|v| v == "5") && s.iter().any(|l| l.contains("max"))
    });
    for (reference, value) in [
        ("400003", "1"),
        ("400004", "2"),
        ("400005", "no such address"),
        ("400006", "4"),
        ("400007", "5"),
    ] {
        assert_eq!(
            row(&screen, reference).get(2).map(String::as_str),
            Some(value),
            "{screen:#?}"
        );
    }
    // The statistics are not cut off: the response times end with their maximum.
    assert!(screen.iter().any(|l| l.contains("/ max ")), "{screen:#?}");
    terminal.keys(&["q"]);
    terminal.wait_for(Duration::from_secs(10), |_| terminal.done());
    assert_eq!(terminal.status(), Some(0));
}

#[test]
fn watch_says_in_its_title_which_path_it_reads() {
    let (_device, secondary, _) = serve_tcp(&["--data", PUMP]);
    // Nothing listens on the primary: watch reads through the secondary, and says so.
    let args = format!(
        "--port tcp://127.0.0.1:1 --secondary-port {} watch 17 --map {MAP} --poll 100ms",
        secondary[1]
    );
    let Some(terminal) = Terminal::run(&args, 120, 30) else {
        return;
    };
    let screen = terminal.wait_for(Duration::from_secs(20), |s| s[0].contains("secondary"));
    assert!(
        screen[0].contains(&format!(
            "slave 17 on {} (secondary path: the primary path cannot be opened",
            secondary[1]
        )),
        "{screen:#?}"
    );
    assert!(
        screen.iter().any(|line| line.contains("1 change of path")),
        "{screen:#?}"
    );
    terminal.keys(&["q"]);
}
