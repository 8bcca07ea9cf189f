use super::*;

#[test]
fn an_ascii_frame_too_long_to_open_names_the_slave_and_function_it_spells() {
    let mut frame = b":113100".to_vec();
    frame.extend([b'0'; 600]);
    frame.extend(b"\r\n");
    let report = describe_frame(&frame, Some(Mode::Ascii), None);
    assert!(!report.valid);
    assert_eq!((report.slave, report.function), (0x11, 0x31));
}

#[test]
fn a_request_is_described_with_its_reference() {
    let report = describe_frame(
        &[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x87],
        None,
        None,
    );
    assert_eq!(report.mode, "rtu");
    assert_eq!(report.kind, Kind::Request);
    assert_eq!((report.slave, report.function), (17, 3));
    assert!(report.valid);
    assert_eq!(report.fields.address, Some(107));
    assert_eq!(report.fields.reference.as_deref(), Some("400108"));
    assert_eq!(report.fields.count, Some(3));
}

#[test]
fn an_answer_carries_its_values_and_an_exception_its_code() {
    let answer = describe_frame(
        &[
            0x11, 0x03, 0x06, 0x02, 0x2B, 0x00, 0x00, 0x00, 0x64, 0xC8, 0xBA,
        ],
        Some(Mode::Rtu),
        Some(Direction::Response),
    );
    assert_eq!(answer.kind, Kind::Response);
    assert_eq!(
        answer.fields.values,
        Some(Values::Registers(vec![555, 0, 100].into()))
    );
    let exception = describe_frame(&[0x0A, 0x81, 0x02, 0xB0, 0x53], Some(Mode::Rtu), None);
    assert_eq!(exception.kind, Kind::Exception);
    assert!(exception.valid);
    assert_eq!(exception.fields.exception, Some(2));
}

#[test]
fn a_frame_that_fails_its_crc_is_described_but_not_valid() {
    let report = describe_frame(
        &[0x11, 0x03, 0x00, 0x6B, 0x00, 0x03, 0x76, 0x88],
        Some(Mode::Rtu),
        None,
    );
    assert!(!report.valid);
    assert_eq!(report.slave, 17);
    assert!(report.error.is_some());
}

#[test]
fn bytes_are_spaced_upper_case_hex() {
    assert_eq!(spaced_hex(&[0x3A, 0x03, 0x0f]), "3A 03 0F");
}
