//! The options a command took, gathered from its arguments' groups for `settings` to
//! resolve, and the values typed before the command's name handed to the groups that
//! take them. A command that does not take a group leaves it `None`, and its settings are
//! the defaults.

use std::path::Path;
use std::time::Duration;

use super::options::{
    AddressArgs, EncodeOptions, EndpointArgs, EveryOption, ExchangeArgs, FormatArgs, LineArgs,
    MasterArgs, ModeArg, PollArgs, RedundancyArgs, RegisterArgs, RepeatArgs, RetriesArgs,
    Rs485Args, SerialLineArgs, SplitArgs, TlsArgs, TraceArgs,
};

/// The option groups of the command given; a group it does not take is `None`.
#[derive(Debug, Default)]
pub struct Taken<'a> {
    pub endpoint: Option<&'a EndpointArgs>,
    pub serial: Option<&'a SerialLineArgs>,
    pub rs485: Option<&'a Rs485Args>,
    pub exchange: Option<&'a ExchangeArgs>,
    pub retries: Option<&'a RetriesArgs>,
    pub repeat: Option<&'a RepeatArgs>,
    pub trace: Option<&'a TraceArgs>,
    pub tls: Option<&'a TlsArgs>,
    pub format: Option<&'a FormatArgs>,
    pub addresses: Option<&'a AddressArgs>,
    pub split: Option<&'a SplitArgs>,
    pub registers: Option<&'a RegisterArgs>,
    pub redundancy: Option<&'a RedundancyArgs>,
    pub polling: Option<&'a PollArgs>,
    /// `--port`.
    pub port: Option<&'a str>,
    /// `--mode` (decode's own, or the endpoint's).
    pub mode: Option<ModeArg>,
    /// `--poll`: the interval of a repeated read (watch's own, or the poll group's).
    pub poll: Option<Duration>,
    /// `--count`: how many polls, or diag's round trips.
    pub count: Option<u64>,
    /// `--log`: the file every row or transaction is appended to.
    pub log: Option<&'a Path>,
    /// dump's `--output`: the file it writes.
    pub file: Option<&'a str>,
}

/// The values typed before the command's name, at each level (`mbtool --port sim
/// encode --mode tcp read-holding ...`), and which option each level gave.
pub struct Before<'a> {
    /// Each level's groups, and the ids typed there and not after; the nearer the
    /// command, the later.
    pub levels: Vec<(Taken<'a>, Vec<String>)>,
}

impl<'a> Before<'a> {
    /// The group of the nearest level that typed `id`, as `slot` picks it from a level.
    fn typed<G>(&self, id: &str, slot: impl Fn(&Taken<'a>) -> Option<&'a G>) -> Option<&'a G> {
        self.levels
            .iter()
            .rev()
            .filter(|(_, ids)| ids.iter().any(|typed| typed == id))
            .find_map(|(taken, _)| slot(taken))
    }
}

/// A command's arguments, or a group of options: handing over the groups it holds, and
/// taking the values typed for them before the command's name.
pub trait Options {
    fn gather<'a>(&'a self, taken: &mut Taken<'a>);
    fn take_before(&mut self, before: &Before);
}

/// [`Options`] for a group that is one slot of [`Taken`]: each field named takes the value
/// typed before the command (its id is its name).
macro_rules! group {
    ($($group:ty => $slot:ident: $($field:ident),+;)*) => {$(
        impl Options for $group {
            fn gather<'a>(&'a self, taken: &mut Taken<'a>) {
                taken.$slot = Some(self);
            }

            fn take_before(&mut self, before: &Before) {
                $(
                    if let Some(group) = before.typed(stringify!($field), |t| t.$slot) {
                        self.$field = group.$field.clone();
                    }
                )+
            }
        }
    )*};
}

/// [`Options`] for arguments that hold groups: each field named hands over its own.
macro_rules! holds {
    ($type:ty: $($field:ident),* $(,)?) => {
        impl $crate::cli::Options for $type {
            fn gather<'a>(&'a self, taken: &mut $crate::cli::Taken<'a>) {
                $(self.$field.gather(taken);)*
            }

            fn take_before(&mut self, before: &$crate::cli::Before) {
                $(self.$field.take_before(before);)*
            }
        }
    };
}
pub(crate) use holds;

/// The id clap gives the option held in `field` of the group `$group`: the field's name,
/// which must be one of the group's fields for the code to compile.
macro_rules! arg_id {
    ($group:ty, $field:ident) => {{
        let _field_of = |group: &$group| -> *const () { std::ptr::addr_of!(group.$field).cast() };
        stringify!($field)
    }};
}
pub(crate) use arg_id;

group! {
    SerialLineArgs => serial: baud, parity, data_bits, stop_bits;
    Rs485Args => rs485: rs485, rs485_delay_before, rs485_delay_after, rts_level, rts_toggle;
    ExchangeArgs => exchange: timeout, frame_gap;
    RetriesArgs => retries: retries;
    RepeatArgs => repeat: retry_non_idempotent;
    TraceArgs => trace: verbose;
    TlsArgs => tls: cert, key, ca, tls_server_name;
    FormatArgs => format: output, json;
    AddressArgs => addresses: pdu_addresses, address_base;
    SplitArgs => split: max_per_request;
    RegisterArgs => registers: value_type, order;
    RedundancyArgs => redundancy: secondary_port, secondary_baud, secondary_parity,
        secondary_data_bits, secondary_stop_bits, secondary_mode, switch_on, switch_when;
}

holds!(LineArgs: endpoint, serial, rs485);
holds!(MasterArgs: line, exchange, retries, trace, tls);
holds!(EveryOption: master, repeat, format, addresses, split, registers, poll, redundancy);
holds!(EncodeOptions: endpoint, format, addresses, split, registers, repeat);

impl Options for EndpointArgs {
    fn gather<'a>(&'a self, taken: &mut Taken<'a>) {
        taken.endpoint = Some(self);
        taken.port = self.port.as_deref();
        taken.mode = self.mode;
    }

    fn take_before(&mut self, before: &Before) {
        if let Some(endpoint) = before.typed(arg_id!(EndpointArgs, port), |t| t.endpoint) {
            self.port.clone_from(&endpoint.port);
        }
        if let Some(mode) = before.mode() {
            self.mode = Some(mode);
        }
    }
}

impl Options for PollArgs {
    fn gather<'a>(&'a self, taken: &mut Taken<'a>) {
        taken.polling = Some(self);
        taken.poll = self.poll;
        taken.count = self.poll_count;
        taken.log = self.log.as_deref();
    }

    fn take_before(&mut self, before: &Before) {
        if let Some(poll) = before.poll() {
            self.poll = Some(poll);
        }
        if let Some(count) = before.count() {
            self.poll_count = Some(count);
        }
        if let Some(log) = before.log() {
            self.log = Some(log.to_path_buf());
        }
    }
}

/// The options that commands also define as their own (watch's `--poll`, diag's
/// `--count`, dump's `--output`), typed before the command's name.
impl Before<'_> {
    pub fn mode(&self) -> Option<ModeArg> {
        self.typed(arg_id!(EndpointArgs, mode), |t| t.endpoint)
            .and_then(|e| e.mode)
    }

    pub fn poll(&self) -> Option<Duration> {
        self.typed(arg_id!(PollArgs, poll), |t| t.polling)
            .and_then(|p| p.poll)
    }

    pub fn count(&self) -> Option<u64> {
        self.typed(arg_id!(PollArgs, poll_count), |t| t.polling)
            .and_then(|p| p.poll_count)
    }

    pub fn log(&self) -> Option<&Path> {
        self.typed(arg_id!(PollArgs, log), |t| t.polling)
            .and_then(|p| p.log.as_deref())
    }

    pub fn output(&self) -> Option<&str> {
        self.typed(arg_id!(FormatArgs, output), |t| t.format)
            .and_then(|f| f.output.as_deref())
    }
}
