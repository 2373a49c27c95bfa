//! The frequency domain: the response functions, modes, peaks and
//! parametric studies.
//!
//! Under harmonic seat motion x0 = X0 e^{jωt} every segment moves as
//! H_i(ω) X0, where A(ω) H = b_k + jω b_c and A(ω) = K − ω²M + jωC
//! ([`Solver`](crate::Solver)). From H come the seat-to-head transmissibility
//! STHT = H_head, the apparent mass APMS = Σ m_i H_i and the driving-point
//! mechanical impedance DPMI = APMS·jω ([`Function`](crate::Function),
//! [`Response`](crate::Response)).
//!
//! - [`analyse_modes`], [`Modes`]: natural frequencies and damping ratios
//!   from the eigenvalues of the 2n×2n state matrix.
//! - [`find_peaks`], [`find_peaks_in`], [`main_peak`]: resonance peaks of a
//!   sweep, refined off the grid by golden-section search.
//! - [`run_study`], [`Study`], [`parse_steps`]: one parameter varied, the three
//!   functions' peaks and their [`Trend`]s.

mod banded;
mod chain;
pub(crate) mod function;
mod modes;
pub(crate) mod peaks;
pub(crate) mod response;
mod study;
mod topology;
mod tree;

pub use function::phase_deg;
pub use modes::{MODES_MAX, Mode, ModeKind, Modes, ModesError, UndampedMode, analyse_modes};
pub use peaks::{Peak, find_peaks, find_peaks_in, main_peak};
pub use response::SWEEP_BLOCK;
pub use study::{
    Direction, Step, Study, StudyError, Trend, Variant, check_study_size, paper_steps, parse_steps,
    round_sig, run_study, run_study_with,
};
