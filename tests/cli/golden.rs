//! The worked frames of the Modbus manuals (every CRC checked):
//! each decodes to the fields the manuals describe, and `encode` builds each request byte
//! for byte.

use crate::support::{mbtool, WORKED};
use mbtool_core::codec::{bits, Direction, Frame, Mode, Pdu, Request, Response};
use mbtool_core::describe::{describe_frame, Kind, Values};
use mbtool_core::input::hexinput::parse_hex;

fn bytes(hex: &str) -> Vec<u8> {
    let mut out = Vec::new();
    parse_hex(hex.as_bytes(), &mut out).expect("test frames are hex");
    out
}

fn decode(hex: &str, direction: Direction) -> Pdu {
    Frame::decode(Mode::Rtu, &bytes(hex), direction)
        .expect("a worked frame decodes")
        .pdu
}

#[test]
fn encode_builds_every_worked_request_byte_for_byte() {
    for (args, request, _) in WORKED {
        let output = mbtool()
            .arg("encode")
            .args(args.split_whitespace())
            .output()
            .unwrap();
        assert!(output.status.success(), "{args}: {output:?}");
        assert_eq!(
            String::from_utf8_lossy(&output.stdout).trim(),
            *request,
            "{args}"
        );
    }
}

#[test]
fn encode_ascii_gives_the_corrected_manual_frame() {
    mbtool()
        .args([
            "encode",
            "--mode",
            "ascii",
            "read-holding",
            "17",
            "400108",
            "3",
        ])
        .assert()
        .success()
        .stdout(":1103006B00037E\n");
}

#[test]
fn every_worked_frame_passes_its_crc_both_ways_of_reading() {
    for (args, request, response) in WORKED {
        for hex in [request, response] {
            let report = describe_frame(&bytes(hex), None, None);
            assert!(report.valid, "{args}: {hex}: {:?}", report.error);
            assert_eq!(report.mode, "rtu");
            assert_eq!(report.slave, 17);
        }
    }
}

#[test]
fn read_coils_20_to_56() {
    let Pdu::Request(request) = decode(WORKED[0].1, Direction::Request) else {
        panic!("a request")
    };
    assert_eq!(
        request,
        Request::ReadCoils {
            address: 19,
            quantity: 37
        }
    );
    let Pdu::Response(response) = decode(WORKED[0].2, Direction::Response) else {
        panic!("a response")
    };
    assert_eq!(
        response,
        Response::ReadCoils {
            packed: vec![0xCD, 0x6B, 0xB2, 0x0E, 0x1B]
        }
    );
    // Coils 27-20 are CD: 1100 1101, coil 20 in the low bit; 37 coils leave 3 padding bits.
    let coils = response.bits(37).unwrap();
    assert_eq!(coils.len(), 37);
    assert_eq!(
        &coils[..8],
        &[true, false, true, true, false, false, true, true]
    );
    assert_eq!(bits::pack(&coils), [0xCD, 0x6B, 0xB2, 0x0E, 0x1B]);
}

#[test]
fn read_inputs_197_to_218() {
    let Pdu::Request(request) = decode(WORKED[1].1, Direction::Request) else {
        panic!("a request")
    };
    assert_eq!(
        request,
        Request::ReadDiscreteInputs {
            address: 196,
            quantity: 22
        }
    );
    let Pdu::Response(response) = decode(WORKED[1].2, Direction::Response) else {
        panic!("a response")
    };
    assert_eq!(
        response,
        Response::ReadDiscreteInputs {
            packed: vec![0xAC, 0xDB, 0x35]
        }
    );
}

#[test]
fn read_holding_108_to_110_is_555_0_100() {
    let report = describe_frame(&bytes(WORKED[2].1), None, None);
    assert_eq!(report.kind, Kind::Request);
    assert_eq!(report.fields.address, Some(107));
    assert_eq!(report.fields.reference.as_deref(), Some("400108"));
    assert_eq!(report.fields.count, Some(3));
    let report = describe_frame(&bytes(WORKED[2].2), None, None);
    assert_eq!(report.kind, Kind::Response);
    assert_eq!(
        report.fields.values,
        Some(Values::Registers(vec![555, 0, 100].into()))
    );
}

#[test]
fn read_input_register_9_is_10() {
    let Pdu::Response(response) = decode(WORKED[3].2, Direction::Response) else {
        panic!("a response")
    };
    assert_eq!(response, Response::ReadInputRegisters { values: vec![10] });
}

#[test]
fn write_coil_173_on_and_register_2_and_registers_2_3() {
    assert_eq!(
        decode(WORKED[4].1, Direction::Request),
        Pdu::Request(Request::WriteSingleCoil {
            address: 172,
            value: true
        })
    );
    assert_eq!(
        decode(WORKED[5].1, Direction::Request),
        Pdu::Request(Request::WriteSingleRegister {
            address: 1,
            value: 3
        })
    );
    assert_eq!(
        decode(WORKED[6].1, Direction::Request),
        Pdu::Request(Request::WriteMultipleRegisters {
            address: 1,
            values: vec![0x000A, 0x0102]
        })
    );
    assert_eq!(
        decode(WORKED[6].2, Direction::Response),
        Pdu::Response(Response::WriteMultipleRegisters {
            address: 1,
            quantity: 2
        })
    );
}

#[test]
fn decode_json_of_the_read_holding_answer() {
    let output = mbtool()
        .args(["decode", "--json", WORKED[2].2])
        .output()
        .unwrap();
    assert!(output.status.success());
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(json["mode"], "rtu");
    assert_eq!(json["kind"], "response");
    assert_eq!(json["slave"], 17);
    assert_eq!(json["function"], 3);
    assert_eq!(json["valid"], true);
    assert_eq!(json["values"], serde_json::json!([555, 0, 100]));
}

#[test]
fn decode_json_of_the_coil_answer_gives_bits_as_0_and_1() {
    let output = mbtool()
        .args(["decode", "--json", WORKED[0].2])
        .output()
        .unwrap();
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    // 37 coils were asked, in 5 bytes: without the request, the bits sure to be values are
    // those of the first 4 bytes and the first of the last; the rest may be padding.
    let values = json["values"].as_array().unwrap();
    assert_eq!(values.len(), 33);
    assert_eq!(json["max_count"], 40);
    assert!(json.get("count").is_none());
    assert_eq!(
        &values[..8],
        &serde_json::json!([1, 0, 1, 1, 0, 0, 1, 1])
            .as_array()
            .unwrap()[..]
    );
}
