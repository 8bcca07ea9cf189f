use super::*;
use crate::sunspec::defs::definition;

/// Model 160 (multiple MPPT): scale factors, a count, a group repeated to the model's end.
fn mppt(modules: &[[u16; 20]], sf: [u16; 4]) -> Vec<u16> {
    let mut registers = vec![160, 8 + 20 * modules.len() as u16];
    registers.extend(sf);
    registers.extend([0, 0, modules.len() as u16, 0xFFFF]);
    for module in modules {
        registers.extend(module);
    }
    registers
}

fn module(id: u16, current: u16) -> [u16; 20] {
    let mut words = [0xFFFF; 20];
    words[0] = id;
    words[1..9].copy_from_slice(&[0x5056, 0x3100, 0, 0, 0, 0, 0, 0]); // "PV1"
    words[9] = current;
    words[10] = 3801;
    words[12..14].copy_from_slice(&[0, 0]); // DCWH: an accumulator of 0 is not implemented
    words[16] = 0x8000; // Tmp: not implemented
    words[17] = 4; // DCSt: MPPT
    words[18..20].copy_from_slice(&[0, 0b1001]); // DCEvt: bits 0 and 3
    words
}

fn point<'a>(points: &'a [SunSpecPoint], name: &str) -> &'a SunSpecPoint {
    points
        .iter()
        .find(|p| p.name == name)
        .unwrap_or_else(|| panic!("no {name}"))
}

#[test]
fn repeated_groups_scale_factors_and_symbols() {
    let def = definition(160).unwrap().unwrap();
    let registers = mppt(&[module(1, 512), module(2, 498)], [0xFFFE, 0xFFFF, 0, 0]);
    let (points, problem) = lay_out(&def, "mppt", 40100, &registers);
    assert_eq!(problem, None);
    let current = point(&points, "mppt.module_2.DCA");
    assert_eq!(current.value, Ok(Value::Float(4.98)));
    assert_eq!(current.scale_factor, Some(-2));
    assert_eq!(current.address, 40100 + 10 + 20 + 9);
    assert_eq!(current.units, "A");
    let voltage = point(&points, "mppt.module_1.DCV");
    assert_eq!(voltage.value, Ok(Value::Float(380.1)));
    assert_eq!(
        point(&points, "mppt.module_1.IDStr").value,
        Ok(Value::Text("PV1".into()))
    );
    assert_eq!(
        point(&points, "mppt.module_1.DCWH").value,
        Err(NoValue::NotImplemented)
    );
    assert_eq!(
        point(&points, "mppt.module_1.Tmp").value,
        Err(NoValue::NotImplemented)
    );
    assert_eq!(
        point(&points, "mppt.module_1.DCSt").meaning.as_deref(),
        Some("MPPT")
    );
    assert_eq!(
        point(&points, "mppt.module_1.DCEvt").meaning.as_deref(),
        Some("GROUND_FAULT,DC_DISCONNECT")
    );
    // The model's own points, then two modules of ten points each.
    assert_eq!(points.len(), 9 + 2 * 10);
    let map = point(&points, "mppt.module_2.DCA").map_point().unwrap();
    assert_eq!((map.scale, map.reference()), (0.01, "440140".to_string()));
}

#[test]
fn a_point_whose_scale_factor_has_no_value_has_none_either() {
    let def = definition(160).unwrap().unwrap();
    // DCA_SF not implemented (0x8000); DCV_SF 11, outside -10..10.
    let registers = mppt(&[module(1, 512)], [0x8000, 11, 0, 0]);
    let (points, _) = lay_out(&def, "mppt", 0, &registers);
    assert_eq!(
        point(&points, "mppt.module_1.DCA").value,
        Err(NoValue::ScaleFactor(
            "its scale factor DCA_SF is not implemented".into()
        ))
    );
    assert_eq!(
        point(&points, "mppt.module_1.DCV").value,
        Err(NoValue::ScaleFactor(
            "its scale factor DCV_SF is 11, outside -10..10".into()
        ))
    );
}

#[test]
fn a_length_that_does_not_fit_the_definition_is_told() {
    let def = definition(160).unwrap().unwrap();
    let mut registers = mppt(&[module(1, 512)], [0xFFFE, 0xFFFF, 0, 0]);
    registers.push(7);
    registers[1] += 1;
    let (points, problem) = lay_out(&def, "mppt", 0, &registers);
    assert_eq!(
        problem.unwrap().0,
        "mppt.module: the 21 registers left are no whole number of its 20"
    );
    assert_eq!(points.len(), 9, "the model's own points are kept");
    // A common model cut short: what lies past its length is left out, and told.
    let common = definition(1).unwrap().unwrap();
    let (points, problem) = lay_out(&common, "common", 0, &[1, 20, 0x4142]);
    assert_eq!(points.len(), 2);
    assert_eq!(points[1].value, Ok(Value::Unsigned(20)));
    assert_eq!(problem.unwrap().0, "common.Mn lies past the model's length");
}

#[test]
fn not_implemented_markers_of_every_type() {
    let cases: [(PointType, &[u16], bool); 12] = [
        (PointType::Int16, &[0x8000], true),
        (PointType::Int16, &[0x8001], false),
        (PointType::Uint16, &[0xFFFF], true),
        (PointType::Acc32, &[0, 0], true),
        (PointType::Acc32, &[0, 1], false),
        (PointType::Int32, &[0x8000, 0], true),
        (PointType::Uint32, &[0xFFFF, 0xFFFF], true),
        (PointType::Float32, &[0x7FC0, 0], true),
        (PointType::Float32, &[0x4366, 0x0000], false),
        (PointType::String, &[0, 0, 0], true),
        (PointType::Uint64, &[0xFFFF; 4], true),
        (PointType::Float64, &[0x7FF8, 0, 0, 0], true),
    ];
    for (point_type, raw, marked) in cases {
        assert_eq!(
            not_implemented(point_type, raw),
            marked,
            "{point_type:?} {raw:?}"
        );
    }
}
