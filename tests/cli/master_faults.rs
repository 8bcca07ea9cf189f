//! The master against a strict scripted slave on a pseudo-terminal, which plays exact bytes:
//! every fault a real bus produces gets the exit status and message that
//! docs/reading-and-writing.md promises.

use std::thread;
use std::time::Duration;

use crate::support::{mbtool, read_frame, rtu, write_all, Pty, WORKED_FRAMES};
use mbtool_core::codec::{Direction, Mode};

/// What the scripted slave does with each request it receives, in order.
enum Act {
    /// Wait, then write these bytes.
    Answer(Duration, Vec<u8>),
    /// Write these pieces, the pause before each: a slow slave, or a USB adapter.
    Pieces(Duration, Vec<Vec<u8>>),
    /// Send the request back as it came: the answer to a diagnostic echo (08/00).
    Echo,
    /// Say nothing.
    Silence,
}

struct Outcome {
    code: i32,
    stdout: String,
    stderr: String,
    /// The request frames the slave received.
    requests: Vec<Vec<u8>>,
}

/// Runs mbtool with `args` against a slave that plays `acts`.
fn against(acts: Vec<Act>, args: &[&str]) -> Outcome {
    against_within("300ms", acts, args)
}

/// As `against`, with `--timeout timeout`.
fn against_within(timeout: &str, acts: Vec<Act>, args: &[&str]) -> Outcome {
    against_deaf_to(None, timeout, acts, args)
}

/// As `against_within`, the slave saying nothing to every request of function `deaf`,
/// which takes no act: a device that ignores a function it does not do.
fn against_deaf_to(deaf: Option<u8>, timeout: &str, acts: Vec<Act>, args: &[&str]) -> Outcome {
    let pty = Pty::new();
    let path = pty.path.clone();
    let mut port = pty.master.try_clone_native().expect("clone the pty master");
    let slave = thread::spawn(move || {
        let mut requests = Vec::new();
        for act in acts {
            if !next_request(&mut port, &mut requests, deaf) {
                break;
            }
            match act {
                Act::Answer(delay, answer) => {
                    thread::sleep(delay);
                    write_all(&mut port, &answer);
                }
                Act::Pieces(pause, pieces) => {
                    for piece in pieces {
                        thread::sleep(pause);
                        write_all(&mut port, &piece);
                    }
                }
                Act::Echo => write_all(&mut port, requests.last().unwrap()),
                Act::Silence => {}
            }
        }
        // Anything more the master sends is counted too (retries that should not happen).
        while let Some((_, bytes)) = read_frame(
            &mut port,
            Mode::Rtu,
            Direction::Request,
            Duration::from_millis(300),
        ) {
            requests.push(bytes);
        }
        requests
    });
    let output = mbtool()
        .args(["--port", &path, "--timeout", timeout])
        .args(args)
        .output()
        .unwrap();
    let requests = slave.join().unwrap();
    drop(pty.master);
    Outcome {
        code: output.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&output.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
        requests,
    }
}

const READ: &[&str] = &["read-holding", "17", "400108", "3", "-o", "values"];
/// Reads requests into `requests` until one not of function `deaf`; false when none comes.
fn next_request(
    port: &mut serialport::TTYPort,
    requests: &mut Vec<Vec<u8>>,
    deaf: Option<u8>,
) -> bool {
    loop {
        let Some((_, bytes)) =
            read_frame(port, Mode::Rtu, Direction::Request, Duration::from_secs(8))
        else {
            return false;
        };
        let function = bytes.get(1).copied();
        requests.push(bytes);
        if function != deaf {
            return true;
        }
    }
}

/// The manuals' read of 400108-400110 from slave 17, and its answer.
fn request() -> Vec<u8> {
    WORKED_FRAMES[4].clone()
}

fn answer() -> Vec<u8> {
    WORKED_FRAMES[5].clone()
}

fn now(bytes: &[u8]) -> Act {
    Act::Answer(Duration::ZERO, bytes.to_vec())
}

fn assert_fails(outcome: &Outcome, code: i32, says: &str) {
    assert_eq!(outcome.code, code, "stderr: {}", outcome.stderr);
    assert!(outcome.stdout.is_empty(), "printed {:?}", outcome.stdout);
    assert_eq!(outcome.stderr.lines().count(), 1, "{}", outcome.stderr);
    assert!(outcome.stderr.starts_with("mbtool: "), "{}", outcome.stderr);
    assert!(
        outcome.stderr.contains(says),
        "{:?} lacks {says:?}",
        outcome.stderr
    );
}

#[test]
fn a_good_answer_is_read() {
    let outcome = against(vec![now(&answer())], READ);
    assert_eq!(outcome.code, 0, "{}", outcome.stderr);
    assert_eq!(outcome.stdout, "555\n0\n100\n");
    assert_eq!(outcome.requests, [request()]);
}

/// The first `count` values `v` for which `body(v)` framed ends in a 00 byte: a frame whose
/// first bytes also pass their CRC, which a framer must not wait on.
fn ending_in_00(count: usize, body: impl Fn(u16) -> Vec<u8>) -> Vec<u16> {
    (0..=u16::MAX)
        .filter(|v| rtu(&body(*v)).last() == Some(&0))
        .take(count)
        .collect()
}

#[test]
fn an_answer_there_at_once_is_read_at_once_whatever_its_last_byte() {
    let read_one = |v: u16| [&[0x11, 0x03, 0x02][..], &v.to_be_bytes()].concat();
    let echo = |v: u16| [&[0x11, 0x06, 0x00, 0x6B][..], &v.to_be_bytes()].concat();
    // Exception codes 1-255, so that each value is a different answer.
    let exception = |code: u16| vec![0x11, 0x83, (code % 255 + 1) as u8];
    let mut cases: Vec<(Vec<String>, Vec<u8>, i32)> = Vec::new();
    for v in ending_in_00(3, read_one).into_iter().chain([555, 0]) {
        let args = "read-holding 17 400108 -o values";
        cases.push((
            args.split(' ').map(String::from).collect(),
            rtu(&read_one(v)),
            0,
        ));
    }
    // Behind a noise byte the answer must be supported by what follows it: the silence
    // after it, not the timeout.
    for v in ending_in_00(2, read_one).into_iter().chain([555]) {
        let args = "read-holding 17 400108 -o values";
        let answer = [&[0xFE][..], &rtu(&read_one(v))].concat();
        cases.push((args.split(' ').map(String::from).collect(), answer, 0));
    }
    for v in ending_in_00(2, echo) {
        let args = format!("write-register 17 400108 {v}");
        cases.push((
            args.split(' ').map(String::from).collect(),
            rtu(&echo(v)),
            0,
        ));
    }
    for code in ending_in_00(2, exception).into_iter().chain([1]) {
        let args = "read-holding 17 400108 -o values";
        // Exit 10 + the exception's code.
        let exit = 10 + i32::from(exception(code)[2]);
        cases.push((
            args.split(' ').map(String::from).collect(),
            rtu(&exception(code)),
            exit,
        ));
    }
    for (args, answer, code) in cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let started = std::time::Instant::now();
        let outcome = against_within("5s", vec![now(&answer)], &args);
        let took = started.elapsed();
        assert_eq!(
            outcome.code, code,
            "{args:?} {answer:02X?}: {}",
            outcome.stderr
        );
        // The slave's helper waits 300 ms for requests after the last; the read must not
        // wait for its 5 s timeout.
        assert!(
            took < Duration::from_secs(1),
            "{args:?} {answer:02X?} took {took:?}"
        );
    }
}

#[test]
fn an_answer_that_comes_in_pieces_with_pauses_is_read_whole_at_once() {
    // A slow slave a byte at a time, 5 ms apart (longer than 3.5 characters at 19200),
    // and a USB adapter's pieces 20 ms apart: the gaps are not the answer's end.
    let bytes = answer().chunks(1).map(<[u8]>::to_vec).collect();
    let halves = vec![answer()[..4].to_vec(), answer()[4..].to_vec()];
    for (pause, pieces) in [(5, bytes), (20, halves)] {
        let started = std::time::Instant::now();
        let args = [&["-b", "19200"], READ].concat();
        let outcome = against_within(
            "5s",
            vec![Act::Pieces(Duration::from_millis(pause), pieces)],
            &args,
        );
        assert_eq!(outcome.code, 0, "{pause} ms: {}", outcome.stderr);
        assert_eq!(
            outcome.stdout.split_whitespace().collect::<Vec<_>>(),
            ["555", "0", "100"]
        );
        assert!(
            started.elapsed() < Duration::from_secs(2),
            "{:?}",
            started.elapsed()
        );
    }
}

#[test]
fn a_bad_crc_is_a_bad_frame() {
    let mut answer = answer();
    answer[10] ^= 0xFF;
    assert_fails(&against(vec![now(&answer)], READ), 4, "CRC mismatch");
}

#[test]
fn an_answer_from_another_slave_is_a_bad_frame() {
    let answer = rtu(&[0x12, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64]);
    assert_fails(&against(vec![now(&answer)], READ), 4, "slave 18");
}

#[test]
fn an_answer_for_another_function_is_a_bad_frame() {
    let answer = rtu(&[0x11, 0x04, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64]);
    assert_fails(&against(vec![now(&answer)], READ), 4, "function 04");
}

#[test]
fn fewer_registers_than_asked_is_a_bad_frame() {
    let answer = rtu(&[0x11, 0x03, 0x04, 0x02, 0x2B, 0x00, 0x00]);
    assert_fails(&against(vec![now(&answer)], READ), 4, "registers: 2");
}

#[test]
fn a_truncated_answer_is_a_bad_frame() {
    assert_fails(
        &against(vec![now(&answer()[..7])], READ),
        4,
        "incomplete answer: 7 bytes",
    );
}

#[test]
fn noise_before_the_answer_is_passed_over() {
    let mut noisy = vec![0x00, 0xFE, 0x11];
    noisy.extend_from_slice(&answer());
    let outcome = against(vec![now(&noisy)], READ);
    assert_eq!(outcome.code, 0, "{}", outcome.stderr);
    assert_eq!(outcome.stdout, "555\n0\n100\n");
}

#[test]
fn a_late_answer_is_a_timeout() {
    let late = Act::Answer(Duration::from_millis(700), answer());
    assert_fails(
        &against(vec![late], READ),
        3,
        "no answer from slave 17 within 300.00 ms",
    );
}

#[test]
fn a_silent_slave_is_a_timeout() {
    assert_fails(&against(vec![Act::Silence], READ), 3, "no answer");
}

#[test]
fn an_exception_gives_10_plus_its_code_and_its_name() {
    let exception = rtu(&[0x11, 0x83, 0x02]);
    assert_fails(
        &against(vec![now(&exception)], READ),
        12,
        "illegal data address",
    );
    let exception = rtu(&[0x11, 0x83, 0x04]);
    assert_fails(
        &against(vec![now(&exception)], READ),
        14,
        "slave device failure",
    );
}

#[test]
fn a_timeout_is_retried_and_an_exception_never() {
    let mut args = READ.to_vec();
    args.extend(["--retries", "2"]);
    let outcome = against(vec![Act::Silence, now(&answer())], &args);
    assert_eq!(outcome.code, 0, "{}", outcome.stderr);
    assert_eq!(outcome.requests.len(), 2);

    let exception = rtu(&[0x11, 0x83, 0x02]);
    let outcome = against(vec![now(&exception)], &args);
    assert_eq!(outcome.code, 12);
    assert_eq!(outcome.requests.len(), 1, "an exception was retried");
}

#[test]
fn a_bad_frame_is_retried() {
    let mut bad = answer();
    bad[3] ^= 1;
    let mut args = READ.to_vec();
    args.extend(["--retries", "1"]);
    let outcome = against(vec![now(&bad), now(&answer())], &args);
    assert_eq!(outcome.code, 0, "{}", outcome.stderr);
    assert_eq!(outcome.requests.len(), 2);
}

#[test]
fn a_write_whose_echo_differs_is_a_bad_frame() {
    let echo = rtu(&[0x11, 0x06, 0x00, 0x01, 0x00, 0x04]);
    let outcome = against(vec![now(&echo)], &["write-register", "17", "400002", "3"]);
    assert_fails(&outcome, 4, "echo");
    assert_eq!(
        outcome.requests,
        [vec![0x11, 0x06, 0x00, 0x01, 0x00, 0x03, 0x9A, 0x9B]]
    );
}

#[test]
fn a_broadcast_write_expects_no_answer() {
    let outcome = against(vec![Act::Silence], &["write-register", "0", "400002", "3"]);
    assert_eq!(outcome.code, 0, "{}", outcome.stderr);
    assert_eq!(outcome.requests.len(), 1);
    assert!(outcome.stdout.contains("broadcast"), "{}", outcome.stdout);
}

#[test]
fn verbose_shows_every_frame_with_a_timestamp() {
    let mut args = READ.to_vec();
    args.push("-v");
    let outcome = against(vec![now(&answer())], &args);
    assert_eq!(outcome.code, 0);
    let lines: Vec<&str> = outcome.stderr.lines().collect();
    assert_eq!(lines.len(), 2, "{}", outcome.stderr);
    assert!(
        lines[0].ends_with("> 11 03 00 6B 00 03 76 87"),
        "{}",
        lines[0]
    );
    assert!(
        lines[1].ends_with("< 11 03 06 02 2B 00 00 00 64 C8 BA"),
        "{}",
        lines[1]
    );
    assert!(lines[0].starts_with('['), "{}", lines[0]);
}

#[test]
fn ascii_mode_on_a_serial_line() {
    let pty = Pty::new();
    let path = pty.path.clone();
    let mut port = pty.master.try_clone_native().unwrap();
    let slave = thread::spawn(move || {
        let request = read_frame(
            &mut port,
            Mode::Ascii,
            Direction::Request,
            Duration::from_secs(5),
        );
        write_all(&mut port, b":110306022B0000006455\r\n");
        request.map(|(_, bytes)| bytes)
    });
    let output = mbtool()
        .args(["--port", &path, "--mode", "ascii", "--timeout", "500ms"])
        .args(READ)
        .output()
        .unwrap();
    let request = slave.join().unwrap();
    assert_eq!(request.as_deref(), Some(&b":1103006B00037E\r\n"[..]));
    assert_eq!(
        String::from_utf8_lossy(&output.stdout),
        "555\n0\n100\n",
        "{output:?}"
    );
}

#[test]
fn a_late_answer_is_never_taken_for_the_next_requests() {
    // The first answer comes after the timeout, with values the next read must not show;
    // the next read is of the same shape, so the master checks the line with an echo
    // (08/00) first, and the late answer is heard there for what it is.
    let late = rtu(&[0x11, 0x03, 0x06, 0x00, 0x01, 0x00, 0x02, 0x00, 0x03]);
    let acts = vec![
        Act::Answer(Duration::from_millis(450), late),
        Act::Echo,
        now(&answer()),
    ];
    let outcome = against(acts, &[READ, &["--poll", "0", "--count", "2"]].concat());
    assert_eq!(outcome.code, 0, "{}", outcome.stderr);
    assert_eq!(outcome.stdout, "555\n0\n100\n", "{}", outcome.stderr);
    assert_eq!(outcome.requests.len(), 3, "{:02X?}", outcome.requests);
    assert_eq!(outcome.requests[1][1..3], [0x08, 0x00, 0x00][..2]);
    assert_eq!(outcome.requests[2], request());
}

#[test]
fn a_write_is_told_as_it_happened_when_answers_are_lost() {
    let write = ["write-register", "17", "400002", "3", "--retries", "2"];
    let echo = rtu(&[0x11, 0x06, 0x00, 0x01, 0x00, 0x03]);
    // The first answer is lost: written, and said to have been sent twice.
    let outcome = against(vec![Act::Silence, now(&echo)], &write);
    assert_eq!(outcome.code, 0, "{}", outcome.stderr);
    assert_eq!(outcome.requests.len(), 2);
    assert!(
        outcome
            .stderr
            .contains("function 06 (Write Single Register) was sent to slave 17 2 times before an answer came"),
        "{}",
        outcome.stderr
    );
    // No answer at all: the write may have been carried out, and the message says so.
    let outcome = against(vec![Act::Silence, Act::Silence, Act::Silence], &write);
    assert_fails(
        &outcome,
        3,
        "the request was sent 3 times and may have been carried out all the same",
    );
    assert_eq!(outcome.requests.len(), 3);
    // raw is told the same way.
    let raw = ["raw", "17", "06 00 01 00 03", "--retries", "2"];
    let outcome = against(vec![Act::Silence, now(&echo)], &raw);
    assert_eq!(outcome.code, 0, "{}", outcome.stderr);
    assert!(
        outcome.stderr.contains("was sent to slave 17 2 times"),
        "{}",
        outcome.stderr
    );
    let outcome = against(vec![Act::Silence, Act::Silence, Act::Silence], &raw);
    assert_fails(&outcome, 3, "may have been carried out all the same");
}

#[test]
fn retries_of_a_request_that_may_do_more_when_sent_twice_are_asked_for_explicitly() {
    // A bit of a register is written with one mask write (22).
    let mask = ["write-register", "17", "400002.03", "1", "--retries", "1"];
    let outcome = against(vec![], &mask);
    assert_fails(&outcome, 2, "give --retry-non-idempotent");
    assert!(outcome.requests.is_empty(), "{:02X?}", outcome.requests);
    let explicit = [&mask[..], &["--retry-non-idempotent"]].concat();
    let outcome = against(vec![Act::Silence, Act::Silence], &explicit);
    assert_eq!(outcome.code, 3, "{}", outcome.stderr);
    assert_eq!(outcome.requests.len(), 2, "{:02X?}", outcome.requests);
}

#[test]
fn a_slave_that_ignores_the_check_is_taken_back_in_step_after_seconds_of_silence() {
    // One answer lost; the slave says nothing to 08 at all. Polled every 500 ms, the read
    // waits while a late answer could still come, then goes on: one lost answer is not
    // the loss of the function for good.
    let mut acts = vec![now(&answer()), Act::Silence];
    acts.extend((0..6).map(|_| now(&answer())));
    let args = [READ, &["--poll", "500ms", "--count", "15"]].concat();
    let outcome = against_deaf_to(Some(0x08), "300ms", acts, &args);
    let answered = outcome.stdout.matches("555\n").count();
    let reads: Vec<usize> = (0..outcome.requests.len())
        .filter(|&i| outcome.requests[i][1] == 0x03)
        .collect();
    let checks = outcome.requests.len() - reads.len();
    assert!(answered >= 2, "{}{}", outcome.stdout, outcome.stderr);
    assert_eq!(reads.len(), answered + 1, "{:02X?}", outcome.requests);
    assert!(
        (6..=12).contains(&checks),
        "{checks} checks: {:02X?}",
        outcome.requests
    );
    // No read went between the checks: the reads after the lost one follow them all.
    assert_eq!(reads[..3], [0, 1, 2 + checks], "{:02X?}", outcome.requests);
}
