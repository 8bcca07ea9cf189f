//! `poll`: a plant's devices kept read.

use clap::Args;

use super::options::{left_out::*, more_in_long_help};
use super::options::{ExchangeArgs, FormatArgs, FormatOrFile, RetriesArgs, SplitArgs, TraceArgs};
use super::taken::holds;

pub(super) const PLANT_ABOUT: &str = "\
Keep every device a plant file describes read, each at its own rate, until Ctrl-C or \
SIGTERM (or for --for DURATION), and end with a summary per device on stderr.

A plant file lists its devices under devices:, each with a name, a port (any --port \
form: tcp://10.0.0.5, /dev/ttyUSB0 with baud, parity, data_bits and stop_bits, \
rtu+tcp://HOST:PORT, sim), a slave, a map (a CSV or Home Assistant register map, beside \
the plant file) and every (1s, 500ms):

  devices:
    - name: meter1
      port: tcp://10.0.0.5
      slave: 1
      map: meter.csv
      every: 1s

A device's points may be given in the plant itself, under points: instead of map:, each \
point's keys the columns of a CSV map (name, ref, type, unit, access, ...). A plant file \
named .toml is read as TOML, each device a [[devices]] table.

A Home Assistant modbus configuration is a plant file as it stands: each hub a device per \
slave, read at its entities' scan_interval (15 s where not given), named after the hub \
(meter, meter/2, meter/2/5s where a slave's entities have several rates).

Every fault of the files is told at once, and nothing is polled until they are all good. \
Each TCP address is polled on a connection of its own, all at once; the devices behind one \
address (unit ids of a gateway), on one serial line or one rtu+tcp:// server are polled in \
turn by one worker, at the line's pace, each device's points read as read --map groups \
them. A device that does not answer \
is asked less often (twice its rate after three failures in a row, doubling up to a \
minute), and never holds back another device's values; a poll that reads nothing is a \
row without values, never the last values again.

Each device's poll is a row: a line of name=value on a terminal; -o csv a header of \
time,device, then a column for every point name of the plant, then error; -o json one \
object a row with time, device, values and errors; -o influx InfluxDB line protocol \
(measurement modbus, tags device and slave, a field a point, the time in nanoseconds), \
for Telegraf's execd and exec inputs.

Beside them, --influx writes the rows to InfluxDB, --mqtt publishes each value to an MQTT \
broker (and takes writes from its .../set topics), and --metrics serves them to \
Prometheus; a server that is down never holds back the polling.";

#[derive(Clone, Debug, Args)]
#[command(after_help = more_in_long_help(&[&[CONNECTION, ADDRESSES, MQTT]]))]
#[command(mut_arg("output", |arg| arg.value_parser(FormatOrFile { plant: true })))]
pub struct PlantArgs {
    /// Plant files (or Home Assistant configurations): devices, each a port, a slave, a map and a rate
    #[arg(required = true, value_name = "FILE")]
    pub files: Vec<std::path::PathBuf>,

    /// Also write every row to InfluxDB: http://HOST:8086/write?db=NAME (1.x) or
    /// http://HOST:8086/api/v2/write?org=ORG&bucket=BUCKET (2.x)
    ///
    /// In batches; a server that is down gets the rows kept for it (--buffer) when it is
    /// back. The token (2.x's, or USER:PASSWORD for 1.x) is read from INFLUX_TOKEN
    #[arg(long, value_name = "URL")]
    pub influx: Option<String>,

    /// Also publish every value to an MQTT broker: mqtt://HOST[:PORT] or mqtts://HOST[:PORT]
    ///
    /// Each value to PREFIX/DEVICE/POINT as text; PREFIX/DEVICE/available says online or
    /// offline as the device answers or not, PREFIX/status whether mbtool runs. A value
    /// published to PREFIX/DEVICE/POINT/set is written to the device, once checked
    /// against the map (writable, type, range); a retained one is not (a command left on
    /// the broker is not one given now)
    #[arg(long, value_name = "URL")]
    pub mqtt: Option<String>,

    /// The first level of the MQTT topics
    #[arg(
        long,
        value_name = "PREFIX",
        default_value = "mbtool",
        requires = "mqtt",
        help_heading = MQTT, hide_short_help = true
    )]
    pub mqtt_prefix: String,

    /// Publish the values retained, so that a new subscriber has the last at once
    #[arg(long, requires = "mqtt", help_heading = MQTT, hide_short_help = true)]
    pub mqtt_retain: bool,

    /// Announce every point to Home Assistant (MQTT discovery), under PREFIX
    #[arg(long, value_name = "PREFIX", num_args = 0..=1, default_missing_value = "homeassistant", requires = "mqtt", help_heading = MQTT, hide_short_help = true)]
    pub mqtt_discovery: Option<String>,

    /// The broker's user; the password is read from MBTOOL_MQTT_PASSWORD
    #[arg(
        long,
        value_name = "USER",
        env = "MBTOOL_MQTT_USER",
        requires = "mqtt",
        help_heading = MQTT, hide_short_help = true
    )]
    pub mqtt_user: Option<String>,

    /// The CA certificates (PEM) that sign an mqtts:// broker's certificate [default: the system's]
    #[arg(long, value_name = "FILE", requires = "mqtt", help_heading = MQTT, hide_short_help = true)]
    pub mqtt_ca: Option<std::path::PathBuf>,

    /// Rows kept for a server that is down; past it the oldest give way, counted
    #[arg(long, value_name = "N", default_value_t = 10_000, value_parser = clap::value_parser!(u32).range(1..))]
    pub buffer: u32,

    /// Serve Prometheus metrics on http://ADDR/metrics: values, polls, errors, response times
    #[arg(long, value_name = "ADDR")]
    pub metrics: Option<String>,

    /// Also append every row to FILE: CSV for a .csv name (the columns of -o csv), JSON Lines else
    ///
    /// Given again, to several files. A file that cannot be written (a full disk) is told
    /// once; its rows are not saved until it can be, and the polling goes on
    #[arg(long, value_name = "FILE")]
    pub log: Vec<std::path::PathBuf>,

    /// Stop after DURATION [default: until Ctrl-C or SIGTERM]
    #[arg(long = "for", value_name = "DURATION", value_parser = mbtool_core::input::duration::parse_duration)]
    pub duration: Option<std::time::Duration>,

    #[command(flatten)]
    pub exchange: ExchangeArgs,
    #[command(flatten)]
    pub retries: RetriesArgs,
    #[command(flatten)]
    pub split: SplitArgs,
    #[command(flatten)]
    pub trace: TraceArgs,
    #[command(flatten)]
    pub format: FormatArgs,
}

holds!(PlantArgs: exchange, retries, split, trace, format);
