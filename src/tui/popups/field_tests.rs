//! The text field's editing: multibyte text, typing over the selected
//! value, the shell's keys.

use super::*;

#[test]
fn edits_at_the_cursor_with_multibyte_text() {
    let mut f = Field::new(Purpose::SavePath, "path", "ab·c");
    f.left();
    f.backspace();
    assert_eq!(f.text, "abc");
    f.home();
    f.insert('x');
    f.delete();
    assert_eq!(f.text, "xbc");
    assert_eq!(f.cursor, 1);
}

#[test]
fn typing_first_replaces_the_prefilled_value() {
    let mut f = Field::new(Purpose::SavePath, "m2", "30.15");
    f.insert_str("35");
    assert_eq!(f.text, "35");
    let mut f = Field::new(Purpose::SavePath, "m2", "30.15");
    f.end();
    f.insert('7');
    assert_eq!(f.text, "30.157");
    let mut f = Field::new(Purpose::SavePath, "m2", "30.15");
    f.backspace();
    assert_eq!(f.text, "");
}

#[test]
fn shell_keys() {
    let mut f = Field::new(Purpose::SavePath, "p", "presets/my-body.toml");
    f.end();
    f.kill_word_part();
    assert_eq!(f.text, "presets/my-body.");
    f.kill_word_part();
    assert_eq!(f.text, "presets/my-");
    f.insert_str("x y");
    f.kill_word();
    assert_eq!(f.text, "presets/my-x ");
    f.kill_word();
    assert_eq!(f.text, "");
    let mut f = Field::new(Purpose::SavePath, "p", "abcdef");
    f.end();
    f.left();
    f.left();
    f.kill_to_start();
    assert_eq!((f.text.as_str(), f.cursor), ("ef", 0));
    f.right();
    f.kill_to_end();
    assert_eq!(f.text, "e");
}
