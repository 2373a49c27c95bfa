//! A one-line text field: pre-filled, edited in place, committed or
//! cancelled by its owner. It keeps the last refusal so the user sees why.

/// What a committed field is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Purpose {
    /// A model parameter: the app parses and sets it (undoable).
    Param(biodyn::Param),
    /// Where to save the preset.
    SavePath,
    /// The open dialog's path.
    OpenPath,
    /// Something the tab that opened the field handles; the tag is the
    /// tab's own (a settings row, "save network", …).
    Tab(usize),
}

#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub purpose: Purpose,
    pub label: String,
    pub text: String,
    /// The pre-filled text: committing it unchanged changes nothing.
    pub initial: String,
    /// Cursor position in chars.
    pub cursor: usize,
    /// Why the last commit was refused.
    pub error: Option<String>,
}

impl Field {
    pub fn new(purpose: Purpose, label: impl Into<String>, text: impl Into<String>) -> Field {
        let text = text.into();
        Field {
            purpose,
            label: label.into(),
            cursor: text.chars().count(),
            initial: text.clone(),
            text,
            error: None,
        }
    }

    fn byte(&self, char_idx: usize) -> usize {
        self.text
            .char_indices()
            .nth(char_idx)
            .map_or(self.text.len(), |(i, _)| i)
    }

    pub fn insert(&mut self, c: char) {
        let at = self.byte(self.cursor);
        self.text.insert(at, c);
        self.cursor += 1;
        self.error = None;
    }

    pub fn backspace(&mut self) {
        if self.cursor > 0 {
            self.cursor -= 1;
            let at = self.byte(self.cursor);
            self.text.remove(at);
            self.error = None;
        }
    }

    pub fn delete(&mut self) {
        if self.cursor < self.text.chars().count() {
            let at = self.byte(self.cursor);
            self.text.remove(at);
            self.error = None;
        }
    }

    pub fn left(&mut self) {
        self.cursor = self.cursor.saturating_sub(1);
    }

    pub fn right(&mut self) {
        self.cursor = (self.cursor + 1).min(self.text.chars().count());
    }

    pub fn home(&mut self) {
        self.cursor = 0;
    }

    pub fn end(&mut self) {
        self.cursor = self.text.chars().count();
    }

    pub fn set_text(&mut self, t: impl Into<String>) {
        self.text = t.into();
        self.end();
        self.error = None;
    }
}

#[cfg(test)]
mod tests {
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
}
