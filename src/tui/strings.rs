//! TUI text that appears in more than one place. Number formatting lives in
//! `crate::view::format`, shared with the command line; tab names live with
//! their tabs (`Tab::title`).

pub const APP: &str = "biodyn";
pub const TOO_SMALL: &str = "terminal too small";
