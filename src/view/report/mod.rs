//! Report writers, one per format, shared by every command and (for export)
//! by the TUI. A command builds its result, wraps it in a `Report`, and the
//! output layer renders it in the format asked for: the table for eyes, CSV
//! and JSON with every number in shortest round-trip form.

pub mod assess;
pub mod axes;
pub mod axes_only;
pub mod csv;
pub mod day;
pub mod html;
pub mod input;
pub mod json;
pub mod meta;
pub mod pan;
pub mod plot;
pub mod points;
pub mod seat;
pub mod seat_design;
pub mod spine;
pub mod study;
pub mod table;

/// The output formats of every command.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Format {
    /// Aligned columns, rounded for reading.
    #[default]
    Table,
    /// Comma-separated, every number in shortest round-trip form.
    Csv,
    /// JSON, every number in shortest round-trip form.
    Json,
}

impl Format {
    pub fn key(self) -> &'static str {
        match self {
            Format::Table => "table",
            Format::Csv => "csv",
            Format::Json => "json",
        }
    }
}

/// A command's result in every format it offers.
pub trait Report {
    /// Aligned text for eyes.
    fn table(&self) -> String;
    /// Comma-separated rows; `None` when the result is not a grid.
    fn csv(&self) -> Option<String> {
        None
    }
    /// A JSON document (pretty, ending in a newline).
    fn json(&self) -> Result<String, serde_json::Error>;
}

/// `text` for a terminal: every line's control characters (a file or
/// operation name that clears the screen or sets the window title) escaped
/// by the one quoting helper, as errors are (`\u{1b}`); the line breaks
/// kept. JSON escapes them itself; CSV cells are quoted.
pub fn terminal_safe(text: &str) -> String {
    text.split('\n')
        .map(|l| biodyn::io::excerpt(l, usize::MAX))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The report in `format`.
pub fn render(report: &dyn Report, format: Format) -> anyhow::Result<String> {
    Ok(match format {
        Format::Table => terminal_safe(&report.table()),
        Format::Csv => report.csv().ok_or_else(|| {
            anyhow::anyhow!("this command has no csv output; use --format table or json")
        })?,
        Format::Json => report.json()?,
    })
}
