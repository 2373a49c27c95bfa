//! Tab 4, Training. Waits for the `biodyn::ann` worker API (branch `ann`);
//! until it lands, the tab says so and every other tab works.

use super::app::App;
use super::keys::Action;
use ratatui::buffer::Buffer;
use ratatui::layout::Rect;
use ratatui::text::Line;
use ratatui::widgets::{Block, Paragraph, Widget, Wrap};

/// A report from the training worker.
#[derive(Debug)]
pub enum TrainMsg {}

#[derive(Debug, Default)]
pub struct TrainingTab {}

impl TrainingTab {
    pub fn running(&self) -> bool {
        false
    }

    /// One line for the status bar while a run is live.
    pub fn summary(&self) -> Option<String> {
        None
    }
}

pub fn on_msg(_app: &mut App, m: TrainMsg) {
    match m {}
}

/// Cancels a running training (on quit).
pub fn stop(_app: &mut App) {}

pub fn on_action(app: &mut App, _a: Action) {
    app.status.text = "training needs the network module, not in this build yet".into();
    app.status.error = true;
}

pub fn commit_setting(_app: &mut App, _row: usize, _text: &str) -> Result<(), String> {
    Err("no training settings in this build".into())
}

pub fn save_net(_app: &mut App, _path: &str) -> Result<(), String> {
    Err("no trained network to save".into())
}

pub fn render(app: &App, area: Rect, buf: &mut Buffer) {
    let th = app.theme;
    Paragraph::new(vec![
        Line::styled("Training", th.heading()),
        Line::raw("The six networks of SPEC §4 train here once the network module is merged."),
    ])
    .wrap(Wrap { trim: true })
    .block(Block::bordered().border_set(th.border_set()))
    .render(area, buf);
}
