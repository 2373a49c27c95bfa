//! Fitting a body model to measured APMS, DPMI or STHT (SPEC §8).
//!
//! Residuals are r = ln|H_model| − ln|H_data| and, where a phase is given,
//! the wrapped phase difference in radians, each divided by its σ when the
//! data carry `_sd` columns. Free parameters are fitted as ln p inside a box;
//! Levenberg–Marquardt runs from the start model and from seeded points
//! around it, and the best run is reported with 95 % intervals: by default
//! profile-likelihood ones (the cost minimised over the other parameters
//! within F(0.95; 1, m − p)·s² of the best), or from the curvature alone.
//!
//! ```
//! use biodyn::Body;
//! use biodyn::fit::{Free, Measured, Settings, fit, free_params};
//!
//! let body = Body::paper(75.0).unwrap();
//! let data = Measured::parse("f_hz,apms_mag\n1,58\n3,70\n5,60\n8,30\n12,20\n", "d.csv").unwrap();
//! let free = free_params(&body, &[Free::Link(3)], &[]).unwrap(); // k4 and c4
//! let result = fit(&body, &data, &free, Settings::default()).unwrap();
//! assert_eq!(result.params.len(), 2);
//! ```

mod data;
mod error;
mod free;
mod interval;
mod lm;
mod profile;
mod quantile;
mod report;
mod residual;
mod run;
mod settings;

pub use data::{Channel, Column, Measured, Quantity};
pub use error::{DataError, FitError, KNOWN};
pub use free::{Bound, Free, FreeParam, free_params, name_of, resolve};
pub use interval::LEVEL;
pub use quantile::student_t;
pub use report::{ColumnRms, Fit, ParamFit, PeakPair};
pub use residual::MAX_SEGMENTS;
pub use run::{Progress, fit, fit_with};
pub use settings::{Intervals, MAX_STARTS, Settings};
