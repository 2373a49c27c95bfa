//! The mouse on the Model tab in a real terminal (tmux): the real binary
//! reads SGR mouse reports (what xterm, tmux and most terminals send with
//! capture on) for a click, a double click and the wheel, and edits a
//! value as Enter would. Skipped when tmux is not installed.

use crate::common::tmux::{start, wait_rc};

#[test]
fn a_double_click_on_a_model_cell_edits_it_in_a_real_terminal() {
    let dir = tempfile::tempdir().expect("tempdir");
    let rc = dir.path().join("rc");
    let Some(t) = start("mouse-tables", "", &rc) else {
        crate::common::skip("tmux not available");
        return;
    };
    t.wait_for("head-neck");
    // Capture off: a click is the terminal's, the app does nothing. The
    // terminal delivers input in order, so once the `M` sent after the
    // double click has taken effect the click has been read too (had it
    // opened k4's field, the `M` would have gone into the field instead).
    let k4 = t.find("pelvis-seat", "90000");
    t.click((k4.0 + 2, k4.1), 2);
    t.keys(&["M"]);
    let s = t.wait_for("M mouse on");
    assert!(!s.contains("(type to replace"), "{s}");

    // A click on m2's mass selects it: Enter then edits m2.
    let m2 = t.find("m2 chest", "30.15");
    t.click((m2.0 + 1, m2.1), 1);
    t.keys(&["Enter"]);
    t.wait_for("30.15 (type to replace");
    t.keys(&["Escape"]);
    t.wait_for("cancelled");

    // The wheel over the table moves the selection a row: m3.
    t.wheel_down(m2);
    t.keys(&["Enter"]);
    t.wait_for("9.15 (type to replace");
    t.keys(&["Escape"]);
    t.wait_for("cancelled");

    // A double click on k4 opens its field, as Enter; typing replaces it.
    t.click((k4.0 + 2, k4.1), 2);
    t.wait_for("90000 (type to replace");
    t.raw("95000");
    t.keys(&["Enter"]);
    // 80 columns keep the full tab names: the mark is "*" there.
    let s = t.wait_for("paper-75kg *");
    assert!(t.find("pelvis-seat", "95000") == k4, "{s}");
    // The change is one undo step.
    t.keys(&["u"]);
    t.wait_for("undid");
    assert_eq!(t.find("pelvis-seat", "90000"), k4);

    t.keys(&["q"]);
    assert_eq!(wait_rc(&rc), "rc=0");
}
