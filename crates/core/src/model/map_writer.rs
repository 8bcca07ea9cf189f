//! A register map written as a CSV map, in the columns [`parse_csv`](super::map::parse_csv)
//! reads: so that points found on a device (its SunSpec models) are read, watched and
//! polled by name afterwards, with the same values.

use super::map::Point;
use crate::input::choice::Choice;

/// The columns written, in the order written.
const HEADER: &str = "name,ref,type,order,scale,offset,unit,access,nan_value,description";

/// `points` as the text of a CSV map, a header row first; `comment` lines (`# ...`) before
/// it say where the map came from.
pub fn to_csv(comment: &[String], points: &[Point]) -> String {
    let mut text = String::new();
    for line in comment {
        text.push_str("# ");
        text.push_str(&line.replace(['\n', '\r'], " "));
        text.push('\n');
    }
    text.push_str(HEADER);
    text.push('\n');
    for point in points {
        let fields = [
            point.name.clone(),
            point.reference(),
            point.kind.name(),
            point.order.name().to_string(),
            point.scale.to_string(),
            point.offset.to_string(),
            point.unit.clone(),
            if point.writable { "rw" } else { "r" }.to_string(),
            point
                .nan_value
                .map(|raw| raw.to_string())
                .unwrap_or_default(),
            point.description.clone(),
        ];
        let fields: Vec<String> = fields.iter().map(|field| quoted(field)).collect();
        text.push_str(&fields.join(","));
        text.push('\n');
    }
    text
}

/// A field as CSV holds it: quoted where it has a comma, a quote, a `#` at its start or
/// spaces at its ends; line breaks become spaces, as a map's line is one line.
fn quoted(field: &str) -> String {
    let field = field.replace(['\n', '\r'], " ");
    let plain = !field.contains([',', '"']) && !field.starts_with('#') && field.trim() == field;
    if plain {
        field
    } else {
        format!("\"{}\"", field.replace('"', "\"\""))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::map::parse_csv;

    #[test]
    fn a_written_map_reads_back_as_it_was() {
        let text = "name,ref,type,order,scale,unit,access,description\n\
                    w,440084,i16,ABCD,0.01,W,r,\"AC Power, total\"\n\
                    t,440090,f32,CDAB,1,\"\",rw,\"say \"\"hi\"\"\"\n\
                    s,440005,string:16,ABCD,1,,r,  padded\n";
        let map = parse_csv("m", text).unwrap();
        let again = parse_csv("m", &to_csv(&["from a test".into()], &map.points)).unwrap();
        let lines = |points: &[Point]| -> Vec<Point> {
            points
                .iter()
                .map(|point| Point {
                    line: 0,
                    ..point.clone()
                })
                .collect()
        };
        assert_eq!(lines(&again.points), lines(&map.points));
        assert_eq!(again.points[0].description, "AC Power, total");
        assert_eq!(again.points[0].scale, 0.01);
    }
}
