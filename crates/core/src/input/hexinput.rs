//! Frames as people paste them: `11 03 00 6B`, `1103006B`, `0x11,0x03`, `\x11\x03`, or an
//! ASCII frame as text (`:1103006B00037E`); and frames as logs print them, with a time,
//! a direction and words around them.

use thiserror::Error;

use crate::codec::adu::hex_digit;
use crate::codec::Direction;

/// Why pasted text is no run of hex bytes.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum HexError {
    /// Nothing but separators.
    #[error("empty: no hex digits")]
    Empty,
    /// A word whose hex digits do not pair into bytes.
    #[error("odd number of hex digits in '{0}': every byte takes two")]
    OddDigits(String),
    /// A `0x` or `\x` prefix with nothing after it.
    #[error("'{0}' has no hex digits after its prefix")]
    NoDigits(String),
    /// A character that is no hex digit, with its column (1-based).
    #[error("'{0}' at column {1} is not a hex digit")]
    NotHex(String, usize),
    /// A line of words, a log's own message (`Waiting for a confirmation...`), with no
    /// frame on it.
    #[error("no frame: the line is words, a log's own message")]
    Message,
    /// A log line whose hex bytes are too few for a frame.
    #[error("no frame: the line's longest run of hex bytes, {0}, is shorter than any frame (4 bytes at least); give one frame a line")]
    TooShort(String),
}

fn is_separator(b: u8) -> bool {
    b.is_ascii_whitespace() || matches!(b, b',' | b';')
}

/// Shows a byte of the input in an error message without printing it raw: a control
/// character by its byte, a space that is no ASCII space (a no-break space pasted from a
/// document) by its code point, since shown as itself it would read as a blank.
fn shown(text: &[u8], at: usize) -> String {
    let rest = text.get(at..).unwrap_or_default();
    match std::str::from_utf8(rest)
        .ok()
        .and_then(|s| s.chars().next())
    {
        Some(c) if c.is_whitespace() && !c.is_ascii() => format!("U+{:04X}", u32::from(c)),
        Some(c) if !c.is_control() => c.to_string(),
        _ => format!("\\x{:02X}", rest.first().copied().unwrap_or_default()),
    }
}

/// Appends the bytes that the hex `text` spells to `out`.
pub fn parse_hex(text: &[u8], out: &mut Vec<u8>) -> Result<(), HexError> {
    let start = out.len();
    let mut i = 0;
    while i < text.len() {
        if is_separator(text[i]) {
            i += 1;
            continue;
        }
        // One token: an optional 0x or \x prefix, then hex digits up to a separator.
        let prefixed = matches!(
            text.get(i..i + 2),
            Some([b'0', b'x' | b'X'] | [b'\\', b'x'])
        );
        let token_start = i;
        if prefixed {
            i += 2;
        }
        let digits_start = i;
        while i < text.len() && !is_separator(text[i]) {
            if text[i] == b'\\' && text.get(i + 1) == Some(&b'x') {
                break;
            }
            if hex_digit(text[i]).is_none() {
                return Err(HexError::NotHex(shown(text, i), i + 1));
            }
            i += 1;
        }
        let digits = &text[digits_start..i];
        match digits.len() {
            0 => {
                let token = String::from_utf8_lossy(&text[token_start..i]);
                return Err(HexError::NoDigits(token.into_owned()));
            }
            1 if prefixed => out.push(hex_digit(digits[0]).unwrap_or_default()),
            n if n % 2 == 1 => {
                let token = String::from_utf8_lossy(&text[token_start..i]);
                return Err(HexError::OddDigits(token.chars().take(40).collect()));
            }
            _ => out.extend(digits.chunks_exact(2).map(|pair| {
                hex_digit(pair[0]).unwrap_or_default() << 4 | hex_digit(pair[1]).unwrap_or_default()
            })),
        }
    }
    if out.len() == start {
        return Err(HexError::Empty);
    }
    Ok(())
}

/// Hex given as several command-line words.
pub fn parse_hex_words(words: &[String]) -> Result<Vec<u8>, HexError> {
    let mut out = Vec::new();
    for word in words {
        parse_hex(word.as_bytes(), &mut out)?;
    }
    if out.is_empty() {
        return Err(HexError::Empty);
    }
    Ok(out)
}

/// The shortest run of hex bytes taken for a frame among other words on a log line: an
/// RTU address, function and CRC.
const SHORTEST_FRAME: usize = 4;

/// The frame a line holds, as [`read_line`] finds it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LineFrame {
    /// The frame's bytes: the hex spelled out, or an ASCII frame's own characters (CR LF
    /// after each, when several are glued together).
    pub bytes: Vec<u8>,
    /// The way the log says the frame went: `>` or `TX` before it is a request, `<` or
    /// `RX` a response.
    pub direction: Option<Direction>,
}

/// How the bytes of a run are spelled; a run keeps to one spelling, so that a time such
/// as `12:03:04` does not join the frame after it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Spelling {
    /// `11 03`, `1103`, `11,03`.
    Plain,
    /// `0x11`.
    Prefixed,
    /// `\x11`, as an escaped string.
    Escaped,
    /// `11:03:00`, as Wireshark copies bytes.
    Colons,
    /// `11-03-00`.
    Hyphens,
    /// `[11][03]`, `<11><03>`, as libmodbus prints them.
    Bracketed,
}

/// A run of hex bytes on a line, or an ASCII frame.
#[derive(Default)]
struct Run {
    bytes: Vec<u8>,
    spelling: Option<Spelling>,
    direction: Option<Direction>,
    /// A direction mark stands between it and the run before it.
    after_mark: bool,
    ascii: bool,
}

/// A direction mark: a word (`TX`, `Rx:`, `[RX]`, `SEND:`, `recv:`) or a symbol (`>`,
/// `<`). `Some((direction, named))`; a named mark is not overridden by a symbol after it,
/// as in QModMaster's `[RTU]>Rx > 10:33:38:374`.
fn direction_mark(word: &[u8]) -> Option<(Direction, bool)> {
    let word = word
        .strip_suffix(b":")
        .or_else(|| word.strip_suffix(b"="))
        .unwrap_or(word);
    let word = word
        .strip_prefix(b"[")
        .and_then(|w| w.strip_suffix(b"]"))
        .unwrap_or(word);
    match word.to_ascii_uppercase().as_slice() {
        b">" | b">>" | b"->" | b"=>" => Some((Direction::Request, false)),
        b"<" | b"<<" | b"<-" | b"<=" => Some((Direction::Response, false)),
        b"TX" | b"SEND" | b"SENT" => Some((Direction::Request, true)),
        b"RX" | b"RECV" | b"RECEIVED" => Some((Direction::Response, true)),
        _ => None,
    }
}

/// A word split where a direction mark is glued to what stands around it, as Modbus Poll
/// writes `000000-Tx:01`, QModMaster `[RTU]>Rx` and Python's logging
/// `DEBUG:pymodbus.transaction:SEND:`: the part before, the mark with its colon, and the
/// part after.
fn split_glued_mark(word: &[u8]) -> Vec<&[u8]> {
    const NAMES: [&[u8]; 4] = [b"TX", b"RX", b"SEND", b"RECV"];
    let alnum = |at: usize| word.get(at).is_some_and(u8::is_ascii_alphanumeric);
    let found = (0..word.len()).find_map(|i| {
        NAMES.iter().find_map(|name| {
            let end = i + name.len();
            let named = word
                .get(i..end)
                .is_some_and(|w| w.eq_ignore_ascii_case(name));
            (named && (i == 0 || !alnum(i - 1)) && !alnum(end) && word.len() > end - i)
                .then_some((i, end))
        })
    });
    let Some((at, end)) = found else {
        return vec![word];
    };
    let end = if matches!(word.get(end), Some(b':' | b'=')) {
        end + 1
    } else {
        end
    };
    // Modbus Poll's newer logs put the line counter after the mark: `Tx:000002-01`.
    let after = &word[end..];
    let digits = after.iter().take_while(|b| b.is_ascii_digit()).count();
    let counter = match after.get(digits) {
        Some(b'-') if (4..=8).contains(&digits) => digits + 1,
        _ => 0,
    };
    [
        &word[..at],
        &word[at..end],
        &after[..counter],
        &after[counter..],
    ]
    .into_iter()
    .filter(|piece| !piece.is_empty())
    .collect()
}

/// The bytes one piece of a word spells in one spelling, or `None` when it is no hex.
fn piece_bytes(piece: &[u8], bracketed: bool) -> Option<(Spelling, Vec<u8>)> {
    let mut bytes = Vec::new();
    for (separator, spelling) in [(b':', Spelling::Colons), (b'-', Spelling::Hyphens)] {
        if piece.contains(&separator) {
            for pair in piece.split(|b| *b == separator) {
                let [high, low] = pair else { return None };
                bytes.push(hex_digit(*high)? << 4 | hex_digit(*low)?);
            }
            return Some((spelling, bytes));
        }
    }
    parse_hex(piece, &mut bytes).ok()?;
    let spelling = if piece.starts_with(b"0x") || piece.starts_with(b"0X") {
        Spelling::Prefixed
    } else if piece.starts_with(b"\\x") {
        Spelling::Escaped
    } else if bracketed {
        Spelling::Bracketed
    } else {
        Spelling::Plain
    };
    Some((spelling, bytes))
}

/// An ASCII frame written as text, `:1103006B00037E`, or several glued together: their
/// characters, each frame ended by CR LF.
fn ascii_frames(word: &[u8]) -> Option<Vec<u8>> {
    let body = word.strip_prefix(b":")?;
    let mut bytes = Vec::with_capacity(word.len() + 2);
    for frame in body.split(|b| *b == b':') {
        if frame.len() < 2 || !frame.iter().all(u8::is_ascii_hexdigit) {
            return None;
        }
        bytes.push(b':');
        bytes.extend_from_slice(frame);
        bytes.extend_from_slice(b"\r\n");
    }
    Some(bytes)
}

/// Reads one line of pasted frames or of a log. A line that is all hex is one frame as
/// given, and one that starts with ':' an ASCII frame. On any other line the frame is the
/// longest run of hex bytes (or an ASCII frame), and what stands around it, a time stamp,
/// `CRC ok`, a `#` comment, is set aside; a direction mark before it says which way it
/// went; a line with a frame after each of two marks of different ways (`TX: ... RX: ...`)
/// holds both. Empty: a blank line, or a comment (`#` first).
pub fn read_line(line: &[u8]) -> Result<Vec<LineFrame>, HexError> {
    let line = line.trim_ascii();
    if line.is_empty() || line.starts_with(b"#") {
        return Ok(Vec::new());
    }
    let before_comment = line
        .split(|b| *b == b'#')
        .next()
        .unwrap_or_default()
        .trim_ascii();
    match frames_of(before_comment) {
        // A '#' that did not start a comment (`frame #1: 11 03 ...`).
        Err(_) if before_comment.len() < line.len() => frames_of(line),
        found => found,
    }
}

/// The frames of a line without its comment.
fn frames_of(line: &[u8]) -> Result<Vec<LineFrame>, HexError> {
    if line.starts_with(b":") {
        return Ok(vec![LineFrame {
            bytes: ascii_frames(line).unwrap_or_else(|| line.to_vec()),
            direction: None,
        }]);
    }
    let mut strict = Vec::new();
    let strict_error = match parse_hex(line, &mut strict) {
        Ok(()) => {
            return Ok(vec![LineFrame {
                bytes: strict,
                direction: None,
            }])
        }
        Err(error) => error,
    };
    // pymodbus 2.x logs the PDU it took out of a frame (`Getting Frame - 0x3 0x6 ...`):
    // no unit, no CRC, so no frame; the frame itself is on its `Processing:` line.
    if contains_ignoring_case(line, b"getting frame") {
        return Err(HexError::Message);
    }
    let mut runs = frames_of_line(line);
    if runs.len() > 1 {
        return Ok(runs
            .into_iter()
            .map(|run| LineFrame {
                bytes: run.bytes,
                direction: run.direction,
            })
            .collect());
    }
    let run = runs.pop();
    let frame = run
        .as_ref()
        .is_some_and(|run| run.ascii || run.bytes.len() >= SHORTEST_FRAME);
    if !frame && (is_prose(line) || is_chatter(line)) {
        return Err(HexError::Message);
    }
    // A byte mistyped among hex bytes (`8G`, `1O`) is a mistake to point at, not a word
    // of a log to set aside.
    if line.split(u8::is_ascii_whitespace).any(mistyped_byte) {
        return Err(strict_error);
    }
    match run {
        Some(run) if frame => Ok(vec![LineFrame {
            bytes: run.bytes,
            direction: run.direction,
        }]),
        Some(run) => Err(HexError::TooShort(crate::codec::hex::spaced_hex(
            &run.bytes,
        ))),
        None => Err(strict_error),
    }
}

/// Whether a line without a frame is words, as the messages tools write among the frames
/// of their logs: two words or more of three letters or more, one of them no hex.
fn is_prose(line: &[u8]) -> bool {
    // Python's logging glues its words with ':' and '.' (`DEBUG:pymodbus.transaction:`).
    let words: Vec<&[u8]> = line
        .split(|b| b.is_ascii_whitespace() || b":.=[]".contains(b))
        .map(|word| word.trim_ascii_end().strip_suffix(b"...").unwrap_or(word))
        .map(|word| word.strip_suffix(b":").unwrap_or(word))
        .filter(|word| word.len() >= 3 && word.iter().all(u8::is_ascii_alphabetic))
        .collect();
    words.len() >= 2 && words.iter().any(|w| !w.iter().all(u8::is_ascii_hexdigit))
}

/// What mbpoll's `-v` prints beside its frames: settings (`iCount=1`, `Set mode=rtu`) and
/// the values read (`[1]: 555`).
fn is_chatter(line: &[u8]) -> bool {
    let setting = |word: &[u8]| {
        word.iter().position(|b| *b == b'=').is_some_and(|at| {
            at >= 2
                && word[..at]
                    .iter()
                    .all(|b| b.is_ascii_alphanumeric() || *b == b'_')
        })
    };
    let value_line = line
        .strip_prefix(b"[")
        .and_then(|rest| rest.iter().position(|b| *b == b']').map(|at| (at, rest)))
        .is_some_and(|(at, rest)| {
            at > 0 && rest[..at].iter().all(u8::is_ascii_digit) && rest.get(at + 1) == Some(&b':')
        });
    value_line || line.split(u8::is_ascii_whitespace).any(setting)
}

/// Whether `line` holds `word`, whatever the case.
fn contains_ignoring_case(line: &[u8], word: &[u8]) -> bool {
    line.windows(word.len())
        .any(|w| w.eq_ignore_ascii_case(word))
}

/// A word of one or two letters and digits, some hex and some not.
fn mistyped_byte(word: &[u8]) -> bool {
    (1..=2).contains(&word.len())
        && word.iter().all(u8::is_ascii_alphanumeric)
        && word.iter().any(u8::is_ascii_hexdigit)
        && !word.iter().all(u8::is_ascii_hexdigit)
}

/// The frames of a log line: the longest run of hex bytes (or its ASCII frame), or, where
/// the line holds frames that direction marks of different ways part (`TX: ... RX: ...`,
/// `> ... < ...`, `... <- ...`), each of them; a first frame without a mark went the other
/// way from the one after it.
fn frames_of_line(line: &[u8]) -> Vec<Run> {
    let mut runs = runs(line);
    let framed: Vec<usize> = (0..runs.len())
        .filter(|i| runs[*i].ascii || runs[*i].bytes.len() >= SHORTEST_FRAME)
        .collect();
    let ways = |i: &usize| runs[*i].direction;
    let parted = framed.len() >= 2
        && framed[1..]
            .iter()
            .all(|i| runs[*i].after_mark && ways(i).is_some())
        && framed.iter().any(|i| ways(i) != ways(&framed[1]));
    if parted {
        let mut kept = Vec::new();
        for i in framed.into_iter().rev() {
            kept.push(runs.swap_remove(i));
        }
        kept.reverse();
        if kept[0].direction.is_none() {
            kept[0].direction = kept[1].direction.map(Direction::opposite);
        }
        return kept;
    }
    // The first of the longest.
    let longest = runs.iter().map(|run| run.bytes.len()).max().unwrap_or(0);
    runs.into_iter()
        .find(|run| run.bytes.len() == longest)
        .into_iter()
        .collect()
}

/// Every run of hex bytes on a log line, and its ASCII frames, each with the direction
/// mark last seen before it.
fn runs(line: &[u8]) -> Vec<Run> {
    let mut best: Vec<Run> = Vec::new();
    let mut run = Run::default();
    let mut mark: Option<(Direction, bool)> = None;
    let mut fresh_mark = false;
    let keep = |run: &mut Run, best: &mut Vec<Run>| {
        let run = std::mem::take(run);
        if !run.bytes.is_empty() {
            best.push(run);
        }
    };
    for word in line
        .split(u8::is_ascii_whitespace)
        .filter(|w| !w.is_empty())
        .flat_map(split_glued_mark)
    {
        if let Some(found) = direction_mark(word) {
            keep(&mut run, &mut best);
            fresh_mark = true;
            let named_before = mark.is_some_and(|(_, named)| named) && run.bytes.is_empty();
            if found.1 || !named_before {
                mark = Some(found);
            }
            continue;
        }
        if let Some(bytes) = ascii_frames(word) {
            keep(&mut run, &mut best);
            run = Run {
                bytes,
                spelling: None,
                direction: mark.map(|(direction, _)| direction),
                after_mark: std::mem::take(&mut fresh_mark),
                ascii: true,
            };
            keep(&mut run, &mut best);
            continue;
        }
        let bracketed = word.iter().any(|b| matches!(b, b'[' | b'<'));
        // libmodbus (and mbpoll -v) write what they send as [11][03] and what they
        // receive as <11><03>.
        let bracket_direction = match word.first() {
            Some(b'[') => Some(Direction::Request),
            Some(b'<') => Some(Direction::Response),
            _ => None,
        };
        let pieces = word.split(|b| {
            matches!(
                b,
                b'[' | b']' | b'<' | b'>' | b'{' | b'}' | b'(' | b')' | b',' | b';'
            )
        });
        for piece in pieces.filter(|p| !p.is_empty()) {
            match piece_bytes(piece, bracketed) {
                Some((spelling, bytes)) => {
                    if run.spelling.is_some_and(|s| s != spelling) {
                        keep(&mut run, &mut best);
                    }
                    if run.bytes.is_empty() {
                        run.direction = mark
                            .map(|(direction, _)| direction)
                            .or(bracket_direction.filter(|_| spelling == Spelling::Bracketed));
                        run.after_mark = std::mem::take(&mut fresh_mark);
                    }
                    run.spelling = Some(spelling);
                    run.bytes.extend_from_slice(&bytes);
                }
                None => keep(&mut run, &mut best),
            }
        }
    }
    keep(&mut run, &mut best);
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hex(text: &str) -> Result<Vec<u8>, HexError> {
        let mut out = Vec::new();
        parse_hex(text.as_bytes(), &mut out).map(|()| out)
    }

    #[test]
    fn the_common_spellings() {
        let want = vec![0x11, 0x03, 0x00, 0x6B];
        assert_eq!(hex("11 03 00 6B"), Ok(want.clone()));
        assert_eq!(hex("1103006b"), Ok(want.clone()));
        assert_eq!(hex("0x11,0x03,0x00,0x6B"), Ok(want.clone()));
        assert_eq!(hex("0x11, 0x3, 0x0, 0x6b"), Ok(want.clone()));
        assert_eq!(hex("\\x11\\x03\\x00\\x6B"), Ok(want));
    }

    #[test]
    fn bad_spellings_say_why() {
        assert!(matches!(hex("110"), Err(HexError::OddDigits(_))));
        assert!(matches!(hex("11 0G"), Err(HexError::NotHex(c, 5)) if c == "G"));
        assert_eq!(hex("  "), Err(HexError::Empty));
        assert!(matches!(hex("11 é"), Err(HexError::NotHex(c, _)) if c == "é"));
        assert!(matches!(hex("11\u{A0}03"), Err(HexError::NotHex(c, 3)) if c == "U+00A0"));
        assert!(matches!(hex("0x"), Err(HexError::NoDigits(_))));
    }
    const REQUEST: [u8; 8] = [0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87];

    /// The one frame of a line.
    fn line(text: &str) -> Result<Option<LineFrame>, HexError> {
        read_line(text.as_bytes()).map(|frames| {
            assert!(frames.len() <= 1, "{text}: {frames:?}");
            frames.into_iter().next()
        })
    }

    #[test]
    fn a_request_and_its_answer_on_one_line_are_two_frames() {
        let answer = [
            0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
        ];
        for text in [
            "12:00:01.123 TX: 11 03 00 6B 00 03 76 87 RX: 11 03 06 02 2B 00 00 00 64 C8 BA",
            "[TX] 1103006B00037687 [RX] 1103 0602 2B00 0000 64C8 BA",
            "11 03 00 6B 00 03 76 87 < 11 03 06 02 2B 00 00 00 64 C8 BA",
            "> 11 03 00 6B 00 03 76 87 < 11 03 06 02 2B 00 00 00 64 C8 BA",
            "-> 11 03 00 6B 00 03 76 87 <- 11 03 06 02 2B 00 00 00 64 C8 BA",
            "TX=1103006B00037687 RX=110306022B00000064C8BA",
        ] {
            let frames = read_line(text.as_bytes()).unwrap();
            assert_eq!(
                frames,
                [
                    LineFrame {
                        bytes: REQUEST.to_vec(),
                        direction: Some(Direction::Request)
                    },
                    LineFrame {
                        bytes: answer.to_vec(),
                        direction: Some(Direction::Response)
                    }
                ],
                "{text}"
            );
        }
    }

    fn frame(bytes: &[u8], direction: Option<Direction>) -> Result<Option<LineFrame>, HexError> {
        Ok(Some(LineFrame {
            bytes: bytes.to_vec(),
            direction,
        }))
    }

    #[test]
    fn log_spellings_give_the_frame() {
        for text in [
            "11 03 00 6B 00 03 76 87",
            "11:03:00:6b:00:03:76:87",
            "11-03-00-6B-00-03-76-87",
            "{0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87};",
            "11 03 00 6B 00 03 76 87  CRC ok  # t=0 req slave=17 fc=3",
            "frame 1103006B00037687 sent",
            "12:03:04 11 03 00 6B 00 03 76 87",
            "2024-01-05 12:03:04.512 DEBUG modbus: 11 03 00 6B 00 03 76 87 (8 bytes)",
        ] {
            assert_eq!(line(text), frame(&REQUEST, None), "{text}");
        }
    }

    #[test]
    fn a_direction_mark_before_the_frame_says_which_way_it_went() {
        let request = frame(&REQUEST, Some(Direction::Request));
        let response = frame(&REQUEST, Some(Direction::Response));
        assert_eq!(line("[    0.000021] > 11 03 00 6B 00 03 76 87"), request);
        assert_eq!(line("[    0.000190] < 11 03 00 6B 00 03 76 87"), response);
        assert_eq!(line("TX 11 03 00 6B 00 03 76 87"), request);
        assert_eq!(line("Rx: 11 03 00 6B 00 03 76 87"), response);
        assert_eq!(line("12:00:01 [RX] 11:03:00:6B:00:03:76:87"), response);
        // Only a mark before the frame counts.
        assert_eq!(
            line("11 03 00 6B 00 03 76 87 < reply"),
            frame(&REQUEST, None)
        );
    }

    /// Lines as the tools that engineers use write them, each with its direction.
    #[test]
    fn the_traffic_logs_of_other_tools_with_their_directions() {
        let request = frame(&REQUEST, Some(Direction::Request));
        let response = frame(&REQUEST, Some(Direction::Response));
        for (tool, text, want) in [
            // Modbus Poll, Communication Traffic window (and its saved log).
            ("Modbus Poll", "000000-Tx:11 03 00 6B 00 03 76 87", &request),
            ("Modbus Poll, counter after", "Tx:000002-11 03 00 6B 00 03 76 87", &request),
            ("Modbus Poll", "000001-Rx:11 03 00 6B 00 03 76 87", &response),
            // QModMaster's bus monitor: mode, direction, time, then the bytes.
            (
                "QModMaster",
                "[RTU]>Tx > 10:33:38:290 : 11  03  00  6B  00  03  76  87  ",
                &request,
            ),
            (
                "QModMaster",
                "[RTU]>Rx > 10:33:38:374 : 11  03  00  6B  00  03  76  87  ",
                &response,
            ),
            // libmodbus debug output, which mbpoll -v prints: sent in [], received in <>.
            ("libmodbus", "[11][03][00][6B][00][03][76][87]", &request),
            ("libmodbus", "<11><03><00><6B><00><03><76><87>", &response),
            // pymodbus debug logging, 2.x and 3.x.
            (
                "pymodbus",
                "DEBUG:pymodbus.transaction:SEND: 0x11 0x3 0x0 0x6b 0x0 0x3 0x76 0x87",
                &request,
            ),
            (
                "pymodbus",
                "2024-03-01 10:00:00,123 DEBUG logging:103 recv: 0x11 0x3 0x0 0x6b 0x0 0x3 0x76 0x87 old_data:  addr=None",
                &response,
            ),
        ] {
            assert_eq!(&line(text), want, "{tool}: {text}");
        }
    }

    #[test]
    fn ascii_frames_as_text_alone_glued_or_logged() {
        let one = frame(b":1103006B00037E\r\n", None);
        assert_eq!(line(":1103006B00037E"), one);
        assert_eq!(
            line("[  0.000100] > :1103006B00037E"),
            frame(b":1103006B00037E\r\n", Some(Direction::Request))
        );
        assert_eq!(
            line(":1103006B00037E:110306022B0000006455"),
            frame(b":1103006B00037E\r\n:110306022B0000006455\r\n", None)
        );
    }

    #[test]
    fn comments_blank_lines_and_lines_without_a_frame() {
        assert_eq!(line("# a comment"), Ok(None));
        assert_eq!(line("   "), Ok(None));
        assert_eq!(
            line("11 03 00 6B 00 03 76 87 # the request"),
            frame(&REQUEST, None)
        );
        assert_eq!(
            line("noise: 00  # t=8339"),
            Err(HexError::TooShort("00".into()))
        );
        // A '#' that starts no comment.
        assert_eq!(
            line("frame #1: 11 03 00 6B 00 03 76 87"),
            frame(&REQUEST, None)
        );
        // An escaped string does not join the 0x bytes before it.
        assert_eq!(
            line("sent 0x11 0x03 0x00 0x6B 0x00 0x03 0x76 0x87 \\x11"),
            frame(&REQUEST, Some(Direction::Request))
        );
        assert!(matches!(line("hello"), Err(HexError::NotHex(c, 1)) if c == "h"));
        // The messages of a log among its frames are words, no frame.
        for message in [
            "hello world",
            "Waiting for a confirmation...",
            "Sys > 10:33:38:100 : Connecting to Serial Port [/dev/ttyUSB0]...OK",
            "DEBUG:pymodbus.transaction:Current transaction state - IDLE",
            "Opening /dev/ttyUSB0 at 19200 bauds (E, 8, 1)",
        ] {
            assert_eq!(line(message), Err(HexError::Message), "{message}");
        }
        // A mistyped byte is pointed at, not set aside as a word of a log.
        assert!(
            matches!(line("11 03 00 6B 00 03 76 8G"), Err(HexError::NotHex(c, 23)) if c == "G")
        );
        assert!(matches!(line("11 O3 00 6B 00 03 76 87"), Err(HexError::NotHex(c, 4)) if c == "O"));
    }
}
