//! The commands that send requests (reads, writes, raw), which `encode` takes too: on
//! the bus with the options of a line and a master, under `encode` with those that shape
//! the frame alone.

use clap::{Args, Subcommand};

use mbtool_core::model::address::Table;

use super::options::{left_out, more_in_long_help, ShortHelp};
use super::options::{
    AddressArgs, EndpointArgs, FormatArgs, MasterArgs, PollArgs, RedundancyArgs, RegisterArgs,
    RepeatArgs, SplitArgs,
};
use super::taken::{holds, Before, Options, Taken};

/// What a request command takes beyond its request: on the bus, the line and the master;
/// under `encode`, the endpoint alone, which picks the frame's envelope.
pub trait Wire {
    /// For the reads, which may repeat on a schedule and use a second path.
    type Read: Args + Options + ShortHelp + Clone + std::fmt::Debug;
    /// For the writes that are sent once.
    type Write: Args + Options + ShortHelp + Clone + std::fmt::Debug;
    /// For the requests that may do more when sent twice (retried only when asked).
    type Repeatable: Args + Options + ShortHelp + Clone + std::fmt::Debug;
}

/// Requests sent on the bus.
#[derive(Clone, Debug)]
pub struct OnTheBus;

impl Wire for OnTheBus {
    type Read = BusRead;
    type Write = MasterArgs;
    type Repeatable = BusRepeatable;
}

/// Requests printed as frames by `encode`.
#[derive(Clone, Debug)]
pub struct Encoded;

impl Wire for Encoded {
    type Read = EndpointArgs;
    type Write = EndpointArgs;
    type Repeatable = EncodedRepeatable;
}

// A request `encode` builds that may do more when sent twice: it takes
// --retry-non-idempotent as the command on the bus does, to be given the same line.
#[derive(Clone, Debug, Args)]
pub struct EncodedRepeatable {
    #[command(flatten)]
    pub endpoint: EndpointArgs,
    #[command(flatten)]
    pub repeat: RepeatArgs,
}

// A read on the bus: the master, a schedule, a second path.
#[derive(Clone, Debug, Args)]
pub struct BusRead {
    #[command(flatten)]
    pub master: MasterArgs,
    #[command(flatten)]
    pub poll: PollArgs,
    #[command(flatten)]
    pub redundancy: RedundancyArgs,
}

// A request on the bus that may do more when sent twice.
#[derive(Clone, Debug, Args)]
pub struct BusRepeatable {
    #[command(flatten)]
    pub master: MasterArgs,
    #[command(flatten)]
    pub repeat: RepeatArgs,
}

// A request command's words, the groups that shape its request, the output, and what
// its wire takes. A plain comment: a doc comment would become the about of the commands.
#[derive(Clone, Debug, Args)]
#[command(after_help = more_in_long_help(&[W::LEFT_OUT, D::LEFT_OUT]))]
pub struct RequestArgs<A: Args, D: Args + ShortHelp, W: Args + ShortHelp> {
    #[command(flatten)]
    pub args: A,
    #[command(flatten)]
    pub wire: W,
    #[command(flatten)]
    pub data: D,
    #[command(flatten)]
    pub format: FormatArgs,
}

// Coils or inputs, several at a time.
#[derive(Clone, Debug, Args)]
pub struct BitData {
    #[command(flatten)]
    pub addresses: AddressArgs,
    #[command(flatten)]
    pub split: SplitArgs,
}

// One address: a coil, or the bits of a register.
#[derive(Clone, Debug, Args)]
pub struct OneBitData {
    #[command(flatten)]
    pub addresses: AddressArgs,
}

// Registers, several at a time, read as values.
#[derive(Clone, Debug, Args)]
pub struct RegisterData {
    #[command(flatten)]
    pub addresses: AddressArgs,
    #[command(flatten)]
    pub split: SplitArgs,
    #[command(flatten)]
    pub registers: RegisterArgs,
}

// One register, as a value.
#[derive(Clone, Debug, Args)]
pub struct OneRegisterData {
    #[command(flatten)]
    pub addresses: AddressArgs,
    #[command(flatten)]
    pub registers: RegisterArgs,
}

// Records of files read as values, in requests as large as the device takes.
#[derive(Clone, Debug, Args)]
pub struct RecordData {
    #[command(flatten)]
    pub split: SplitArgs,
    #[command(flatten)]
    pub registers: RegisterArgs,
}

// Registers shown as values: a raw PDU's answer, file records written.
#[derive(Clone, Debug, Args)]
pub struct ValueData {
    #[command(flatten)]
    pub registers: RegisterArgs,
}

impl<A: Args, D: Args + Options + ShortHelp, W: Args + Options + ShortHelp> Options
    for RequestArgs<A, D, W>
{
    fn gather<'a>(&'a self, taken: &mut Taken<'a>) {
        self.data.gather(taken);
        self.format.gather(taken);
        self.wire.gather(taken);
    }

    fn take_before(&mut self, before: &Before) {
        self.data.take_before(before);
        self.format.take_before(before);
        self.wire.take_before(before);
    }
}

holds!(BusRead: master, poll, redundancy);

impl ShortHelp for BusRead {
    const LEFT_OUT: &'static [&'static str] = &[
        left_out::CONNECTION,
        left_out::RS485,
        left_out::TLS,
        left_out::WATCHING,
        left_out::REDUNDANCY,
    ];
}

impl ShortHelp for BusRepeatable {
    const LEFT_OUT: &'static [&'static str] = MasterArgs::LEFT_OUT;
}

impl ShortHelp for BitData {
    const LEFT_OUT: &'static [&'static str] = &[left_out::ADDRESSES];
}

impl ShortHelp for OneBitData {
    const LEFT_OUT: &'static [&'static str] = &[left_out::ADDRESSES];
}

impl ShortHelp for RegisterData {
    const LEFT_OUT: &'static [&'static str] = &[left_out::ADDRESSES];
}

impl ShortHelp for OneRegisterData {
    const LEFT_OUT: &'static [&'static str] = &[left_out::ADDRESSES];
}

impl ShortHelp for RecordData {
    const LEFT_OUT: &'static [&'static str] = &[left_out::ADDRESSES];
}

impl ShortHelp for ValueData {
    const LEFT_OUT: &'static [&'static str] = &[];
}
holds!(BusRepeatable: master, repeat);
holds!(EncodedRepeatable: endpoint, repeat);

impl ShortHelp for EncodedRepeatable {
    const LEFT_OUT: &'static [&'static str] = &[left_out::CONNECTION];
}
holds!(BitData: addresses, split);
holds!(OneBitData: addresses);
holds!(RegisterData: addresses, split, registers);
holds!(OneRegisterData: addresses, registers);
holds!(RecordData: split, registers);
holds!(ValueData: registers);

// The commands that send requests; `encode` takes the same ones. A plain comment: a doc
// comment would become the about of `encode`.
#[derive(Clone, Debug, Subcommand)]
#[command(defer = true)]
pub enum RequestCommand<W: Wire> {
    /// Read coils (function 01)
    ReadCoils(RequestArgs<ReadArgs<Coils>, BitData, W::Read>),
    /// Read discrete inputs (function 02)
    #[command(visible_alias = "read-discrete-inputs")]
    ReadInputs(RequestArgs<ReadArgs<DiscreteInputs>, BitData, W::Read>),
    /// Read holding registers (function 03)
    #[command(visible_alias = "read-holding-registers")]
    ReadHolding(RequestArgs<ReadArgs<HoldingRegisters>, RegisterData, W::Read>),
    /// Read input registers (function 04)
    #[command(visible_alias = "read-input-regs")]
    ReadInputRegisters(RequestArgs<ReadArgs<InputRegisters>, RegisterData, W::Read>),
    /// Read by reference: its first digit picks the table
    Read(RequestArgs<ReadReferenceArgs, RegisterData, W::Read>),
    /// Write one coil (function 05)
    WriteCoil(RequestArgs<WriteCoilArgs, OneBitData, W::Write>),
    /// Write coils (function 15)
    WriteCoils(RequestArgs<WriteArgs<Coils>, BitData, W::Write>),
    /// Write one holding register (function 06)
    WriteRegister(RequestArgs<WriteRegisterArgs, OneRegisterData, W::Repeatable>),
    /// Write holding registers (function 16)
    WriteRegisters(RequestArgs<WriteArgs<HoldingRegisters>, RegisterData, W::Write>),
    /// Write by reference: 05/06 for one value, 15/16 for more
    Write(RequestArgs<WriteByReferenceArgs, RegisterData, W::Repeatable>),
    /// Read records of files (function 20)
    ReadFile(RequestArgs<ReadFileArgs, RecordData, W::Write>),
    /// Write records of a file (function 21)
    WriteFile(RequestArgs<WriteFileArgs, ValueData, W::Repeatable>),
    /// Set bits of a register in one request (function 22)
    MaskWrite(RequestArgs<MaskWriteArgs, OneBitData, W::Repeatable>),
    /// Write then read registers in one request (function 23)
    ReadWrite(RequestArgs<ReadWriteArgs, OneRegisterData, W::Repeatable>),
    /// Read a FIFO queue (function 24)
    ReadFifo(RequestArgs<ReadFifoArgs, OneRegisterData, W::Write>),
    /// Send any PDU and decode the answer
    Raw(RequestArgs<RawArgs, ValueData, W::Repeatable>),
}

impl<W: Wire> RequestCommand<W> {
    /// The command's arguments, as the groups of options they hold.
    pub fn options_mut(&mut self) -> &mut dyn Options {
        use RequestCommand as C;
        match self {
            C::ReadCoils(r) => r,
            C::ReadInputs(r) => r,
            C::ReadHolding(r) => r,
            C::ReadInputRegisters(r) => r,
            C::Read(r) => r,
            C::WriteCoil(r) => r,
            C::WriteCoils(r) => r,
            C::WriteRegister(r) => r,
            C::WriteRegisters(r) => r,
            C::Write(r) => r,
            C::ReadFile(r) => r,
            C::WriteFile(r) => r,
            C::MaskWrite(r) => r,
            C::ReadWrite(r) => r,
            C::ReadFifo(r) => r,
            C::Raw(r) => r,
        }
    }
}

/// What the words of a command mean, by the table it reads or writes.
pub trait Words: Clone + std::fmt::Debug + Send + Sync + 'static {
    const TABLE: Table;
    /// The first address, in `-h`.
    const ADDRESS: &'static str;
    /// The first address, in `--help`.
    const ADDRESS_LONG: &'static str;
    /// The first address of a write, in `--help`.
    const WRITE_ADDRESS_LONG: &'static str = Self::ADDRESS_LONG;
    /// How many to read.
    const COUNT: &'static str;
    /// The values to write.
    const VALUES: &'static str = "The values, each converted by --type";
}

/// The coils.
#[derive(Clone, Debug)]
pub struct Coils;

impl Words for Coils {
    const TABLE: Table = Table::Coils;
    const ADDRESS: &'static str = "First coil: 000020, 19, or a range 000020-000056";
    const ADDRESS_LONG: &'static str = "First coil: a reference (000020) or a number (19; \
        counted from 0, or from 1 with --address-base 1), or an inclusive range \
        (000020-000056)";
    const WRITE_ADDRESS_LONG: &'static str = "First coil: a reference (000020) or a number \
        (19; counted from 0, or from 1 with --address-base 1), or a range that holds exactly \
        the values given";
    const COUNT: &'static str = "How many coils to read [default: 1]";
    const VALUES: &'static str = "Each 0/1/on/off, or one bit string such as 10110";
}

/// The discrete inputs.
#[derive(Clone, Debug)]
pub struct DiscreteInputs;

impl Words for DiscreteInputs {
    const TABLE: Table = Table::DiscreteInputs;
    const ADDRESS: &'static str = "First discrete input: 100197, 196, or a range 100197-100218";
    const ADDRESS_LONG: &'static str = "First discrete input: a reference (100197) or a \
        number (196; counted from 0, or from 1 with --address-base 1), or an inclusive range \
        (100197-100218)";
    const COUNT: &'static str = "How many inputs to read [default: 1]";
}

/// The input registers.
#[derive(Clone, Debug)]
pub struct InputRegisters;

impl Words for InputRegisters {
    const TABLE: Table = Table::InputRegisters;
    const ADDRESS: &'static str =
        "First input register: 300009, 8, a range 300009-300011, or a bit 300009.00";
    const ADDRESS_LONG: &'static str = "First input register: a reference (300009), a number \
        (8; counted from 0, or from 1 with --address-base 1), an inclusive range \
        (300009-300011), or a bit of a register (300009.00), COUNT then counting bits";
    const COUNT: &'static str = HoldingRegisters::COUNT;
}

/// The holding registers.
#[derive(Clone, Debug)]
pub struct HoldingRegisters;

impl Words for HoldingRegisters {
    const TABLE: Table = Table::HoldingRegisters;
    const ADDRESS: &'static str =
        "First holding register: 400108, 107, a range 400108-400110, or a bit 400108.05";
    const ADDRESS_LONG: &'static str = "First holding register: a reference (400108), a \
        number (107, 0x6B; counted from 0, or from 1 with --address-base 1), an inclusive \
        range (400108-400110), or a bit of a register (400108.05), COUNT then counting bits";
    const WRITE_ADDRESS_LONG: &'static str = "First holding register: a reference (400002) \
        or a number (1; counted from 0, or from 1 with --address-base 1), or a range that \
        holds exactly the values given";
    const COUNT: &'static str = "How many registers to read [default: 1]; with --type wider \
        than 16 bits, how many values of that type";
}

#[derive(Clone, Debug, Args)]
pub struct ReadArgs<T: Words> {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    #[arg(index = 1)]
    pub slave: String,
    #[arg(index = 2, help = T::ADDRESS, long_help = T::ADDRESS_LONG)]
    pub address: String,
    #[arg(index = 3, help = T::COUNT)]
    pub count: Option<String>,
    #[arg(skip)]
    pub words: std::marker::PhantomData<T>,
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
pub struct WriteArgs<T: Words> {
    /// Slave address: 1-247, or 0 to broadcast
    #[arg(index = 1)]
    pub slave: String,
    #[arg(index = 2, help = T::ADDRESS, long_help = T::WRITE_ADDRESS_LONG)]
    pub address: String,
    #[arg(index = 3, help = T::VALUES, required = true, allow_negative_numbers = true)]
    pub values: Vec<String>,
    #[arg(skip)]
    pub words: std::marker::PhantomData<T>,
}

#[derive(Clone, Debug, Args)]
pub struct ReadByReferenceArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    ///
    /// With --map, left out where the map gives every point's slave (Home Assistant's
    /// entities are slave 1 where they give none)
    #[arg(required_unless_present = "map", value_name = "SLAVE")]
    pub slave: Option<String>,
    /// A reference whose first digit picks the table: 000020, 100197, 300009, 400108
    ///
    /// 1-based: 000020 coils, 100197 discrete inputs, 300009 input registers, 400108 holding
    /// registers; an inclusive range (400108-400110), or a bit of a register (400108.05),
    /// COUNT then counting bits; with --map, a point's name
    #[arg(required_unless_present = "map", value_name = "REFERENCE")]
    pub reference: Option<String>,
    /// How many values to read [default: 1]
    ///
    /// For registers with --type wider than 16 bits, values of that type; with --map, a
    /// point's name
    pub count: Option<String>,
    /// With --map: more points' names [default: every point of the map]
    #[arg(value_name = "NAME")]
    pub names: Vec<String>,
    /// The points of a register map (CSV, or Home Assistant YAML), by name
    #[arg(long, value_name = "FILE")]
    pub map: Option<std::path::PathBuf>,
}

#[derive(Clone, Debug, Args)]
pub struct WriteByReferenceArgs {
    /// Slave address: 1-247, or 0 to broadcast
    ///
    /// With --map, left out where the map gives every point's slave (Home Assistant's
    /// entities are slave 1 where they give none)
    pub slave: String,
    /// A coil (000020) or holding register (400001) reference, a range, or a bit (400001.03)
    ///
    /// 1-based; a range holds exactly the values given; a bit of a holding register is set
    /// alone with function 22; with --map, NAME=VALUE
    #[arg(required_unless_present = "map", value_name = "REFERENCE")]
    pub reference: Option<String>,
    /// The values: registers each converted by --type; coils 0/1/on/off, or 10110
    ///
    /// Coils each 0/1/on/off, or one bit string such as 10110; left out for a bit given its
    /// value in place (400108.05=1); with --map, more NAME=VALUE
    #[arg(allow_negative_numbers = true)]
    pub values: Vec<String>,
    /// Write points of a register map by name: NAME=VALUE, scale and offset taken back out
    #[arg(long, value_name = "FILE")]
    pub map: Option<std::path::PathBuf>,
    /// Force the function: 5 or 15 for coils, 6 or 16 for registers, 22 for a bit
    ///
    /// With 22, a bit of a register is set with function 22 alone: a device that does not
    /// know it answers exception 01, where without --function it is read (03) and written
    /// (06) instead
    #[arg(long, value_name = "CODE", value_parser = ["5", "6", "15", "16", "22"])]
    pub function: Option<String>,
}

#[derive(Clone, Debug, Args)]
pub struct RawArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// The PDU in hex, function code first (03 00 6B 00 03)
    #[arg(required = true, num_args = 1.., value_name = "PDU_HEX")]
    pub pdu: Vec<String>,
}

#[derive(Clone, Debug, Args)]
pub struct ReadFileArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// FILE:RECORD COUNT pairs: 4:1 2 reads records 1-2 of file 4
    ///
    /// Files are 1-65535, records 0-9999; COUNT counts values of --type. The groups go in one
    /// request, or in as many as the limits of one answer (245 bytes) need.
    #[arg(required = true, value_name = "FILE:RECORD COUNT")]
    pub groups: Vec<String>,
}

#[derive(Clone, Debug, Args)]
pub struct WriteFileArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// The file and first record: 4:7
    pub place: String,
    /// The values, each converted by --type
    #[arg(required = true, allow_negative_numbers = true)]
    pub values: Vec<String>,
}

#[derive(Clone, Debug, Args)]
pub struct MaskWriteArgs {
    /// Slave address: 1-247, or 0 to broadcast
    pub slave: String,
    /// A holding register (400005), or one of its bits set alone: 400108.05=1
    ///
    /// The register becomes (current AND the AND mask) OR (the OR mask AND NOT the AND mask),
    /// in the device, in one request. A bit is given as REF.BIT=VALUE or REF.BIT VALUE.
    #[arg(value_name = "REF")]
    pub reference: String,
    /// The AND mask, then the OR mask (0x00F2 0x0025); or a bit's value
    #[arg(value_name = "AND OR")]
    pub masks: Vec<String>,
}

#[derive(Clone, Debug, Args)]
pub struct ReadWriteArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// The first holding register to read: 400004
    #[arg(value_name = "READREF")]
    pub read: String,
    /// How many values of --type to read (at most 125 registers)
    pub count: String,
    /// The first holding register to write, before the read: 400015
    #[arg(value_name = "WRITEREF")]
    pub write: String,
    /// The values to write, each converted by --type (at most 121 registers)
    #[arg(required = true, allow_negative_numbers = true)]
    pub values: Vec<String>,
}

#[derive(Clone, Debug, Args)]
pub struct ReadFifoArgs {
    /// Slave address: 1-247 on serial lines, unit id 0-255 over TCP
    pub slave: String,
    /// The FIFO queue's pointer register: 401247
    #[arg(value_name = "REF")]
    pub reference: String,
}

// `read`: a reference (or a map's points), and the layouts of what it reads.
#[derive(Clone, Debug, Args)]
pub struct ReadReferenceArgs {
    #[command(flatten)]
    pub read: ReadByReferenceArgs,
    /// Show the registers read as every type and byte order
    ///
    /// u16 to f64 in each order (ABCD, CDAB, BADC, DCBA) from the first register, and the
    /// registers as text, bytes in order and swapped
    #[arg(long, conflicts_with_all = ["map", "expect"])]
    pub layouts: bool,
    /// The value the device holds (229.0, or a range 228..231): the layouts that give it
    ///
    /// Every type and order at every register read, nearest first, and a map line for
    /// the best to paste into a CSV map (name,ref,type,order)
    #[arg(
        long,
        value_name = "VALUE",
        conflicts_with = "map",
        allow_hyphen_values = true
    )]
    pub expect: Option<String>,
}
