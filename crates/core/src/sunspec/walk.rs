//! Reading a SunSpec device: the `SunS` marker found at one of the usual bases, then the
//! chain of models walked to its end marker, each model laid out by its definition.
//!
//! The registers are read ahead, 125 at a time, across the model boundaries: a device
//! with a contiguous map (most are) is read in as few requests as its size allows. A
//! device that refuses a read past what the chain has shown so far is read, from then
//! on, exactly as the chain says: each header, then each model's body.

use super::defs::{self, ModelDef};
use super::points::{lay_out, NoValue, SunSpecPoint};
use super::SunSpecError;
use crate::codec::answer::Mismatch;
use crate::codec::{ExceptionCode, Request, Response};
use crate::master::run::RunError;
use crate::master::{Master, MasterError};

/// Where SunSpec says its map may start, in the order they are tried.
pub const BASES: [u16; 3] = [40000, 50000, 0];

/// `SunS`, the marker of a SunSpec map, as two registers.
const MARKER: [u16; 2] = [0x5375, 0x6E53];

/// The id that ends the chain of models.
const END: u16 = 0xFFFF;

/// The most registers one read asks for.
const MOST: u16 = 125;

/// The most requests a model the device refused is read again with, in halves.
const MOST_TO_SPLIT: usize = 64;

/// A SunSpec device as read.
#[derive(Clone, Debug, PartialEq)]
pub struct SunSpecDevice {
    /// The protocol address of the marker.
    pub base: u16,
    /// The models, in the order of the chain.
    pub models: Vec<ModelReading>,
    /// How many requests the scan took, those refused included.
    pub requests: usize,
    /// Why the chain ended before its end marker, if it did.
    pub cut: Option<Cut>,
}

/// How the chain of models ended before its end marker.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Cut {
    /// What was found where the next model belonged.
    pub reason: String,
    /// Whether models may have been lost (a header refused or past the registers), not
    /// only the end marker missing (zeros after the last model).
    pub models_lost: bool,
    /// The exception the device refused the next header with.
    pub refused: Option<ExceptionCode>,
}

/// One model of the chain.
#[derive(Clone, Debug, PartialEq)]
pub struct ModelReading {
    /// Its id.
    pub id: u16,
    /// The protocol address of its ID register.
    pub address: u16,
    /// Its length, as the device gives it (the registers after ID and L).
    pub length: u16,
    /// Its name in a map: the definition's (`common`, `inverter_three_phase`), `_2` after
    /// the second of a kind; `model_ID` for a model SunSpec has not published.
    pub name: String,
    /// Its name for people, from its definition.
    pub label: Option<String>,
    /// Its points, in register order.
    pub points: Vec<SunSpecPoint>,
    /// What kept some or all of its points from being shown.
    pub problem: Option<String>,
    /// The exception the device refused some of its registers with.
    pub refused: Option<ExceptionCode>,
    /// Whether SunSpec has published its definition (it is laid out by it).
    pub published: bool,
}

/// Reads the device's SunSpec map: at `base` when given, else at the first of [`BASES`]
/// that holds the marker.
pub fn read_device(
    master: &mut Master,
    slave: u8,
    base: Option<u16>,
) -> Result<SunSpecDevice, SunSpecError> {
    let mut reader = Reader {
        master,
        slave,
        window_start: 0,
        window: Vec::new(),
        ahead: true,
        extra_refused: false,
        requests: 0,
    };
    let bases: Vec<u16> = match base {
        Some(base) => vec![base],
        None => BASES.to_vec(),
    };
    let base = reader.find_marker(&bases)?;
    let mut device = SunSpecDevice {
        base,
        models: Vec::new(),
        requests: 0,
        cut: None,
    };
    let mut address = u32::from(base) + 2;
    loop {
        let (id, length) = match reader.header(address) {
            Ok(Some(header)) => header,
            Ok(None) => break,
            Err(Missed::Refused(code)) => {
                device.cut = Some(Cut {
                    reason: format!(
                        "the device refused the model header at register {address} ({}) before the end marker",
                        code.name()
                    ),
                    models_lost: true,
                    refused: Some(code),
                });
                break;
            }
            Err(Missed::Failed(error)) => return Err(SunSpecError::Run(error)),
        };
        if id == 0 {
            // Registers left at zero after the last model, where its end marker belongs.
            device.cut = Some(Cut {
                reason: format!(
                    "register {address} holds model id 0 where a model or the end marker (0xFFFF) belongs"
                ),
                models_lost: false,
                refused: None,
            });
            break;
        }
        let end = address + 2 + u32::from(length);
        if end > 0x1_0000 {
            device.cut = Some(Cut {
                reason: format!(
                    "model {id} at register {address} is {length} registers long, past the last register"
                ),
                models_lost: true,
                refused: None,
            });
            break;
        }
        let model = reader.model(&device.models, id, address as u16, length)?;
        device.models.push(model);
        address = end;
    }
    device.requests = reader.requests;
    Ok(device)
}

/// Why a read of the map got no registers.
enum Missed {
    /// The device refused it.
    Refused(ExceptionCode),
    /// No usable answer, or the conversation ended.
    Failed(RunError),
}

/// A register the device refused alone: its offset in what was asked, and the exception.
type Refusal = (usize, ExceptionCode);

struct Reader<'a> {
    master: &'a mut Master,
    slave: u8,
    /// The registers read last, contiguous from `window_start`.
    window_start: u32,
    window: Vec<u16>,
    /// Whether reads go past what the chain has shown, as long as the device allows.
    ahead: bool,
    /// Whether the device refused a model's read together with the next header.
    extra_refused: bool,
    requests: usize,
}

impl Reader<'_> {
    /// The first of `bases` whose two registers are `SunS`.
    /// Each base is asked for its two registers alone: a read ahead at a base that holds
    /// nothing would be refused, and cost a second request there.
    fn find_marker(&mut self, bases: &[u16]) -> Result<u16, SunSpecError> {
        self.ahead = false;
        let found = self.marker_among(bases);
        self.ahead = true;
        found
    }

    fn marker_among(&mut self, bases: &[u16]) -> Result<u16, SunSpecError> {
        let mut held = Vec::new();
        let mut refusals = Vec::new();
        let mut silent = 0;
        for base in bases {
            match self.get(u32::from(*base), 2, 0) {
                Ok(registers) if registers == MARKER => return Ok(*base),
                Ok(registers) => held.push((
                    *base,
                    format!("{:04X} {:04X}, not SunS", registers[0], registers[1]),
                )),
                Err(Missed::Refused(code)) => {
                    refusals.push(code);
                    held.push((*base, code.name().to_string()));
                }
                Err(Missed::Failed(RunError::Master(MasterError::Timeout { .. })))
                    if bases.len() > 1 =>
                {
                    silent += 1;
                    held.push((*base, "no answer".into()));
                }
                Err(Missed::Failed(error)) => return Err(SunSpecError::Run(error)),
            }
        }
        if silent == bases.len() {
            let timeout = MasterError::Timeout {
                slave: self.slave,
                timeout: self.master.timeout(),
            };
            return Err(SunSpecError::Run(timeout.into()));
        }
        // A device that refuses every base alike says so, as it would any read.
        if refusals.len() == bases.len() && refusals.iter().all(|code| *code == refusals[0]) {
            return Err(SunSpecError::Run(RunError::Exception {
                slave: self.slave,
                function: crate::codec::function::READ_HOLDING_REGISTERS,
                code: refusals[0],
            }));
        }
        Err(SunSpecError::NotFound { tried: held })
    }

    /// The id and length of the model at `address`; `None` at the end marker (whose length
    /// some devices leave out).
    fn header(&mut self, address: u32) -> Result<Option<(u16, u16)>, Missed> {
        match self.get(address, 2, 0) {
            Ok(header) if header[0] == END => Ok(None),
            Ok(header) => Ok(Some((header[0], header[1]))),
            Err(Missed::Refused(code)) => match self.get(address, 1, 0)?.first() {
                Some(&END) => Ok(None),
                _ => Err(Missed::Refused(code)),
            },
            Err(failed) => Err(failed),
        }
    }

    /// Reads and lays out the model `id` at `address`; a model without a published
    /// definition is named, and its registers are not read.
    fn model(
        &mut self,
        before: &[ModelReading],
        id: u16,
        address: u16,
        length: u16,
    ) -> Result<ModelReading, SunSpecError> {
        let definition = defs::definition(id);
        let base_name = match &definition {
            Some(Ok(def)) => def.group.name.clone(),
            _ => format!("model_{id}"),
        };
        let same = before
            .iter()
            .filter(|model| model.id == id && model.name.starts_with(&base_name))
            .count();
        let name = match same {
            0 => base_name,
            n => format!("{base_name}_{}", n + 1),
        };
        let mut model = ModelReading {
            id,
            address,
            length,
            name,
            label: None,
            points: Vec::new(),
            problem: None,
            refused: None,
            published: false,
        };
        let def: ModelDef = match definition {
            None => {
                model.problem = Some("SunSpec has published no definition of it".into());
                return Ok(model);
            }
            Some(Err(error)) => {
                model.problem = Some(error.to_string());
                return Ok(model);
            }
            Some(Ok(def)) => def,
        };
        model.label = def.group.label.clone();
        model.published = true;
        let count = usize::from(length) + 2;
        let (registers, refused) = match self.get(u32::from(address), count, 2) {
            Ok(registers) => (registers, Vec::new()),
            Err(Missed::Refused(_)) => self.around_refusals(u32::from(address), count)?,
            Err(Missed::Failed(error)) => return Err(SunSpecError::Run(error)),
        };
        let (mut points, problem) = lay_out(&def, &model.name, address, &registers);
        let mut problems: Vec<String> = problem.map(|problem| problem.0).into_iter().collect();
        if let Some((_, code)) = refused.first() {
            for point in &mut points {
                let start = usize::from(point.address.wrapping_sub(address));
                let span = start..start + point.raw.len();
                if let Some((_, code)) = refused.iter().find(|(at, _)| span.contains(at)) {
                    point.value = Err(NoValue::Refused(code.name().to_string()));
                    point.meaning = None;
                }
            }
            problems.push(format!(
                "the device refused {} of its registers ({})",
                refused.len(),
                code.name()
            ));
            model.refused = Some(*code);
        }
        model.points = points;
        model.problem = (!problems.is_empty()).then(|| problems.join("; "));
        Ok(model)
    }

    /// `count` registers from `address` where the device refused them read together: read
    /// in halves, down to single registers; those it refuses alone are 0 in the registers
    /// given back, and listed (offset from `address`) with the exception.
    fn around_refusals(
        &mut self,
        address: u32,
        count: usize,
    ) -> Result<(Vec<u16>, Vec<Refusal>), SunSpecError> {
        let mut registers = vec![0; count];
        let mut refused = Vec::new();
        let mut pending = vec![(0, count)];
        let mut asked = 0;
        while let Some((start, length)) = pending.pop() {
            if asked == MOST_TO_SPLIT {
                // A model refused all over is not read a register at a time.
                let code = refused
                    .first()
                    .map_or(ExceptionCode::ILLEGAL_DATA_ADDRESS, |(_, code)| *code);
                refused.extend((start..start + length).map(|at| (at, code)));
                continue;
            }
            asked += 1;
            let asked = u16::try_from(length.min(usize::from(MOST))).unwrap_or(MOST);
            match self.read(address + start as u32, asked) {
                Ok(values) => {
                    registers[start..start + values.len()].copy_from_slice(&values);
                    if length > values.len() {
                        pending.push((start + values.len(), length - values.len()));
                    }
                }
                Err(Missed::Refused(code)) if length == 1 => refused.push((start, code)),
                Err(Missed::Refused(_)) => {
                    let half = length / 2;
                    pending.push((start + half, length - half));
                    pending.push((start, half));
                }
                Err(Missed::Failed(error)) => return Err(SunSpecError::Run(error)),
            }
        }
        refused.sort_unstable_by_key(|(at, _)| *at);
        Ok((registers, refused))
    }

    /// `count` registers from `address`, from what was read already where it holds them.
    /// Where more is read, as much as one request takes while the device allows reads
    /// ahead; once it has refused one, `extra` registers after them (the next model's
    /// header), unless it refuses those too.
    fn get(&mut self, address: u32, count: usize, extra: u16) -> Result<Vec<u16>, Missed> {
        let want_end = address + count as u32;
        let window_end = self.window_start + self.window.len() as u32;
        if address < self.window_start || address > window_end {
            self.window_start = address;
            self.window.clear();
        }
        while self.window_start + (self.window.len() as u32) < want_end {
            let from = self.window_start + self.window.len() as u32;
            let needed = (want_end - from).min(u32::from(MOST)) as u16;
            let room = (0x1_0000 - from).min(u32::from(MOST)) as u16;
            // The reads to try, longest first: ahead, with the extra, what is needed.
            let with_extra = needed.saturating_add(extra).min(room);
            let mut tries = Vec::with_capacity(3);
            if self.ahead && room > with_extra {
                tries.push(room);
            }
            if with_extra > needed && !self.extra_refused {
                tries.push(with_extra);
            }
            tries.push(needed);
            let mut registers = Err(Missed::Refused(ExceptionCode::ILLEGAL_DATA_ADDRESS));
            for count in tries {
                registers = self.read(from, count);
                match registers {
                    Err(Missed::Refused(_)) => {
                        self.ahead &= count <= with_extra;
                        // A device that refuses a model read with the next header refuses
                        // every such read: models are read alone from then on.
                        self.extra_refused |= count == with_extra && count > needed;
                    }
                    _ => break,
                }
            }
            let registers = registers?;
            self.window.extend(registers);
        }
        let start = (address - self.window_start) as usize;
        Ok(self.window[start..start + count].to_vec())
    }

    fn read(&mut self, address: u32, count: u16) -> Result<Vec<u16>, Missed> {
        self.requests += 1;
        let request = Request::ReadHoldingRegisters {
            address: address as u16,
            quantity: count,
        };
        match self.master.answer(self.slave, &request) {
            Ok(Some(Response::ReadHoldingRegisters { values })) => Ok(values),
            // The master lets through only an answer that fits; a broadcast has none.
            Ok(answer) => Err(Missed::Failed(RunError::Master(MasterError::BadFrame {
                slave: self.slave,
                reason: Mismatch::Function {
                    asked: request.function(),
                    answered: answer.map_or(0, |response| response.function()),
                }
                .into(),
            }))),
            Err(RunError::Exception { code, .. }) => Err(Missed::Refused(code)),
            Err(error) => Err(Missed::Failed(error)),
        }
    }
}

#[cfg(test)]
mod tests;
