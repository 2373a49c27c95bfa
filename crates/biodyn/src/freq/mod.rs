//! The frequency domain: bands, the response functions (STHT, DPMI, APMS),
//! modes, peaks and parametric studies.

pub(crate) mod banded;
pub(crate) mod chain;
pub mod function;
pub mod modes;
pub mod peaks;
pub mod response;
pub mod study;
pub(crate) mod topology;
pub(crate) mod tree;
