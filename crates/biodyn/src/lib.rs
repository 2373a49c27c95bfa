//! biodyn: biodynamics of the seated human body under vertical whole-body
//! vibration. The library holds the physics and the networks; it has no
//! terminal code and prints nothing. The `biodyn` binary's TUI and CLI are
//! thin front ends over it.
//!
//! ```
//! use biodyn::{Band, Body, Function, Solver};
//!
//! // The paper's Boileau & Rakheja chain for a 75 kg body.
//! let body = Body::paper(75.0).unwrap();
//! let solver = Solver::new(&body);
//! let r = solver.at(4.5);
//! assert!(r.mag(Function::Stht) > 1.5); // the head moves more than the seat near 4.5 Hz
//! // APMS tends to the seated mass (78.1 % of body mass) at low frequency.
//! let low = solver.at(0.01).mag(Function::Apms);
//! assert!((low - 0.781 * 75.0).abs() < 0.01);
//! let curve = solver.sweep(&Band::default()); // 0.5–20 Hz at 0.1 Hz
//! assert_eq!(curve.len(), 196);
//! ```

pub mod ann;
mod band;
pub mod body;
mod clock;
pub mod exposure;
pub mod fit;
pub mod freq;
pub mod io;
pub mod iso2631;
mod linalg;
mod lm;
mod rng;
pub mod seat;
mod simd;
pub mod time;

pub use band::{Band, BandError, check_freq};
pub use body::model::{Body, End, Link, Param, Seat, Segment};
pub use body::preset::Preset;
pub use clock::{Clock, ManualClock};
pub use freq::function::{Function, Response};
pub use freq::response::Solver;
pub use rng::Rng;
