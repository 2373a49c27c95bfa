//! TUI text that appears in more than one place. Number formatting lives in
//! `crate::view::format`, shared with the command line.

pub const APP: &str = "biodyn";
pub const TOO_SMALL: &str = "terminal too small";
pub const TABS: [&str; 4] = ["1 Model", "2 Responses", "3 Study", "4 Training"];
