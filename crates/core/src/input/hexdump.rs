//! Hex dumps as tools print them: Wireshark's "Copy as Hex Dump", `hexdump -C`, `xxd` and
//! `od -A x -t x1`. Each line is an offset, the bytes, and for most a column of the bytes as
//! characters: the offset and the characters are set aside. A frame a dump spans is the
//! bytes of its lines while each line's offset is the count of bytes before it.

/// One line of a dump.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DumpLine {
    /// Its offset as written: hex, or for `od` octal (its default) or decimal (`-A d`).
    pub offset: String,
    /// Its bytes; none on the line of `hexdump` and `od` that gives the length at the end.
    pub bytes: Vec<u8>,
}

impl DumpLine {
    /// Whether its offset is `count`, the bytes of the dump before it, in any of the bases
    /// dumps write offsets in.
    pub fn is_at(&self, count: usize) -> bool {
        [16, 8, 10].into_iter().any(|radix| {
            u64::from_str_radix(&self.offset, radix).is_ok_and(|at| at == count as u64)
        })
    }
}

/// The most bytes a dump line holds (`xxd -c 32`).
const MOST_ON_A_LINE: usize = 32;

/// The line of a dump `line` is, if it is one: an offset of 4 to 8 hex digits followed by a
/// colon (`xxd`), by two spaces or more (Wireshark, `hexdump -C`), or of 6 digits or more
/// (`od`); then bytes of two hex digits (`xxd`: groups of them) up to the character column,
/// which starts at a `|` or after a wider gap than between bytes.
pub fn dump_line(line: &[u8]) -> Option<DumpLine> {
    let line = line.trim_ascii_end();
    let digits = line.iter().take_while(|b| b.is_ascii_hexdigit()).count();
    if !(4..=8).contains(&digits) {
        return None;
    }
    let offset = std::str::from_utf8(&line[..digits]).ok()?.to_string();
    let mut rest = &line[digits..];
    let xxd = rest.first() == Some(&b':');
    if xxd {
        rest = &rest[1..];
    }
    let lead = rest
        .iter()
        .take_while(|b| matches!(b, b' ' | b'\t'))
        .count();
    if rest.is_empty() {
        return (!xxd).then_some(DumpLine {
            offset,
            bytes: Vec::new(),
        });
    }
    if lead == 0 || !(xxd || lead >= 2 || digits >= 6) {
        return None;
    }
    // The gap before the character column: wider than the one in the middle of a line.
    let column_gap = if xxd { 2 } else { 3 };
    let mut bytes = Vec::new();
    let mut at = lead;
    let mut first = true;
    while at < rest.len() {
        let gap = rest[at..]
            .iter()
            .take_while(|b| matches!(b, b' ' | b'\t'))
            .count();
        at += gap;
        // `hexdump -C` puts its characters in |...|, `od -t x1z` in >...<.
        if at >= rest.len() || matches!(rest[at], b'|' | b'>') || (!first && gap >= column_gap) {
            break;
        }
        let end = at
            + rest[at..]
                .iter()
                .take_while(|b| !matches!(b, b' ' | b'\t'))
                .count();
        let token = &rest[at..end];
        let pairs = token.len() / 2;
        let fits = token.len() % 2 == 0 && (token.len() == 2 || (xxd && pairs <= 4));
        if !fits || !token.iter().all(u8::is_ascii_hexdigit) {
            // A column of characters after a single space is no dump's.
            return None;
        }
        for pair in token.chunks_exact(2) {
            let text = std::str::from_utf8(pair).ok()?;
            bytes.push(u8::from_str_radix(text, 16).ok()?);
        }
        if bytes.len() > MOST_ON_A_LINE {
            return None;
        }
        first = false;
        at = end;
    }
    (!bytes.is_empty()).then_some(DumpLine { offset, bytes })
}

#[cfg(test)]
mod tests {
    use super::*;

    const FRAME: [u8; 8] = [0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87];

    #[test]
    fn each_tools_dump_line() {
        for line in [
            "0000   11 03 00 6b 00 03 76 87                           ...k..v.",
            "00000000  11 03 00 6b 00 03 76 87                           |...k..v.|",
            "00000000: 1103 006b 0003 7687                      ...k..v.",
            "00000000: 11 03 00 6b 00 03 76 87                          ...k..v.",
            "000000 11 03 00 6b 00 03 76 87",
            "0000000 11 03 00 6b 00 03 76 87",
            "000000 11 03 00 6b 00 03 76 87  >...k..v.<",
        ] {
            let read = dump_line(line.as_bytes()).unwrap();
            assert!(read.is_at(0), "{line}");
            assert_eq!(read.bytes, FRAME, "{line}");
        }
        // The character column may look like hex; the gap before it tells it apart.
        let line =
            dump_line(b"0010   41 42 43 44                                       ABCD").unwrap();
        assert_eq!(line.bytes, [0x41, 0x42, 0x43, 0x44]);
        assert!(line.is_at(16));
        // od's default offsets are octal: 0000020 is 16.
        assert!(dump_line(b"0000020 41 42").unwrap().is_at(16));
        // A full line, with hexdump's gap in the middle.
        let full = "00000010  00 01 02 03 04 05 06 07  08 09 0a 0b 0c 0d 0e 0f  |................|";
        assert_eq!(
            dump_line(full.as_bytes()).unwrap().bytes,
            (0..16).collect::<Vec<u8>>()
        );
        // The length at the end of hexdump's and od's dumps.
        let end = dump_line(b"00000008").unwrap();
        assert!(end.bytes.is_empty() && end.is_at(8));
    }

    #[test]
    fn frames_as_people_paste_them_are_no_dump() {
        for line in [
            "11 03 00 6B 00 03 76 87",
            "1103 006B 0003 7687",
            "1103006B00037687",
            "0000 0000 0006 1103 006B 0003",
            "00000000 0006 1103",
            "TX: 11 03 00 6B",
            "",
        ] {
            assert_eq!(dump_line(line.as_bytes()), None, "{line}");
        }
    }
}
