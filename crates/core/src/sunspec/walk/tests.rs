use std::time::Duration;

use super::*;
use crate::codec::Mode;
use crate::master::MasterOptions;
use crate::model::values::Value;
use crate::slave::sim::SimTransport;
use crate::slave::{datafile, Slave};

/// A master on a device holding the registers of `data` (a data file's text), slave 1.
fn device(data: &str) -> Master {
    let model = datafile::parse("device", data).unwrap();
    let transport = SimTransport::standing_in_for(Mode::Tcp, Slave::new(&[1], model));
    Master::new(
        Box::new(transport),
        MasterOptions {
            mode: Mode::Tcp,
            timeout: Duration::from_millis(100),
            retries: 0,
            retry_non_idempotent: false,
            frame_gap: Duration::ZERO,
            character: Duration::ZERO,
            silence: Duration::ZERO,
            turnaround: Duration::ZERO,
        },
    )
}

/// `SunS`, a common model of 66 registers holding `Acme` as its manufacturer, then `rest`.
fn image(reference: u32, rest: &str) -> String {
    let mut common = vec!["21365 28243 1 66 16739 28005".to_string()];
    common.extend(std::iter::repeat_n("0".to_string(), 64));
    format!("{reference} = {} {rest}\n", common.join(" "))
}

#[test]
fn the_chain_is_walked_at_each_usual_base() {
    for (base, reference) in [(40000, 440001), (50000, 450001), (0, 400001)] {
        let data = image(reference, "65535 0");
        let found = read_device(&mut device(&data), 1, None).unwrap();
        assert_eq!(found.base, base);
        assert_eq!(found.models.len(), 1);
        let common = &found.models[0];
        assert_eq!(
            (common.id, common.length, common.name.as_str()),
            (1, 66, "common")
        );
        assert_eq!(common.address, base + 2);
        let maker = common
            .points
            .iter()
            .find(|p| p.name == "common.Mn")
            .unwrap();
        assert_eq!(maker.value, Ok(Value::Text("Acme".into())));
        assert_eq!(found.cut, None);
    }
}

#[test]
fn an_end_marker_without_its_length_ends_the_chain() {
    let data = image(440001, "65535");
    let found = read_device(&mut device(&data), 1, None).unwrap();
    assert_eq!((found.models.len(), found.cut), (1, None));
}

#[test]
fn models_of_a_kind_are_numbered_and_unknown_ones_named() {
    let data = image(440001, "64999 2 7 7 1 66 0 0 65535 0");
    // The second common model: 66 registers, its first two a manufacturer of 0 0.
    let data = data.replace(
        " 1 66 0 0 65535 0",
        &format!(" 1 66{} 65535 0", " 0".repeat(66)),
    );
    let found = read_device(&mut device(&data), 1, None).unwrap();
    let names: Vec<&str> = found.models.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(names, ["common", "model_64999", "common_2"]);
    assert_eq!(
        found.models[1].problem.as_deref(),
        Some("SunSpec has published no definition of it")
    );
    assert!(found.models[2].points[0].name.starts_with("common_2."));
}

#[test]
fn no_marker_is_told_base_by_base() {
    let mut master = device("440001 = 1 2\n");
    match read_device(&mut master, 1, None) {
        Err(SunSpecError::NotFound { tried }) => assert_eq!(
            tried,
            [
                (40000, "0001 0002, not SunS".to_string()),
                (50000, "illegal data address".to_string()),
                (0, "illegal data address".to_string()),
            ]
        ),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_chain_that_runs_off_the_registers_or_is_refused_is_cut() {
    // The model after the common one says it is longer than the registers left.
    let data = image(465401, "1 200");
    let found = read_device(&mut device(&data), 1, Some(65400)).unwrap();
    assert_eq!(found.models.len(), 1);
    let cut = found.cut.unwrap();
    assert!(cut.reason.contains("past the last register"), "{cut:?}");
    assert!(cut.models_lost && cut.refused.is_none());
    // No end marker: the registers after the common model do not exist.
    let data = image(440001, "");
    let found = read_device(&mut device(&data), 1, None).unwrap();
    assert_eq!(found.models.len(), 1);
    assert_eq!(
        found.cut,
        Some(Cut {
            reason: "the device refused the model header at register 40070 (illegal data address) before the end marker".into(),
            models_lost: true,
            refused: Some(ExceptionCode::ILLEGAL_DATA_ADDRESS),
        })
    );
}

proptest::proptest! {
    /// Whatever a device holds after its marker, the walk ends, within the registers, and
    /// never panics.
    #[test]
    fn any_registers_after_the_marker_are_walked_to_an_end(
        words in proptest::collection::vec(
            proptest::prop_oneof![
                proptest::prelude::any::<u16>(),
                proptest::sample::select(vec![1u16, 66, 103, 50, 160, 0xFFFF, 0, 2]),
            ],
            0..600,
        ),
    ) {
        let text: Vec<String> = words.iter().map(u16::to_string).collect();
        let data = format!("440001 = 21365 28243 {}\n", text.join(" "));
        let found = read_device(&mut device(&data), 1, None).unwrap();
        // A point with a value was read: its registers are the device's.
        for model in &found.models {
            for point in model.points.iter().filter(|point| point.value.is_ok()) {
                let end = u32::from(point.address) + point.raw.len() as u32;
                proptest::prop_assert!(end <= 40002 + words.len() as u32, "{point:?}");
            }
        }
        proptest::prop_assert!(found.requests <= 70 * (found.models.len() + 1) + 10);
    }
}
