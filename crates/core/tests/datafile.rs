//! Properties of the data file that `dump` writes and `restore` and `serve --data` read:
//! what is written reads back exactly, nothing is made up for an address the file does not
//! give a value, and no text panics the reader.
#![allow(clippy::unwrap_used, clippy::expect_used)] // a test stops at what it did not expect

use mbtool_core::codec::FileRecords;
use mbtool_core::model::address::{reference, Table};
use mbtool_core::model::values::ReadData;
use mbtool_core::slave::datafile::DataFileError;
use mbtool_core::slave::datafile::{entries, parse, render, render_files, Entry, EntryError};
use proptest::collection::vec;
use proptest::prelude::*;

fn table() -> impl Strategy<Value = Table> {
    prop_oneof![
        Just(Table::Coils),
        Just(Table::DiscreteInputs),
        Just(Table::InputRegisters),
        Just(Table::HoldingRegisters),
    ]
}

/// Runs of one table that neither overlap nor meet (a dump writes one line a run), each
/// with values of the table's kind.
fn runs_of(table: Table) -> impl Strategy<Value = Vec<Entry>> {
    vec((1u32..300, 1usize..40), 0..8).prop_flat_map(move |gaps_and_sizes| {
        let mut at = 0u32;
        let mut layout = Vec::new();
        for (gap, size) in gaps_and_sizes {
            let start = at + gap;
            if start + size as u32 > 65536 {
                break;
            }
            layout.push((start, size));
            at = start + size as u32;
        }
        layout
            .into_iter()
            .map(move |(start, size)| {
                let address = u16::try_from(start).unwrap();
                if table.is_bits() {
                    vec(any::<bool>(), size)
                        .prop_map(move |bits| Entry {
                            table,
                            address,
                            values: ReadData::Bits(bits),
                        })
                        .boxed()
                } else {
                    vec(any::<u16>(), size)
                        .prop_map(move |registers| Entry {
                            table,
                            address,
                            values: ReadData::Registers(registers),
                        })
                        .boxed()
                }
            })
            .collect::<Vec<_>>()
    })
}

/// A device's tables as `dump` finds them: runs in each table, in the order `entries` lists.
fn dumped() -> impl Strategy<Value = Vec<Entry>> {
    (
        runs_of(Table::Coils),
        runs_of(Table::DiscreteInputs),
        runs_of(Table::InputRegisters),
        runs_of(Table::HoldingRegisters),
    )
        .prop_map(|(a, b, c, d)| [a, b, c, d].concat())
}

fn spelled(values: &ReadData) -> Vec<String> {
    match values {
        ReadData::Bits(bits) => bits.iter().map(|b| u8::from(*b).to_string()).collect(),
        ReadData::Registers(registers) => registers.iter().map(u16::to_string).collect(),
    }
}

proptest! {
    #[test]
    fn every_data_file_dump_writes_reads_back_exactly(dump in dumped()) {
        let text = render(&dump);
        let model = parse("dump.txt", &text).unwrap();
        prop_assert_eq!(entries(&model), dump);
    }

    #[test]
    fn a_range_given_more_or_fewer_values_than_addresses_is_refused(
        table in table(),
        address in 0u16..60000,
        size in 2u32..100,
        given in 2usize..120,
    ) {
        prop_assume!(given != size as usize);
        let last = u32::from(address) + size - 1;
        let values = vec!["1"; given].join(" ");
        let text = format!(
            "# a hand-edited file\n{}-{} = {values}\n",
            reference(table, address),
            reference(table, u16::try_from(last).unwrap()),
        );
        match parse("r.txt", &text) {
            Err(DataFileError::Line { line: 2, error: EntryError::RangeCount { .. }, .. }) => {}
            other => prop_assert!(false, "{text:?} gave {other:?}"),
        }
    }

    #[test]
    fn an_address_given_twice_is_refused(dump in dumped(), pick in any::<prop::sample::Index>(), at in any::<prop::sample::Index>()) {
        prop_assume!(!dump.is_empty());
        let entry = pick.get(&dump);
        let words = spelled(&entry.values);
        // One address of the run given again, on a line of its own at the end.
        let offset = at.index(words.len());
        let address = entry.address + u16::try_from(offset).unwrap();
        let text = format!(
            "{}{} = {}\n",
            render(&dump),
            reference(entry.table, address),
            words[offset]
        );
        let lines = text.lines().count();
        match parse("twice.txt", &text) {
            Err(DataFileError::Line { line, error: EntryError::Repeated { reference: named, .. }, .. }) => {
                prop_assert_eq!(line, lines);
                prop_assert_eq!(named, String::from(reference(entry.table, address)));
            }
            other => prop_assert!(false, "{text:?} gave {other:?}"),
        }
    }

    #[test]
    fn every_file_record_dump_writes_reads_back_exactly(runs in file_runs()) {
        let text = render_files(&runs);
        let model = parse("dump", &text).unwrap();
        prop_assert_eq!(model.files.runs(), runs);
        // Only the records written exist.
        for run in model.files.runs() {
            if run.record > 0 && !model.files.holds(run.file, run.record - 1) {
                prop_assert!(model.files.read(run.file, run.record - 1, 1).is_err());
            }
        }
    }

    #[test]
    fn file_and_fifo_lines_of_any_text_never_panic_the_reader(
        text in "((file|fifo|record| |[0-9]{1,6}|=|:|-|f32|x){0,12}\n){0,6}",
    ) {
        let _ = parse("text", &text);
    }

    #[test]
    fn arbitrary_text_never_panics_the_reader(text in "([0-9x\\-= \"#a-z.]{0,40}\n){0,10}") {
        let _ = parse("any.txt", &text);
    }

    #[test]
    fn arbitrary_bytes_never_panic_the_reader(bytes in vec(any::<u8>(), 0..400)) {
        let _ = parse("any.txt", &String::from_utf8_lossy(&bytes));
    }
}

/// Runs of records of several files that neither overlap nor meet, as `dump` writes them.
fn file_runs() -> impl Strategy<Value = Vec<FileRecords>> {
    vec((1u16..5, 1u16..200, vec(any::<u16>(), 1..30)), 0..8).prop_map(|runs| {
        let mut at = std::collections::BTreeMap::<u16, u32>::new();
        let mut kept = Vec::new();
        for (file, gap, values) in runs {
            let start = at.get(&file).copied().unwrap_or(0) + u32::from(gap);
            let end = start + values.len() as u32;
            if end > 10000 {
                continue;
            }
            at.insert(file, end);
            kept.push(FileRecords {
                file,
                record: start as u16,
                values,
            });
        }
        kept.sort_by_key(|run| (run.file, run.record));
        kept
    })
}
