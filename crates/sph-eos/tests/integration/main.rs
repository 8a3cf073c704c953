//! sph-eos integration tests: the point values and Hugoniot of docs/reference/tillotson.md,
//! derivative and thermodynamic-consistency checks, temperature model.

// Reference values are pasted with all the digits the 40-digit reference printed.
#![allow(clippy::excessive_precision)]

mod common;
mod hugoniot;
mod other_eos;
mod thermal;
mod tillotson;
