//! mbtool's master against tokio-modbus, an implementation we did not write, as a slave on
//! TCP (127.0.0.1) and in RTU on a pseudo-terminal pair: every read and write command,
//! counts at the protocol limits, and values read back after writing them.

use std::future::{ready, Ready};
use std::sync::{Arc, Mutex};

use crate::support::{run_against as run, values_of as values, writes_read_back, PtyPair};
use tokio_modbus::prelude::{ExceptionCode, Request, Response, SlaveRequest};

/// The slave's tables: 1000 addresses each, so that address 1000 and above is exception 02.
#[derive(Clone)]
struct Tables {
    coils: Arc<Mutex<Vec<bool>>>,
    inputs: Arc<Vec<bool>>,
    input_registers: Arc<Vec<u16>>,
    holding: Arc<Mutex<Vec<u16>>>,
}

const SIZE: usize = 4000;

impl Tables {
    /// The manuals' example values.
    fn new() -> Self {
        let mut coils = vec![false; SIZE];
        for (i, byte) in [0xCDu8, 0x6B, 0xB2, 0x0E, 0x1B].iter().enumerate() {
            for bit in 0..8 {
                let at = 19 + i * 8 + bit;
                if at < 19 + 37 {
                    coils[at] = byte & (1 << bit) != 0;
                }
            }
        }
        let mut inputs = vec![false; SIZE];
        for (i, byte) in [0xACu8, 0xDB, 0x35].iter().enumerate() {
            for bit in 0..8 {
                let at = 196 + i * 8 + bit;
                if at < 196 + 22 {
                    inputs[at] = byte & (1 << bit) != 0;
                }
            }
        }
        let mut input_registers = vec![0u16; SIZE];
        input_registers[8] = 10;
        let mut holding = vec![0u16; SIZE];
        holding[107..110].copy_from_slice(&[555, 0, 100]);
        Tables {
            coils: Arc::new(Mutex::new(coils)),
            inputs: Arc::new(inputs),
            input_registers: Arc::new(input_registers),
            holding: Arc::new(Mutex::new(holding)),
        }
    }
}

fn range(address: u16, count: usize) -> Result<std::ops::Range<usize>, ExceptionCode> {
    let start = usize::from(address);
    if start + count > SIZE {
        return Err(ExceptionCode::IllegalDataAddress);
    }
    Ok(start..start + count)
}

impl Tables {
    fn answer(&self, request: Request<'static>) -> Result<Response, ExceptionCode> {
        Ok(match request {
            Request::ReadCoils(a, n) => {
                Response::ReadCoils(self.coils.lock().unwrap()[range(a, n.into())?].to_vec())
            }
            Request::ReadDiscreteInputs(a, n) => {
                Response::ReadDiscreteInputs(self.inputs[range(a, n.into())?].to_vec())
            }
            Request::ReadInputRegisters(a, n) => {
                Response::ReadInputRegisters(self.input_registers[range(a, n.into())?].to_vec())
            }
            Request::ReadHoldingRegisters(a, n) => Response::ReadHoldingRegisters(
                self.holding.lock().unwrap()[range(a, n.into())?].to_vec(),
            ),
            Request::WriteSingleCoil(a, v) => {
                self.coils.lock().unwrap()[range(a, 1)?][0] = v;
                Response::WriteSingleCoil(a, v)
            }
            Request::WriteMultipleCoils(a, values) => {
                self.coils.lock().unwrap()[range(a, values.len())?].copy_from_slice(&values);
                Response::WriteMultipleCoils(a, values.len() as u16)
            }
            Request::WriteSingleRegister(a, v) => {
                self.holding.lock().unwrap()[range(a, 1)?][0] = v;
                Response::WriteSingleRegister(a, v)
            }
            Request::WriteMultipleRegisters(a, values) => {
                self.holding.lock().unwrap()[range(a, values.len())?].copy_from_slice(&values);
                Response::WriteMultipleRegisters(a, values.len() as u16)
            }
            _ => return Err(ExceptionCode::IllegalFunction),
        })
    }
}

impl tokio_modbus::server::Service for Tables {
    type Request = SlaveRequest<'static>;
    type Response = Option<Response>;
    type Exception = ExceptionCode;
    type Future = Ready<Result<Self::Response, Self::Exception>>;

    fn call(&self, request: Self::Request) -> Self::Future {
        // A real slave is silent for other slave ids.
        if request.slave != 17 {
            return ready(Ok(None));
        }
        ready(self.answer(request.request).map(Some))
    }
}

/// Every command against one slave, `port` being the connection options.
fn exercise(port: &[String]) {
    assert_eq!(
        values(port, "read-holding 17 400108 3"),
        ["555", "0", "100"]
    );
    assert_eq!(values(port, "read 17 400108-400110"), ["555", "0", "100"]);
    assert_eq!(values(port, "read-input-registers 17 300009"), ["10"]);
    let coils = values(port, "read-coils 17 000020 37");
    assert_eq!(coils[..8], ["1", "0", "1", "1", "0", "0", "1", "1"]);
    assert_eq!(coils.len(), 37);
    let inputs = values(port, "read-inputs 17 100197-100218");
    assert_eq!(inputs[..8], ["0", "0", "1", "1", "0", "1", "0", "1"]);

    writes_read_back(port);

    // The table and JSON a user sees.
    let (_, table) = run(port, "read-holding 17 400108 3");
    for text in ["400108", "400110", "555", "100"] {
        assert!(table.contains(text), "{table}");
    }
    let (_, json) = run(port, "read-holding 17 400108 3 --json");
    let json: serde_json::Value = serde_json::from_str(json.trim()).unwrap();
    assert_eq!(
        json["values"][0],
        serde_json::json!({"address": 107, "ref": "400108", "value": 555})
    );

    // raw, an exception, a silent slave id.
    let (code, out) = run(port, "raw 17 03 00 6B 00 03 --json");
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("[555,0,100]"), "{out}");
    let (code, out) = run(port, "read-holding 17 404500");
    assert_eq!(code, 12, "{out}");
    assert!(out.contains("illegal data address"), "{out}");
    let (code, _) = run(port, "read-holding 18 400108 --timeout 200ms");
    assert_eq!(code, 3);
}

#[test]
fn against_tokio_modbus_on_tcp() {
    let runtime = tokio::runtime::Runtime::new().unwrap();
    let listener = runtime
        .block_on(tokio::net::TcpListener::bind("127.0.0.1:0"))
        .unwrap();
    let port = listener.local_addr().unwrap().port();
    let tables = Tables::new();
    runtime.spawn(async move {
        let server = tokio_modbus::server::tcp::Server::new(listener);
        let on_connected = move |stream, _| {
            let tables = tables.clone();
            async move { Ok(Some((tables, stream))) }
        };
        let _ = server.serve(&on_connected, |_| {}).await;
    });
    exercise(&["--port".into(), format!("tcp://127.0.0.1:{port}")]);
    // The runtime, and with it the server, stops here.
}

#[test]
fn against_tokio_modbus_in_rtu_on_a_pty() {
    let Some(pair) = PtyPair::new() else { return };
    let runtime = tokio::runtime::Runtime::new().unwrap();
    let path = pair.a.clone();
    let server = runtime
        .block_on(async move { tokio_modbus::server::rtu::Server::new_from_path(&path, 19200) });
    let server = server.expect("tokio-modbus opens its end of the pty pair");
    runtime.spawn(server.serve_forever(Tables::new()));
    exercise(&["--port".into(), pair.b.display().to_string()]);
    drop(runtime);
}
