//! Properties of SunSpec and of the maps written from it: any registers laid out by any
//! published model never panic, and every point lies inside the model's registers; a map
//! written from any points reads back as the same points.
#![allow(clippy::unwrap_used, clippy::expect_used)] // a test stops at what it did not expect

use mbtool_core::model::map::{parse_csv, Kind, Point};
use mbtool_core::model::map_writer::to_csv;
use mbtool_core::model::values::ValueType;
use mbtool_core::sunspec::defs::definition;
use mbtool_core::sunspec::points::lay_out;
use proptest::collection::vec;
use proptest::prelude::*;

/// The published models, a few of each family: common, inverters, MPPT, storage, DER.
const MODELS: [u16; 10] = [1, 101, 103, 120, 121, 124, 129, 160, 705, 802];

proptest! {
    #[test]
    fn any_registers_lay_out_within_the_model(
        model in proptest::sample::select(MODELS.to_vec()),
        registers in vec(any::<u16>(), 0..400),
        address in any::<u16>(),
    ) {
        let def = definition(model).unwrap().unwrap();
        let (points, _) = lay_out(&def, "m", address, &registers);
        for point in &points {
            let offset = point.address.wrapping_sub(address) as usize;
            prop_assert!(offset + point.raw.len() <= registers.len());
            prop_assert_eq!(&registers[offset..offset + point.raw.len()], point.raw.as_slice());
        }
    }

    #[test]
    fn a_written_map_reads_back_as_the_points_it_was_written_from(
        points in vec(point(), 1..20),
    ) {
        // Names are unique in a map, and points do not overlap: eight registers each.
        let points: Vec<Point> = points
            .into_iter()
            .enumerate()
            .map(|(i, p)| Point { name: format!("{}{i}", p.name), address: 8 * i as u16, ..p })
            .collect();
        let text = to_csv(&["a comment, with \"quotes\"\nand a line break".into()], &points);
        let read = parse_csv("m", &text).unwrap();
        let unlined = |points: &[Point]| -> Vec<Point> {
            points.iter().map(|p| Point { line: 0, ..p.clone() }).collect()
        };
        prop_assert_eq!(unlined(&read.points), unlined(&points));
    }
}

/// A point of holding registers as a SunSpec map has them: a number scaled by a power of
/// ten, or text; any label and unit.
fn point() -> impl Strategy<Value = Point> {
    let map = parse_csv(
        "m",
        "name,ref,type,scale,unit,access,description\n\
         p,400001,u16,1,,r,\n",
    )
    .unwrap();
    let template = map.points[0].clone();
    (
        "[A-Za-z][A-Za-z0-9_.]{0,20}",
        0u16..65000,
        proptest::sample::select(vec![
            "u16", "i16", "u32", "i32", "u64", "i64", "f32", "f64", "string:8",
        ]),
        -10i32..=10,
        "[ -~]{0,12}",
        any::<bool>(),
        "[ -~]{0,40}",
    )
        .prop_map(move |(name, address, kind, power, unit, writable, label)| {
            let line = format!(
                "name,ref,type\n{name},4{:05},{kind}\n",
                u32::from(address) + 1
            );
            let typed = parse_csv("m", &line).unwrap().points.remove(0);
            Point {
                name,
                address,
                kind: typed.kind,
                scale: format!("1e{power}").parse().unwrap(),
                unit: unit.trim().to_string(),
                writable,
                description: label.trim().to_string(),
                // A whole-number point's mark of no value: 0, as an accumulator's.
                nan_value: (power % 3 == 0
                    && matches!(
                        typed.kind,
                        Kind::Number(
                            ValueType::U16
                                | ValueType::I16
                                | ValueType::U32
                                | ValueType::I32
                                | ValueType::U64
                                | ValueType::I64
                        )
                    ))
                .then_some(0),
                ..template.clone()
            }
        })
}
