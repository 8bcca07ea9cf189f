//! What `dump` and `restore` say besides the data file: ranges of references, the time of
//! a dump, and the values that read back differently.

use mbtool_core::master::backup::{Difference, Place};
use mbtool_core::model::address::{reference, Table};

/// `400011-400019`, or `400050` for one address.
pub fn range_text(table: Table, address: u16, count: u32) -> String {
    let last = u32::from(address) + count.saturating_sub(1);
    match u16::try_from(last) {
        Ok(last) if last != address => {
            format!("{}-{}", reference(table, address), reference(table, last))
        }
        _ => reference(table, address).into(),
    }
}

/// Now, in UTC: `2026-11-23 15:30:07 UTC`.
pub fn utc_now() -> String {
    chrono::Utc::now()
        .format("%Y-%m-%d %H:%M:%S UTC")
        .to_string()
}

/// `400010: wrote 5, read back 0`.
/// A run of records as dump tells it: `file 4 records 0-99`.
pub fn records_text(span: &mbtool_core::codec::FileSpan) -> String {
    match span.count {
        1 => format!("file {} record {}", span.file, span.record),
        count => format!(
            "file {} records {}-{}",
            span.file,
            span.record,
            u32::from(span.record) + u32::from(count) - 1
        ),
    }
}

pub fn difference_text(difference: &Difference) -> String {
    let found = match difference.found {
        Some(value) => format!("read back {value}"),
        None => "the device refused to read it back (exception 02)".to_string(),
    };
    let place = match difference.place {
        Place::Address(table, address) => reference(table, address).to_string(),
        Place::Record { file, record } => format!("file {file} record {record}"),
    };
    format!("{place}: wrote {}, {found}", difference.wanted)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges() {
        assert_eq!(range_text(Table::HoldingRegisters, 10, 9), "400011-400019");
        assert_eq!(range_text(Table::Coils, 0, 1), "000001");
    }
}
