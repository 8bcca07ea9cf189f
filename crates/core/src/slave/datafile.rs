//! The data file of `mbtool serve --data FILE`: which addresses exist and their first values.
//!
//! One entry a line; `#` starts a comment:
//!
//! ```text
//! # holding registers 400108-400110, as in the manuals
//! 400108 = 555 0 100
//! 400001 = 3.14 f32          # a typed value takes as many registers as its type
//! 400010 = 1.5 f32 CDAB      # ... in a byte order
//! 400020 = "PUMP 1" ascii    # text, two characters a register
//! 400200-400299 = 0          # a range with one value: every address gets it
//! 000020-000023 = 1 0 1 1    # coils: on/off, 1/0, true/false; one value an address
//! 300009 = 10
//! file 4 record 1 = 3582 32  # records 1-2 of file 4 (function 20, 21)
//! fifo 401247 = 440 4740     # the FIFO queue whose pointer is 401247 (function 24)
//! ```
//!
//! With a data file only the addresses, records and queues it names exist; any other gets
//! exception 02. A FIFO queue may hold more than the 31 values one answer carries: reading
//! it then gets exception 03, as the specification says.
//! Nothing is made up: a range takes one value for each of its addresses or one value for
//! all of them, and an address is named once.

use std::collections::BTreeMap;
use std::path::Path;

use thiserror::Error;

use crate::codec::file::MAX_RECORD;
use crate::codec::FileRecords;
use crate::input::choice::Choice;
use crate::model::address::{parse_reference_span, reference, AddressError, Table};
use crate::model::faults::{told, Faults};
use crate::model::values::ReadData;
use crate::model::values::{parse_coil, ByteOrder, ValueType};
use crate::slave::{DataModel, FileData};

/// Why a data file cannot be loaded.
#[derive(Debug, Error)]
pub enum DataFileError {
    /// The file cannot be read.
    #[error("cannot read {path}: {error}")]
    Read {
        /// The file as named.
        path: String,
        /// Why it could not be read.
        error: std::io::Error,
    },
    /// An entry of the file is wrong.
    #[error("{path}:{line}: {error}")]
    Line {
        /// The file as named.
        path: String,
        /// The entry's line, from 1.
        line: usize,
        /// What is wrong with it.
        error: EntryError,
    },
    /// Several entries are wrong: each, in the order of the file, at most
    /// [`MOST_TOLD`](crate::model::faults::MOST_TOLD), and how many more there are. Shown
    /// one a line.
    #[error("{}", told(.errors, *.more))]
    Lines {
        /// The first errors.
        errors: Vec<DataFileError>,
        /// How many more there are.
        more: usize,
    },
}

/// What is wrong with one entry of a data file.
#[derive(Debug, Error, PartialEq, Eq)]
pub enum EntryError {
    /// A line that is neither an entry, a comment nor blank.
    #[error("an entry is REFERENCE = VALUE..., as in 400108 = 555")]
    NotAnEntry,
    /// The reference does not read as one.
    #[error(transparent)]
    Reference(#[from] AddressError),
    /// A quoted text without its closing quote.
    #[error("a quoted text has no closing '\"'")]
    OpenQuote,
    /// Nothing after `=`.
    #[error("no value: give one after '='")]
    NoValue,
    /// A value type given for coils or discrete inputs.
    #[error("{0}s are bits: a type does not apply")]
    TypeOfBits(&'static str),
    /// A value that does not read as the table's or the type's.
    #[error("{0}")]
    Value(String),
    /// A range given more or fewer values than it has addresses (and not one for all).
    #[error(
        "the range has {size} {unit}s and the values fill {values}: \
         give one value for each address, or one value for all"
    )]
    RangeCount {
        /// Addresses the values fill.
        values: usize,
        /// Addresses in the range.
        size: u32,
        /// What an address holds: `register`, `coil`, ...
        unit: &'static str,
    },
    /// An address that an earlier entry names too.
    #[error("{reference} is given already on line {line}: give each address once")]
    Repeated {
        /// The first address named twice.
        reference: String,
        /// The earlier entry's line, from 1.
        line: usize,
    },
    /// Values that run past address 65535.
    #[error("the values run past the last address of the table ({0})")]
    PastEnd(String),
    /// A `file` or `fifo` entry whose place does not read.
    #[error("{0}")]
    Place(String),
}

/// Splits the value part into words, a double-quoted string being one word.
fn words(text: &str) -> Result<Vec<String>, EntryError> {
    let mut words = Vec::new();
    let mut rest = text.trim();
    while !rest.is_empty() {
        if let Some(quoted) = rest.strip_prefix('"') {
            let end = quoted.find('"').ok_or(EntryError::OpenQuote)?;
            words.push(quoted[..end].to_string());
            rest = quoted[end + 1..].trim_start();
        } else {
            let end = rest.find(char::is_whitespace).unwrap_or(rest.len());
            words.push(rest[..end].to_string());
            rest = rest[end..].trim_start();
        }
    }
    Ok(words)
}

/// The addresses each table's entries have named so far, as `start -> (end, line)`.
#[derive(Default)]
struct Claims {
    tables: [BTreeMap<u32, (u32, usize)>; 4],
    /// Each file record named, with its line.
    records: BTreeMap<(u16, u16), usize>,
    /// Each FIFO queue's pointer named, with its line.
    fifos: BTreeMap<u16, usize>,
}

impl Claims {
    /// Claims `[start, end)` of `table` for the entry on `line`, or names the first
    /// address an earlier entry claimed.
    fn claim(&mut self, table: Table, start: u32, end: u32, line: usize) -> Result<(), EntryError> {
        let claims = &mut self.tables[table as usize];
        // Only the nearest claim at or before `start`, and the first after it, can overlap:
        // claims never overlap each other.
        let before = claims.range(..=start).next_back();
        let after = claims.range(start..end).next();
        let clash = match (before, after) {
            (Some((_, &(before_end, line))), _) if before_end > start => Some((start, line)),
            (_, Some((&after_start, &(_, line)))) => Some((after_start, line)),
            _ => None,
        };
        if let Some((address, line)) = clash {
            return Err(EntryError::Repeated {
                reference: reference(table, u16::try_from(address).unwrap_or(u16::MAX)).into(),
                line,
            });
        }
        claims.insert(start, (end, line));
        Ok(())
    }
}

/// The values of an entry, its type and byte order (written after them) taken off.
fn typed_words(values: &str) -> Result<(Vec<String>, ValueType, ByteOrder), EntryError> {
    let mut words = words(values)?;
    let mut order = ByteOrder::Abcd;
    let mut kind = ValueType::U16;
    if let Some(o) = words.last().and_then(|w| ByteOrder::from_name(w)) {
        order = o;
        words.pop();
    }
    if let Some(t) = words.last().and_then(|w| ValueType::from_name(w)) {
        kind = t;
        words.pop();
    }
    if words.is_empty() {
        return Err(EntryError::NoValue);
    }
    Ok((words, kind, order))
}

/// The registers an entry's values make.
fn registers(values: &str) -> Result<Vec<u16>, EntryError> {
    let (words, kind, order) = typed_words(values)?;
    let mut registers = Vec::new();
    for word in &words {
        registers.extend(kind.parse(word, order).map_err(EntryError::Value)?);
    }
    Ok(registers)
}

/// A number of a file entry, in decimal, 0x hex or 0b binary, at most `max`.
fn number_of(word: Option<&str>, what: &str, max: u16) -> Result<u16, EntryError> {
    word.and_then(|w| crate::input::number::parse_int(w).ok())
        .and_then(|n| u16::try_from(n).ok())
        .filter(|n| *n <= max)
        .ok_or_else(|| EntryError::Place(format!("give {what}, as in file 4 record 1 = 10 20")))
}

/// What `count` records from `record` are called: `record 5`, `records 5-9`.
fn records_named(record: u16, count: usize) -> String {
    match count {
        1 => format!("record {record}"),
        _ => format!("records {record}-{}", usize::from(record) + count - 1),
    }
}

/// A `file N record R[-R] = ...` entry: records of a file; a range takes one value for
/// each record or one value for all.
fn file_entry(
    model: &mut DataModel,
    claims: &mut Claims,
    place: &str,
    values: &str,
    number: usize,
) -> Result<(), EntryError> {
    let mut words = place.split_whitespace().skip(1);
    let file = number_of(words.next(), "a file number 1-65535", u16::MAX)?;
    if file == 0 {
        return Err(EntryError::Place(
            "file 0 does not exist: files are numbered 1-65535".into(),
        ));
    }
    if words.next() != Some("record") {
        return Err(EntryError::Place(
            "a file entry is file N record R = VALUE..., as in file 4 record 1 = 10 20".into(),
        ));
    }
    let records = words.next();
    if words.next().is_some() {
        return Err(EntryError::NotAnEntry);
    }
    let (first, last) = match records.and_then(|r| r.split_once('-')) {
        Some((first, last)) => (Some(first), Some(last)),
        None => (records, None),
    };
    let what = "a record number 0-9999";
    let record = number_of(first, what, MAX_RECORD)?;
    let size = match last {
        Some(last) => {
            let last = number_of(Some(last), what, MAX_RECORD)?;
            if last < record {
                return Err(EntryError::Place(format!(
                    "records {record}-{last}: the first record of a range comes first"
                )));
            }
            Some(u32::from(last - record) + 1)
        }
        None => None,
    };
    let (words, kind, order) = typed_words(values)?;
    let mut registers = Vec::new();
    for word in &words {
        registers.extend(kind.parse(word, order).map_err(EntryError::Value)?);
    }
    let values = fill(size, registers, kind.width(), "record")?;
    if values.is_empty() {
        return Err(EntryError::NoValue);
    }
    if usize::from(record) + values.len() > usize::from(MAX_RECORD) + 1 {
        return Err(EntryError::Place(format!(
            "{} of file {file} run past record {MAX_RECORD}",
            records_named(record, values.len())
        )));
    }
    for at in record..record + values.len() as u16 {
        if let Some(line) = claims.records.insert((file, at), number) {
            return Err(EntryError::Place(format!(
                "record {at} of file {file} is given already on line {line}: give each record once"
            )));
        }
    }
    model.files.preset(file, record, &values);
    Ok(())
}

/// A `fifo REF = ...` entry: a FIFO queue, oldest value first.
fn fifo_entry(
    model: &mut DataModel,
    claims: &mut Claims,
    place: &str,
    values: &str,
    number: usize,
) -> Result<(), EntryError> {
    let target = place.trim_start()["fifo".len()..].trim();
    let span = parse_reference_span(target)?;
    if span.table != Table::HoldingRegisters || span.count.is_some() {
        return Err(EntryError::Place(format!(
            "a FIFO queue's pointer is one holding register, as in fifo 401247: '{target}' is not"
        )));
    }
    if let Some(line) = claims.fifos.insert(span.address, number) {
        return Err(EntryError::Place(format!(
            "the FIFO queue at {target} is given already on line {line}: give each queue once"
        )));
    }
    // An empty queue is a queue too: `fifo 401247 =`.
    let queue = match values.trim() {
        "" => Vec::new(),
        values => registers(values)?,
    };
    model.fifos.set(span.address, queue);
    Ok(())
}

/// One entry on line `number`: fills `model` and declares the addresses it names.
fn entry(
    model: &mut DataModel,
    claims: &mut Claims,
    line: &str,
    number: usize,
) -> Result<(), EntryError> {
    let (target, values) = line.split_once('=').ok_or(EntryError::NotAnEntry)?;
    match target.split_whitespace().next() {
        Some("file") => return file_entry(model, claims, target, values, number),
        Some("fifo") => return fifo_entry(model, claims, target, values, number),
        _ => {}
    }
    let span = parse_reference_span(target.trim())?;
    let (words, kind, order) = typed_words(values)?;
    let start = u32::from(span.address);
    if span.table.is_bits() {
        if kind != ValueType::U16 {
            return Err(EntryError::TypeOfBits(span.table.name()));
        }
        let bits = words
            .iter()
            .map(|w| parse_coil(w).map_err(EntryError::Value))
            .collect::<Result<Vec<_>, _>>()?;
        let values = fill(span.count, bits, 1, span.table.name())?;
        check_end(span.table, start, values.len())?;
        claims.claim(span.table, start, start + values.len() as u32, number)?;
        let table = if span.table == Table::Coils {
            &mut model.coils
        } else {
            &mut model.discrete_inputs
        };
        table.preset(span.address, &values);
        table.declare(start, start + values.len() as u32);
    } else {
        let mut registers = Vec::new();
        for word in &words {
            registers.extend(kind.parse(word, order).map_err(EntryError::Value)?);
        }
        let values = fill(span.count, registers, kind.width(), span.table.name())?;
        check_end(span.table, start, values.len())?;
        claims.claim(span.table, start, start + values.len() as u32, number)?;
        let table = if span.table == Table::HoldingRegisters {
            &mut model.holding_registers
        } else {
            &mut model.input_registers
        };
        table.preset(span.address, &values);
        table.declare(start, start + values.len() as u32);
    }
    Ok(())
}

/// The values of an entry's addresses: as given, or, for a range given one value (`one`
/// addresses wide: a typed value may take several registers), that value repeated over
/// the range. Any other count for a range is refused: no address gets a value nobody gave.
fn fill<T: Copy>(
    range: Option<u32>,
    values: Vec<T>,
    one: usize,
    unit: &'static str,
) -> Result<Vec<T>, EntryError> {
    let Some(size) = range else {
        return Ok(values);
    };
    let size_addresses = size as usize;
    if values.len() == size_addresses {
        return Ok(values);
    }
    if values.len() == one && size_addresses % one == 0 {
        return Ok(values
            .iter()
            .copied()
            .cycle()
            .take(size_addresses)
            .collect());
    }
    Err(EntryError::RangeCount {
        values: values.len(),
        size,
        unit,
    })
}

fn check_end(table: Table, start: u32, count: usize) -> Result<(), EntryError> {
    if start as usize + count > 65536 {
        return Err(EntryError::PastEnd(reference(table, 65535).into()));
    }
    Ok(())
}

/// Reads a data file's text; `name` is used in error messages.
pub fn parse(name: &str, text: &str) -> Result<DataModel, DataFileError> {
    let mut model = DataModel {
        files: FileData::only_given(),
        ..DataModel::default()
    };
    // Only what the file names exists: every table starts with nothing declared.
    for table in [
        Table::Coils,
        Table::DiscreteInputs,
        Table::InputRegisters,
        Table::HoldingRegisters,
    ] {
        model.declare(table, 0, 0);
    }
    let mut claims = Claims::default();
    let mut faults = Faults::default();
    for (number, line) in text.lines().enumerate() {
        let content = match line.find('#') {
            // A '#' inside a quoted text is part of it.
            Some(at) if line[..at].matches('"').count() % 2 == 0 => &line[..at],
            _ => line,
        };
        if content.trim().is_empty() {
            continue;
        }
        if let Err(error) = entry(&mut model, &mut claims, content, number + 1) {
            faults.add(DataFileError::Line {
                path: name.to_string(),
                line: number + 1,
                error,
            });
        }
    }
    faults.or(model, |errors, more| DataFileError::Lines { errors, more })
}

/// A run of addresses of one table with their values, as one or more lines of a data file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Entry {
    /// The table.
    pub table: Table,
    /// The first address, 0-based.
    pub address: u16,
    /// The values, in address order.
    pub values: ReadData,
}

/// The entries of a data model: every run of addresses that exists, table by table.
pub fn entries(model: &DataModel) -> Vec<Entry> {
    let mut entries = Vec::new();
    let bits = [
        (Table::Coils, &model.coils),
        (Table::DiscreteInputs, &model.discrete_inputs),
    ];
    for (table, data) in bits {
        entries.extend(data.runs().into_iter().map(|(address, values)| Entry {
            table,
            address,
            values: ReadData::Bits(values),
        }));
    }
    let registers = [
        (Table::InputRegisters, &model.input_registers),
        (Table::HoldingRegisters, &model.holding_registers),
    ];
    for (table, data) in registers {
        entries.extend(data.runs().into_iter().map(|(address, values)| Entry {
            table,
            address,
            values: ReadData::Registers(values),
        }));
    }
    entries
}

/// The lines of a data file holding `entries`: one `REF = values` line a run, registers
/// as decimal u16, coils and inputs as 1/0.
pub fn render(entries: &[Entry]) -> String {
    let mut text = String::new();
    for entry in entries {
        let words: Vec<String> = match &entry.values {
            ReadData::Bits(bits) => bits.iter().map(|b| u8::from(*b).to_string()).collect(),
            ReadData::Registers(registers) => registers.iter().map(u16::to_string).collect(),
        };
        text.push_str(&format!(
            "{} = {}\n",
            reference(entry.table, entry.address),
            words.join(" ")
        ));
    }
    text
}

/// The lines of a data file holding `runs` of file records: `file N record R = values`.
pub fn render_files(runs: &[FileRecords]) -> String {
    let mut text = String::new();
    for run in runs {
        let words: Vec<String> = run.values.iter().map(u16::to_string).collect();
        text.push_str(&format!(
            "file {} record {} = {}\n",
            run.file,
            run.record,
            words.join(" ")
        ));
    }
    text
}

/// Reads the data file at `path` into a data model: every entry or none.
pub fn load(path: &Path) -> Result<DataModel, DataFileError> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|error| DataFileError::Read {
        path: name.clone(),
        error,
    })?;
    parse(&name, &text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::codec::ExceptionCode;

    #[test]
    fn the_documented_example() {
        let text = r#"
# holding registers 400108-400110, as in the manuals
400108 = 555 0 100
400001 = 3.14 f32
400010 = 1.5 f32 CDAB
400020 = "PUMP #1" ascii
400200-400299 = 7
000020-000023 = 1 0 1 1
300009 = 10
"#;
        let model = parse("data", text).unwrap();
        assert_eq!(model.holding_registers.read(107, 3), Ok(vec![555, 0, 100]));
        assert_eq!(model.holding_registers.read(0, 2), Ok(vec![0x4048, 0xF5C3]));
        assert_eq!(model.holding_registers.read(9, 2), Ok(vec![0x0000, 0x3FC0]));
        assert_eq!(
            model.holding_registers.read(19, 4),
            Ok(vec![
                u16::from_be_bytes(*b"PU"),
                u16::from_be_bytes(*b"MP"),
                u16::from_be_bytes(*b" #"),
                u16::from_be_bytes(*b"1\0")
            ])
        );
        assert_eq!(model.holding_registers.read(250, 1), Ok(vec![7]));
        assert_eq!(model.coils.read(19, 4), Ok(vec![true, false, true, true]));
        assert_eq!(model.input_registers.read(8, 1), Ok(vec![10]));
        // Only what is named exists.
        assert_eq!(
            model.holding_registers.read(300, 1),
            Err(ExceptionCode::ILLEGAL_DATA_ADDRESS)
        );
        assert_eq!(
            model.discrete_inputs.read(0, 1),
            Err(ExceptionCode::ILLEGAL_DATA_ADDRESS)
        );
    }

    #[test]
    fn a_bad_line_is_named_with_its_number() {
        let error = parse("plant.txt", "400001 = 1\n400002 = 12a\n").unwrap_err();
        assert_eq!(
            error.to_string(),
            "plant.txt:2: '12a' is not a number: write it in decimal, 0x hex or 0b binary"
        );
        let error = parse("plant.txt", "# ok\n\n400001 555\n").unwrap_err();
        assert!(
            error.to_string().starts_with("plant.txt:3: an entry is"),
            "{error}"
        );
        let error = parse("p", "000001 = 2").unwrap_err();
        assert!(error.to_string().contains("not a coil value"), "{error}");
    }

    #[test]
    fn a_range_repeats_one_value() {
        let model = parse("data", "000001-000004 = on\n400001-400004 = 1.5 f32\n").unwrap();
        assert_eq!(model.coils.read(0, 4), Ok(vec![true; 4]));
        assert_eq!(
            model.holding_registers.read(0, 4),
            Ok(vec![0x3FC0, 0, 0x3FC0, 0])
        );
    }

    #[test]
    fn a_range_with_more_or_fewer_values_than_addresses_is_refused() {
        for (text, message) in [
            (
                "400001-400003 = 1 2\n",
                "d:1: the range has 3 holding registers and the values fill 2: \
                 give one value for each address, or one value for all",
            ),
            (
                "\n400001-400002 = 1 2 3\n",
                "d:2: the range has 2 holding registers and the values fill 3: \
                 give one value for each address, or one value for all",
            ),
            (
                "000001-000008 = on off on on\n",
                "d:1: the range has 8 coils and the values fill 4: \
                 give one value for each address, or one value for all",
            ),
            (
                // One f32 (two registers) cannot fill three registers evenly.
                "400001-400003 = 1.5 f32\n",
                "d:1: the range has 3 holding registers and the values fill 2: \
                 give one value for each address, or one value for all",
            ),
        ] {
            assert_eq!(parse("d", text).unwrap_err().to_string(), message);
        }
    }

    #[test]
    fn an_address_named_twice_is_refused_with_the_earlier_line() {
        for (text, message) in [
            (
                "400001 = 1 2\n400001 = 3\n",
                "d:2: 400001 is given already on line 1: give each address once",
            ),
            (
                "400005-400010 = 0\n# note\n400001 = 1 2 3 4 5\n",
                "d:3: 400005 is given already on line 1: give each address once",
            ),
            (
                "400001-400010 = 0\n400010 = 1.5 f32\n",
                "d:2: 400010 is given already on line 1: give each address once",
            ),
            (
                "400001 = 1.5 f32\n400020 = 1\n400002 = 7\n",
                "d:3: 400002 is given already on line 1: give each address once",
            ),
        ] {
            assert_eq!(parse("d", text).unwrap_err().to_string(), message);
        }
        // The same address in another table is another address; ranges that meet are fine.
        let model = parse(
            "d",
            "400001 = 1\n300001 = 2\n000001 = 1\n400002-400003 = 5\n",
        );
        assert!(model.is_ok(), "{model:?}");
    }

    #[test]
    fn rendered_entries_read_back_as_the_same_entries() {
        let text =
            "400001-400040 = 7\n400050 = 1 2 3\n000001-000020 = 1\n000021 = 0 1\n300009 = 10\n";
        let first = entries(&parse("data", text).unwrap());
        let rendered = render(&first);
        assert_eq!(entries(&parse("again", &rendered).unwrap()), first);
        // One line a run.
        assert!(rendered
            .starts_with("000001 = 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 0 1\n300009 = 10\n"));
    }

    #[test]
    fn files_and_fifos_are_entries_too() {
        let text = "file 4 record 1 = 3582 32\nfile 4 record 3 = 1.5 f32\nfifo 401247 = 440 4740\n";
        let model = parse("d", text).unwrap();
        assert_eq!(model.files.read(4, 1, 4), Ok(vec![3582, 32, 0x3FC0, 0]));
        // Only the records named exist.
        assert_eq!(
            model.files.read(4, 0, 1),
            Err(ExceptionCode::ILLEGAL_DATA_ADDRESS)
        );
        assert_eq!(model.fifos.read(1246), Ok(vec![440, 4740]));
        assert_eq!(
            model.fifos.read(1247),
            Err(ExceptionCode::ILLEGAL_DATA_ADDRESS)
        );
        assert_eq!(
            render_files(&model.files.runs()),
            "file 4 record 1 = 3582 32 16320 0\n"
        );
        for (text, message) in [
            ("file 0 record 1 = 1", "d:1: file 0 does not exist: files are numbered 1-65535"),
            ("file 2 record 9999 = 1 2", "d:1: records 9999-10000 of file 2 run past record 9999"),
            (
                "file 2 record 5 = 1 2\nfile 2 record 6 = 3",
                "d:2: record 6 of file 2 is given already on line 1: give each record once",
            ),
            ("fifo 300001 = 1", "d:1: a FIFO queue's pointer is one holding register, as in fifo 401247: '300001' is not"),
            ("file 2 rec 5 = 1", "d:1: a file entry is file N record R = VALUE..., as in file 4 record 1 = 10 20"),
        ] {
            assert_eq!(parse("d", text).unwrap_err().to_string(), message);
        }
        // Ranges of records, numbers in hex, an empty queue.
        let model = parse("d", "file 0x10 record 0-3 = 7\nfifo 400002 =\n").unwrap();
        assert_eq!(model.files.read(16, 0, 4), Ok(vec![7; 4]));
        assert_eq!(model.fifos.read(1), Ok(vec![]));
        assert!(parse("d", "file 3 record 5-7 = 1 2").is_err());
        assert!(parse("d", "file 3 record 7-5 = 1").is_err());
        // A queue longer than one answer carries is kept, and answered with exception 03.
        let long = format!("fifo 400001 = {}", vec!["7"; 32].join(" "));
        assert_eq!(
            parse("d", &long).unwrap().fifos.read(0),
            Err(ExceptionCode::ILLEGAL_DATA_VALUE)
        );
    }
}
