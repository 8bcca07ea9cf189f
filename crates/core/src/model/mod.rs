//! The model: Modicon references and protocol addresses, value types and byte orders, a
//! serial line's settings, register maps and the files they come in. What users type is
//! read in `input`.

pub mod address;
pub mod faults;
pub mod home_assistant;
pub mod layouts;
pub mod line;
pub mod map;
pub mod map_file;
pub mod map_writer;
pub mod plant;
pub mod shown;
pub mod spread;
pub mod structure;
pub mod values;
