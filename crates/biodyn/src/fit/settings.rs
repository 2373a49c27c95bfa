//! What a fit is asked for besides the model, data and free parameters; its
//! own file so the run and the report both read it without importing each
//! other.

/// Most starts a fit takes.
pub const MAX_STARTS: usize = 1000;

/// Settings of a fit besides the model, data and free parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    pub starts: usize,
    pub seed: u64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings { starts: 8, seed: 1 }
    }
}
