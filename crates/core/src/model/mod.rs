//! The model: Modicon references and protocol addresses, value types and byte orders, and
//! the spellings of what users type (numbers, durations, pasted frames, named settings).

pub mod address;
pub mod choice;
pub mod duration;
pub mod faults;
pub mod hexdump;
pub mod hexinput;
pub mod home_assistant;
pub mod line;
pub mod map;
pub mod map_file;
pub mod number;
pub mod shown;
pub mod spread;
pub mod structure;
pub mod values;
