//! What a fit is asked for besides the model, data and free parameters; its
//! own file so the run and the report both read it without importing each
//! other.

/// Most starts a fit takes.
pub const MAX_STARTS: usize = 1000;

/// How the 95 % intervals are found.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Intervals {
    /// Profile likelihood: where the cost, minimised over the other free
    /// parameters, stays within F(0.95; 1, m − p)·s² of the best, taking in
    /// every other minimum the starts found within it.
    #[default]
    Profile,
    /// From the curvature at the best minimum alone (linearised, with
    /// Student's t): quick, and too narrow where the cost is not quadratic.
    Curvature,
}

impl Intervals {
    /// The name in reports and options: "profile" or "curvature".
    pub fn key(self) -> &'static str {
        match self {
            Intervals::Profile => "profile",
            Intervals::Curvature => "curvature",
        }
    }
}

/// Settings of a fit besides the model, data and free parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    pub starts: usize,
    pub seed: u64,
    pub intervals: Intervals,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            starts: 8,
            seed: 1,
            intervals: Intervals::Profile,
        }
    }
}
