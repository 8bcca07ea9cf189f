//! A plant on a bad day: a device unplugged and back, a slave that answers one request in
//! three, a serial line whose port vanishes. The other devices' rows go on at their rate,
//! and no value is shown that was not read.

use std::io::{Read, Write};
use std::net::TcpListener;
use std::time::Duration;

use super::{device, json_rows, plant, rows_of};
use crate::support::{serve, serve_pty, serve_tcp, PtyPair};

/// A Modbus TCP device that answers only every third request (reading registers, each
/// 7), the others left unanswered; it lasts as long as the test.
fn answers_one_in_three() -> u16 {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    std::thread::spawn(move || {
        let mut asked = 0u32;
        for mut stream in listener.incoming().map_while(Result::ok) {
            let mut head = [0u8; 7];
            while stream.read_exact(&mut head).is_ok() {
                let length = usize::from(u16::from_be_bytes([head[4], head[5]]));
                let mut pdu = vec![0u8; length.saturating_sub(1)];
                if stream.read_exact(&mut pdu).is_err() {
                    break;
                }
                asked += 1;
                if asked % 3 != 0 || pdu.len() < 5 {
                    continue;
                }
                let count = u16::from_be_bytes([pdu[3], pdu[4]]);
                let mut answer = head.to_vec();
                answer.extend([pdu[0], (count * 2) as u8]);
                for _ in 0..count {
                    answer.extend(7u16.to_be_bytes());
                }
                let length = (answer.len() - 6) as u16;
                answer[4..6].copy_from_slice(&length.to_be_bytes());
                let _ = stream.write_all(&answer);
            }
        }
    });
    port
}

/// The times of `rows`, as milliseconds of the day.
fn times(rows: &[&serde_json::Value]) -> Vec<i64> {
    rows.iter()
        .map(|row| {
            let time = row["time"].as_str().unwrap();
            let time = chrono::DateTime::parse_from_rfc3339(time).unwrap();
            time.timestamp_millis()
        })
        .collect()
}

#[test]
fn a_device_unplugged_and_back_and_one_that_answers_one_request_in_three_hold_back_no_other() {
    let (_steady, _, steady) = serve_tcp(&[]);
    let (unplugged, _, port) = serve_tcp(&[]);
    let flaky = answers_one_in_three();
    let at = |port: u16| format!("tcp://127.0.0.1:{port}");
    let (_dir, path) = plant(&[
        device("steady", &at(steady), 17, "100ms"),
        device("unplugged", &at(port), 17, "100ms"),
        device("flaky", &at(flaky), 17, "100ms"),
    ]);
    let replug = std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(1000));
        drop(unplugged);
        std::thread::sleep(Duration::from_millis(1000));
        let back = serve(&["--port", &at(port)]);
        std::thread::sleep(Duration::from_secs(4));
        drop(back);
    });
    let args = [&path, "--for", "5s", "--timeout", "150ms", "--retries", "0"];
    let (code, rows, stderr) = json_rows(&args);
    replug.join().unwrap();
    assert_eq!(code, 0, "{stderr}");

    // The steady device: a row every 100 ms throughout, never a gap of a poll missed.
    let steady = rows_of(&rows, "steady");
    assert!(steady.len() >= 45, "{}", steady.len());
    let gaps: Vec<i64> = times(&steady).windows(2).map(|w| w[1] - w[0]).collect();
    assert!(gaps.iter().all(|gap| *gap < 190), "{gaps:?}");
    assert!(steady.iter().all(|row| row["values"]["speed"] == 555));

    // Unplugged: values, then rows that say why there are none, then values again.
    let unplugged = rows_of(&rows, "unplugged");
    let read: Vec<bool> = unplugged
        .iter()
        .map(|row| row["values"]["speed"] == 555)
        .collect();
    let first_gap = read.iter().position(|r| !r).expect("a row without values");
    let back = first_gap
        + read[first_gap..]
            .iter()
            .position(|r| *r)
            .expect("values again");
    assert!(first_gap >= 5 && back > first_gap, "{read:?}");
    for row in &unplugged[first_gap..back] {
        assert_eq!(row["values"], serde_json::json!({}), "{row}");
        assert!(row["error"].is_string(), "{row}");
    }
    assert!(read[back..].iter().all(|r| *r), "{read:?}");

    // One in three: each point of each row is a value read (7) or why there is none,
    // never the last value again.
    let flaky = rows_of(&rows, "flaky");
    let mut read = 0;
    for row in &flaky {
        let values = row["values"].as_object().unwrap();
        assert!(values.values().all(|value| *value == 7), "{row}");
        read += values.len();
        let mut points: Vec<&String> = values.keys().collect();
        match row["errors"].as_object() {
            Some(errors) => points.extend(errors.keys()),
            None if values.is_empty() => assert!(row["error"].is_string(), "{row}"),
            None => {}
        }
        points.sort();
        if !points.is_empty() {
            assert_eq!(points, ["flow", "level", "speed"], "{row}");
        }
    }
    assert!(read >= 10 && flaky.len() >= 8, "{read} values in {flaky:?}");
}

#[test]
fn a_serial_line_whose_port_vanishes_holds_back_no_other_device() {
    let Some(pair) = PtyPair::new() else { return };
    let (line, port) = serve_pty(&pair, &["--slave", "17", "--slave", "18"]);
    let (_tcp, _, tcp) = serve_tcp(&[]);
    let (_dir, path) = plant(&[
        device("a", &port[1], 17, "100ms"),
        device("b", &port[1], 18, "100ms"),
        device("tcp", &format!("tcp://127.0.0.1:{tcp}"), 17, "100ms"),
    ]);
    let vanish = std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(1000));
        drop(line);
        drop(pair);
    });
    let (code, rows, stderr) = json_rows(&[&path, "--for", "3s", "--timeout", "100ms"]);
    vanish.join().unwrap();
    assert_eq!(code, 0, "{stderr}");
    let tcp = rows_of(&rows, "tcp");
    assert!(tcp.len() >= 27, "{}", tcp.len());
    let gaps: Vec<i64> = times(&tcp).windows(2).map(|w| w[1] - w[0]).collect();
    assert!(gaps.iter().all(|gap| *gap < 190), "{gaps:?}");
    for name in ["a", "b"] {
        let line = rows_of(&rows, name);
        assert!(line[0]["values"]["speed"] == 555, "{:?}", line[0]);
        let last = line.last().unwrap();
        assert_eq!(last["values"], serde_json::json!({}), "{last}");
        assert!(last["error"].is_string(), "{last}");
    }
}

/// A noisy serial line (noise bytes before the answers, one answer in five corrupted):
/// every value a row shows is the one the device holds, never one read from a bad frame,
/// and most polls read whole.
#[test]
fn a_noisy_serial_line_shows_no_value_the_device_does_not_hold() {
    let Some(pair) = PtyPair::new() else { return };
    let noise = [
        "--slave",
        "17",
        "--slave",
        "18",
        "--garbage",
        "--corrupt",
        "20%",
        "--seed",
        "7",
    ];
    let (_line, port) = serve_pty(&pair, &noise);
    let (_dir, path) = plant(&[
        device("a", &port[1], 17, "100ms"),
        device("b", &port[1], 18, "100ms"),
    ]);
    let (code, rows, stderr) = json_rows(&[&path, "--for", "3s", "--timeout", "200ms"]);
    assert_eq!(code, 0, "{stderr}");
    let held = serde_json::json!({"speed": 555, "level": 0, "flow": 100});
    let mut whole = 0;
    for row in &rows {
        let values = row["values"].as_object().unwrap();
        for (name, value) in values {
            assert_eq!(value, &held[name], "{row}");
        }
        whole += usize::from(values.len() == 3);
    }
    assert!(
        rows.len() >= 20 && whole * 2 >= rows.len(),
        "{whole} whole of {}",
        rows.len()
    );
}
