//! sph-eos integration tests: verification.md §8 point values and Hugoniot, derivative and
//! thermodynamic-consistency checks, temperature model.

// Reference values are pasted with all the digits the 40-digit reference printed.
#![allow(clippy::excessive_precision)]

mod common;
mod hugoniot;
mod other_eos;
mod thermal;
mod tillotson;
