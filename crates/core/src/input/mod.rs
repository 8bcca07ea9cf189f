//! What users type and paste, read: numbers in any spelling, durations, frames pasted from
//! a log or a datasheet, hex dumps, and settings picked by name.

pub mod choice;
pub mod duration;
pub mod hexdump;
pub mod hexinput;
pub mod hosts;
pub mod number;
