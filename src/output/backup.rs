//! What `dump` and `restore` say besides the data file: ranges of references, the time of
//! a dump, and the values that read back differently.

use std::time::{SystemTime, UNIX_EPOCH};

use mbtool_core::master::backup::Difference;
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
    let seconds = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let (days, rest) = (seconds / 86_400, seconds % 86_400);
    let (year, month, day) = civil_from_days(i64::try_from(days).unwrap_or_default());
    format!(
        "{year:04}-{month:02}-{day:02} {:02}:{:02}:{:02} UTC",
        rest / 3600,
        rest % 3600 / 60,
        rest % 60
    )
}

/// The calendar date of a day counted from 1970-01-01 (Howard Hinnant's algorithm).
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let day_of_era = z.rem_euclid(146_097);
    let year_of_era =
        (day_of_era - day_of_era / 1460 + day_of_era / 36_524 - day_of_era / 146_096) / 365;
    let day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
    let shifted_month = (5 * day_of_year + 2) / 153;
    let day = (day_of_year - (153 * shifted_month + 2) / 5 + 1) as u32;
    let month = if shifted_month < 10 {
        shifted_month + 3
    } else {
        shifted_month - 9
    } as u32;
    let year = year_of_era + era * 400 + i64::from(month <= 2);
    (year, month, day)
}

/// `400010: wrote 5, read back 0`.
pub fn difference_text(difference: &Difference) -> String {
    let found = match difference.found {
        Some(value) => format!("read back {value}"),
        None => "the device refused to read it back (exception 02)".to_string(),
    };
    format!(
        "{}: wrote {}, {found}",
        reference(difference.table, difference.address),
        difference.wanted
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        assert_eq!(civil_from_days(20_415), (2025, 11, 23));
        assert_eq!(civil_from_days(11_016), (2000, 2, 29));
    }

    #[test]
    fn ranges() {
        assert_eq!(range_text(Table::HoldingRegisters, 10, 9), "400011-400019");
        assert_eq!(range_text(Table::Coils, 0, 1), "000001");
    }
}
