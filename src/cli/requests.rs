//! The commands that send requests (reads, writes, raw), which `encode` takes too.

use clap::{Args, Subcommand};

use mbtool_core::master::plan::{How, Operation};
use mbtool_core::model::address::Table;

// The commands that send requests; `encode` takes the same ones. A plain comment: a doc
// comment would become the about of `encode`, which builds these commands late.
#[derive(Clone, Debug, Subcommand)]
#[command(defer = true)]
pub enum RequestCommand {
    /// Read coils (function 01)
    ReadCoils(ReadArgs),
    /// Read discrete inputs (function 02)
    #[command(visible_alias = "read-discrete-inputs")]
    ReadInputs(ReadArgs),
    /// Read holding registers (function 03)
    #[command(visible_alias = "read-holding-registers")]
    ReadHolding(ReadArgs),
    /// Read input registers (function 04)
    #[command(visible_alias = "read-input-regs")]
    ReadInputRegisters(ReadArgs),
    /// Read by reference: its first digit picks the table
    Read(ReadByReferenceArgs),
    /// Write one coil (function 05)
    WriteCoil(WriteCoilArgs),
    /// Write coils (function 15)
    WriteCoils(WriteArgs),
    /// Write one holding register (function 06)
    WriteRegister(WriteRegisterArgs),
    /// Write holding registers (function 16)
    WriteRegisters(WriteArgs),
    /// Write by reference: 05/06 for one value, 15/16 for more
    Write(WriteByReferenceArgs),
    /// Send any PDU and decode the answer
    Raw(RawArgs),
}

impl RequestCommand {
    /// The operation the command asks of the core's planner, its words as typed.
    pub fn operation(&self) -> Operation<'_> {
        use RequestCommand as C;
        fn read(a: &ReadArgs, table: Option<Table>) -> Operation<'_> {
            Operation::Read {
                slave: &a.slave,
                address: &a.address,
                table,
                count: a.count.as_deref(),
            }
        }
        match self {
            C::ReadCoils(a) => read(a, Some(Table::Coils)),
            C::ReadInputs(a) => read(a, Some(Table::DiscreteInputs)),
            C::ReadHolding(a) => read(a, Some(Table::HoldingRegisters)),
            C::ReadInputRegisters(a) => read(a, Some(Table::InputRegisters)),
            C::Read(a) => Operation::Read {
                slave: a.slave(),
                address: a.reference.as_deref().unwrap_or_default(),
                table: None,
                count: a.count.as_deref(),
            },
            C::WriteCoil(a) => Operation::Write {
                slave: &a.slave,
                address: &a.address,
                table: Some(Table::Coils),
                values: std::slice::from_ref(&a.value),
                how: How::Single,
            },
            C::WriteRegister(a) => Operation::Write {
                slave: &a.slave,
                address: &a.address,
                table: Some(Table::HoldingRegisters),
                values: std::slice::from_ref(&a.value),
                how: How::OneRegister,
            },
            C::WriteCoils(a) | C::WriteRegisters(a) => Operation::Write {
                slave: &a.slave,
                address: &a.address,
                table: Some(if matches!(self, C::WriteCoils(_)) {
                    Table::Coils
                } else {
                    Table::HoldingRegisters
                }),
                values: &a.values,
                how: How::Multiple,
            },
            C::Write(a) => Operation::Write {
                slave: &a.slave,
                address: a.reference.as_deref().unwrap_or_default(),
                table: None,
                values: &a.values,
                how: How::Function(a.function.as_deref().and_then(|f| f.parse().ok())),
            },
            C::Raw(a) => Operation::Raw {
                slave: &a.slave,
                pdu: &a.pdu,
            },
        }
    }
}

#[derive(Clone, Debug, Args)]
pub struct ReadArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// First holding register: a reference (400108), a number (107, 0x6B; counted from 0, or from 1 with --address-base 1),
    /// an inclusive range (400108-400110), or a bit of a register (400108.05), COUNT then
    /// counting bits
    pub address: String,
    /// How many registers to read [default: 1]; with --type wider than 16 bits, values of
    /// that type
    pub count: Option<String>,
}

#[derive(Clone, Debug, Args)]
pub struct WriteCoilArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// Coil: a reference (000020) or a number (19; counted from 0, or from 1 with --address-base 1)
    pub address: String,
    /// on, off, 1, 0, true or false
    pub value: String,
}

#[derive(Clone, Debug, Args)]
pub struct WriteRegisterArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// Holding register: a reference (400002) or a number (1; counted from 0, or from 1 with --address-base 1)
    pub address: String,
    /// The value, converted by --type
    #[arg(allow_negative_numbers = true)]
    pub value: String,
}

#[derive(Clone, Debug, Args)]
pub struct WriteArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// First holding register: a reference (400002) or a number (1; counted from 0, or from 1 with --address-base 1), or a
    /// range that holds exactly the values given
    pub address: String,
    /// The values: registers each converted by --type; coils each 0/1/on/off, or one bit
    /// string such as 10110
    #[arg(required = true, allow_negative_numbers = true)]
    pub values: Vec<String>,
}

#[derive(Clone, Debug, Args)]
pub struct ReadByReferenceArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP; with --map, left out
    /// where the map gives every point's slave (Home Assistant's entities are slave 1 where
    /// they give none)
    #[arg(required_unless_present = "map", value_name = "SLAVE")]
    pub slave: Option<String>,
    /// A reference, 1-based, whose first digit picks the table (000020 coils, 100197
    /// discrete inputs, 300009 input registers, 400108 holding registers), an inclusive range
    /// (400108-400110), or a bit of a register (400108.05), COUNT then counting bits;
    /// with --map, a point's name
    #[arg(required_unless_present = "map", value_name = "REFERENCE")]
    pub reference: Option<String>,
    /// How many values to read [default: 1]; for registers with --type wider than 16
    /// bits, values of that type; with --map, a point's name
    pub count: Option<String>,
    /// With --map: more points' names [default: every point of the map]
    #[arg(value_name = "NAME")]
    pub names: Vec<String>,
    /// Read the points of a register map (CSV, or Home Assistant YAML), by name
    #[arg(long, value_name = "FILE")]
    pub map: Option<std::path::PathBuf>,
}

impl ReadByReferenceArgs {
    /// With --map: the slave typed, and the names of the points to read (every word after
    /// SLAVE). A first word that is no slave id is a point's name, SLAVE left out.
    pub fn map_words(&self) -> (Option<&str>, Vec<&str>) {
        let is_slave = |word: &str| mbtool_core::model::number::parse_int(word).is_ok();
        let (slave, first) = match self.slave.as_deref() {
            Some(word) if is_slave(word) => (Some(word), None),
            word => (None, word),
        };
        let names = first
            .into_iter()
            .chain(self.reference.as_deref())
            .chain(self.count.as_deref())
            .chain(self.names.iter().map(String::as_str))
            .collect();
        (slave, names)
    }

    /// The slave typed, for a read by reference (which needs it: clap asks for it).
    pub fn slave(&self) -> &str {
        self.slave.as_deref().unwrap_or_default()
    }
}

#[derive(Clone, Debug, Args)]
pub struct WriteByReferenceArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// A coil (000020) or holding register (400001) reference, 1-based; a range that holds exactly
    /// the values given, or a bit of a holding register (400001.03), set alone with
    /// function 22; with --map, NAME=VALUE
    #[arg(required_unless_present = "map", value_name = "REFERENCE")]
    pub reference: Option<String>,
    /// The values: registers each converted by --type; coils each 0/1/on/off, or one bit
    /// string such as 10110; with --map, more NAME=VALUE
    #[arg(required_unless_present = "map", allow_negative_numbers = true)]
    pub values: Vec<String>,
    /// Write points of a register map by name: NAME=VALUE, scale and offset taken back out
    #[arg(long, value_name = "FILE")]
    pub map: Option<std::path::PathBuf>,
    /// Force the function: 5 or 15 for coils, 6 or 16 for registers
    #[arg(long, value_name = "CODE", value_parser = ["5", "6", "15", "16"])]
    pub function: Option<String>,
}

impl WriteByReferenceArgs {
    /// The NAME=VALUE words of a write by map.
    pub fn assignments(&self) -> Vec<&str> {
        self.reference
            .iter()
            .chain(&self.values)
            .map(String::as_str)
            .collect()
    }
}

#[derive(Clone, Debug, Args)]
pub struct RawArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// The PDU in hex, function code first (03 00 6B 00 03)
    #[arg(required = true, num_args = 1.., value_name = "PDU_HEX")]
    pub pdu: Vec<String>,
}
