//! Trend sentences of a study, for both fronts.

use biodyn::freq::study::Trend;

/// One sentence per function: peak magnitude, peak frequency, share of band.
pub fn sentence(t: &Trend) -> String {
    format!(
        "{}: peak magnitude {}, peak frequency {}; the magnitude rises at every step over {:.0} % of the band and falls over {:.0} %",
        t.function.name(),
        t.peak_mag.word(),
        t.peak_f.word(),
        100.0 * t.rises_share,
        100.0 * t.falls_share
    )
}
