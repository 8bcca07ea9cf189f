//! The commands that talk to a slave: reads, writes, `raw`, and polling.

use std::io::Write;

use anyhow::Result;

use mbtool::connection::{Connector, Role};
use mbtool::error::Error;
use mbtool::output;
use mbtool::output::decode::DecodeWriter;
use mbtool::output::read::{write_done, ReadWriter, WriteDetail, WriteDone};
use mbtool::settings::job::{Layouts, RequestWords, TypedWords};
use mbtool::settings::Settings;
use mbtool_core::codec::{Frame, Mode, Pdu, Request};
use mbtool_core::describe::describe_frame;
use mbtool_core::master::plan::{How, Plan};
use mbtool_core::master::range::{read_range, Items};
use mbtool_core::master::run::Written;
use mbtool_core::master::{Master, Reply};
use mbtool_core::model::address::{bit_reference, reference, Table};
use mbtool_core::model::layouts::{at_start, rank};
use mbtool_core::model::values::{ReadData, ValueType};

pub fn run(settings: &Settings, words: &RequestWords) -> Result<u8> {
    // The whole command line is checked before a port is opened.
    if settings.poll.count.is_some() && settings.poll.interval.is_none() {
        return Err(Error::usage(
            "--count N stops a --poll after N reads: give --poll INTERVAL too, or, for N \
             values, give COUNT after the address (read-holding 17 400108 3)",
        )
        .into());
    }
    if settings.poll.log.is_some() && settings.poll.interval.is_none() {
        return Err(
            Error::usage("--log keeps the rows of a --poll: give --poll INTERVAL too").into(),
        );
    }
    let request = match words {
        RequestWords::ByMap(map) => return super::map::by_map(settings, map)?.run(settings),
        RequestWords::Typed(request) => request,
    };
    let plan = super::shared::plan_for(settings, request)?;
    super::shared::refuse_unsafe_retries(settings, &plan.requests)?;
    if let TypedWords::Read {
        layouts: Some(layouts),
        ..
    } = request
    {
        return read_layouts(settings, &plan, layouts);
    }
    let target = Connector::new(&settings.connection, Role::Master)?;
    if let (Some(interval), Some((table, address))) = (settings.poll.interval, plan.reads) {
        return poll_reads(settings, &target, &plan, (table, address), interval);
    }
    let mut connection = target.connect()?;
    let mode = target.mode;
    let master = &mut connection.master;
    if settings.output.verbose {
        master.trace(super::shared::tracer(mode));
    }
    let mut out = output::stdout();
    let code = match (request, plan.reads) {
        (TypedWords::Raw { .. }, _) => raw(settings, master, &plan, mode, &mut out),
        (TypedWords::ReadFile { .. }, _) => read_files(settings, master, &plan, &mut out),
        (TypedWords::ReadFifo { .. }, _) => read_fifo(settings, master, &plan, &mut out),
        (
            TypedWords::MaskWrite { .. }
            | TypedWords::Write {
                how: How::Function(Some(22)),
                ..
            },
            _,
        ) => writes(settings, master, &plan, Emulate::No, &mut out),
        (_, Some((table, address))) => reads(settings, master, &plan, table, address, &mut out),
        (_, None) => writes(settings, master, &plan, Emulate::MaskWrite, &mut out),
    };
    super::shared::tell_switches(settings, master);
    super::shared::tell_after_requests(master);
    let code = code.map_err(|error| match error.downcast::<Error>() {
        Ok(error) => connection.explain(error).into(),
        Err(error) => error,
    })?;
    out.flush()?;
    Ok(code)
}

fn reads(
    settings: &Settings,
    master: &mut Master,
    plan: &Plan,
    table: Table,
    address: u16,
    out: &mut Box<dyn Write>,
) -> Result<u8> {
    let result = master.read(plan, table, address).map_err(Error::from)?;
    ReadWriter::new(settings.output.style).write(out, &result.into())?;
    Ok(0)
}

/// `--poll` of a read: the rows of every poll, a dropped connection opened again.
fn poll_reads(
    settings: &Settings,
    target: &Connector,
    plan: &Plan,
    (table, address): (Table, u16),
    interval: std::time::Duration,
) -> Result<u8> {
    let writer = |format| {
        let style = output::Style {
            format,
            ..settings.output.style
        };
        ReadWriter::new(style).polling(plan)
    };
    // A poll of a range reads around its holes, as watch does.
    let items = Items {
        value_type: settings.data.value_type,
        order: settings.data.order,
        max_per_request: settings.data.max_per_request,
    };
    super::poll::run(
        settings,
        target,
        interval,
        |master| read_range(master, plan, (table, address), items),
        writer,
    )
}

/// Whether a mask write the slave does not know is done with a read and a write.
#[derive(PartialEq, Eq)]
enum Emulate {
    /// As `write` of a bit does.
    MaskWrite,
    /// `mask-write` asks for function 22 alone.
    No,
}

fn read_files(
    settings: &Settings,
    master: &mut Master,
    plan: &Plan,
    out: &mut Box<dyn Write>,
) -> Result<u8> {
    let groups = master.read_files(plan).map_err(Error::from)?;
    output::records::write_files(out, settings.output.style, plan.slave, &groups)?;
    Ok(0)
}

fn read_fifo(
    settings: &Settings,
    master: &mut Master,
    plan: &Plan,
    out: &mut Box<dyn Write>,
) -> Result<u8> {
    let values = master.read_fifo(plan).map_err(Error::from)?;
    let address = match plan.requests.first() {
        Some(Request::ReadFifoQueue { address }) => *address,
        _ => 0,
    };
    let place = (
        settings.output.style.address_base.number(address),
        reference(Table::HoldingRegisters, address),
    );
    output::records::write_fifo(
        out,
        settings.output.style,
        plan.slave,
        (place.0, place.1.as_ref()),
        &values,
    )?;
    Ok(0)
}

fn writes(
    settings: &Settings,
    master: &mut Master,
    plan: &Plan,
    emulate: Emulate,
    out: &mut Box<dyn Write>,
) -> Result<u8> {
    let written = match emulate {
        Emulate::MaskWrite => master.write(plan).map_err(Error::from)?,
        Emulate::No => {
            for request in &plan.requests {
                master.answer(plan.slave, request).map_err(Error::from)?;
            }
            Written {
                count: plan.requests.len(),
                mask_write_emulated: false,
            }
        }
    };
    let Some(first) = plan.requests.first() else {
        return Ok(0);
    };
    if let Request::WriteFileRecord { groups } = first {
        let Some(group) = groups.first() else {
            return Ok(0);
        };
        let done = WriteDone {
            slave: plan.slave,
            function: first.function(),
            address: u32::from(group.record),
            reference: format!("file {} record {}", group.file, group.record),
            count: written.count / settings.data.value_type.width(),
            broadcast: plan.slave == 0,
            detail: WriteDetail {
                file: Some(group.file),
                record: Some(group.record),
                ..WriteDetail::default()
            },
        };
        write_done(out, settings.output.format, &done)?;
        return Ok(0);
    }
    let (table, address) = match first {
        Request::WriteSingleCoil { address, .. } | Request::WriteMultipleCoils { address, .. } => {
            (Table::Coils, *address)
        }
        Request::WriteSingleRegister { address, .. }
        | Request::WriteMultipleRegisters { address, .. }
        | Request::MaskWriteRegister { address, .. } => (Table::HoldingRegisters, *address),
        _ => return Ok(0),
    };
    let reference = match first {
        // One bit changed: that bit; any other masks: the register.
        Request::MaskWriteRegister { and_mask, .. } if (!and_mask).count_ones() == 1 => {
            bit_reference(table, address, (!and_mask).trailing_zeros() as u8)
        }
        _ => reference(table, address).into(),
    };
    if written.mask_write_emulated {
        super::shared::note_mask_write_emulated(plan.slave, &reference);
    }
    let done = WriteDone {
        slave: plan.slave,
        // A bit set by a read and a write says the write that did it.
        function: match written.mask_write_emulated {
            true => mbtool_core::codec::function::WRITE_SINGLE_REGISTER,
            false => first.function(),
        },
        address: settings.output.style.address_base.number(address),
        reference,
        // Values as the user typed them: one f32 is two registers.
        count: match first {
            Request::MaskWriteRegister { .. } => 1,
            _ if table == Table::HoldingRegisters => {
                written.count / settings.data.value_type.width()
            }
            _ => written.count,
        },
        broadcast: plan.slave == 0,
        detail: match first {
            Request::MaskWriteRegister {
                and_mask, or_mask, ..
            } if !written.mask_write_emulated => WriteDetail {
                and_mask: Some(*and_mask),
                or_mask: Some(*or_mask),
                ..WriteDetail::default()
            },
            _ => WriteDetail::default(),
        },
    };
    write_done(out, settings.output.format, &done)?;
    Ok(0)
}

/// `raw`: the answer decoded like `mbtool decode` shows a frame; an exception also sets
/// the exit status.
fn raw(
    settings: &Settings,
    master: &mut Master,
    plan: &Plan,
    mode: Mode,
    out: &mut Box<dyn Write>,
) -> Result<u8> {
    let Some(request) = plan.requests.first() else {
        return Ok(0);
    };
    let (pdu, code) = match master.reply(plan.slave, request).map_err(Error::from)? {
        Reply::Broadcast => return Ok(0),
        Reply::Response(response) => (Pdu::Response(response), 0),
        Reply::Exception(exception) => {
            let code = Error::Exception {
                slave: plan.slave,
                function: exception.function,
                code: exception.code,
            }
            .exit_code();
            (Pdu::Exception(exception), code)
        }
    };
    let frame = Frame {
        mode,
        slave: plan.slave,
        transaction: 0,
        pdu,
    };
    let bytes = frame.encode().map_err(|e| Error::usage(e.to_string()))?;
    let report = describe_frame(
        &bytes,
        Some(mode),
        Some(mbtool_core::codec::Direction::Response),
    );
    let mut writer = DecodeWriter::new(settings.output.style);
    writer.write(out, &bytes, &report)?;
    Ok(code)
}

/// `read --layouts` and `read --expect`: the registers read as every type and order, or
/// the layouts that give the value expected, nearest first, and the best as a map line.
fn read_layouts(settings: &Settings, plan: &Plan, layouts: &Layouts) -> Result<u8> {
    let Some((table, address)) = plan.reads.filter(|(table, _)| !table.is_bits()) else {
        return Err(Error::usage(
            "--layouts and --expect read registers: give a 3xxxxx or 4xxxxx reference",
        )
        .into());
    };
    if settings.data.value_type != ValueType::U16 || plan.bits.is_some() {
        return Err(Error::usage(
            "--layouts and --expect read every type from the registers: leave out --type and bits, and give COUNT in registers",
        )
        .into());
    }
    if settings.poll.interval.is_some() {
        return Err(Error::usage("--layouts and --expect read once: leave out --poll").into());
    }
    let target = Connector::new(&settings.connection, Role::Master)?;
    let mut connection = target.connect()?;
    if settings.output.verbose {
        connection.master.trace(super::shared::tracer(target.mode));
    }
    let read = connection.master.read(plan, table, address);
    super::shared::tell_after_requests(&mut connection.master);
    let read = read.map_err(|e| connection.explain(Error::from(e)))?;
    let ReadData::Registers(registers) = read.data else {
        return Ok(0);
    };
    let start = output::layouts::Start { table, address };
    let (format, colour) = (settings.output.format, settings.output.style.colour);
    let mut out = output::stdout();
    match layouts {
        Layouts::All => {
            output::layouts::write_layouts(
                &mut out,
                format,
                colour,
                &start,
                &at_start(&registers),
            )?;
        }
        Layouts::Expect(expected) => {
            let candidates = rank(&registers, *expected);
            let Some(best) = candidates.first() else {
                out.flush()?;
                mbtool::note!(
                    "mbtool: no type or order of the {} read gives {}: read more registers, or check the address",
                    output::plural(registers.len(), "register"),
                    expected
                );
                return Ok(1);
            };
            output::layouts::write_candidates(&mut out, format, colour, &start, &candidates)?;
            out.flush()?;
            mbtool::note!(
                "mbtool: the best, as a line of a CSV map (name,ref,type,order): {}",
                output::layouts::map_line(&start, &best.reading)
            );
            // A wider type at the same register giving the value as exactly: only a reading
            // that does not fit the narrower one tells them apart.
            let alike = candidates.iter().skip(1).find(|other| {
                other.reading.offset == best.reading.offset
                    && other.distance == best.distance
                    && other.reading.registers.len() != best.reading.registers.len()
            });
            if let Some(other) = alike {
                mbtool::note!(
                    "mbtool: {} gives it as well; read again when the value is larger to tell them apart",
                    output::layouts::map_line(&start, &other.reading)
                        .trim_start_matches("value,")
                );
            }
        }
    }
    out.flush()?;
    Ok(0)
}
