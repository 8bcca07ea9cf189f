//! SunSpec: the register maps of inverters, meters and batteries that follow the SunSpec
//! Alliance's models. A device is found by its `SunS` marker, its chain of models walked,
//! and each model laid out by the definition the Alliance publishes (`models/`, their
//! JSON as they publish it), names, units and scale factors applied.

pub mod defs;
pub mod points;
pub mod walk;

use thiserror::Error;

use crate::master::run::RunError;

/// Why a device's SunSpec map could not be read.
#[derive(Debug, Error)]
pub enum SunSpecError {
    /// None of the bases holds the marker; what each gave.
    #[error("no SunSpec map: {}", tried_text(.tried))]
    NotFound {
        /// Each base tried (a protocol address) and what was there.
        tried: Vec<(u16, String)>,
    },
    /// A read failed in a way that ends the scan (no answer, the port gone).
    #[error(transparent)]
    Run(RunError),
}

fn tried_text(tried: &[(u16, String)]) -> String {
    tried
        .iter()
        .map(|(base, said)| format!("register {base}: {said}"))
        .collect::<Vec<_>>()
        .join(", ")
}
