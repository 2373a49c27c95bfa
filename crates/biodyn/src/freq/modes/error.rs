//! Why a modal analysis is refused, with the frequency written so that a
//! mode near 1e-7 Hz and one near 1 kHz both read right.

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModesError {
    #[error(
        "the eigenvalue solver did not converge for this model: check for extreme parameter ratios"
    )]
    NoConvergence,
    #[error(
        "modes of a {segments}-segment model are not computed: the state-matrix eigenvalue solve grows as n³ (limit {max} segments, several seconds there); responses and peaks work at any size"
    )]
    TooBig { segments: usize, max: usize },
    #[error(
        "mode near {} Hz cannot be trusted (relative residual {residual:.1e}, limit {limit:.0e}): the model's masses and stiffnesses span too many orders of magnitude for the eigenvalue solve; bring the extreme values closer (e.g. a rigid joint is well modelled by 1e9 N/m)",
        hz_text(*.hz)
    )]
    Untrusted { hz: f64, residual: f64, limit: f64 },
    #[error(
        "mode near {} Hz cannot be trusted: the state matrix puts it at {} Hz, the pencil K + λC + λ²M at {} Hz (relative gap {drift:.1e}, more than its neighbours allow): the model's masses and stiffnesses span too many orders of magnitude for the eigenvalue solve; bring the extreme values closer",
        hz_text(*.hz),
        hz_exact(*.hz0),
        hz_exact(*.hz)
    )]
    Drift { hz: f64, hz0: f64, drift: f64 },
    #[error(
        "the links of this model form loops too wide for the band solver used to refine the modes: use fewer cross links"
    )]
    LoopsTooWide,
}

/// A frequency for a message, 4 significant digits: fixed decimals read
/// 0.000000 Hz for a mode near 1e-7 Hz.
fn hz_text(v: f64) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    let a = v.abs();
    if !(1e-3..1e6).contains(&a) {
        return format!("{v:.3e}");
    }
    let decimals = (3 - a.log10().floor() as i32).max(0) as usize;
    format!("{v:.decimals$}")
}

/// A frequency with 7 significant digits, where two close values are compared.
fn hz_exact(v: f64) -> String {
    format!("{v:.6e}")
}
