//! Field tags of this tab's text fields, one list: the tab opens the data,
//! go-to and compare fields, the fit dialog's keys (`fit_keys.rs`) the
//! starts and seed fields. Its own file, so `fit_keys.rs` takes them from
//! a sibling, not from the `mod.rs` that uses it.

pub const TAG_DATA: usize = 0;
pub const TAG_STARTS: usize = 1;
pub const TAG_SEED: usize = 2;
pub const TAG_GOTO: usize = 3;
pub const TAG_COMPARE: usize = 4;
